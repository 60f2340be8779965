#include <sinew/engine/loads.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/state.h>
#include <sinew/forces/expression_based_forces.h>
#include <sinew/forces/two_frame_linker.h>

#include <utility>

namespace sinew::forces {

ExpressionBasedCoordinateForce::ExpressionBasedCoordinateForce(
    std::string name, int coordinate, std::shared_ptr<const Expression> expression)
    : name_(std::move(name)), coordinate_(coordinate), expression_(std::move(expression)) {}

double ExpressionBasedCoordinateForce::CalcForce(const engine::ForceContext& context) const {
  const double values[2] = {context.state.q[coordinate_], context.state.u[coordinate_]};
  return expression_->Evaluate(values);
}

void ExpressionBasedCoordinateForce::AddLoads(const engine::ForceContext& context,
                                              engine::Loads& loads) const {
  loads.AddGeneralizedForce(coordinate_, CalcForce(context));
}

std::optional<engine::ForceSupport> ExpressionBasedCoordinateForce::Support() const {
  return engine::ForceSupport{{}, {coordinate_}};
}

ExpressionBasedPointToPointForce::ExpressionBasedPointToPointForce(
    std::string name, int body1, const Vec3& point1, int body2, const Vec3& point2,
    std::shared_ptr<const Expression> expression)
    : name_(std::move(name)),
      body1_(body1),
      body2_(body2),
      point1_(point1),
      point2_(point2),
      expression_(std::move(expression)) {}

void ExpressionBasedPointToPointForce::AddLoads(const engine::ForceContext& context,
                                                engine::Loads& loads) const {
  const engine::State& s = context.state;
  const engine::BodyState& b1 = s.bodies[body1_];
  const engine::BodyState& b2 = s.bodies[body2_];
  const Vec3 p_GP1 = engine::PoseOf(b1) * point1_;
  const Vec3 p_GP2 = engine::PoseOf(b2) * point2_;
  const Vec3 r_G = p_GP2 - p_GP1;
  const double d = r_G.norm();
  if (!(d > 0.0)) return;
  const Vec3 v_rel_G = engine::PointVelocity(b2, p_GP2) - engine::PointVelocity(b1, p_GP1);
  const double values[2] = {d, v_rel_G.dot(r_G) / d};
  const Vec3 f_G = expression_->Evaluate(values) / d * r_G;
  loads.AddForceAtPoint(s, body1_, point1_, f_G);
  loads.AddForceAtPoint(s, body2_, point2_, -f_G);
}

std::optional<engine::ForceSupport> ExpressionBasedPointToPointForce::Support() const {
  return SupportOfBodies(body1_, body2_);
}

const std::vector<std::string>& ExpressionBushingStiffness::VariableNames() {
  static const std::vector<std::string> names = {"theta_x", "theta_y", "theta_z",
                                                 "delta_x", "delta_y", "delta_z"};
  return names;
}

Vec6 ExpressionBushingStiffness::Calc(const Vec6& q) const {
  Vec6 fk;
  for (int i = 0; i < 6; ++i) fk[i] = expressions_[i]->Evaluate({q.data(), 6});
  return fk;
}

}  // namespace sinew::forces
