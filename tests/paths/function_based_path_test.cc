// OpenSim 4.5's FunctionBasedPath against closed forms
// (tests/data/sinew/function_based_paths.osim): its length is a known polynomial of the
// coordinates, so the length, the lengthening speed, the moment arms and the generalized force of a
// tension are known exactly; a path that gives moment arm and speed functions uses them (OpenSim's
// rule); and malformed paths are refused naming the file, line and component.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/osim_reader.h>
#include <sinew/paths/path_analysis.h>
#include <sinew/paths/path_loads.h>
#include <sinew/paths/speed_columns.h>

#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "path_test_util.h"

namespace sinew::paths {
namespace {

const std::string kModel = testing::kDataDir + "/sinew/function_based_paths.osim";

// The spring's length (m) and its partial derivatives, as the model's comment writes them.
double SpringLength(double q1, double q2) {
  return 0.3 + 0.02 * q2 - 0.01 * q2 * q2 - 0.04 * q1 + 0.015 * q1 * q2 + 0.005 * q1 * q1;
}
double SpringSlope1(double q1, double q2) { return -0.04 + 0.015 * q2 + 0.01 * q1; }
double SpringSlope2(double q1, double q2) { return 0.02 - 0.02 * q2 + 0.015 * q1; }

// Poses (q1, q2) and speeds (u1, u2), inside and far outside the motion's range.
constexpr std::array<std::array<double, 4>, 4> kPoses = {{{0.3, -0.2, 0.0, 0.0},
                                                          {-1.1, 0.7, 0.5, -1.2},
                                                          {2.0, 1.5, -3.0, 0.25},
                                                          {-2.5, -3.0, 1.0, 2.0}}};

// Polynomials of degree 2 evaluated in doubles of magnitude < 1: rounding stays near 1e-16.
constexpr double kTolerance = 1e-14;

class FunctionBasedPathTest : public ::testing::Test {
 protected:
  FunctionBasedPathTest()
      : model_(kModel),
        q1_(model_.spec.FindCoordinate("q1")),
        q2_(model_.spec.FindCoordinate("q2")),
        spring_(model_.FindPath("spring")),
        act_(model_.FindPath("act")) {}

  std::vector<double> Q(double q1, double q2) const {
    std::vector<double> q = model_.tree.default_q();
    q[q1_] = q1;
    q[q2_] = q2;
    return q;
  }

  testing::PathModel model_;
  int q1_, q2_, spring_, act_;
};

TEST_F(FunctionBasedPathTest, ReadsBothPathsWithTheirFunctions) {
  ASSERT_EQ(model_.paths.paths().size(), 2u);
  ASSERT_GE(spring_, 0);
  ASSERT_GE(act_, 0);
  const GeometryPath& spring = model_.paths.paths()[spring_];
  ASSERT_NE(spring.function_path(), nullptr);
  EXPECT_TRUE(spring.points().empty());
  EXPECT_EQ(spring.function_path()->coordinates, (std::vector<int>{q1_, q2_}));
  EXPECT_EQ(spring.function_path()->length_function->TypeName(), "MultivariatePolynomialFunction");
  EXPECT_TRUE(spring.function_path()->moment_arm_functions.empty());
  EXPECT_EQ(spring.function_path()->lengthening_speed_function, nullptr);
  const GeometryPath& act = model_.paths.paths()[act_];
  ASSERT_NE(act.function_path(), nullptr);
  EXPECT_EQ(act.function_path()->moment_arm_functions.size(), 1u);
  EXPECT_NE(act.function_path()->lengthening_speed_function, nullptr);
  // Nothing of the model is left out.
  EXPECT_TRUE(model_.paths.ListOmissions(model_.spec).empty());
}

TEST_F(FunctionBasedPathTest, LengthSpeedAndMomentArmsAreTheClosedForm) {
  PathAnalysis analysis(model_.spec, model_.tree, model_.couplers, model_.paths, {q1_, q2_});
  for (const auto& [q1, q2, u1, u2] : kPoses) {
    const std::vector<double> q = Q(q1, q2);
    std::vector<double> u(q.size(), 0.0);
    u[q1_] = u1;
    u[q2_] = u2;
    analysis.Calc(q, u);
    SCOPED_TRACE("q1 = " + std::to_string(q1) + ", q2 = " + std::to_string(q2));
    EXPECT_NEAR(analysis.lengths()[spring_], SpringLength(q1, q2), kTolerance);
    EXPECT_NEAR(analysis.lengthening_speeds()[spring_],
                SpringSlope1(q1, q2) * u1 + SpringSlope2(q1, q2) * u2, kTolerance);
    EXPECT_NEAR(analysis.moment_arm(0, spring_), -SpringSlope1(q1, q2), kTolerance);
    EXPECT_NEAR(analysis.moment_arm(1, spring_), -SpringSlope2(q1, q2), kTolerance);
    // The moment arms are -dL/dq of the length the path reports (central differences: the
    // third derivative is zero, so only rounding, ~1e-16 / h, remains).
    const double h = 1e-4;
    const auto length = [&](double a, double b) { return model_.CalcLength(spring_, Q(a, b)); };
    EXPECT_NEAR(analysis.moment_arm(0, spring_),
                -(length(q1 + h, q2) - length(q1 - h, q2)) / (2 * h), 1e-10);
    EXPECT_NEAR(analysis.moment_arm(1, spring_),
                -(length(q1, q2 + h) - length(q1, q2 - h)) / (2 * h), 1e-10);
    // The actuator's path gives its own moment arm and speed functions: OpenSim uses them
    // as they are (they need not be the derivatives of the length), and its moment arm about
    // a coordinate it does not list is zero.
    EXPECT_NEAR(analysis.lengths()[act_], 0.2 * q1 + 0.01, kTolerance);
    EXPECT_NEAR(analysis.moment_arm(0, act_), 0.1 * q1 - 0.05, kTolerance);
    EXPECT_EQ(analysis.moment_arm(1, act_), 0.0);
    EXPECT_NEAR(analysis.lengthening_speeds()[act_], 0.001 + 0.7 * u1, kTolerance);
  }
}

TEST_F(FunctionBasedPathTest, GeneralizedForceIsMinusTensionTimesTheLengthGradient) {
  const double tension = 7.5;  // N
  std::vector<Transform> X_GB(static_cast<size_t>(model_.tree.num_bodies()));
  SpeedColumns columns;
  PathState state;
  PathLoads loads;
  for (const auto& [q1, q2, u1, u2] : kPoses) {
    const std::vector<double> q = Q(q1, q2);
    kinematics::CalcBodyPoses(model_.tree, q, X_GB);
    CalcSpeedColumns(model_.tree, q, X_GB, columns);
    model_.paths.paths()[spring_].CalcState(q, X_GB, state);
    CalcPathLoads(state, X_GB, tension, loads);
    // No points: the tension acts on the coordinates only.
    EXPECT_TRUE(loads.point_forces.empty());
    std::vector<double> Q_gen(q.size(), 0.0);
    AddGeneralizedForces(loads, X_GB, columns, Q_gen);
    EXPECT_NEAR(Q_gen[q1_], -tension * SpringSlope1(q1, q2), tension * kTolerance);
    EXPECT_NEAR(Q_gen[q2_], -tension * SpringSlope2(q1, q2), tension * kTolerance);
    // OpenSim's FunctionBasedPath::produceForces: tension times the moment arm function.
    model_.paths.paths()[act_].CalcState(q, X_GB, state);
    CalcPathLoads(state, X_GB, tension, loads);
    std::fill(Q_gen.begin(), Q_gen.end(), 0.0);
    AddGeneralizedForces(loads, X_GB, columns, Q_gen);
    EXPECT_NEAR(Q_gen[q1_], tension * (0.1 * q1 - 0.05), tension * kTolerance);
    EXPECT_EQ(Q_gen[q2_], 0.0);
  }
}

// The model file with `from` replaced by `to`, read; the error's text (empty when it reads).
std::string ReadEdited(const std::string& from, const std::string& to) {
  std::ifstream in(kModel);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  try {
    io::ReadOsimString(text, "edited.osim");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(FunctionBasedPathErrorsTest, MalformedPathsAreRefusedNamingTheComponent) {
  const std::string coordinates =
      "<coordinate_paths>/jointset/shoulder/q1 /jointset/elbow/q2</coordinate_paths>";
  // The length function takes two arguments; one coordinate is listed.
  std::string error =
      ReadEdited(coordinates, "<coordinate_paths>/jointset/elbow/q2</coordinate_paths>");
  EXPECT_NE(error.find("edited.osim:"), std::string::npos) << error;
  EXPECT_NE(error.find("/forceset/spring/path"), std::string::npos) << error;
  EXPECT_NE(error.find("takes 2 argument(s), but 1 are expected"), std::string::npos) << error;
  error = ReadEdited(coordinates,
                     "<coordinate_paths>/jointset/shoulder/q1 "
                     "/jointset/shoulder/q1</coordinate_paths>");
  EXPECT_NE(error.find("listed more than once"), std::string::npos) << error;
  error = ReadEdited(
      coordinates, "<coordinate_paths>/jointset/shoulder/q1 /jointset/elbow/q9</coordinate_paths>");
  EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
  error = ReadEdited(coordinates, "<coordinate_paths></coordinate_paths>");
  EXPECT_NE(error.find("lists no coordinate"), std::string::npos) << error;
  error = ReadEdited(
      "<length_function>\n              <PolynomialFunction>\n                "
      "<coefficients>0.2 0.01</coefficients>\n              </PolynomialFunction>\n"
      "            </length_function>",
      "");
  EXPECT_NE(error.find("/forceset/act/path"), std::string::npos) << error;
  EXPECT_NE(error.find("has no <length_function>"), std::string::npos) << error;
  // The speed function takes (q1, u1): two arguments, not three.
  error = ReadEdited("<coefficients>0.001 0.7 0</coefficients>\n                <dimension>2",
                     "<coefficients>0.001 0.7 0 0</coefficients>\n                <dimension>3");
  EXPECT_NE(error.find("<lengthening_speed_function> takes 3 argument(s), but 2 are expected"),
            std::string::npos)
      << error;
  // Moment arm functions, when given, are one per coordinate.
  error =
      ReadEdited("<coordinate_paths>/jointset/shoulder/q1</coordinate_paths>",
                 "<coordinate_paths>/jointset/shoulder/q1 /jointset/elbow/q2</coordinate_paths>");
  EXPECT_NE(error.find("/forceset/act/path"), std::string::npos) << error;
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace sinew::paths
