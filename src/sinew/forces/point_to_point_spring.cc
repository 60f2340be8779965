#include <sinew/engine/loads.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/forces/point_to_point_spring.h>
#include <sinew/forces/two_frame_linker.h>

#include <utility>

namespace sinew::forces {

PointToPointSpring::PointToPointSpring(std::string name, int body1, const Vec3& point1, int body2,
                                       const Vec3& point2, double stiffness, double rest_length)
    : name_(std::move(name)),
      body1_(body1),
      body2_(body2),
      point1_(point1),
      point2_(point2),
      stiffness_(stiffness),
      rest_length_(rest_length) {}

namespace {
// The vector from point1 to point2, in G.
Vec3 Span(const engine::State& s, int b1, const Vec3& p1, int b2, const Vec3& p2) {
  return engine::PoseOf(s.bodies[b2]) * p2 - engine::PoseOf(s.bodies[b1]) * p1;
}
}  // namespace

double PointToPointSpring::CalcLength(const engine::ForceContext& context) const {
  return Span(context.state, body1_, point1_, body2_, point2_).norm();
}

Vec3 PointToPointSpring::CalcForceOnBody1(const engine::State& state) const {
  const Vec3 r = Span(state, body1_, point1_, body2_, point2_);
  const double d = r.norm();
  if (!(d > 0.0)) return Vec3::Zero();
  return stiffness_ * (d - rest_length_) / d * r;
}

void PointToPointSpring::AddLoads(const engine::ForceContext& context, engine::Loads& loads) const {
  const Vec3 f_G = CalcForceOnBody1(context.state);
  loads.AddForceAtPoint(context.state, body1_, point1_, f_G);
  loads.AddForceAtPoint(context.state, body2_, point2_, -f_G);
}

std::vector<std::string> PointToPointSpring::RecordLabels(const engine::System& system) const {
  std::vector<std::string> labels;
  for (int body : {body1_, body2_}) {
    for (const char* kind : {".force.", ".point."}) {
      for (const char* axis : {"X", "Y", "Z"}) {
        labels.push_back(name_ + "." + system.bodies()[body].name + kind + axis);
      }
    }
  }
  return labels;
}

void PointToPointSpring::CalcRecordValues(const engine::ForceContext& context,
                                          std::vector<double>& values) const {
  const engine::State& s = context.state;
  const Vec3 f_G = CalcForceOnBody1(s);
  const Vec3 p_G1 = engine::PoseOf(s.bodies[body1_]) * point1_;
  const Vec3 p_G2 = engine::PoseOf(s.bodies[body2_]) * point2_;
  for (const Vec3& v : {f_G, p_G1, Vec3(-f_G), p_G2})
    values.insert(values.end(), v.begin(), v.end());
}

std::optional<engine::ForceSupport> PointToPointSpring::Support() const {
  return SupportOfBodies(body1_, body2_);
}

double PointToPointSpring::CalcPotentialEnergy(const engine::ForceContext& context) const {
  const double stretch = CalcLength(context) - rest_length_;
  return 0.5 * stiffness_ * stretch * stretch;
}

}  // namespace sinew::forces
