// OpenSim's PrescribedForce through the parser: a closed-form motion under a force growing in
// time, and the loads at a turned pose by hand for each of forceIsGlobal / pointIsGlobal, on
// an offset frame (4.x socket_frame) and on a body (3.x <body>, FunctionSet properties).
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/math/rotation.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <utility>

#include "forces/osim_text_models.h"

namespace sinew {
namespace {

std::unique_ptr<engine::System> ParseText(const std::string& text, opensim::Report* report) {
  testing::ParsedModel parsed = testing::ParseOsimText(text, "prescribed.osim");
  *report = parsed.report;
  return std::move(parsed.system);
}

TEST(PrescribedForceTest, GrowingForceMovesASliderAsTheClosedForm) {
  // F = 3 t along the slider (ground x) on a 2 kg block from rest at 0.1: x = 0.1 + t^3 / 4.
  const std::string text = testing::SliderModel(
      R"(<PrescribedForce name="push"><socket_frame>/bodyset/block</socket_frame>
<forceFunctions><objects><LinearFunction><coefficients>3 0</coefficients></LinearFunction>
<Constant><value>0</value></Constant><Constant><value>0</value></Constant></objects>
</forceFunctions></PrescribedForce>)");
  opensim::Report report;
  auto system = ParseText(text, &report);
  ASSERT_TRUE(report.not_simulated().empty());
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-12;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  engine::State state = engine::MakeDefaultState(*system);
  double worst = 0.0;
  for (int k = 1; k <= 20; ++k) {
    const double t = 0.1 * k;
    integrator->StepTo(state, t);
    worst = std::max(worst, std::abs(state.q[0] - 0.1 - t * t * t / 4.0));
  }
  // rk45 is exact for a cubic x(t) up to rounding.
  EXPECT_LT(worst, 1e-13);
  std::cout << "prescribed force on a slider: worst error " << worst << " m\n";
}

// A free box turned by body-fixed XYZ angles (0.3, -0.2, 0.5) and placed at (0.1, 0.2, 0.3),
// with a PrescribedForce `force` in its ForceSet and an offset frame on it.
std::string BoxModel(const std::string& force) {
  return R"(<OpenSimDocument Version="40000"><Model name="m">
<gravity>0 0 0</gravity><Ground name="ground"/>
<BodySet><objects><Body name="box"><mass>1</mass><inertia>1 1 1 0 0 0</inertia>
<components><PhysicalOffsetFrame name="box_offset"><socket_parent>..</socket_parent>
<translation>0.2 0 -0.1</translation><orientation>0 0 1.5707963267948966</orientation>
</PhysicalOffsetFrame></components></Body></objects></BodySet>
<JointSet><objects><FreeJoint name="free"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/box</socket_child_frame><coordinates>
<Coordinate name="rx"><default_value>0.3</default_value></Coordinate>
<Coordinate name="ry"><default_value>-0.2</default_value></Coordinate>
<Coordinate name="rz"><default_value>0.5</default_value></Coordinate>
<Coordinate name="tx"><default_value>0.1</default_value></Coordinate>
<Coordinate name="ty"><default_value>0.2</default_value></Coordinate>
<Coordinate name="tz"><default_value>0.3</default_value></Coordinate>
</coordinates></FreeJoint></objects></JointSet>
<ForceSet><objects>)" +
         force + R"(</objects></ForceSet></Model></OpenSimDocument>)";
}

// F(t) = (1, 2t, -3), P = (0.1, 0, -0.2), T = (0.5, 0, 0) as PrescribedForce properties.
const char* const kFunctions = R"(
<forceFunctions><objects><Constant><value>1</value></Constant>
<LinearFunction><coefficients>2 0</coefficients></LinearFunction>
<Constant><value>-3</value></Constant></objects></forceFunctions>
<pointFunctions><objects><Constant><value>0.1</value></Constant>
<Constant><value>0</value></Constant><Constant><value>-0.2</value></Constant></objects>
</pointFunctions>
<torqueFunctions><objects><Constant><value>0.5</value></Constant>
<Constant><value>0</value></Constant><Constant><value>0</value></Constant></objects>
</torqueFunctions>)";

SpatialVec BoxLoad(const std::string& force, double t) {
  opensim::Report report;
  auto system = ParseText(BoxModel(force), &report);
  EXPECT_TRUE(report.not_simulated().empty());
  engine::State state = engine::MakeDefaultState(*system, t);
  engine::Loads loads(system->num_bodies(), system->num_coordinates());
  system->force_elements()[0]->AddLoads(system->MakeForceContext(0, state), loads);
  return loads.body[system->FindBody("box")];
}

TEST(PrescribedForceTest, LoadsOnAnOffsetFrameFollowTheGlobalFlags) {
  // At t = 0.5: F = (1, 1, -3), P = (0.1, 0, -0.2), T = (0.5, 0, 0). The box: R_GB from its
  // free joint's angles, origin p = (0.1, 0.2, 0.3); the frame: turned 90 degrees about the
  // box's z, at (0.2, 0, -0.1) in the box. The load is [torque about the box origin; force].
  const double t = 0.5;
  const Vec3 F(1, 1, -3), P(0.1, 0, -0.2), T(0.5, 0, 0), p_GB(0.1, 0.2, 0.3);
  const Mat3 R_GB = RotationFromBodyFixedXYZ(Vec3(0.3, -0.2, 0.5));
  Mat3 R_BF;  // 90 degrees about z: x -> y, y -> -x
  R_BF << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const Vec3 p_BF(0.2, 0, -0.1);
  const Mat3 R_GF = R_GB * R_BF;
  auto load = [](const Vec3& torque, const Vec3& force) {
    SpatialVec l;
    l << torque, force;
    return l;
  };
  struct Case {
    const char* flags;
    SpatialVec expected;
  };
  const Vec3 r_frame_point = R_GB * (p_BF + R_BF * P);  // P in the frame, from the box origin
  const Vec3 r_global_point = P - p_GB;                 // P in ground, from the box origin
  const Case cases[] = {
      {"<forceIsGlobal>true</forceIsGlobal><pointIsGlobal>false</pointIsGlobal>",
       load(r_frame_point.cross(F) + T, F)},
      {"<forceIsGlobal>false</forceIsGlobal><pointIsGlobal>false</pointIsGlobal>",
       load(r_frame_point.cross(R_GF * F) + R_GF * T, R_GF * F)},
      {"<forceIsGlobal>true</forceIsGlobal><pointIsGlobal>true</pointIsGlobal>",
       load(r_global_point.cross(F) + T, F)},
      {"<forceIsGlobal>false</forceIsGlobal><pointIsGlobal>true</pointIsGlobal>",
       load(r_global_point.cross(R_GF * F) + R_GF * T, R_GF * F)},
  };
  for (const Case& c : cases) {
    const std::string force =
        "<PrescribedForce name=\"p\"><socket_frame>/bodyset/box/box_offset"
        "</socket_frame>" +
        std::string(c.flags) + kFunctions + "</PrescribedForce>";
    EXPECT_TRUE(BoxLoad(force, t).isApprox(c.expected, 1e-13)) << c.flags;
  }
  // OpenSim's defaults are forceIsGlobal true, pointIsGlobal false.
  const std::string defaults =
      "<PrescribedForce name=\"p\"><socket_frame>/bodyset/box/box_offset"
      "</socket_frame>" +
      std::string(kFunctions) + "</PrescribedForce>";
  EXPECT_TRUE(BoxLoad(defaults, t).isApprox(cases[0].expected, 1e-13));
}

TEST(PrescribedForceTest, OldLayoutNamesTheBodyAndFunctionSets) {
  // 3.x: <body> and <FunctionSet name="forceFunctions">; no point: the body origin. Force in
  // the body's frame (forceIsGlobal false): R_GB F, and T turned likewise.
  const std::string force = R"(<PrescribedForce name="p"><body>box</body>
<forceIsGlobal>false</forceIsGlobal>
<FunctionSet name="forceFunctions"><objects><Constant><value>1</value></Constant>
<Constant><value>2</value></Constant><Constant><value>3</value></Constant></objects></FunctionSet>
<FunctionSet name="torqueFunctions"><objects><Constant><value>0</value></Constant>
<Constant><value>0</value></Constant><Constant><value>-1</value></Constant></objects></FunctionSet>
</PrescribedForce>)";
  const Mat3 R_GB = RotationFromBodyFixedXYZ(Vec3(0.3, -0.2, 0.5));
  SpatialVec expected;
  expected << R_GB * Vec3(0, 0, -1), R_GB * Vec3(1, 2, 3);
  EXPECT_TRUE(BoxLoad(force, 0.0).isApprox(expected, 1e-13));
}

TEST(PrescribedForceTest, TwoOfThreeComponentsIsAnError) {
  const std::string force = R"(<PrescribedForce name="p"><socket_frame>/bodyset/box</socket_frame>
<forceFunctions><objects><Constant><value>1</value></Constant>
<Constant><value>2</value></Constant></objects></forceFunctions></PrescribedForce>)";
  try {
    BoxLoad(force, 0.0);
    ADD_FAILURE() << "accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("prescribed.osim:"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("/forceset/p"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("three"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sinew
