// Checks shared by the tests of OpenSim's deprecated muscles (Schutte1993Muscle_Deprecated,
// Thelen2003Muscle_Deprecated), whose equilibrium is OpenSim's computeIsometricForce: a balance
// of tendon and fiber forces to 0.01 N (IsometricImbalance).
#pragma once

#include <gtest/gtest.h>
#include <sinew/functions/constant.h>
#include <sinew/muscles/path_actuator.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "slider_model.h"

namespace sinew::muscles {

// d(imbalance)/d(fiber length) (N/m) at `fiber` by central differences: 0.01 N over it is how
// far OpenSim's 0.01 N balance may leave the fiber from the exact one.
template <class Model>
double BalanceStiffness(const Model& model, double activation, double fiber, double length) {
  const double h = 1e-7;
  return std::abs(model.IsometricImbalance(activation, fiber + h, length) -
                  model.IsometricImbalance(activation, fiber - h, length)) /
         (2 * h);
}

// The muscle `muscle_xml` (named "musc", on the slider's path) equilibrated at activation 0.2
// on the locked slider, then 1 s under the excitation 0.2 at accuracy 1e-12. OpenSim's
// iteration balances the forces to 0.01 N; the fiber then settles onto the exact balance, at
// most 0.01 N over the stiffness of the balance away, and the tendon force by at most 0.01 N.
template <class Model>
void ExpectEquilibriumHoldsUnderConstantExcitation(const std::string& muscle_xml) {
  auto parsed = Parse(SliderModel(muscle_xml, true), /*equilibrate=*/true);
  parsed->parser.SetExcitationFunction("musc", std::make_shared<functions::Constant>(0.2));
  auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-12});
  integrator->SetController(parsed->parser.GetController());
  engine::State state = engine::MakeDefaultState(*parsed->system);
  ASSERT_EQ(parsed->system->state_variable_names(),
            (std::vector<std::string>{"musc/activation", "musc/fiber_length"}));
  state.z[0] = 0.2;
  engine::InitializeStateVariables(*parsed->system, state);
  const auto& muscle = dynamic_cast<const PathActuator&>(*parsed->system->force_elements()[0]);
  const auto& model = dynamic_cast<const Model&>(muscle.model());
  const double fiber0 = state.z[1];
  const MuscleQuantities q0 = muscle.CalcQuantities(parsed->system->MakeForceContext(0, state));
  EXPECT_GT(q0.tendon_force, 10.0);
  const double length =
      muscle.CalcPathKinematics(parsed->system->MakeForceContext(0, state)).length;
  EXPECT_LE(std::abs(model.IsometricImbalance(0.2, fiber0, length)), 0.01);
  const double stiffness = BalanceStiffness(model, 0.2, fiber0, length);
  integrator->StepTo(state, 1.0);
  EXPECT_NEAR(state.z[0], 0.2, 1e-12);
  EXPECT_NEAR(state.z[1], fiber0, 0.01 / stiffness);
  const MuscleQuantities q1 = muscle.CalcQuantities(parsed->system->MakeForceContext(0, state));
  EXPECT_NEAR(q1.tendon_force, q0.tendon_force, 0.01);
  // Settled: the fiber at rest, the forces balanced far better than OpenSim's 0.01 N.
  EXPECT_NEAR(q1.fiber_velocity, 0.0, 1e-9);
  EXPECT_NEAR(model.IsometricImbalance(0.2, state.z[1], length), 0.0, 1e-6);
  std::printf(
      "equilibrium: imbalance %.3g N at the start, fiber moved %.3g m (bound %.3g m), "
      "tendon force by %.3g N\n",
      model.IsometricImbalance(0.2, fiber0, length), state.z[1] - fiber0, 0.01 / stiffness,
      q1.tendon_force - q0.tendon_force);
}

}  // namespace sinew::muscles
