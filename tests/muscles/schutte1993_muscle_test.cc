// Schutte1993Muscle_Deprecated through the parser and the engine: activation against the closed
// form of its linear equation, a muscle at equilibrium staying there, OpenSim's own equilibrium
// fiber lengths (AnalyzeTool's MuscleAnalysis of BothLegs.osim), and wrist_mass.osim's 26
// muscles over 0.5 s (activations against the closed form, power of every muscle's loads
// against tension times lengthening speed).
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/functions/constant.h>
#include <sinew/io/osim_reader.h>
#include <sinew/io/storage.h>
#include <sinew/muscles/path_actuator.h>
#include <sinew/muscles/simm_muscle_spec.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "muscles/deprecated_equilibrium_check.h"
#include "paths/path_test_util.h"
#include "slider_model.h"

namespace sinew::muscles {
namespace {

// A Schutte muscle "musc" on the slider's path with OpenSim's default properties but these.
std::string Schutte() {
  return std::string(R"(<Schutte1993Muscle_Deprecated name="musc">)") + kPath +
         R"(<max_isometric_force>500</max_isometric_force><optimal_fiber_length>0.12</optimal_fiber_length>
<tendon_slack_length>0.27</tendon_slack_length><pennation_angle_at_optimal>0.2</pennation_angle_at_optimal>
</Schutte1993Muscle_Deprecated>)";
}

const PathActuator& MuscleOf(const engine::System& system, int k = 0) {
  return dynamic_cast<const PathActuator&>(*system.force_elements()[k]);
}

// With a constant excitation u the activation equation is linear: da/dt = -(a - u) r / time_scale
// with r = activation1 u + activation2 while rising and activation2 while falling, so
// a(t) = u + (a0 - u) exp(-r t / time_scale). OpenSim's defaults: 7.667, 1.459854, 0.1 s.
TEST(Schutte1993MuscleTest, ActivationFollowsTheClosedFormOfItsLinearEquation) {
  for (const auto& [a0, u] : {std::pair{0.0, 0.6}, std::pair{0.9, 0.2}}) {
    auto parsed = Parse(SliderModel(Schutte(), true), /*equilibrate=*/true);
    parsed->parser.SetExcitationFunction("musc", std::make_shared<functions::Constant>(u));
    auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-10});
    integrator->SetController(parsed->parser.GetController());
    engine::State state = engine::MakeDefaultState(*parsed->system);
    state.z[0] = a0;
    engine::InitializeStateVariables(*parsed->system, state);
    const double rate = (u > a0 ? 7.667 * u + 1.459854 : 1.459854) / 0.1;
    for (double t : {0.01, 0.05, 0.2}) {
      integrator->StepTo(state, t);
      EXPECT_NEAR(state.z[0], u + (a0 - u) * std::exp(-rate * t), 1e-8) << a0 << " " << t;
    }
  }
}

// deprecated_equilibrium_check.h says what is checked and why.
TEST(Schutte1993MuscleTest, MuscleAtEquilibriumStaysThereUnderConstantExcitation) {
  ExpectEquilibriumHoldsUnderConstantExcitation<Schutte1993Muscle>(Schutte());
}

// OpenSim's AnalyzeTool test (testAnalyzeTool.cpp, "testTutorialOne"): BothLegs.osim's states
// with the knee swept from -120 to about 90 degrees, activations 1, muscles equilibrated at
// every row (solve_for_equilibrium_for_auxiliary_states), and MuscleAnalysis's fiber lengths of
// RF and VASINT stored (in 2012). BothLegs' bodies are massless, so Sinew cannot build its
// engine system; the paths come from the kinematics and the muscles from the spec. OpenSim's
// iteration stops when tendon and fiber force agree to 0.01 N, so where the stored length
// balances the forces to 0.01 N (at Sinew's path length, with the file's curves) both answers
// lie within 0.01 N of the same root: within 0.02 N over the stiffness of the balance. Where
// the stored length does not balance them (the file was written by an older OpenSim), only
// OpenSim's own test tolerance, 1e-4 m, is asserted.
void ExpectOpenSimsEquilibriumFiberLengths(const std::string& states_file,
                                           const std::string& reference_file) {
  const std::string dir = std::string(SINEW_TEST_DATA_DIR) +
                          "/opensim-org/opensim-core/Applications/Analyze/tests/resources/";
  const paths::testing::PathModel m(dir + "BothLegs.osim");
  const io::Storage states = io::ReadStorage(dir + states_file);
  const io::Storage reference = io::ReadStorage(dir + reference_file);
  ASSERT_EQ(states.NumRows(), reference.NumRows());
  int balanced = 0;
  double worst_balanced = 0.0, worst_other = 0.0;
  for (const std::string name : {"RF", "VASINT"}) {
    const int path = m.FindPath(name);
    ASSERT_GE(path, 0) << name;
    const auto force = std::find_if(m.spec.forces.begin(), m.spec.forces.end(),
                                    [&](const model::ForceSpec& f) { return f.name == name; });
    ASSERT_EQ(force->type, "Schutte1993Muscle");
    const Schutte1993Muscle muscle = ReadSchutte1993Muscle(m.spec, *force);
    const int activation = states.FindColumn(name + ".activation");
    const int column = reference.FindColumn(name);
    ASSERT_GE(activation, 0);
    ASSERT_GE(column, 0);
    for (int r = 0; r < states.NumRows(); ++r) {
      std::vector<double> q = m.tree.default_q();
      for (size_t c = 0; c < m.spec.coordinates.size(); ++c) {
        const int k = states.FindColumn(m.spec.coordinates[c].name);
        if (k >= 0) q[c] = states.Value(r, k);
      }
      m.couplers.Apply(q);  // OpenSim assembles the couplers before equilibrating
      VecX z(2);
      z << states.Value(r, activation), 0.0;
      muscle.Equilibrate({m.CalcLength(path, q), 0.0}, name, z);
      const double length = m.CalcLength(path, q), sinew = z[1];
      const double expected = reference.Value(r, column), error = std::abs(sinew - expected);
      // The stiffness of OpenSim's balance measure about Sinew's root (central difference).
      const double h = 1e-7;
      const double stiffness = (muscle.IsometricImbalance(z[0], sinew + h, length) -
                                muscle.IsometricImbalance(z[0], sinew - h, length)) /
                               (2 * h);
      if (std::abs(muscle.IsometricImbalance(z[0], expected, length)) <= 0.01) {
        // Both within 0.01 N of the same root: 0.02 N over the stiffness, plus the file's
        // rounding.
        ++balanced;
        worst_balanced = std::max(worst_balanced, error);
        EXPECT_LT(error, 0.02 / std::abs(stiffness) + 5e-9) << name << " row " << r;
      } else {
        worst_other = std::max(worst_other, error);
        EXPECT_LT(error, 1e-4) << name << " row " << r;  // OpenSim's own test's tolerance
      }
    }
  }
  std::printf(
      "%s: %d of %d rows balanced in the file (within 0.01 N), worst difference there %.3g m; "
      "elsewhere %.3g m\n",
      reference_file.c_str(), balanced, 2 * states.NumRows(), worst_balanced, worst_other);
}

TEST(Schutte1993MuscleTest, EquilibriumFiberLengthsMatchOpenSimsMuscleAnalysis) {
  ExpectOpenSimsEquilibriumFiberLengths("plotterGeneratedStates.sto",
                                        "std_BothLegs_fiberLength.sto");
}

TEST(Schutte1993MuscleTest, EquilibriumFiberLengthsMatchOpenSimsMuscleAnalysisAtHip45) {
  ExpectOpenSimsEquilibriumFiberLengths("plotterGeneratedStatesHip45.sto",
                                        "std_BothLegsHip45__FiberLength.sto");
}

// wrist_mass.osim (wrist.osim with 1 kg bodies: wrist.osim's own bodies are massless), its 26
// Schutte1993Muscles equilibrated at activation 0 and excited at 0.3 for 0.5 s: every
// activation follows the closed form (activation1 0.01, activation2 0.04, time_scale 0.1), the
// states stay finite, every muscle pulls, and the power each muscle's loads deliver to the
// bodies equals -tension times its lengthening speed.
TEST(Schutte1993MuscleTest, WristMassSimulatesWithAllItsMuscles) {
  const std::string osim = std::string(SINEW_TEST_DATA_DIR) +
                           "/opensim-org/opensim-core/OpenSim/Simulation/Test/wrist_mass.osim";
  auto parsed = ParseFile(osim, /*equilibrate=*/true);
  std::vector<int> muscles;
  for (size_t k = 0; k < parsed->system->force_elements().size(); ++k) {
    const auto* actuator =
        dynamic_cast<const PathActuator*>(parsed->system->force_elements()[k].get());
    if (!actuator) continue;
    muscles.push_back(static_cast<int>(k));
    parsed->parser.SetExcitationFunction(actuator->name(),
                                         std::make_shared<functions::Constant>(0.3));
  }
  ASSERT_EQ(muscles.size(), 26u);
  auto integrator = engine::MakeIntegrator("rk45", *parsed->system, {.accuracy = 1e-7});
  integrator->SetController(parsed->parser.GetController());
  engine::State state = engine::MakeDefaultState(*parsed->system);
  double worst_activation = 0.0, worst_power = 0.0, smallest_tension = 1e300;
  for (double t : {0.1, 0.25, 0.5}) {
    integrator->StepTo(state, t);
    ASSERT_TRUE(state.z.allFinite()) << t;
    ASSERT_TRUE(state.u.allFinite()) << t;
    const double a = 0.3 * (1.0 - std::exp(-(0.01 * 0.3 + 0.04) * t / 0.1));
    int pulling = 0;
    for (size_t i = 0; i < muscles.size(); ++i) {
      const auto& muscle = MuscleOf(*parsed->system, muscles[i]);
      const std::vector<std::string>& names = parsed->system->state_variable_names();
      const auto activation =
          std::find(names.begin(), names.end(), muscle.name() + "/activation") - names.begin();
      EXPECT_NEAR(state.z[activation], a, 1e-6) << muscle.name();
      worst_activation = std::max(worst_activation, std::abs(state.z[activation] - a));
      const engine::ForceContext context = parsed->system->MakeForceContext(muscles[i], state);
      const MuscleQuantities q = muscle.CalcQuantities(context);
      const PathKinematics path = muscle.CalcPathKinematics(context);
      pulling += q.tendon_force > 0.0 ? 1 : 0;
      const double power = -q.tendon_force * path.lengthening_speed;
      const double delivered = engine::CalcForcePower(*parsed->system, state, muscles[i]);
      EXPECT_NEAR(delivered, power, 1e-9 * (1.0 + std::abs(power))) << muscle.name() << " at " << t;
      worst_power = std::max(worst_power, std::abs(delivered - power) / (1.0 + std::abs(power)));
      smallest_tension = std::min(smallest_tension, q.tendon_force);
    }
    EXPECT_EQ(pulling, 26) << t;
  }
  std::printf(
      "wrist_mass: activation within %.3g of the closed form, power within %.3g "
      "(relative), smallest tension %.3g N\n",
      worst_activation, worst_power, smallest_tension);
}

}  // namespace
}  // namespace sinew::muscles
