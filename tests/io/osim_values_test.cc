// Every number of a model file is checked where it is read (XmlDocument::ReadNumbers): NaN and
// infinities are errors naming the file, the line and the component, instead of passing and
// failing later as a singular system with no line. Bounds (ranges) may be infinite, as OpenSim
// writes them.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/osim_reader.h>

#include <cmath>
#include <string>

namespace sinew {
namespace {

// One body on a pin; `{prop}` placeholders are replaced by the test's values.
std::string Model(const std::string& tag, const std::string& value) {
  std::string text = R"(<?xml version="1.0" encoding="UTF-8" ?>
<OpenSimDocument Version="40000">
  <Model name="m">
    <gravity>0 -9.80665 0</gravity>
    <Ground name="ground"/>
    <BodySet name="bodyset">
      <objects>
        <Body name="rod">
          <mass>1</mass>
          <mass_center>0 -0.5 0</mass_center>
          <inertia>0.1 0.1 0.1 0 0 0</inertia>
        </Body>
      </objects>
    </BodySet>
    <JointSet name="jointset">
      <objects>
        <PinJoint name="pin">
          <socket_parent_frame>ground_offset</socket_parent_frame>
          <socket_child_frame>rod_offset</socket_child_frame>
          <coordinates>
            <Coordinate name="q">
              <default_value>0.3</default_value>
              <default_speed_value>0</default_speed_value>
              <range>-3 3</range>
            </Coordinate>
          </coordinates>
          <frames>
            <PhysicalOffsetFrame name="ground_offset">
              <socket_parent>/ground</socket_parent>
              <translation>0 1 0</translation>
              <orientation>0 0 0</orientation>
            </PhysicalOffsetFrame>
            <PhysicalOffsetFrame name="rod_offset">
              <socket_parent>/bodyset/rod</socket_parent>
              <translation>0 0 0</translation>
              <orientation>0 0 0</orientation>
            </PhysicalOffsetFrame>
          </frames>
        </PinJoint>
      </objects>
    </JointSet>
  </Model>
</OpenSimDocument>
)";
  if (tag.empty()) return text;
  const size_t open = text.find("<" + tag + ">");
  const size_t close = text.find("</" + tag + ">", open);
  EXPECT_NE(open, std::string::npos) << tag;
  text.replace(open, close - open, "<" + tag + ">" + value);
  return text;
}

int LineOf(const std::string& text, const std::string& needle) {
  int line = 1;
  for (size_t i = 0; i < text.find(needle); ++i) line += text[i] == '\n';
  return line;
}

struct BadValue {
  const char* tag;
  const char* value;
  const char* component;
};

class OsimValuesTest : public ::testing::TestWithParam<BadValue> {};

TEST_P(OsimValuesTest, NonFiniteNumberIsAnErrorAtItsLine) {
  const BadValue bad = GetParam();
  const std::string text = Model(bad.tag, bad.value);
  try {
    io::ReadOsimString(text, "bad.osim");
    ADD_FAILURE() << "<" << bad.tag << ">" << bad.value << " was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "bad.osim") << e.what();
    EXPECT_EQ(e.where().line, LineOf(text, std::string("<") + bad.tag + ">" + bad.value))
        << e.what();
    EXPECT_EQ(e.component(), bad.component) << e.what();
    EXPECT_NE(std::string(e.what()).find("finite"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    EveryKindOfValue, OsimValuesTest,
    ::testing::Values(BadValue{"mass", "nan", "/bodyset/rod"},
                      BadValue{"mass", "inf", "/bodyset/rod"},
                      BadValue{"mass_center", "0 NaN 0", "/bodyset/rod"},
                      BadValue{"inertia", "0.1 inf 0.1 0 0 0", "/bodyset/rod"},
                      BadValue{"gravity", "0 -inf 0", "/"},
                      BadValue{"default_value", "nan", "/jointset/pin/q"},
                      BadValue{"default_speed_value", "-Inf", "/jointset/pin/q"},
                      BadValue{"translation", "0 nan 0", "/jointset/pin/ground_offset"},
                      BadValue{"orientation", "inf 0 0", "/jointset/pin/ground_offset"}));

TEST(OsimValuesTest, RangesMayBeInfiniteButNotNaN) {
  const model::ModelSpec spec = io::ReadOsimString(Model("range", "-Inf Inf"), "ok.osim");
  ASSERT_EQ(spec.coordinates.size(), 1u);
  EXPECT_TRUE(std::isinf(spec.coordinates[0].range_min));
  EXPECT_TRUE(std::isinf(spec.coordinates[0].range_max));
  EXPECT_THROW(io::ReadOsimString(Model("range", "-3 nan"), "bad.osim"), Error);
}

}  // namespace
}  // namespace sinew
