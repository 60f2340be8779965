// Builders of OpenSim's bushings (BushingForce, FunctionBasedBushingForce,
// ExpressionBasedBushingForce): two frames, a stiffness law and damping.
#include <sinew/forces/bushing_force.h>
#include <sinew/forces/expression_based_forces.h>
#include <sinew/functions/constant.h>
#include <sinew/model/element_values.h>
#include <sinew/opensim/internal/force_registry.h>

#include <array>

namespace sinew::opensim::internal {
namespace {

forces::LinkedFrames LinkedFramesOf(const ForceBuildInput& in) {
  forces::LinkedFrames frames;
  std::tie(frames.body1, frames.X_B1F) = MapFrame(in, "frame1");
  std::tie(frames.body2, frames.X_B2M) = MapFrame(in, "frame2");
  return frames;
}

// [rotational; translational] from two Vec3 properties (default zero). Simbody refuses negative
// bushing constants, so Sinew does too.
Vec6 RotationalTranslational(const ForceBuildInput& in, const char* rotational,
                             const char* translational) {
  Vec6 values;
  values << in.values.Vector3(rotational, Vec3::Zero()),
      in.values.Vector3(translational, Vec3::Zero());
  if ((values.array() < 0.0).any()) {
    in.values.Fail(std::string("<") + rotational + "> and <" + translational +
                   "> must not be negative");
  }
  return values;
}

Vec6 DampingOf(const ForceBuildInput& in) {
  return RotationalTranslational(in, "rotational_damping", "translational_damping");
}

std::shared_ptr<engine::ForceElement> MakeBushing(
    const ForceBuildInput& in, std::shared_ptr<const forces::BushingStiffness> stiffness) {
  return std::make_shared<forces::BushingForce>(in.force.name, LinkedFramesOf(in),
                                                std::move(stiffness), DampingOf(in));
}

}  // namespace

std::shared_ptr<engine::ForceElement> BuildBushingForce(const ForceBuildInput& in) {
  return MakeBushing(in, std::make_shared<forces::LinearBushingStiffness>(RotationalTranslational(
                             in, "rotational_stiffness", "translational_stiffness")));
}

std::shared_ptr<engine::ForceElement> BuildFunctionBasedBushingForce(const ForceBuildInput& in) {
  static const char* const kProperties[6] = {"m_x_theta_x_function", "m_y_theta_y_function",
                                             "m_z_theta_z_function", "f_x_delta_x_function",
                                             "f_y_delta_y_function", "f_z_delta_z_function"};
  std::array<functions::FunctionPtr, 6> functions;
  for (int i = 0; i < 6; ++i) {
    const auto it = in.force.functions.find(kProperties[i]);
    // OpenSim's default for each is Constant(0).
    functions[i] = it != in.force.functions.end() && !it->second.empty()
                       ? it->second.front()
                       : std::make_shared<functions::Constant>(0.0);
  }
  return MakeBushing(in, std::make_shared<forces::FunctionBushingStiffness>(functions));
}

std::shared_ptr<engine::ForceElement> BuildExpressionBasedBushingForce(const ForceBuildInput& in) {
  static const char* const kProperties[6] = {"Mx_expression", "My_expression", "Mz_expression",
                                             "Fx_expression", "Fy_expression", "Fz_expression"};
  std::array<std::shared_ptr<const forces::Expression>, 6> expressions;
  for (int i = 0; i < 6; ++i) {
    expressions[i] = ParseExpression(in, kProperties[i], "0.0",
                                     forces::ExpressionBushingStiffness::VariableNames());
  }
  return MakeBushing(in, std::make_shared<forces::ExpressionBushingStiffness>(expressions));
}

}  // namespace sinew::opensim::internal
