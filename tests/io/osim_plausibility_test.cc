// Values that are numbers but not physical: a negative moment of inertia is an error at its
// line; an indefinite inertia, an inertia that breaks the triangle inequality and a default
// value outside the coordinate's range are warnings (OpenSim reads them, real models have them).
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>

#include <string>

#include "corpus.h"

namespace sinew {
namespace {

// A 4.x model with one body (inertia `inertia`) on a pin joint whose coordinate has
// `coordinate_properties`.
std::string Model(const std::string& inertia, const std::string& coordinate_properties = "") {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n"
         "<OpenSimDocument Version=\"40000\">\n"
         "  <Model name=\"m\">\n"
         "    <Ground name=\"ground\"/>\n"
         "    <BodySet name=\"bodyset\"><objects>\n"
         "        <Body name=\"b\">\n"
         "          <mass>1</mass>\n"
         "          <inertia>" +
         inertia +
         "</inertia>\n"
         "        </Body>\n"
         "    </objects></BodySet>\n"
         "    <JointSet name=\"jointset\"><objects>\n"
         "        <PinJoint name=\"j\">\n"
         "          <socket_parent_frame>/ground</socket_parent_frame>\n"
         "          <socket_child_frame>/bodyset/b</socket_child_frame>\n"
         "          <coordinates><Coordinate name=\"q\">" +
         coordinate_properties +
         "</Coordinate></coordinates>\n"
         "        </PinJoint>\n"
         "    </objects></JointSet>\n"
         "  </Model>\n"
         "</OpenSimDocument>\n";
}

// The one warning of `spec` that contains `fragment` (a failure when there is none).
const Diagnostic* FindWarning(const model::ModelSpec& spec, const std::string& fragment) {
  for (const Diagnostic& d : spec.warnings) {
    if (d.message.find(fragment) != std::string::npos) return &d;
  }
  ADD_FAILURE() << "no warning containing '" << fragment << "'";
  return nullptr;
}

TEST(OsimPlausibility, APhysicalInertiaReadsWithoutWarnings) {
  const model::ModelSpec spec = io::ReadOsimString(Model("0.1 0.1 0.1 0 0 0"), "p.osim");
  EXPECT_TRUE(spec.warnings.empty()) << spec.warnings.front().Format();
}

TEST(OsimPlausibility, ANegativeMomentIsAnErrorAtItsLine) {
  try {
    io::ReadOsimString(Model("-0.1 0.1 0.1 0 0 0"), "p.osim");
    FAIL() << "a negative moment must be an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "p.osim");
    EXPECT_EQ(e.where().line, 8);
    EXPECT_EQ(e.component(), "/bodyset/b");
    EXPECT_NE(e.message().find("negative moment of inertia (the diagonal is -0.1, 0.1, 0.1)"),
              std::string::npos)
        << e.what();
  }
}

TEST(OsimPlausibility, AnIndefiniteInertiaIsAWarning) {
  // Diagonal 1, 1, 1 with products 1: principal moments -1 ... (1 - 2 < 0).
  const model::ModelSpec spec = io::ReadOsimString(Model("1 1 1 1 1 0"), "p.osim");
  const Diagnostic* warning = FindWarning(spec, "indefinite inertia matrix");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->where.line, 8);
  EXPECT_EQ(warning->component, "/bodyset/b");
}

TEST(OsimPlausibility, ATriangleInequalityViolationIsAWarning) {
  const model::ModelSpec spec = io::ReadOsimString(Model("0.1 0.1 0.3 0 0 0"), "p.osim");
  const Diagnostic* warning = FindWarning(
      spec, "inertia violates the triangle inequality (principal moments 0.1, 0.1, 0.3");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->where.line, 8);
  // Equality (a thin rod, a flat plate) is physical.
  EXPECT_TRUE(io::ReadOsimString(Model("0.1 0.2 0.3 0 0 0"), "p.osim").warnings.empty());
}

TEST(OsimPlausibility, ADefaultValueOutsideTheRangeIsAWarning) {
  const model::ModelSpec spec = io::ReadOsimString(
      Model("0.1 0.1 0.1 0 0 0", "<default_value>1e308</default_value><range>-1 1</range>"),
      "p.osim");
  const Diagnostic* warning =
      FindWarning(spec, "<default_value> 1e+308 is outside <range> [-1, 1]");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->where.line, 15);
  EXPECT_EQ(warning->component, "/jointset/j/q");
  EXPECT_TRUE(io::ReadOsimString(
                  Model("0.1 0.1 0.1 0 0 0", "<default_value>1</default_value><range>-1 1</range>"),
                  "p.osim")
                  .warnings.empty());
}

TEST(OsimPlausibility, SoccerKickingModelReadsWithTriangleWarnings) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const model::ModelSpec spec =
      io::ReadOsim((testing::CorpusDir() /
                    "opensim-org/opensim-models/Models/SoccerKick/SoccerKickingModel.osim")
                       .string());
  int triangle = 0;
  for (const Diagnostic& d : spec.warnings) {
    triangle += d.message.find("triangle inequality") != std::string::npos;
  }
  EXPECT_EQ(triangle, 2);  // toes_r and toes_l
}

}  // namespace
}  // namespace sinew
