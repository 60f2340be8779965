#include <sinew/contact/collision_model.h>

#include <algorithm>

namespace sinew::contact {
namespace {

constexpr double kShortestSegment = 1e-3;  // m

}  // namespace

bool CollisionModel::CanCollide(int a, int b) const {
  if (a == b) return false;
  if (a == model::kGroundIndex || b == model::kGroundIndex) return true;
  return std::none_of(jointed.begin(), jointed.end(), [&](const std::pair<int, int>& p) {
    return (p.first == a && p.second == b) || (p.first == b && p.second == a);
  });
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
  // One segment per joint end that lies on a body other than ground.
  std::vector<double> lengths;
  for (const model::JointSpec& j : spec.joints) {
    for (const auto& [body, p_BJ] :
         {std::pair{j.parent_body, j.X_PF.p}, std::pair{j.child_body, j.X_BM.p}}) {
      if (body == model::kGroundIndex || p_BJ.norm() < kShortestSegment) continue;
      model.shapes.push_back({body, Vec3::Zero(), p_BJ, 0.0});
      lengths.push_back(p_BJ.norm());
    }
  }
  if (lengths.empty()) return model;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double radius = std::max(0.1 * lengths[lengths.size() / 2], kShortestSegment);
  for (CollisionCylinder& c : model.shapes) c.radius = radius;
  return model;
}

}  // namespace sinew::contact
