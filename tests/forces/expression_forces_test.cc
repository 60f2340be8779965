// OpenSim's ExpressionBasedCoordinateForce, ExpressionBasedPointToPointForce,
// ExpressionBasedBushingForce and FunctionBasedBushingForce through the parser: closed forms,
// hand computations at nontrivial states, agreement with the linear BushingForce, and errors
// that name the file, line and force.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "forces/osim_text_models.h"

namespace sinew {
namespace {

const std::string kData = SINEW_TEST_DATA_DIR;

using Parsed = testing::ParsedModel;
using testing::SliderModel;

Parsed ParseText(const std::string& text, const std::string& file) {
  return testing::ParseOsimText(text, file);
}

// The loads of the force named `name` alone.
engine::Loads LoadsOf(const Parsed& p, const engine::State& state, const std::string& name) {
  const auto& elements = p.system->force_elements();
  const auto it = std::find(elements.begin(), elements.end(), p.report.GetForce(name)->load);
  EXPECT_NE(it, elements.end()) << name;
  const int k = static_cast<int>(it - elements.begin());
  engine::Loads loads(p.system->num_bodies(), p.system->num_coordinates());
  elements[k]->AddLoads(p.system->MakeForceContext(k, state), loads);
  return loads;
}

TEST(ExpressionForceTest, CoordinateForceSpringFollowsTheClosedForm) {
  // f = -40 q on a 2 kg slider from x0 = 0.1 at rest: x = x0 cos(sqrt(20) t).
  const Parsed p = ParseText(SliderModel(R"(<ExpressionBasedCoordinateForce name="spring">
<coordinate>x</coordinate><expression>-40 * q</expression></ExpressionBasedCoordinateForce>)"),
                             "expression_spring.osim");
  ASSERT_TRUE(p.report.not_simulated().empty());
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-12;
  auto integrator = engine::MakeIntegrator("rk45", *p.system, settings);
  engine::State state = engine::MakeDefaultState(*p.system);
  double worst = 0.0;
  for (int k = 1; k <= 40; ++k) {
    const double t = 0.05 * k;
    integrator->StepTo(state, t);
    worst = std::max(worst, std::abs(state.q[0] - 0.1 * std::cos(std::sqrt(20.0) * t)));
  }
  EXPECT_LT(worst, 5e-12);  // 6.8e-13 m measured at accuracy 1e-12
  std::cout << "expression spring: worst error " << worst << " m\n";
}

TEST(ExpressionForceTest, CoordinateForceEvaluatesQAndQdot) {
  // q^2 - 3 qdot at q = 0.3, qdot = -0.2: 0.09 + 0.6 = 0.69 (whitespace removed as OpenSim).
  const Parsed p = ParseText(SliderModel(R"(<ExpressionBasedCoordinateForce name="f">
<coordinate>x</coordinate><expression>q^2 - 3*qdot</expression></ExpressionBasedCoordinateForce>)"),
                             "expression_q.osim");
  engine::State state = engine::MakeDefaultState(*p.system);
  engine::SetCoordinateValue(*p.system, state, "x", 0.3);
  engine::SetCoordinateSpeed(*p.system, state, "x", -0.2);
  EXPECT_NEAR(LoadsOf(p, state, "f").mobility[0], 0.69, 1e-15);
}

TEST(ExpressionForceTest, PointToPointForcePullsWithTheExpressionOfDAndDdot) {
  // Point1 at (0, 1, 0) on ground, point2 at the block's origin (0.6, 0, 0) moving at 0.5 m/s
  // along x: r = (0.6, -1, 0), d = sqrt(1.36), ddot = 0.5 * 0.6 / d. F = 2 d + ddot pulls the
  // block towards point1: -F r / d.
  const Parsed p = ParseText(SliderModel(R"(<ExpressionBasedPointToPointForce name="rope">
<body1>ground</body1><point1>0 1 0</point1><body2>block</body2><point2>0 0 0</point2>
<expression>2*d + ddot</expression></ExpressionBasedPointToPointForce>)"),
                             "expression_p2p.osim");
  engine::State state = engine::MakeDefaultState(*p.system);
  engine::SetCoordinateValue(*p.system, state, "x", 0.6);
  engine::SetCoordinateSpeed(*p.system, state, "x", 0.5);
  const Vec3 r(0.6, -1.0, 0.0);
  const double d = std::sqrt(1.36), ddot = 0.5 * 0.6 / d;
  const Vec3 expected = -(2 * d + ddot) * r / d;
  const int block = p.system->FindBody("block");
  const engine::Loads loads = LoadsOf(p, state, "rope");
  EXPECT_TRUE(loads.body[block].tail<3>().isApprox(expected, 1e-14));
  EXPECT_LT(loads.body[block].head<3>().norm(), 1e-14);  // at the body origin
}

// The line of `needle` in `text` (1-based).
int LineOf(const std::string& text, const std::string& needle) {
  const size_t at = text.find(needle);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

TEST(ExpressionForceTest, MalformedExpressionsNameFileLineAndForce) {
  for (const std::string expression : {"3*q+", "2*x", "q**2", "sin(q"}) {
    const std::string text = SliderModel(
        "<ExpressionBasedCoordinateForce name=\"bad\">\n<coordinate>x</coordinate>\n"
        "<expression>" +
        expression + "</expression></ExpressionBasedCoordinateForce>");
    try {
      ParseText(text, "bad.osim");
      ADD_FAILURE() << expression << " was accepted";
    } catch (const Error& error) {
      const std::string where =
          "bad.osim:" + std::to_string(LineOf(text, "<expression>")) + ": /forceset/bad: ";
      EXPECT_NE(std::string(error.what()).find(where), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find(expression), std::string::npos) << error.what();
    }
  }
}

// BushingForceModel_30000.osim (3.x: a 1 kg ball on a vertical slider, coordinate ball_h) with
// its BushingForce replaced by `bushing`.
std::string BallWith(const std::string& bushing) {
  std::ifstream in(
      kData + "/opensim-org/opensim-core/OpenSim/Simulation/Test/BushingForceModel_30000.osim");
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const size_t begin = text.find("<BushingForce");
  const size_t end = text.find("</BushingForce>") + std::string("</BushingForce>").size();
  return text.replace(begin, end - begin, bushing);
}

TEST(ExpressionForceTest, NonlinearBushingsOfTheOldLayoutGiveTheHandComputedForce) {
  // 3.x layout (body_1, body_2, location_body_2): frame M at (0, 0.1, 0) on the ball, frame F
  // at ground's origin; with ball_h = 0.2 the ball is at (0, 0.2, 0), so delta = (0, 0.3, 0).
  // Fy = 1000 delta_y^3 = 27 N: the ball gets -27 N along y, at M (on the line through the
  // ball's origin, so no torque).
  const std::string expression = R"(<ExpressionBasedBushingForce name="bushing">
<body_1>ground</body_1><body_2>ball</body_2><location_body_2>0 0.1 0</location_body_2>
<Fy_expression>1000*delta_y^3</Fy_expression></ExpressionBasedBushingForce>)";
  const std::string function = R"(<FunctionBasedBushingForce name="bushing">
<body_1>ground</body_1><body_2>ball</body_2><location_body_2>0 0.1 0</location_body_2>
<f_y_delta_y_function><PolynomialFunction><coefficients>1000 0 0 0</coefficients>
</PolynomialFunction></f_y_delta_y_function></FunctionBasedBushingForce>)";
  for (const std::string& bushing : {expression, function}) {
    const Parsed p = ParseText(BallWith(bushing), "ball.osim");
    ASSERT_TRUE(p.report.not_simulated().empty());
    engine::State state = engine::MakeDefaultState(*p.system);
    engine::SetCoordinateValue(*p.system, state, "ball_h", 0.2);
    const engine::Loads loads = LoadsOf(p, state, "bushing");
    const int ball = p.system->FindBody("ball");
    EXPECT_TRUE(loads.body[ball].tail<3>().isApprox(Vec3(0, -27.0, 0), 1e-13)) << bushing;
    EXPECT_LT(loads.body[ball].head<3>().norm(), 1e-13) << bushing;
  }
}

TEST(ExpressionForceTest, LinearFunctionAndExpressionBushingsEqualTheLinearBushing) {
  // The same frames, stiffness and damping as a BushingForce, written as a
  // FunctionBasedBushingForce of LinearFunctions and as an ExpressionBasedBushingForce: the
  // loads at a turned, moving pose of bushings.osim's free body are the same.
  std::ifstream in(kData + "/sinew/bushings.osim");
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const std::string frames = R"(<socket_frame1>/forceset/hang/ground_offset</socket_frame1>
<socket_frame2>/forceset/hang/link_offset</socket_frame2>
<rotational_damping>0.1 0.2 0.3</rotational_damping>
<translational_damping>1 2 3</translational_damping>)";
  const char* const kFunctions[6] = {"m_x_theta_x", "m_y_theta_y", "m_z_theta_z",
                                     "f_x_delta_x", "f_y_delta_y", "f_z_delta_z"};
  const char* const kExpressions[6] = {"Mx", "My", "Mz", "Fx", "Fy", "Fz"};
  const char* const kVariables[6] = {"theta_x", "theta_y", "theta_z",
                                     "delta_x", "delta_y", "delta_z"};
  const double k[6] = {20, 30, 40, 200, 300, 400};
  std::string function = "<FunctionBasedBushingForce name=\"fun\">" + frames;
  std::string expression = "<ExpressionBasedBushingForce name=\"expr\">" + frames;
  for (int i = 0; i < 6; ++i) {
    const std::string ki = std::to_string(static_cast<int>(k[i]));
    function += "<LinearFunction name=\"" + std::string(kFunctions[i]) +
                "_function\"><coefficients>" + ki + " 0</coefficients></LinearFunction>";
    expression += "<" + std::string(kExpressions[i]) + "_expression>" + ki + "*" + kVariables[i] +
                  "</" + kExpressions[i] + "_expression>";
  }
  function += "</FunctionBasedBushingForce>";
  expression += "</ExpressionBasedBushingForce>";
  const std::string damping = "<rotational_damping>0 0 0</rotational_damping>";
  text.replace(text.find(damping), damping.size(),
               "<rotational_damping>0.1 0.2 0.3</rotational_damping>");
  const std::string t_damping = "<translational_damping>0 0 0</translational_damping>";
  text.replace(text.find(t_damping), t_damping.size(),
               "<translational_damping>1 2 3</translational_damping>");
  text.insert(text.find("</objects>\n\t\t</ForceSet>"), function + "\n" + expression + "\n");
  const Parsed p = ParseText(text, "three_bushings.osim");
  ASSERT_TRUE(p.report.not_simulated().empty());
  const engine::State state = engine::MakeDefaultState(*p.system);
  const int link = p.system->FindBody("link");
  const SpatialVec linear = LoadsOf(p, state, "hang").body[link];
  EXPECT_GT(linear.norm(), 10.0);
  for (const char* name : {"fun", "expr"}) {
    const SpatialVec other = LoadsOf(p, state, name).body[link];
    EXPECT_LT((other - linear).norm(), 1e-12 * linear.norm()) << name;
  }
}

}  // namespace
}  // namespace sinew
