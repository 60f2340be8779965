// The loads a path applies are consistent with its lengthening speed: a tension T along the
// path delivers the power -T dL/dt to the bodies and coordinates (virtual power), at any pose
// and speeds, here on arm26's six wrapped paths (cylinders, ellipsoids, three wraps on TRIlong).
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/loads.h>
#include <sinew/muscles/path_actuator.h>
#include <sinew/opensim/parser.h>

#include <cmath>
#include <string>

namespace sinew::muscles {
namespace {

TEST(PathPowerTest, TensionLoadsDeliverMinusTensionTimesLengtheningSpeed) {
  opensim::OpenSimParser parser;
  const auto system = parser.Parse(std::string(SINEW_TEST_DATA_DIR) +
                                   "/opensim-org/opensim-models/Models/Arm26/arm26.osim");
  int checked = 0;
  for (const double elbow : {0.2, 1.0, 2.0}) {
    engine::State state = engine::MakeDefaultState(*system);
    state.q[0] = 0.3;
    state.q[1] = elbow;
    state.u[0] = 0.7;
    state.u[1] = -1.3;
    engine::PlaceBodies(*system, state);
    for (const auto& element : system->force_elements()) {
      const auto* actuator = dynamic_cast<const PathActuator*>(element.get());
      if (!actuator) continue;
      PathScratch& scratch = EnginePath::Scratch();
      const PathKinematics path = actuator->path().Calc(state, scratch);
      engine::Loads loads(system->num_bodies(), system->num_coordinates());
      const double tension = 100.0;
      actuator->path().AddTensionLoads(state, tension, scratch, loads);
      double power = loads.mobility.dot(state.u);
      for (int b = 0; b < system->num_bodies(); ++b) {
        power += loads.body[b].head<3>().dot(state.bodies[b].w_GB) +
                 loads.body[b].tail<3>().dot(state.bodies[b].v_GB);
      }
      // Measured: equal to all printed digits (12) on the 18 checks.
      EXPECT_NEAR(power, -tension * path.lengthening_speed,
                  1e-9 * tension * (1.0 + std::abs(path.lengthening_speed)))
          << actuator->name() << " at elbow " << elbow;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 18);
}

}  // namespace
}  // namespace sinew::muscles
