// ControlSet files (io::ParseControlSet): ControlLinear nodes with OpenSim's rules for
// interpolation, steps and extrapolation (ControlLinear::getControlValue), ControlConstant, the
// ".excitation" suffix, and errors naming file, line and control. Expected values are worked by
// hand from those rules.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/read_controls.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace sinew::io {
namespace {

// A ControlSet holding `controls`.
std::string ControlSetText(const std::string& controls) {
  return "<OpenSimDocument Version=\"30000\">\n<ControlSet name=\"c\">\n<objects>\n" + controls +
         "</objects>\n</ControlSet>\n</OpenSimDocument>\n";
}

// A ControlLinear named `name` through nodes (1, 10), (2, 30), (4, 20) with the given flags.
std::string Linear(const std::string& name, const std::string& flags) {
  std::string nodes;
  for (const auto& [t, v] : {std::pair{1, 10}, {2, 30}, {4, 20}}) {
    nodes += "<ControlLinearNode><t>" + std::to_string(t) + "</t><value>" + std::to_string(v) +
             "</value></ControlLinearNode>";
  }
  return "<ControlLinear name=\"" + name + "\">" + flags + "<x_nodes>" + nodes +
         "</x_nodes></ControlLinear>\n";
}

TEST(ReadControlsTest, ControlLinearInterpolatesAndExtrapolatesAsOpenSim) {
  const auto controls = ParseControlSet(ControlSetText(Linear("a.excitation", "")), "c.xml");
  ASSERT_EQ(controls.count("a"), 1u);  // ".excitation" names actuator a
  const functions::Function& a = *controls.at("a");
  EXPECT_DOUBLE_EQ(a.Calc(1.5), 20.0);  // halfway from 10 to 30
  EXPECT_DOUBLE_EQ(a.Calc(3.0), 25.0);
  EXPECT_DOUBLE_EQ(a.Calc(0.0), -10.0);  // the first segment's line, extended (slope 20)
  EXPECT_DOUBLE_EQ(a.Calc(6.0), 10.0);   // the last segment's line, extended (slope -5)
}

TEST(ReadControlsTest, ControlLinearWithoutExtrapolationHoldsTheEnds) {
  const auto controls =
      ParseControlSet(ControlSetText(Linear("a", "<extrapolate>false</extrapolate>")), "c.xml");
  EXPECT_DOUBLE_EQ(controls.at("a")->Calc(0.0), 10.0);
  EXPECT_DOUBLE_EQ(controls.at("a")->Calc(6.0), 20.0);
  EXPECT_DOUBLE_EQ(controls.at("a")->Calc(1.5), 20.0);
}

// Steps: a node's value holds on (t(i-1), t(i)], so at a node its own value and just after it
// the next node's; outside the nodes the end values, even with extrapolate true (OpenSim
// extrapolates only linear controls).
TEST(ReadControlsTest, StepsTakeTheNextNodesValueAndNeverExtrapolate) {
  const auto controls = ParseControlSet(
      ControlSetText(Linear("a", "<use_steps>true</use_steps><extrapolate>true</extrapolate>")),
      "c.xml");
  const functions::Function& a = *controls.at("a");
  EXPECT_EQ(a.Calc(1.0), 10.0);
  EXPECT_EQ(a.Calc(1.001), 30.0);
  EXPECT_EQ(a.Calc(2.0), 30.0);
  EXPECT_EQ(a.Calc(3.0), 20.0);
  EXPECT_EQ(a.Calc(0.0), 10.0);
  EXPECT_EQ(a.Calc(9.0), 20.0);
  EXPECT_EQ(a.CalcDerivative(9.0, 1), 0.0);
}

TEST(ReadControlsTest, ControlConstantIsItsValueOrZero) {
  const auto controls =
      ParseControlSet(ControlSetText("<ControlConstant name=\"k.excitation\"><value>0.25</value>"
                                     "</ControlConstant>\n<ControlConstant name=\"z\"/>\n"),
                      "c.xml");
  EXPECT_EQ(controls.at("k")->Calc(-3.0), 0.25);
  EXPECT_EQ(controls.at("k")->Calc(7.0), 0.25);
  EXPECT_EQ(controls.at("z")->Calc(1.0), 0.0);
}

TEST(ReadControlsTest, UnsupportedOrRepeatedControlsNameFileLineAndControl) {
  const auto error = [](const std::string& controls) {
    try {
      ParseControlSet(ControlSetText(controls), "c.xml");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("<ControlLinearSpline name=\"s\"/>\n"),
            "c.xml:4: /controlset/s: control type <ControlLinearSpline> is not supported "
            "(ControlLinear and ControlConstant are)");
  EXPECT_EQ(error(Linear("a", "") + Linear("a.excitation", "")),
            "c.xml:5: /controlset/a.excitation: a second control for actuator 'a'");
}

// A storage table of controls (OpenSim's ControlSet(Storage)): each column a ControlLinear
// through its rows, linear between them and extrapolated beyond.
TEST(ReadControlsTest, StorageTableColumnsAreLinearControls) {
  const std::string file = ::testing::TempDir() + "/sinew_controls_table.sto";
  std::ofstream(file) << "controls\nversion=1\nnRows=3\nnColumns=3\ninDegrees=no\nendheader\n"
                         "time\ta.excitation\tb\n1\t10\t0\n2\t30\t1\n4\t20\t1\n";
  const auto controls = ReadControlSet(file);
  ASSERT_EQ(controls.size(), 2u);
  EXPECT_DOUBLE_EQ(controls.at("a")->Calc(1.5), 20.0);
  EXPECT_DOUBLE_EQ(controls.at("a")->Calc(6.0), 10.0);
  EXPECT_DOUBLE_EQ(controls.at("b")->Calc(0.0), -1.0);
  std::remove(file.c_str());
}

}  // namespace
}  // namespace sinew::io
