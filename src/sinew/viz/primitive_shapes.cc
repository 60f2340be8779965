#include <sinew/viz/primitive_shapes.h>

#include <cmath>
#include <numbers>

namespace sinew::viz {
namespace {

constexpr int kSegments = 24;  // around an axis
constexpr int kRings = 12;     // pole to pole
constexpr float kPi = std::numbers::pi_v<float>;

uint32_t AddVertex(io::TriangleMesh& m, const io::Vec3f& p, const io::Vec3f& n) {
  m.positions.push_back(p);
  m.normals.push_back(n.normalized());
  return static_cast<uint32_t>(m.positions.size() - 1);
}

// A flat disc at height y facing `up` (+1 or -1), radius 1 around the y axis.
void AddDisc(io::TriangleMesh& m, float y, float up) {
  const uint32_t center = AddVertex(m, io::Vec3f(0, y, 0), io::Vec3f(0, up, 0));
  const uint32_t first = static_cast<uint32_t>(m.positions.size());
  for (int i = 0; i < kSegments; ++i) {
    const float a = 2 * kPi * i / kSegments;
    AddVertex(m, io::Vec3f(std::cos(a), y, std::sin(a)), io::Vec3f(0, up, 0));
  }
  for (int i = 0; i < kSegments; ++i) {
    const uint32_t a = first + i, b = first + (i + 1) % kSegments;
    // Counter-clockwise seen from the side the normal points to.
    if (up > 0) {
      m.triangles.push_back({center, b, a});
    } else {
      m.triangles.push_back({center, a, b});
    }
  }
}

// Adds a triangle unless two of its corners coincide (the poles of the UV sphere).
void AddTriangle(io::TriangleMesh& m, uint32_t a, uint32_t b, uint32_t c) {
  const auto& p = m.positions;
  if ((p[a] - p[b]).norm() < 1e-6f || (p[b] - p[c]).norm() < 1e-6f ||
      (p[c] - p[a]).norm() < 1e-6f) {
    return;
  }
  m.triangles.push_back({a, b, c});
}

// Connects rings of kSegments + 1 vertices (seam duplicated) starting at `first`.
void StitchRings(io::TriangleMesh& m, uint32_t first, int rings) {
  const uint32_t stride = kSegments + 1;
  for (int r = 0; r + 1 < rings; ++r) {
    for (int i = 0; i < kSegments; ++i) {
      const uint32_t a = first + r * stride + i, b = a + 1, c = a + stride, d = c + 1;
      AddTriangle(m, a, c, b);
      AddTriangle(m, b, c, d);
    }
  }
}

}  // namespace

std::shared_ptr<const io::TriangleMesh> UnitSphere() {
  static const auto mesh = [] {
    auto m = std::make_shared<io::TriangleMesh>();
    // Rings from the north pole (y = 1) to the south pole; angle a runs from +x towards -z
    // so that the stitched quads face outwards.
    for (int r = 0; r <= kRings; ++r) {
      const float polar = kPi * r / kRings;
      for (int i = 0; i <= kSegments; ++i) {
        const float a = 2 * kPi * i / kSegments;
        const io::Vec3f p(std::sin(polar) * std::cos(a), std::cos(polar),
                          -std::sin(polar) * std::sin(a));
        AddVertex(*m, p, p);
      }
    }
    StitchRings(*m, 0, kRings + 1);
    return m;
  }();
  return mesh;
}

std::shared_ptr<const io::TriangleMesh> UnitCylinder() {
  static const auto mesh = [] {
    auto m = std::make_shared<io::TriangleMesh>();
    for (float y : {1.0f, -1.0f}) {
      for (int i = 0; i <= kSegments; ++i) {
        const float a = 2 * kPi * i / kSegments;
        const io::Vec3f n(std::cos(a), 0, -std::sin(a));
        AddVertex(*m, io::Vec3f(n.x(), y, n.z()), n);
      }
    }
    StitchRings(*m, 0, 2);
    AddDisc(*m, 1, 1);
    AddDisc(*m, -1, -1);
    return m;
  }();
  return mesh;
}

std::shared_ptr<const io::TriangleMesh> UnitBox() {
  static const auto mesh = [] {
    auto m = std::make_shared<io::TriangleMesh>();
    for (int axis = 0; axis < 3; ++axis) {
      for (float sign : {1.0f, -1.0f}) {
        io::Vec3f n = io::Vec3f::Zero();
        n[axis] = sign;
        // u, v span the face with u x v = n.
        io::Vec3f u = io::Vec3f::Zero(), v = io::Vec3f::Zero();
        u[(axis + 1) % 3] = 1;
        v[(axis + 2) % 3] = sign;
        const uint32_t a = AddVertex(*m, n - u - v, n), b = AddVertex(*m, n + u - v, n),
                       c = AddVertex(*m, n + u + v, n), d = AddVertex(*m, n - u + v, n);
        m->triangles.push_back({a, b, c});
        m->triangles.push_back({a, c, d});
      }
    }
    return m;
  }();
  return mesh;
}

std::shared_ptr<const io::TriangleMesh> UnitCone() {
  static const auto mesh = [] {
    auto m = std::make_shared<io::TriangleMesh>();
    const float slope = 1.0f / std::sqrt(2.0f);  // normal tilt for height 1, radius 1
    for (int i = 0; i < kSegments; ++i) {
      const float a0 = 2 * kPi * i / kSegments, a1 = 2 * kPi * (i + 1) / kSegments;
      const float am = 0.5f * (a0 + a1);
      const io::Vec3f n0(std::cos(a0) * slope, slope, -std::sin(a0) * slope);
      const io::Vec3f n1(std::cos(a1) * slope, slope, -std::sin(a1) * slope);
      const io::Vec3f nm(std::cos(am) * slope, slope, -std::sin(am) * slope);
      const uint32_t b0 = AddVertex(*m, io::Vec3f(std::cos(a0), 0, -std::sin(a0)), n0);
      const uint32_t b1 = AddVertex(*m, io::Vec3f(std::cos(a1), 0, -std::sin(a1)), n1);
      const uint32_t apex = AddVertex(*m, io::Vec3f(0, 1, 0), nm);
      m->triangles.push_back({b0, b1, apex});
    }
    AddDisc(*m, 0, -1);
    return m;
  }();
  return mesh;
}

std::shared_ptr<const io::TriangleMesh> MakeTorus(double tube_ratio) {
  auto m = std::make_shared<io::TriangleMesh>();
  const float t = static_cast<float>(tube_ratio);
  // Rings around the tube; each ring is a circle of kSegments + 1 vertices.
  for (int r = 0; r <= kSegments; ++r) {
    const float a = 2 * kPi * r / kSegments;  // around y
    const io::Vec3f radial(std::cos(a), 0, -std::sin(a));
    for (int i = 0; i <= kSegments; ++i) {
      const float b = 2 * kPi * i / kSegments;  // around the tube
      const io::Vec3f n = radial * std::cos(b) + io::Vec3f(0, std::sin(b), 0);
      AddVertex(*m, radial + t * n, n);
    }
  }
  StitchRings(*m, 0, kSegments + 1);
  return m;
}

}  // namespace sinew::viz
