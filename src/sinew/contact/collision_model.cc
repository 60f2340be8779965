#include <sinew/contact/collision_model.h>

#include <algorithm>
#include <map>
#include <utility>

namespace sinew::contact {
namespace {

constexpr double kShortestSegment = 1e-3;  // m
// Two joints of a body at one point (Rajagopal2015's knee and patella on the femur) give one
// segment: identical cylinders are one shape, and as two they would touch twice.
constexpr double kSameEnd = 1e-9;  // m

}  // namespace

bool CollisionModel::CanCollide(int a, int b) const {
  if (a == b) return false;
  if (a == model::kGroundIndex || b == model::kGroundIndex) return true;
  return std::none_of(jointed.begin(), jointed.end(), [&](const std::pair<int, int>& p) {
    return (p.first == a && p.second == b) || (p.first == b && p.second == a);
  });
}

bool IsClosedConvex(const ShapeMesh& mesh) {
  if (mesh.triangles.empty()) return false;
  // Closed: each undirected edge in exactly two triangles.
  std::map<std::pair<int, int>, int> edges;
  const int num_vertices = static_cast<int>(mesh.vertices.size());
  for (const std::array<int, 3>& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a < 0 || a >= num_vertices) return false;
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  }
  if (std::any_of(edges.begin(), edges.end(), [](const auto& e) { return e.second != 2; }))
    return false;
  // Convex: each triangle's plane supports the vertices (all on one side of it).
  Vec3 low = mesh.vertices.front(), high = low;
  for (const Vec3& v : mesh.vertices) low = low.cwiseMin(v), high = high.cwiseMax(v);
  const double tolerance = 1e-9 * (high - low).norm();
  for (const std::array<int, 3>& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    if (n.norm() == 0.0) continue;  // a degenerate triangle has no plane of its own
    const Vec3 u = n.normalized();
    double above = 0.0, below = 0.0;
    for (const Vec3& v : mesh.vertices) {
      const double h = u.dot(v - a);
      above = std::max(above, h), below = std::min(below, h);
    }
    if (above > tolerance && below < -tolerance) return false;
  }
  return true;
}

int MeshPairHull(const MeshPairSide& a, const MeshPairSide& b) {
  if (!a.moves && !b.moves) return -1;
  if (b.moves && b.closed_convex) return 1;
  if (a.moves && a.closed_convex) return 0;
  return b.moves ? 1 : 0;
}

void AddGroundPlane(CollisionModel& model, double height, int material) {
  CollisionGeometry plane;
  plane.name = kGroundPlaneName;
  plane.kind = CollisionShapeKind::kHalfSpace;
  // S's x axis points down (-y): its solid x > 0 is y < height.
  Mat3 R_GS;
  R_GS << 0, 1, 0, -1, 0, 0, 0, 0, 1;  // columns: x_S = -y, y_S = x, z_S = z
  plane.X_BS = Transform(R_GS, Vec3(0, height, 0));
  plane.material = material;
  model.geometry.push_back(plane);
}

CollisionModel BuildCollisionModel(const model::ModelSpec& spec, const std::vector<int>& depth,
                                   int family_1, int family_2) {
  CollisionModel model;
  model.family.assign(spec.bodies.size(), 0);
  for (size_t b = 1; b < spec.bodies.size(); ++b) {
    model.family[b] = depth[b] % 2 == 1 ? family_1 : family_2;
  }
  for (const model::JointSpec& j : spec.joints)
    model.jointed.emplace_back(j.parent_body, j.child_body);
  // One segment per distinct joint point on a body other than ground; the radius from every
  // joint's segment, as the seed's joints give them.
  std::vector<double> lengths;
  const auto made = [&](int body, const Vec3& p_BJ) {
    return std::any_of(model.shapes.begin(), model.shapes.end(), [&](const CollisionCylinder& c) {
      return c.body == body && (c.p_B_end - p_BJ).norm() < kSameEnd;
    });
  };
  for (const model::JointSpec& j : spec.joints) {
    for (const auto& [body, p_BJ] :
         {std::pair{j.parent_body, j.X_PF.p}, std::pair{j.child_body, j.X_BM.p}}) {
      if (body == model::kGroundIndex || p_BJ.norm() < kShortestSegment) continue;
      lengths.push_back(p_BJ.norm());
      if (!made(body, p_BJ)) model.shapes.push_back({body, Vec3::Zero(), p_BJ, 0.0});
    }
  }
  if (lengths.empty()) return model;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double radius = std::max(0.1 * lengths[lengths.size() / 2], kShortestSegment);
  for (CollisionCylinder& c : model.shapes) c.radius = radius;
  return model;
}

}  // namespace sinew::contact
