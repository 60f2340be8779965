// OpenSim's passive springs and CoordinateCouplerConstraints through the parser: a model written
// for these tests (closed form, conserved energy, coupler residual) and real models whose
// patellae follow the knee through their couplers (Rajagopal2016, leg6dof9musc).
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/projection.h>
#include <sinew/opensim/parser.h>
#include <sinew/opensim/support.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace sinew {
namespace {

const std::string kData = SINEW_TEST_DATA_DIR;

// The largest |phi| of the constraints the parser built from the file's couplers.
double WorstCouplerResidual(const opensim::Report& report, const engine::System& system,
                            const engine::State& state) {
  double worst = 0.0;
  VecX phi(1);
  for (const auto& [name, info] : report.constraints()) {
    if (!info.constraint) continue;
    info.constraint->CalcPositionError(system, state, phi);
    worst = std::max(worst, std::abs(phi[0]));
  }
  return worst;
}

TEST(SpringsCouplersTest, WrittenModelFollowsItsClosedFormAndConservesEnergy) {
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kData + "/sinew/springs.osim");
  const opensim::Report& report = parser.GetReport();
  for (const char* force : {"block_spring", "arm_limit", "arm_spring"}) {
    ASSERT_NE(report.GetForce(force), nullptr) << force;
    EXPECT_NE(report.GetForce(force)->load, nullptr) << force;
  }
  ASSERT_NE(report.GetConstraint("follower_coupler"), nullptr);
  EXPECT_NE(report.GetConstraint("follower_coupler")->constraint, nullptr);
  EXPECT_TRUE(report.not_simulated().empty());
  // The coupled PinJoint is parameterized (the engine refuses couplers on direct pins).
  EXPECT_EQ(report.GetJoint("arm_pin")->form, engine::JointForm::kParameterized);

  engine::IntegratorSettings settings;
  settings.accuracy = 1e-11;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  engine::State state = engine::MakeDefaultState(*system);
  EXPECT_LT(WorstCouplerResidual(report, *system, state), 1e-10);
  const double e0 = engine::CalcMechanicalEnergy(*system, state);
  const int block_x = system->FindCoordinate("block_x");
  const int arm = system->FindCoordinate("arm_angle");
  double worst_x = 0.0, worst_phi = 0.0, worst_energy = 0.0, arm_min = 1.0, arm_max = 0.0;
  for (int k = 1; k <= 40; ++k) {
    const double t = 0.05 * k;
    integrator->StepTo(state, t);
    worst_x = std::max(worst_x, std::abs(state.q[block_x] - 0.3 - 0.1 * std::cos(5.0 * t)));
    worst_phi = std::max(worst_phi, WorstCouplerResidual(report, *system, state));
    worst_energy =
        std::max(worst_energy, std::abs(engine::CalcMechanicalEnergy(*system, state) - e0));
    arm_min = std::min(arm_min, state.q[arm]);
    arm_max = std::max(arm_max, state.q[arm]);
  }
  const double steps = static_cast<double>(integrator->stats().steps);
  EXPECT_LT(worst_x, 1e-7);
  EXPECT_LT(worst_phi, 1e-8);
  // Energy scale ~5 J; at most accuracy x scale per step.
  EXPECT_LT(worst_energy, 5.0 * steps * settings.accuracy);
  // The arm went into both limits' bands (20 deg = 0.349 rad, -25 deg = -0.436 rad).
  EXPECT_GT(arm_max, 0.349);
  EXPECT_LT(arm_min, -0.436);
  std::cout << "springs.osim: block error " << worst_x << " m, coupler residual " << worst_phi
            << ", energy drift " << worst_energy << " J in " << steps << " steps, arm in ["
            << arm_min << ", " << arm_max << "] rad\n";
}

struct CoupledModel {
  std::string file;
  std::vector<std::pair<std::string, std::string>> pairs;  // dependent, independent (f = x)
};

TEST(SpringsCouplersTest, PatellaeFollowTheKneesOfRealModels) {
  const std::vector<CoupledModel> models = {
      {"opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim",
       {{"knee_angle_r_beta", "knee_angle_r"}, {"knee_angle_l_beta", "knee_angle_l"}}},
      {"opensim-org/opensim-core/OpenSim/Simulation/Test/"
       "testSimulationUtilities_leg6dof9musc_20303.osim",
       {{"knee_angle_pat_r", "knee_angle_r"}}}};
  for (const CoupledModel& model : models) {
    opensim::OpenSimParser parser;
    auto system = parser.Parse(kData + "/" + model.file);
    const opensim::Report& report = parser.GetReport();
    EXPECT_EQ(report.constraints().size(), model.pairs.size()) << model.file;
    for (const std::string& line : report.not_simulated()) {
      EXPECT_EQ(line.find("CoordinateCouplerConstraint"), std::string::npos) << line;
    }
    engine::State state = engine::MakeDefaultState(*system);
    EXPECT_LT(WorstCouplerResidual(report, *system, state), 1e-10) << model.file;
    // Unforced, the model falls freely and its joints do not move: swing the knees (the couplers
    // are identities, so equal speeds satisfy them).
    for (const auto& [dependent, independent] : model.pairs) {
      engine::SetCoordinateSpeed(*system, state, independent, 2.0);
      engine::SetCoordinateSpeed(*system, state, dependent, 2.0);
    }
    engine::IntegratorSettings settings;
    settings.accuracy = 1e-6;
    auto integrator = engine::MakeIntegrator("rk45", *system, settings);
    double worst = 0.0, knee_travel = 0.0;
    const int knee = system->FindCoordinate(model.pairs[0].second);
    const double knee0 = state.q[knee];
    for (int k = 1; k <= 4; ++k) {
      integrator->StepTo(state, 0.05 * k);
      worst = std::max(worst, WorstCouplerResidual(report, *system, state));
      for (const auto& [dependent, independent] : model.pairs) {
        EXPECT_NEAR(state.q[system->FindCoordinate(dependent)],
                    state.q[system->FindCoordinate(independent)], 1e-8)
            << model.file << " " << dependent;
      }
      knee_travel = std::max(knee_travel, std::abs(state.q[knee] - knee0));
    }
    // The projection holds positions to min(1e-3 accuracy, 1e-10) after every step.
    EXPECT_LT(worst, 1e-8) << model.file;
    EXPECT_LT(engine::CalcPositionErrors(*system, state).lpNorm<Eigen::Infinity>(), 1e-8);
    EXPECT_GT(knee_travel, 1e-3) << model.file;  // the knee moved, and the patella with it
    std::cout << model.file << ": coupler residual " << worst << ", knee moved " << knee_travel
              << " rad in 0.2 s, " << integrator->stats().steps << " steps\n";
  }
}

TEST(SpringsCouplersTest, NotEnforcedCouplerIsNotBuilt) {
  model::ConstraintSpec coupler;
  coupler.type = "CoordinateCouplerConstraint";
  EXPECT_TRUE(opensim::IsConstraintSimulated(coupler));
  coupler.enabled = false;
  EXPECT_FALSE(opensim::IsConstraintSimulated(coupler));
}

}  // namespace
}  // namespace sinew
