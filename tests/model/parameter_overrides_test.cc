// ApplyParameterOverrides changes exactly what the builders read: a force's property in its
// element (read back through ElementValues, as the builders read it), a body's mass properties
// and a coordinate's defaults in their typed fields; and rejects every bad override with the
// file, a line and the component.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/osim_reader.h>
#include <sinew/model/element_values.h>
#include <sinew/model/parameter_overrides.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace sinew::model {
namespace {

const std::string kData = SINEW_TEST_DATA_DIR;
// OpenSim 2.x arm26 (3.x-style inertia_xx ... properties, Thelen2003Muscle BIClong at line 588).
const std::string kArm26 =
    kData + "/opensim-org/opensim-core/Applications/Forward/tests/resources/arm26.osim";
const std::string kSprings = kData + "/sinew/springs.osim";

const ForceSpec& Force(const ModelSpec& spec, const std::string& name) {
  for (const ForceSpec& f : spec.forces) {
    if (f.name == name) return f;
  }
  throw std::runtime_error("no force " + name);
}

// Reads property `tag` of force `name` as a builder does.
double ForceProperty(const ModelSpec& spec, const std::string& name, const std::string& tag) {
  const ForceSpec& force = Force(spec, name);
  return ElementValues(force.element, spec.file, force.path).Double(tag, NAN);
}

TEST(ParameterOverridesTest, ForcePropertyIsReadBackExactly) {
  ModelSpec spec = io::ReadOsim(kArm26);
  const double original = ForceProperty(spec, "BICshort", "max_isometric_force");
  // A value whose shortest decimal form has 17 digits must survive the text round trip.
  const double value = 1000.0 / 3.0;
  ApplyParameterOverrides(spec, {{"BIClong/max_isometric_force", {value}}});
  EXPECT_EQ(ForceProperty(spec, "BIClong", "max_isometric_force"), value);
  EXPECT_EQ(ForceProperty(spec, "BICshort", "max_isometric_force"), original);
  // By path, and the later of two overrides wins.
  ApplyParameterOverrides(spec, {{"/forceset/BIClong/max_isometric_force", {700}},
                                 {"BIClong/max_isometric_force", {0.1 + 0.2}}});
  EXPECT_EQ(ForceProperty(spec, "BIClong", "max_isometric_force"), 0.1 + 0.2);
}

TEST(ParameterOverridesTest, BodyMassProperties) {
  ModelSpec spec = io::ReadOsim(kArm26);
  const int b = spec.FindBody("r_humerus");
  ApplyParameterOverrides(spec, {{"r_humerus/mass", {2.5}},
                                 {"r_humerus/mass_center", {0.01, -0.2, 0.02}},
                                 {"r_humerus/inertia_xy", {0.001}}});
  EXPECT_EQ(spec.bodies[b].mass, 2.5);
  EXPECT_EQ(spec.bodies[b].mass_center, Vec3(0.01, -0.2, 0.02));
  EXPECT_EQ(spec.bodies[b].inertia(0, 1), 0.001);
  EXPECT_EQ(spec.bodies[b].inertia(1, 0), 0.001);
  ApplyParameterOverrides(spec, {{"/bodyset/r_humerus/inertia", {1, 2, 3, 0.4, 0.5, 0.6}}});
  Mat3 expected;
  expected << 1, 0.4, 0.5, 0.4, 2, 0.6, 0.5, 0.6, 3;
  EXPECT_EQ(spec.bodies[b].inertia, expected);
}

TEST(ParameterOverridesTest, CoordinateDefaultsAndRange) {
  ModelSpec spec = io::ReadOsim(kArm26);
  const int c = spec.FindCoordinate("r_elbow_flex");
  ApplyParameterOverrides(spec, {{"r_elbow_flex/default_value", {1.25}},
                                 {"r_elbow_flex/default_speed_value", {-0.5}},
                                 {"r_elbow_flex/range", {-1, INFINITY}}});
  EXPECT_EQ(spec.coordinates[c].default_value, 1.25);
  EXPECT_EQ(spec.coordinates[c].default_speed_value, -0.5);
  EXPECT_EQ(spec.coordinates[c].range_min, -1);
  EXPECT_EQ(spec.coordinates[c].range_max, INFINITY);
}

// Expects `overrides` to be rejected naming `file`, `line` (-1: any), `component`, and a
// message containing `words`.
void ExpectRejected(const std::string& file, const std::vector<ParameterOverride>& overrides,
                    int line, const std::string& component, const std::string& words) {
  ModelSpec spec = io::ReadOsim(file);
  try {
    ApplyParameterOverrides(spec, overrides);
    ADD_FAILURE() << overrides.front().key << " was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, file);
    if (line >= 0) {
      EXPECT_EQ(e.where().line, line) << e.what();
    }
    EXPECT_EQ(e.component(), component) << e.what();
    EXPECT_NE(e.message().find(words), std::string::npos) << e.what();
  }
}

TEST(ParameterOverridesTest, UnknownComponentSuggestsCloseNames) {
  ExpectRejected(kArm26, {{"BIClng/max_isometric_force", {1}}}, 0, "BIClng",
                 "close names: BIClong");
  ExpectRejected(kArm26, {{"/forceset/nothing/max_isometric_force", {1}}}, 0, "/forceset/nothing",
                 "no body, coordinate or force has this path");
  ExpectRejected(kArm26, {{"max_isometric_force", {1}}}, 0, "max_isometric_force",
                 "'<component>/<property>'");
}

TEST(ParameterOverridesTest, PropertyMustBeWrittenAndNumeric) {
  // The muscle's element has no <stiffness>; its numeric properties are listed.
  ExpectRejected(kArm26, {{"BIClong/stiffness", {1}}}, 588, "/forceset/BIClong",
                 "max_isometric_force");
  ExpectRejected(kSprings, {{"block_spring/coordinate", {1}}}, -1, "/forceset/block_spring",
                 "not a numeric property");
  ExpectRejected(kArm26, {{"r_humerus/volume", {1}}}, -1, "/bodyset/r_humerus",
                 "mass, mass_center, inertia");
}

TEST(ParameterOverridesTest, ValueCountAndNumbersAreChecked) {
  // max_isometric_force is at line 831, mass_center is a 3-vector.
  ExpectRejected(kArm26, {{"BIClong/max_isometric_force", {1, 2}}}, 831, "/forceset/BIClong",
                 "expects 1 number, given 2");
  ExpectRejected(kArm26, {{"BIClong/max_isometric_force", {NAN}}}, 831, "/forceset/BIClong",
                 "no NaN");
  ExpectRejected(kArm26, {{"r_humerus/mass_center", {0, 1}}}, -1, "/bodyset/r_humerus",
                 "expects 3 numbers, given 2");
  ExpectRejected(kArm26, {{"r_humerus/mass", {INFINITY}}}, -1, "/bodyset/r_humerus", "finite");
  ExpectRejected(kArm26, {{"r_humerus/mass", {-1}}}, -1, "/bodyset/r_humerus", "negative");
  ExpectRejected(kArm26, {{"r_humerus/inertia", {1, -1, 1, 0, 0, 0}}}, -1, "/bodyset/r_humerus",
                 "negative");
  ExpectRejected(kArm26, {{"r_elbow_flex/range", {1, 0}}}, -1, "/jointset/r_elbow/r_elbow_flex",
                 "minimum");
}

TEST(ParameterOverridesTest, OtherKindsAreRefusedByName) {
  ExpectRejected(kSprings, {{"block_slide/reverse", {1}}}, -1, "/jointset/block_slide",
                 "a joint's properties cannot be overridden yet");
  ExpectRejected(kSprings, {{"follower_coupler/scale_factor", {1}}}, -1,
                 "/constraintset/follower_coupler", "a constraint's properties");
  ExpectRejected(kSprings, {{"ground/mass", {1}}}, -1, "/ground", "ground has no mass");
}

TEST(ParameterOverridesTest, AmbiguousNameAsksForAPath) {
  ModelSpec spec = io::ReadOsim(kSprings);
  spec.coordinates[spec.FindCoordinate("block_x")].name = "block_spring";
  try {
    ApplyParameterOverrides(spec, {{"block_spring/default_value", {1}}});
    ADD_FAILURE() << "an ambiguous name was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, kSprings);
    EXPECT_EQ(e.component(), "block_spring");
    EXPECT_NE(e.message().find("ambiguous"), std::string::npos) << e.what();
    EXPECT_NE(e.message().find("/forceset/block_spring"), std::string::npos) << e.what();
  }
  // The path settles it.
  ApplyParameterOverrides(spec, {{"/forceset/block_spring/stiffness", {8}}});
  EXPECT_EQ(ForceProperty(spec, "block_spring", "stiffness"), 8);
}

}  // namespace
}  // namespace sinew::model
