// The skeleton build on real OpenSim files: SinglePin and DoublePendulum3D (3.x-era CustomJoints)
// reproduce OpenSim's stored states; gait2354 conserves energy; bad models give clear errors.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/projection.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/build_system.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "engine/test_models.h"

namespace sinew {
namespace {

using engine::testing::ReadStoColumns;

const std::string kData = SINEW_TEST_DATA_DIR;
const std::string kResources =
    kData + "/opensim-org/opensim-core/Applications/Analyze/tests/resources/";

// Runs `model` from the first row of `initial_states` (as OpenSim's Forward tool did) and
// returns the largest differences from `states` over every stored row.
void RunAgainstOpenSim(const std::string& model, const std::string& initial_states,
                       const std::string& states, double* dq, double* du) {
  const model::ModelSpec spec = io::ReadOsim(kResources + model);
  const auto system = opensim::BuildSystem(spec);
  engine::State state = engine::MakeDefaultState(*system);
  const auto init = ReadStoColumns(kResources + initial_states);
  for (int c = 0; c < system->num_coordinates(); ++c) {
    const std::string& name = system->coordinates()[c].name;
    state.q[c] = init.at(name)[0];
    state.u[c] = init.at(name + "_u")[0];
  }
  engine::PlaceBodies(*system, state);
  const auto ref = ReadStoColumns(kResources + states);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  *dq = *du = 0.0;
  const auto& time = ref.at("time");
  for (size_t row = 0; row < time.size(); ++row) {
    integrator->StepTo(state, time[row]);
    for (int c = 0; c < system->num_coordinates(); ++c) {
      const std::string& name = system->coordinates()[c].name;
      *dq = std::max(*dq, std::abs(state.q[c] - ref.at(name)[row]));
      *du = std::max(*du, std::abs(state.u[c] - ref.at(name + "_u")[row]));
    }
  }
  EXPECT_NEAR(state.t, 3.0, 1e-12);
}

TEST(BuildSystemTest, SinglePinReproducesOpenSim) {
  double dq, du;
  RunAgainstOpenSim("SinglePin.osim", "SinglePin_InitialStates.sto", "SinglePin_states.sto", &dq,
                    &du);
  std::printf("SinglePin.osim: max |dq| = %.3g rad, max |du| = %.3g rad/s\n", dq, du);
  // Asserted within ~3x of the published figures (docs/engine.md): measured 3.1e-8 rad and
  // 9.7e-8 rad/s. The difference is OpenSim's own integration error at its accuracy setting.
  EXPECT_LT(dq, 1e-7);
  EXPECT_LT(du, 3e-7);
}

TEST(BuildSystemTest, DoublePendulum3DReproducesOpenSim) {
  double dq, du;
  RunAgainstOpenSim("DoublePendulum3D.osim", "DoublePendulum3D_InitialStates.sto",
                    "DoublePendulum3D_states.sto", &dq, &du);
  std::printf("DoublePendulum3D.osim: max |dq| = %.3g rad, max |du| = %.3g rad/s\n", dq, du);
  // Within ~3x of the published 1.05e-7 rad and 5.7e-7 rad/s (docs/engine.md).
  EXPECT_LT(dq, 3e-7);
  EXPECT_LT(du, 2e-6);
}

// gait2354 hung from its pelvis (pelvis coordinates locked), limbs swinging from a bent pose:
// passive, so kinetic + gravity energy is conserved; constraints stay satisfied.
TEST(BuildSystemTest, Gait2354HungFromPelvisConservesEnergy) {
  model::ModelSpec spec = io::ReadOsim(kData +
                                       "/opensim-org/opensim-models/Pipelines/Gait2354_Simbody/"
                                       "OutputReference/subject01_simbody_adjusted.osim");
  for (model::CoordinateSpec& c : spec.coordinates) {
    if (c.name.rfind("pelvis_", 0) == 0) c.locked = true;
  }
  const auto system = opensim::BuildSystem(spec);
  engine::State state = engine::MakeDefaultState(*system);
  const struct {
    const char* name;
    double q, u;
  } pose[] = {{"hip_flexion_r", 0.6, 1.0},   {"knee_angle_r", -0.9, 0.0},
              {"hip_flexion_l", -0.3, -0.5}, {"knee_angle_l", -0.2, 2.0},
              {"ankle_angle_r", 0.2, 0.0},   {"lumbar_extension", -0.2, 0.5},
              {"hip_adduction_l", 0.1, 0.3}, {"lumbar_bending", 0.1, -0.4}};
  for (const auto& p : pose) {
    state.q[system->FindCoordinate(p.name)] = p.q;
    state.u[system->FindCoordinate(p.name)] = p.u;
  }
  engine::PlaceBodies(*system, state);
  const double e0 = engine::CalcMechanicalEnergy(*system, state);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-9;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  engine::KktSolver kkt(*system);
  double drift = 0.0, max_kinetic = 0.0, phi = 0.0, vel = 0.0;
  for (int i = 1; i <= 20; ++i) {
    integrator->StepTo(state, 0.1 * i);
    drift = std::max(drift, std::abs(engine::CalcMechanicalEnergy(*system, state) - e0));
    max_kinetic = std::max(max_kinetic, engine::CalcKineticEnergy(*system, state));
    phi = std::max(phi, engine::CalcPositionErrors(*system, state).lpNorm<Eigen::Infinity>());
    vel = std::max(vel, engine::CalcVelocityErrors(*system, state, kkt).lpNorm<Eigen::Infinity>());
  }
  std::printf(
      "gait2354 hung, 2 s: |dE|/|E0| = %.2g, |dE|/max T = %.2g, |phi| = %.2g, "
      "|Jv - c| = %.2g, steps %ld\n",
      drift / std::abs(e0), drift / max_kinetic, phi, vel, integrator->stats().steps);
  EXPECT_GT(max_kinetic, 1.0);  // the limbs really move
  // Within ~5x of the published figures (README, docs/engine.md): relative drift 6.8e-12,
  // residuals 9.4e-13 (positions) and 2.8e-14 (velocities).
  EXPECT_LT(drift / std::abs(e0), 3e-11);
  EXPECT_LT(phi, 5e-12);
  EXPECT_LT(vel, 1e-13);
}

TEST(BuildSystemTest, MasslessModelIsRejected) {
  model::ModelSpec spec = io::ReadOsim(kResources + "SinglePin.osim");
  for (model::BodySpec& b : spec.bodies) b.mass = 0.0;
  try {
    opensim::BuildSystem(spec);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("zero mass"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("SinglePin.osim"), std::string::npos) << e.what();
  }
}

TEST(BuildSystemTest, NegativeMassNamesTheBody) {
  model::ModelSpec spec = io::ReadOsim(kResources + "SinglePin.osim");
  spec.bodies[1].mass = -1.0;
  try {
    opensim::BuildSystem(spec);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("rod1"), std::string::npos) << e.what();
    EXPECT_GT(e.where().line, 0);
  }
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// The linear-time tree elimination and a dense LU solve the same KKT system.
TEST(BuildSystemTest, TreeEliminationEqualsDenseLu) {
  const model::ModelSpec spec =
      io::ReadOsim(kData +
                   "/opensim-org/opensim-models/Pipelines/Gait2354_Simbody/OutputReference/"
                   "subject01_simbody_adjusted.osim");
  for (bool direct : {true, false}) {
    opensim::BuildOptions options;
    options.direct_joints = direct;
    const auto system = opensim::BuildSystem(spec, options);
    engine::State state = engine::MakeDefaultState(*system);
    for (int c = 0; c < system->num_coordinates(); ++c) {
      state.q[c] = 0.3 * std::sin(1.0 + c);
      state.u[c] = std::cos(2.0 * c);
    }
    engine::PlaceBodies(*system, state);
    engine::Data tree(*system), dense(*system, engine::KktSolver::Method::kDense);
    ASSERT_EQ(tree.kkt.num_extra_equations(), 0);
    const engine::Accelerations a = engine::CalcAccelerations(*system, state, nullptr, tree);
    const engine::Accelerations b = engine::CalcAccelerations(*system, state, nullptr, dense);
    EXPECT_LT((a.vdot - b.vdot).lpNorm<Eigen::Infinity>(), 1e-9 * (1 + b.vdot.norm()));
    EXPECT_LT((a.lambda - b.lambda).lpNorm<Eigen::Infinity>(), 1e-9 * (1 + b.lambda.norm()));
  }
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// Direct Cartesian joints (Pin, Ball, Universal, Weld) and the coordinate-parameterized form
// give the same motion on real models: Rajagopal2016 (Pin, Universal, Weld, CustomJoint) and the
// chrono Newton's cradle (Ball).
TEST(BuildSystemTest, DirectAndParameterizedJointsAgreeOnRealModels) {
  for (const std::string file : {"/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim",
                                 "/projectchrono/chrono/data/opensim/newton_cradle.osim"}) {
    const model::ModelSpec spec = io::ReadOsim(kData + file);
    double max_dq = 0.0;
    engine::State end[2];
    for (int direct = 0; direct < 2; ++direct) {
      opensim::BuildOptions options;
      options.direct_joints = direct == 1;
      const auto system = opensim::BuildSystem(spec, options);
      engine::State state = engine::MakeDefaultState(*system);
      for (int c = 0; c < system->num_coordinates(); ++c) state.u[c] = 0.3 * std::sin(c + 1.0);
      engine::PlaceBodies(*system, state);
      engine::IntegratorSettings settings;
      settings.accuracy = 1e-10;
      engine::MakeIntegrator("rk45", *system, settings)->StepTo(state, 0.2);
      end[direct] = state;
    }
    for (int c = 0; c < end[0].q.size(); ++c) {
      max_dq = std::max(max_dq, std::abs(end[0].q[c] - end[1].q[c]));
    }
    for (size_t b = 0; b < end[0].bodies.size(); ++b) {
      EXPECT_LT((end[0].bodies[b].p_GB - end[1].bodies[b].p_GB).norm(), 1e-7) << file << b;
    }
    std::printf("%s: direct vs parameterized, max |dq| = %.2g\n", file.c_str(), max_dq);
    EXPECT_LT(max_dq, 1e-7) << file;
  }
}

}  // namespace
}  // namespace sinew
