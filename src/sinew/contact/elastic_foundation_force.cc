#include <sinew/contact/elastic_foundation_force.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>

#include <utility>

namespace sinew::contact {
namespace {

// The point of `other` (posed at X_GO) nearest to the point p_G, when p_G is inside it.
std::optional<Vec3> NearestSurfacePointInside(const ContactShape& other, const Transform& X_GO,
                                              const Vec3& p_G) {
  if (other.kind == ShapeKind::kHalfSpace) {
    const Vec3 p_O = X_GO.Inverse() * p_G;
    if (!(p_O.x() > 0.0)) return std::nullopt;
    return X_GO * Vec3(0.0, p_O.y(), p_O.z());
  }
  if (other.kind == ShapeKind::kSphere) {
    const Vec3 r = p_G - X_GO.p;
    const double distance = r.norm();
    if (!(distance < other.radius) || distance == 0.0) return std::nullopt;
    return Vec3(X_GO.p + other.radius / distance * r);
  }
  return std::nullopt;
}

}  // namespace

ElasticFoundationForce::ElasticFoundationForce(std::string name, std::vector<ContactShape> shapes,
                                               std::vector<ContactMaterial> materials,
                                               double transition_velocity,
                                               std::vector<RecordGroup> groups)
    : ContactForce(std::move(name), std::move(groups)),
      shapes_(std::move(shapes)),
      materials_(std::move(materials)),
      springs_(shapes_.size()),
      transition_velocity_(transition_velocity) {
  for (size_t s = 0; s < shapes_.size(); ++s) {
    if (shapes_[s].kind != ShapeKind::kMesh) continue;
    const ShapeMesh& mesh = *shapes_[s].mesh;
    for (const std::array<int, 3>& t : mesh.triangles) {
      const Vec3& a = mesh.vertices[t[0]];
      const Vec3& b = mesh.vertices[t[1]];
      const Vec3& c = mesh.vertices[t[2]];
      springs_[s].push_back({(a + b + c) / 3.0, 0.5 * (b - a).cross(c - a).norm()});
    }
  }
  for (int i = 0; i < static_cast<int>(shapes_.size()); ++i) {
    if (shapes_[i].kind != ShapeKind::kMesh) continue;
    for (int j = 0; j < static_cast<int>(shapes_.size()); ++j) {
      if (j != i && shapes_[j].body != shapes_[i].body && shapes_[j].kind != ShapeKind::kMesh)
        pairs_.emplace_back(i, j);
    }
  }
}

double ElasticFoundationForce::VisitContacts(const engine::State& state,
                                             ContactSink& sink) const {
  double energy = 0.0;
  for (const auto& [m, o] : pairs_) {
    const ContactShape& mesh = shapes_[m];
    const ContactShape& other = shapes_[o];
    const ContactMaterial& material = materials_[m];
    const engine::BodyState& mesh_body = state.bodies[mesh.body];
    const engine::BodyState& other_body = state.bodies[other.body];
    const Transform X_GM = engine::PoseOf(mesh_body) * mesh.X_BC;
    const Transform X_GO = engine::PoseOf(other_body) * other.X_BC;
    for (const Spring& spring : springs_[m]) {
      const Vec3 p_GQ = X_GM * spring.p_CQ;
      const std::optional<Vec3> p_GP = NearestSurfacePointInside(other, X_GO, p_GQ);
      if (!p_GP) continue;
      const Vec3 displacement = *p_GP - p_GQ;
      const double x = displacement.norm();
      if (x == 0.0) continue;
      const Vec3 n_G = displacement / x;
      const Vec3 v_G =
          engine::PointVelocity(other_body, *p_GP) - engine::PointVelocity(mesh_body, *p_GP);
      const double v_normal = v_G.dot(n_G);
      const Vec3 v_tangent = v_G - v_normal * n_G;
      const double kA = material.stiffness * spring.area;
      energy += 0.5 * kA * x * x;
      const double f = kA * x * (1.0 + material.dissipation * v_normal);
      if (!(f > 0.0)) continue;
      Vec3 f_G = f * n_G;
      const double v_slip = v_tangent.norm();
      if (v_slip != 0.0) {
        f_G += FrictionForce(f, v_slip, material.static_friction, material.dynamic_friction,
                             material.viscous_friction, transition_velocity_) *
               v_tangent / v_slip;
      }
      // The mesh (body 2 of the load) gets f_G, the other shape its opposite.
      sink.Add({other.body, mesh.body, *p_GP, f_G});
    }
  }
  return energy;
}

}  // namespace sinew::contact
