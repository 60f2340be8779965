// Path actuators, Thelen2003Muscle and Millard2012EquilibriumMuscle through the OpenSim parser
// and the engine, against closed forms: a PathActuator's constant tension accelerating a block,
// activation under a constant excitation (the separable first-order equation), a muscle at
// equilibrium staying there, and the errors of bad muscle parameters; Rajagopal2016's 80
// Millard muscles built and simulated.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/pose.h>
#include <sinew/functions/constant.h>
#include <sinew/io/osim_reader.h>
#include <sinew/muscles/path_actuator.h>
#include <sinew/opensim/parser.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "slider_model.h"

namespace sinew::muscles {
namespace {

std::string Thelen(const std::string& extra) {
  return std::string(R"(<Thelen2003Muscle name="musc">)") + kPath +
         R"(<max_isometric_force>500</max_isometric_force><optimal_fiber_length>0.12</optimal_fiber_length>
<tendon_slack_length>0.27</tendon_slack_length><pennation_angle_at_optimal>0.2</pennation_angle_at_optimal>
<activation_time_constant>0.01</activation_time_constant><deactivation_time_constant>0.04</deactivation_time_constant>
<default_activation>0.2</default_activation>)" +
         extra + "</Thelen2003Muscle>";
}

std::string Millard(const std::string& extra) {
  return std::string(R"(<Millard2012EquilibriumMuscle name="musc">)") + kPath +
         R"(<max_isometric_force>500</max_isometric_force><optimal_fiber_length>0.12</optimal_fiber_length>
<tendon_slack_length>0.27</tendon_slack_length><pennation_angle_at_optimal>0.2</pennation_angle_at_optimal>
<activation_time_constant>0.01</activation_time_constant><deactivation_time_constant>0.04</deactivation_time_constant>
<default_activation>0.2</default_activation>)" +
         extra + "</Millard2012EquilibriumMuscle>";
}

std::string DeGroote() {
  return std::string(R"(<DeGrooteFregly2016Muscle name="musc">)") + kPath +
         R"(<max_isometric_force>500</max_isometric_force><optimal_fiber_length>0.12</optimal_fiber_length>
<tendon_slack_length>0.27</tendon_slack_length><pennation_angle_at_optimal>0.2</pennation_angle_at_optimal>
<default_activation>0.2</default_activation></DeGrooteFregly2016Muscle>)";
}

TEST(PathActuatorTest, ConstantTensionAcceleratesTheBlockAsTheClosedForm) {
  auto parsed = Parse(
      SliderModel(std::string(R"(<PathActuator name="act"><optimal_force>30</optimal_force>)") +
                      kPath + "</PathActuator>",
                  false));
  parsed->parser.SetExcitationFunction("act", std::make_shared<functions::Constant>(0.5));
  auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-10});
  integrator->SetController(parsed->parser.GetController());
  engine::State state = engine::MakeDefaultState(*parsed->system);
  integrator->StepTo(state, 0.3);
  // Tension 15 N pulls the block towards the ground point (reached at x = -0.3 m, t = 0.33 s):
  // x = 0.1 - 15 t^2 / (2 * 2 kg).
  EXPECT_NEAR(engine::GetCoordinateValue(*parsed->system, state, "x"), 0.1 - 15.0 * 0.09 / 4.0,
              1e-10);
  EXPECT_NEAR(engine::GetCoordinateSpeed(*parsed->system, state, "x"), -15.0 * 0.3 / 2.0, 1e-9);
}

TEST(PathSpringTest, StretchedSpringOscillatesAsTheClosedFormAndConservesEnergy) {
  ExpectStretchedSpringOscillatesAsTheClosedForm(kPath);
  // A spring without its properties (OpenSim's defaults are NaN) is refused by name.
  EXPECT_THROW(Parse(SliderModel(
                   std::string(R"(<PathSpring name="spring">)") + kPath + "</PathSpring>", false)),
               Error);
}

// Activation of the muscle "musc" (default activation 0.2, activation time constant 0.01 s)
// under the constant excitation 0.8: da/dt = (u - a) / (tau (0.5 + 1.5 a)) integrates to
// t(a) = tau [-1.5 (a - a0) - (0.5 + 1.5 u) ln((u - a) / (u - a0))].
void ExpectActivationFollowsTheClosedForm(const std::string& muscle) {
  auto parsed = Parse(SliderModel(muscle, true));
  const double u = 0.8, a0 = 0.2, tau = 0.01;
  parsed->parser.SetExcitationFunction("musc", std::make_shared<functions::Constant>(u));
  auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-10});
  integrator->SetController(parsed->parser.GetController());
  engine::State state = engine::MakeDefaultState(*parsed->system);
  for (double a : {0.3, 0.5, 0.7, 0.79}) {
    const double t = tau * (-1.5 * (a - a0) - (0.5 + 1.5 * u) * std::log((u - a) / (u - a0)));
    integrator->StepTo(state, t);
    EXPECT_NEAR(state.z[0], a, 1e-8) << "t = " << t;
  }
}

TEST(ThelenMuscleTest, ActivationRisesAsTheClosedFormOfItsFirstOrderEquation) {
  ExpectActivationFollowsTheClosedForm(Thelen(""));
}

// The muscle "musc" equilibrated on the locked slider under the constant excitation 0.2, then
// integrated for 1 s at accuracy 1e-12: the force balance holds to `balance` (N) at the start,
// the fiber state (`fiber_state`) stays within `fiber` and the tendon force within `force` (N).
void ExpectEquilibriumHeld(const std::string& muscle_text, double balance, double fiber,
                           double force, const std::string& fiber_state = "fiber_length") {
  auto parsed = Parse(SliderModel(muscle_text, true), /*equilibrate=*/true);
  parsed->parser.SetExcitationFunction("musc", std::make_shared<functions::Constant>(0.2));
  auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-12});
  integrator->SetController(parsed->parser.GetController());
  engine::State state = engine::MakeDefaultState(*parsed->system);
  ASSERT_EQ(parsed->system->state_variable_names(),
            (std::vector<std::string>{"musc/activation", "musc/" + fiber_state}));
  const double fiber0 = state.z[1];
  const auto* muscle = dynamic_cast<const PathActuator*>(parsed->system->force_elements()[0].get());
  ASSERT_NE(muscle, nullptr);
  const MuscleQuantities q0 = muscle->CalcQuantities(parsed->system->MakeForceContext(0, state));
  // At equilibrium the fiber force along the tendon is the tendon force.
  EXPECT_NEAR((q0.active_fiber_force + q0.passive_fiber_force) * std::cos(q0.pennation_angle),
              q0.tendon_force, balance);
  EXPECT_GT(q0.tendon_force, 10.0);
  integrator->StepTo(state, 1.0);
  EXPECT_NEAR(state.z[0], 0.2, 1e-12);
  EXPECT_NEAR(state.z[1], fiber0, fiber);
  const MuscleQuantities q1 = muscle->CalcQuantities(parsed->system->MakeForceContext(0, state));
  EXPECT_NEAR(q1.tendon_force, q0.tendon_force, force);
}

TEST(ThelenMuscleTest, MuscleAtEquilibriumStaysThereUnderConstantExcitation) {
  // Thelen's Newton iteration balances to 1e-9 max_isometric_force (500 N). The fiber may move
  // by the integrator's 1e-12; the musculotendon stiffness along the fiber here is about
  // 5e4 N/m, so the tendon force by 5e-8 N.
  ExpectEquilibriumHeld(Thelen(""), 1e-9 * 500, 1e-12, 1e-7);
}

// Millard's activation dynamics are Thelen's equation with the same time constants, so the
// same closed form holds.
TEST(Millard2012MuscleTest, ActivationRisesAsTheClosedFormOfItsFirstOrderEquation) {
  ExpectActivationFollowsTheClosedForm(Millard(""));
}

TEST(Millard2012MuscleTest, MuscleAtEquilibriumStaysThereUnderConstantExcitation) {
  // OpenSim's equilibrium tolerance is 1e-8 max_isometric_force (5e-6 N) on the force balance;
  // over a musculotendon stiffness of order 1e4 N/m that moves the fiber by at most about
  // 1e-9 m while it settles.
  ExpectEquilibriumHeld(Millard(""), 1e-8 * 500, 1e-9, 1e-8 * 500);
}

// DeGroote's equilibrium is a bisection on the normalized tendon force to an interval of
// 1e-10: the balance holds to about 1e-10 max_isometric_force (5e-8 N) and the state drifts by
// no more than that interval while it settles.
TEST(DeGrooteFregly2016MuscleTest, MuscleAtEquilibriumStaysThereUnderConstantExcitation) {
  ExpectEquilibriumHeld(DeGroote(), 1e-9 * 500, 1e-9, 1e-9 * 500, "normalized_tendon_force");
}

// Rajagopal2016: its 80 Millard2012EquilibriumMuscles (some with rigid tendons) are built on
// their wrapped paths, start at equilibrium at the default pose, and 20 ms of the model falling
// under gravity, muscles at their default activations, integrate to finite states.
TEST(Millard2012MuscleTest, Rajagopal2016BuildsAndSimulates) {
  const std::string osim = std::string(SINEW_TEST_DATA_DIR) +
                           "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim";
  auto parsed = ParseFile(osim, /*equilibrate=*/true);
  int millard = 0, rigid = 0;
  for (const auto& element : parsed->system->force_elements()) {
    const auto* actuator = dynamic_cast<const PathActuator*>(element.get());
    if (!actuator || actuator->StateVariableNames().empty()) continue;
    ++millard;
    rigid += actuator->StateVariableNames().size() == 1 ? 1 : 0;
  }
  EXPECT_EQ(millard, 80);
  EXPECT_GT(rigid, 0);
  auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-5});
  integrator->SetController(parsed->parser.GetController());
  engine::State state = engine::MakeDefaultState(*parsed->system);
  integrator->StepTo(state, 0.02);
  EXPECT_DOUBLE_EQ(state.t, 0.02);
  EXPECT_TRUE(state.z.allFinite());
  for (const engine::BodyState& body : state.bodies)
    EXPECT_TRUE(engine::PoseOf(body).p.allFinite());
}

// An evaluation visits each muscle once for its loads and its state variables' derivatives
// (engine::CalcLoads with zdot: the path's course and the fiber dynamics computed once): the
// same loads and derivatives, bit for bit, as the two computed apart, on Rajagopal2016 moving
// with its muscles excited.
TEST(Millard2012MuscleTest, LoadsAndStateDerivativesTogetherEqualThemApart) {
  const std::string osim = std::string(SINEW_TEST_DATA_DIR) +
                           "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim";
  auto parsed = ParseFile(osim, /*equilibrate=*/true);
  const engine::System& system = *parsed->system;
  engine::State state = engine::MakeDefaultState(system);
  for (int c = 0; c < system.num_coordinates(); ++c) state.u[c] = std::sin(c + 1.0);
  engine::PlaceBodies(system, state);
  for (int i = 0; i < state.inputs.size(); ++i) state.inputs[i] = 0.3 + 0.005 * i;
  engine::Loads together(system.num_bodies(), system.num_coordinates()), apart = together;
  VecX zdot_together = VecX::Zero(state.z.size()), zdot_apart = zdot_together;
  Eigen::Ref<VecX> zdot = zdot_together;
  engine::CalcLoads(system, state, nullptr, together, &zdot);
  engine::CalcLoads(system, state, nullptr, apart);
  engine::CalcStateVariableDerivatives(system, state, zdot_apart);
  ASSERT_GT(state.z.size(), 80);
  EXPECT_TRUE(zdot_together == zdot_apart);
  EXPECT_GT(zdot_apart.cwiseAbs().maxCoeff(), 0.0);
  for (int b = 0; b < system.num_bodies(); ++b) EXPECT_TRUE(together.body[b] == apart.body[b]) << b;
  EXPECT_TRUE(together.mobility == apart.mobility);
}

TEST(ThelenMuscleTest, IgnoredFlagsAreReported) {
  // OpenSim's Thelen2003Muscle does not use these flags; Sinew follows it and says so.
  auto parsed =
      Parse(SliderModel(Thelen("<ignore_tendon_compliance>true</ignore_tendon_compliance>"), true));
  const auto& warnings = parsed->parser.GetReport().warnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].component, "/forceset/musc");
  EXPECT_NE(warnings[0].message.find("ignore_tendon_compliance is true, but Thelen2003Muscle "
                                     "ignores it"),
            std::string::npos)
      << warnings[0].message;
}

TEST(ThelenMuscleTest, BadParametersNameFileAndMuscle) {
  try {
    Parse(SliderModel(Thelen("<Flen>0.9</Flen>"), true));
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("muscle_test.osim"), std::string::npos)
        << std::string(error.what());
    EXPECT_NE(std::string(error.what()).find("/forceset/musc"), std::string::npos)
        << std::string(error.what());
    EXPECT_NE(std::string(error.what()).find("Flen"), std::string::npos)
        << std::string(error.what());
  }
}

}  // namespace
}  // namespace sinew::muscles
