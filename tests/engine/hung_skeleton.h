// The hung skeletons of issue #15's accuracy benchmark, shared by Sinew's benchmark
// (benchmarks/engine_skeleton.cc), the same motion in Simbody (benchmarks/simbody_hung.cc) and
// the comparison tests (tests/simbody): a skeleton hung from
// its locked pelvis, limbs swinging from a bent pose (that of
// BuildSystemTest.Gait2354HungFromPelvisConservesEnergy, except that the left knee is given its
// speed towards flexion: towards extension it soon left the range of the knee's splines, whose
// linear extrapolation makes the accelerations jump), one simulated second.
#pragma once

#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/projection.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/build_system.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <memory>
#include <string>

namespace sinew::engine::testing {

struct HungSkeleton {
  sinew::model::ModelSpec spec;  ///< as read, pelvis coordinates locked
  std::unique_ptr<sinew::engine::System> system;
  sinew::engine::State start;
};

/// The models' files in tests/data.
inline const std::string kGait2354HungFile =
    std::string(SINEW_TEST_DATA_DIR) +
    "/opensim-org/opensim-models/Pipelines/Gait2354_Simbody/OutputReference/"
    "subject01_simbody_adjusted.osim";
inline const std::string kRajagopal2016HungFile =
    std::string(SINEW_TEST_DATA_DIR) +
    "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim";

/// `flexion`: the sign of knee flexion in the model (-1 for gait2354, +1 for Rajagopal2016).
/// `with_constraints`: build through the parser with the model's constraints (Rajagopal2016's
/// patella couplers) and forces other than its muscles; otherwise the skeleton alone.
inline HungSkeleton MakeHungSkeleton(const std::string& file, bool with_constraints,
                                     double flexion) {
  HungSkeleton hung;
  hung.spec = sinew::io::ReadOsim(file);
  for (sinew::model::CoordinateSpec& c : hung.spec.coordinates) {
    if (c.name.rfind("pelvis_", 0) == 0) c.locked = true;
  }
  if (with_constraints) {
    sinew::OpenSimParser parser;
    for (const sinew::model::ForceSpec& force : hung.spec.forces) {
      if (force.type == "Millard2012EquilibriumMuscle") parser.DisableForce(force.name);
    }
    hung.system = std::make_unique<sinew::engine::System>(hung.spec.gravity);
    parser.ParseSpec(*hung.system, hung.spec);
    hung.system->Finalize();
  } else {
    hung.system = sinew::opensim::BuildSystem(hung.spec);
  }
  hung.start = sinew::engine::MakeDefaultState(*hung.system);
  const struct {
    const char* name;
    double q, u;
  } pose[] = {{"hip_flexion_r", 0.6, 1.0},   {"knee_angle_r", 0.9 * flexion, 0.0},
              {"hip_flexion_l", -0.3, -0.5}, {"knee_angle_l", 0.2 * flexion, 2.0 * flexion},
              {"ankle_angle_r", 0.2, 0.0},   {"lumbar_extension", -0.2, 0.5},
              {"hip_adduction_l", 0.1, 0.3}, {"lumbar_bending", 0.1, -0.4}};
  for (const auto& p : pose) {
    hung.start.q[hung.system->FindCoordinate(p.name)] = p.q;
    hung.start.u[hung.system->FindCoordinate(p.name)] = p.u;
  }
  sinew::engine::PlaceBodies(*hung.system, hung.start);
  if (hung.system->HasExtraConstraints()) sinew::engine::ProjectState(*hung.system, hung.start);
  return hung;
}

/// One simulated second of `hung` with Sinew's `scheme` at `accuracy`.
inline sinew::engine::State RunHung(const HungSkeleton& hung, const char* scheme, double accuracy,
                                    sinew::engine::IntegratorStats* stats) {
  sinew::engine::State state = hung.start;
  sinew::engine::IntegratorSettings settings;
  settings.accuracy = accuracy;
  // Constraints to 1e-3 of the accuracy (the default), but not below what double rounding
  // allows on these models' 1e-1 m lever arms.
  settings.constraint_tolerance = std::max(1e-3 * accuracy, 1e-13);
  auto integrator = sinew::engine::MakeIntegrator(scheme, *hung.system, settings);
  integrator->StepTo(state, 1.0);
  if (stats != nullptr) *stats = integrator->stats();
  return state;
}

}  // namespace sinew::engine::testing
