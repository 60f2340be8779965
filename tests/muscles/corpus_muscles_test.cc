// Every Millard2012EquilibriumMuscle of the OpenSim corpus (SINEW_CORPUS_DIR): its properties
// read and make a muscle, and at the model's default pose (path length with the paths' points,
// wrap objects not applied; a Scholz2015GeometryPath is not computed) the equilibrium at the
// muscle's default activation and at full activation converges, with fiber force along the tendon
// equal to the tendon force within OpenSim's tolerance, or leaves the fiber at its minimum length.
// The counts are exact, so a muscle that newly fails fails the test until the expectation is
// changed on purpose. The same for the Schutte1993 muscles (below).
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/muscles/millard2012_equilibrium.h>
#include <sinew/muscles/millard2012_spec.h>
#include <sinew/muscles/simm_muscle_spec.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include "corpus.h"
#include "paths/path_test_util.h"

namespace sinew::muscles {
namespace {

namespace fs = std::filesystem;

TEST(CorpusMusclesTest, EveryMillard2012MuscleEquilibratesAtTheDefaultPose) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const std::vector<fs::path> files = sinew::testing::CorpusModelFiles();
  int models = 0, muscles = 0, without_path = 0, converged = 0, at_lower_bound = 0;
  for (const fs::path& file : files) {
    std::unique_ptr<paths::testing::PathModel> m;
    try {
      m = std::make_unique<paths::testing::PathModel>(file.string());
    } catch (const Error& e) {
      continue;  // the reader's one refusal (docs/testing.md)
    }
    std::vector<double> q = m->tree.default_q();
    m->couplers.Apply(q);
    bool any = false;
    for (const model::ForceSpec& force : m->spec.forces) {
      if (force.type != "Millard2012EquilibriumMuscle") continue;
      any = true;
      ++muscles;
      const Millard2012Muscle muscle = ReadMillard2012Muscle(m->spec, force);
      const int p = m->FindPath(force.name);
      if (p < 0) {  // a path Sinew does not compute (Scholz2015GeometryPath)
        ++without_path;
        continue;
      }
      const double length = m->CalcLength(p, q);
      const double fiso = muscle.parameters().max_isometric_force;
      for (double activation : {muscle.parameters().default_activation, 1.0}) {
        const Millard2012Equilibrium eq =
            SolveMillard2012Equilibrium(muscle, activation, length, 0.0);
        if (eq.status == Millard2012Equilibrium::Status::kFiberAtLowerBound) {
          ++at_lower_bound;
          EXPECT_EQ(eq.fiber_length, muscle.minimum_fiber_length());
          continue;
        }
        ++converged;
        const Millard2012Dynamics d =
            CalcMillard2012Dynamics(muscle, activation, eq.fiber_length, length, 0.0);
        EXPECT_NEAR(d.fiber_force_along_tendon, d.tendon_force, 1e-8 * fiso)
            << file << " " << force.name << " at activation " << activation;
      }
    }
    if (any) ++models;
  }
  std::cout << models << " models, " << muscles << " Millard2012 muscles (" << without_path
            << " without a computed path); equilibria: " << converged << " converged, "
            << at_lower_bound << " at the minimum fiber length\n";
  // 24 files hold Millard2012 muscles; the reader refuses one (opensim-creator_382_repro.osim).
  EXPECT_EQ(models, 23);
  EXPECT_EQ(muscles, 846);
  EXPECT_EQ(at_lower_bound, 0);
  EXPECT_EQ(without_path, 1);
  EXPECT_EQ(converged + at_lower_bound, 2 * (muscles - without_path));
}

// Every Schutte1993Muscle(_Deprecated) of the corpus (no corpus model has a RigidTendonMuscle):
// its properties and curves read and make a muscle, and at the model's default pose its
// equilibrium at activations 0.01 and 1 (OpenSim's iteration) balances tendon force and fiber
// force along the tendon to OpenSim's 0.01 N; counted apart, those whose tendon is slack there.
TEST(CorpusMusclesTest, EverySchutte1993MuscleEquilibratesAtTheDefaultPose) {
  SINEW_SKIP_WITHOUT_CORPUS();
  std::map<std::string, int> muscles_per_model;
  int balanced = 0, slack = 0, failed = 0;
  for (const fs::path& file : sinew::testing::CorpusModelFiles()) {
    std::unique_ptr<paths::testing::PathModel> m;
    try {
      m = std::make_unique<paths::testing::PathModel>(file.string());
    } catch (const Error&) {
      continue;  // the reader's one refusal (docs/testing.md)
    }
    std::vector<double> q = m->tree.default_q();
    m->couplers.Apply(q);
    for (const model::ForceSpec& force : m->spec.forces) {
      if (!force.type.starts_with("Schutte1993Muscle")) continue;
      ++muscles_per_model[file.filename().string()];
      const Schutte1993Muscle muscle = ReadSchutte1993Muscle(m->spec, force);
      const int p = m->FindPath(force.name);
      ASSERT_GE(p, 0) << file << " " << force.name;
      const PathKinematics path{m->CalcLength(p, q), 0.0};
      for (double activation : {0.01, 1.0}) {
        VecX z(2);
        z << activation, 0.0;
        try {
          muscle.Equilibrate(path, force.name, z);
        } catch (const Error& e) {
          ++failed;
          std::cout << file.filename() << ": " << e.what() << "\n";
          continue;
        }
        const MuscleQuantities quantities = muscle.Calc(z, activation, path);
        ++(quantities.tendon_force == 0.0 ? slack : balanced);
        EXPECT_LE(std::abs(muscle.IsometricImbalance(activation, z[1], path.length)), 0.01)
            << file << " " << force.name << " at activation " << activation;
      }
    }
  }
  int muscles = 0;
  for (const auto& [name, count] : muscles_per_model) {
    std::cout << name << ": " << count << " Schutte1993 muscles\n";
    muscles += count;
  }
  std::cout << "equilibria: " << balanced << " balanced, " << slack << " with a slack tendon, "
            << failed << " without equilibrium\n";
  // wrist.osim 25, wrist_mass.osim 26, BothLegs.osim and BothLegs22.osim 93 each,
  // PushUpToesOnGroundWithMuscles.osim 100, Neck3dof_point_constraint.osim 5.
  EXPECT_EQ(muscles_per_model.size(), 6u);
  EXPECT_EQ(muscles, 342);
  EXPECT_EQ(balanced + slack + failed, 2 * muscles);
  EXPECT_EQ(failed, 0);
}

}  // namespace
}  // namespace sinew::muscles
