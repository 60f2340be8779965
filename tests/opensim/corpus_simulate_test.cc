// Every model of the corpus (SINEW_CORPUS_DIR; files under 3 MB) either builds and simulates a few
// milliseconds with satisfied constraints and finite states, or is refused with a sinew::Error
// (never a crash or NaNs). Skipped when the corpus is absent.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/projection.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/build_system.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "corpus.h"

namespace sinew {
namespace {

// The corpus's .osim files under 3 MB, sorted.
// Under AddressSanitizer (about 10x slower) the sweep leaves out the stepping of models too
// stiff to step within the test's time there: PushUpToesOnGroundWithMuscles's 100
// Schutte1993Muscle_Deprecated fibers start at length 0 (OpenSim's default for the deprecated
// muscles), so their tendons pull several times their maximum force and rk45 takes ~30 s of
// Release time for the 5 ms. They are still built and assembled there, and the Release sweep
// steps them.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kUnderAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kUnderAddressSanitizer = true;
#else
constexpr bool kUnderAddressSanitizer = false;
#endif
#else
constexpr bool kUnderAddressSanitizer = false;
#endif
bool TooStiffToStepUnderSanitizer(const std::filesystem::path& file) {
  return kUnderAddressSanitizer && file.filename() == "PushUpToesOnGroundWithMuscles.osim";
}

TEST(CorpusSimulateTest, EveryModelSimulatesOrIsRefusedClearly) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const std::vector<std::filesystem::path> files = testing::CorpusModelFiles(3'000'000);
  int simulated = 0;
  std::map<std::string, std::string> refused;  // file name -> error message
  for (const auto& file : files) {
    try {
      const model::ModelSpec spec = io::ReadOsim(file.string());
      const auto system = opensim::BuildSystem(spec);
      engine::State state = engine::MakeDefaultState(*system);
      engine::IntegratorSettings settings;
      settings.accuracy = 1e-5;
      auto integrator = engine::MakeIntegrator("rk45", *system, settings);
      if (!TooStiffToStepUnderSanitizer(file)) integrator->StepTo(state, 0.005);
      EXPECT_TRUE(state.q.allFinite()) << file;
      EXPECT_LT(engine::CalcPositionErrors(*system, state).lpNorm<Eigen::Infinity>(), 1e-8) << file;
      ++simulated;
    } catch (const Error& e) {
      refused[file.filename().string()] = e.what();
    }
  }
  std::printf("corpus: %d models simulated, %zu refused with an error\n", simulated,
              refused.size());
  for (const auto& [name, message] : refused) {
    std::printf("  refused %s: %s\n", name.c_str(), message.c_str());
  }
  // 131 of the 136 models simulate. The 5 refusals, each for its reason: three models whose
  // bodies all have zero mass (kinematics only), an IK-only model with a massless free body,
  // and the broken repro whose femur hangs from nothing. A new refusal fails this test.
  const std::map<std::string, std::string> expected = {
      {"BothLegs.osim", "every body has zero mass"},
      {"BothLegs22.osim", "every body has zero mass"},
      {"constraintTest_ikOnly.osim", "loadcell2: engine: the equations of motion are singular"},
      {"opensim-creator_382_repro.osim", "body 'femur_r' is not connected to ground"},
      {"wrist.osim", "every body has zero mass"}};
  EXPECT_EQ(simulated, 131);
  EXPECT_EQ(refused.size(), expected.size());
  for (const auto& [name, reason] : expected) {
    const auto it = refused.find(name);
    if (it == refused.end()) {
      ADD_FAILURE() << name << " was expected to be refused (" << reason << ")";
      continue;
    }
    EXPECT_NE(it->second.find(reason), std::string::npos) << it->second;
  }
}

// The same sweep through the OpenSim parser, which adds what the skeleton build leaves out and
// the engine simulates (actuators, springs, coordinate limit forces, couplers): every model
// that builds keeps all its constraints, couplers included, to 1e-8 after 5 ms. Prints the
// models that the parser refuses, with the reason.
TEST(CorpusSimulateTest, EveryModelSimulatesWithItsForcesAndConstraints) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const std::vector<std::filesystem::path> files = testing::CorpusModelFiles(3'000'000);
  int simulated = 0, with_couplers = 0;
  std::map<std::string, std::string> refused;
  for (const auto& file : files) {
    try {
      opensim::OpenSimParser parser;
      const auto system = parser.Parse(file.string());
      engine::State state = engine::MakeDefaultState(*system);
      EXPECT_LT(engine::CalcPositionErrors(*system, state).lpNorm<Eigen::Infinity>(), 1e-8) << file;
      engine::IntegratorSettings settings;
      settings.accuracy = 1e-5;
      auto integrator = engine::MakeIntegrator("rk45", *system, settings);
      if (!TooStiffToStepUnderSanitizer(file)) integrator->StepTo(state, 0.005);
      EXPECT_TRUE(state.q.allFinite()) << file;
      EXPECT_LT(engine::CalcPositionErrors(*system, state).lpNorm<Eigen::Infinity>(), 1e-8) << file;
      ++simulated;
      if (system->HasExtraConstraints()) ++with_couplers;
    } catch (const Error& e) {
      refused[file.filename().string()] = e.what();
    }
  }
  std::printf("corpus through the parser: %d models simulated (%d with couplers), %zu refused\n",
              simulated, with_couplers, refused.size());
  for (const auto& [name, message] : refused) {
    std::printf("  refused %s: %s\n", name.c_str(), message.c_str());
  }
  // The skeleton sweep's 5 refusals, 1 contact model (below), and 3 of opensim-creator's bug
  // repros that the parser
  // refuses by name: a coupler on a FreeJoint rotation (its speed is an angular velocity, not
  // the angle's rate), a coupler without a coupled_coordinates_function, and a
  // SpringGeneralizedForce that names no coordinate (OpenSim cannot connect either); and since
  // Thelen2003Muscles are simulated, the repro whose muscle has tendon_slack_length 0 (its
  // normalized tendon length would divide by zero); and since Millard2012EquilibriumMuscles are
  // simulated, the example whose Millard muscle runs along a Scholz2015GeometryPath (not read).
  // Since Schutte1993Muscles are simulated, wrist_mass, Neck3dof_point_constraint and
  // PushUpToesOnGroundWithMuscles simulate with theirs (from fiber length 0, OpenSim's default
  // for that class); wrist.osim and the two BothLegs models stay refused for their massless
  // bodies.
  const std::map<std::string, std::string> expected = {
      {"BothLegs.osim", "every body has zero mass"},
      {"BothLegs22.osim", "every body has zero mass"},
      {"constraintTest_ikOnly.osim", "loadcell2: engine: the equations of motion are singular"},
      {"opensim-creator_1070_repro.osim",
       "/forceset/ADD_BREV_PROS_1_R: tendon_slack_length must be greater than zero"},
      {"opensim-creator_382_repro.osim", "body 'femur_r' is not connected to ground"},
      {"Scholz2015GeometryPathExample.osim",
       "/forceset/scholz_muscle: has no GeometryPath or FunctionBasedPath"},
      {"opensim-creator_515-3_repro.osim",
       "couples 'rx' of FreeJoint freejoint, whose speed is an angular velocity"},
      {"opensim-creator_515_repro.osim", "has no coupled_coordinates_function"},
      {"opensim-creator_524_repro.osim", "coordinate '' is not a coordinate of the model"},
      {"wrist.osim", "every body has zero mass"},
      // Contact: an ElasticFoundationForce between two meshes, which Sinew does not simulate
      // yet. (Two osim-rl walkers whose default pose, pelvis_ty 0, puts their foot spheres
      // ~0.9 m inside the platform were refused until rk45 retried trial steps whose stages
      // blow up (NonFiniteForceTest): their Hunt-Crossley forces now push them out at 0.7 m/s.)
      {"visualize_contacts.osim", "mesh-to-mesh elastic foundation contact is not simulated yet"}};
  EXPECT_EQ(simulated, 125);
  EXPECT_EQ(refused.size(), expected.size());
  for (const auto& [name, reason] : expected) {
    const auto it = refused.find(name);
    if (it == refused.end()) {
      ADD_FAILURE() << name << " was expected to be refused (" << reason << ")";
      continue;
    }
    EXPECT_NE(it->second.find(reason), std::string::npos) << it->second;
  }
}

}  // namespace
}  // namespace sinew
