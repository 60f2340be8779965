#include "viz/rasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"

namespace sinew::viz {
namespace {

constexpr int kSupersample = 2;  // samples per pixel along each axis

// World pose of every vertex and normal of a part.
struct PosedPart {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
};

PosedPart Pose(const VisualPart& part, const Transform& X_GB) {
  PosedPart out;
  const Transform X_GG = X_GB * part.X_BG;  // part frame in ground
  // Normals transform with the inverse transpose of R * diag(scale).
  const Vec3 inv_scale = part.scale.cwiseInverse();
  const TriangleMesh& m = *part.mesh;
  out.positions.reserve(m.positions.size());
  out.normals.reserve(m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    out.positions.push_back(X_GG * part.scale.cwiseProduct(m.positions[i].cast<double>()));
    const Vec3 n = i < m.normals.size() ? Vec3(m.normals[i].cast<double>()) : Vec3::UnitY();
    out.normals.push_back((X_GG.R * inv_scale.cwiseProduct(n)).normalized());
  }
  return out;
}

}  // namespace

Vec3 ParseViewDirection(const std::string& view) {
  if (view == "front") return Vec3(1, 0.15, 0);
  if (view == "back") return Vec3(-1, 0.15, 0);
  if (view == "right") return Vec3(0, 0.15, 1);
  if (view == "left") return Vec3(0, 0.15, -1);
  if (view == "top") return Vec3(0.01, 1, 0);
  if (view == "iso") return Vec3(1.0, 0.35, 0.8);
  throw Error("unknown view '" + view + "' (front, back, right, left, top or iso)");
}

std::pair<Vec3, Vec3> SceneBounds(const VisualScene& scene, const std::vector<Transform>& X_GB) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const VisualBody& body : scene.bodies) {
    if (body.body >= static_cast<int>(X_GB.size())) continue;
    for (const VisualPart& part : body.parts) {
      if (!part.mesh) continue;
      for (const Vec3& p : Pose(part, X_GB[body.body]).positions) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
  }
  if (!(lo.x() <= hi.x())) return {Vec3::Constant(-1), Vec3::Constant(1)};
  return {lo, hi};
}

Camera FrameCamera(const std::pair<Vec3, Vec3>& bounds, const Vec3& direction, double aspect) {
  Camera camera;
  camera.target = 0.5 * (bounds.first + bounds.second);
  const double radius = std::max(0.5 * (bounds.second - bounds.first).norm(), 1e-3);
  const double fov = std::min(camera.fov_y, 2 * std::atan(aspect * std::tan(camera.fov_y / 2)));
  camera.eye = camera.target + direction.normalized() * (1.05 * radius / std::sin(fov / 2));
  return camera;
}

Image RenderScene(const VisualScene& scene, const std::vector<Transform>& X_GB,
                  const Camera& camera, const RenderOptions& options) {
  if (options.width <= 0 || options.height <= 0 || options.width > 16384 ||
      options.height > 16384) {
    throw Error("render: image size must be between 1 and 16384 pixels");
  }
  const int w = options.width * kSupersample, h = options.height * kSupersample;
  // Camera basis: z from target to eye (looking down -z), x right, y up.
  const Vec3 cz = (camera.eye - camera.target).normalized();
  Vec3 cx = camera.up.cross(cz);
  if (cx.norm() < 1e-9) cx = Vec3::UnitX().cross(cz);
  cx.normalize();
  const Vec3 cy = cz.cross(cx);
  const double focal = 0.5 * h / std::tan(0.5 * camera.fov_y);  // pixels
  const double near = 1e-3 * (camera.eye - camera.target).norm();
  // Lights in ground: a key light from above-front-right and a fill light from the camera.
  const Vec3 key = (Vec3(0.5, 1.0, 0.6)).normalized();
  std::vector<float> depth(static_cast<size_t>(w) * h, std::numeric_limits<float>::infinity());
  std::vector<Vec3> color(static_cast<size_t>(w) * h, options.background);

  for (const VisualBody& body : scene.bodies) {
    if (body.body >= static_cast<int>(X_GB.size())) continue;
    for (const VisualPart& part : body.parts) {
      if (!part.mesh || part.mesh->empty()) continue;
      const PosedPart posed = Pose(part, X_GB[body.body]);
      // Camera-space coordinates and screen projections of every vertex.
      const size_t n = posed.positions.size();
      std::vector<Vec3> view(n);
      for (size_t i = 0; i < n; ++i) {
        const Vec3 d = posed.positions[i] - camera.eye;
        view[i] = Vec3(d.dot(cx), d.dot(cy), -d.dot(cz));  // z = distance in front of the eye
      }
      for (const auto& t : part.mesh->triangles) {
        const Vec3 &a = view[t[0]], &b = view[t[1]], &c = view[t[2]];
        if (a.z() < near || b.z() < near || c.z() < near) continue;  // behind the camera
        double sx[3], sy[3];
        const Vec3* v[3] = {&a, &b, &c};
        for (int k = 0; k < 3; ++k) {
          sx[k] = 0.5 * w + focal * v[k]->x() / v[k]->z();
          sy[k] = 0.5 * h - focal * v[k]->y() / v[k]->z();
        }
        const double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
        if (std::abs(area) < 1e-12) continue;
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min({sx[0], sx[1], sx[2]}))));
        const int x1 =
            std::min(w - 1, static_cast<int>(std::ceil(std::max({sx[0], sx[1], sx[2]}))));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min({sy[0], sy[1], sy[2]}))));
        const int y1 =
            std::min(h - 1, static_cast<int>(std::ceil(std::max({sy[0], sy[1], sy[2]}))));
        for (int y = y0; y <= y1; ++y) {
          for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            // Barycentric weights from edge functions (either winding: double-sided).
            double l0 = ((sx[1] - px) * (sy[2] - py) - (sx[2] - px) * (sy[1] - py)) / area;
            double l1 = ((sx[2] - px) * (sy[0] - py) - (sx[0] - px) * (sy[2] - py)) / area;
            double l2 = 1 - l0 - l1;
            if (l0 < 0 || l1 < 0 || l2 < 0) continue;
            // Perspective-correct interpolation: weights over depth.
            const double w0 = l0 / a.z(), w1 = l1 / b.z(), w2 = l2 / c.z();
            const double z = 1 / (w0 + w1 + w2);
            const size_t at = static_cast<size_t>(y) * w + x;
            if (z >= depth[at]) continue;
            depth[at] = static_cast<float>(z);
            Vec3 normal =
                (w0 * posed.normals[t[0]] + w1 * posed.normals[t[1]] + w2 * posed.normals[t[2]])
                    .normalized();
            // Light both sides: turn the normal towards the viewer.
            const Vec3 point = z * (w0 * posed.positions[t[0]] + w1 * posed.positions[t[1]] +
                                    w2 * posed.positions[t[2]]);
            if (normal.dot(camera.eye - point) < 0) normal = -normal;
            const double diffuse =
                0.25 + 0.55 * std::max(0.0, normal.dot(key)) + 0.3 * std::max(0.0, normal.dot(cz));
            const Vec3 shaded = (part.color * diffuse).cwiseMin(Vec3::Ones());
            color[at] = part.opacity * shaded + (1 - part.opacity) * color[at];
          }
        }
      }
    }
  }
  // Average each block of samples into one pixel.
  Image image(options.width, options.height);
  const double norm = 1.0 / (kSupersample * kSupersample);
  for (int y = 0; y < options.height; ++y) {
    for (int x = 0; x < options.width; ++x) {
      Vec3 sum = Vec3::Zero();
      for (int j = 0; j < kSupersample; ++j) {
        for (int i = 0; i < kSupersample; ++i) {
          sum += color[static_cast<size_t>(y * kSupersample + j) * w + x * kSupersample + i];
        }
      }
      uint8_t* p = image.At(x, y);
      for (int k = 0; k < 3; ++k) {
        p[k] = static_cast<uint8_t>(std::lround(std::clamp(sum[k] * norm, 0.0, 1.0) * 255));
      }
    }
  }
  return image;
}

}  // namespace sinew::viz
