// `sinew forward` end to end on OpenSim's own Forward test resources: SinglePin's setup
// reproduces OpenSim's stored states; the pendulum setups (gravity, and an external force
// standing in for it) follow the exact pendulum equation; the states file's row is the one
// OpenSim takes; subject01's setup appends CMC's actuators, applies its controls and ground
// reaction forces, and warns about its muscles; the comparisons that need muscles are skipped
// with that reason until muscles are simulated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using engine::testing::ReadStoColumns;
using Columns = std::map<std::string, std::vector<double>>;

const std::string kAnalyze = std::string(SINEW_TEST_DATA_DIR) +
                             "/opensim-org/opensim-core/Applications/Analyze/tests/resources/";
const std::string kForward = std::string(SINEW_TEST_DATA_DIR) +
                             "/opensim-org/opensim-core/Applications/Forward/tests/resources/";

// The value of coordinate column `value` at time t, by cubic Hermite interpolation between
// the reported rows with the speed column `speed` as its derivative (error O(h^4): ~1e-9 rad
// for the 0.01 s rows of these runs, far below the integrators' own errors).
double HermiteAt(const Columns& table, const std::string& value, const std::string& speed,
                 double t) {
  const std::vector<double>& time = table.at("time");
  const std::vector<double>& q = table.at(value);
  const std::vector<double>& u = table.at(speed);
  size_t i = std::upper_bound(time.begin(), time.end(), t) - time.begin();
  i = std::clamp<size_t>(i, 1, time.size() - 1);
  const double h = time[i] - time[i - 1];
  const double s = (t - time[i - 1]) / h;
  const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
  const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
  return h00 * q[i - 1] + h10 * h * u[i - 1] + h01 * q[i] + h11 * h * u[i];
}

// The label of coordinate `name`'s value (or speed) column in an OpenSim 4 states table.
std::string PathLabel(const Columns& table, const std::string& name, const std::string& kind) {
  const std::string suffix = "/" + name + "/" + kind;
  for (const auto& [label, column] : table) {
    if (label.size() > suffix.size() &&
        label.compare(label.size() - suffix.size(), suffix.size(), suffix) == 0) {
      return label;
    }
  }
  return "";
}

// theta'' = -(g / L) sin(theta) by classical RK4 at step h (the exact pendulum, written here).
double ExactPendulumAngle(double theta0, double g_over_l, double t_end, double h = 1e-4) {
  double theta = theta0, omega = 0.0;
  const int n = static_cast<int>(std::lround(t_end / h));
  for (int i = 0; i < n; ++i) {
    const auto f = [g_over_l](double th) { return -g_over_l * std::sin(th); };
    const double k1t = omega, k1w = f(theta);
    const double k2t = omega + h / 2 * k1w, k2w = f(theta + h / 2 * k1t);
    const double k3t = omega + h / 2 * k2w, k3w = f(theta + h / 2 * k2t);
    const double k4t = omega + h * k3w, k4w = f(theta + h * k3t);
    theta += h / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
    omega += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
  }
  return theta;
}

class ForwardTest : public testing::CliTest {
 protected:
  // Runs `sinew forward SETUP ARGS --quiet --out DIR` into the test's folder `out`.
  testing::CliRun Forward(const std::string& setup, const std::string& out,
                          const std::string& args = "") const {
    return Run("forward " + setup + " " + args + " --quiet --out " + Path(out));
  }
  // Writes `text` to the test's folder as `name` and returns its path.
  std::string Write(const std::string& name, const std::string& text) const {
    std::ofstream(Path(name)) << text;
    return Path(name);
  }
};

// OpenSim's SinglePin setup (format 20300, empty model_file, a disabled ControlSetController,
// corrective spring settings) from SinglePin_InitialStates.sto (q = 1 rad) for 3 s at the
// setup's integrator_error_tolerance 1e-3 and maximum step 0.01 s (the step bound keeps both
// integrators far below the tolerance): 3.2e-8 rad and 9.7e-8 rad/s from OpenSim's stored
// states measured, as `simulate` at accuracy 1e-10 (OpenSim's states are themselves 3e-8 rad
// from the exact pendulum).
TEST_F(ForwardTest, SinglePinSetupReproducesOpenSim) {
  const testing::CliRun run = Forward(kAnalyze + "SinglePin_Setup_Forward.xml", "pin",
                                      "--model " + kAnalyze + "SinglePin.osim");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("controller <ControlSetController> is disabled"), std::string::npos)
      << run.err;
  const Columns ours = ReadStoColumns(Path("pin/SinglePin_states.sto"));
  const Columns ref = ReadStoColumns(kAnalyze + "SinglePin_states.sto");
  ASSERT_EQ(ours.at("time").front(), 0.0);
  ASSERT_NEAR(ours.at("time").back(), 3.0, 1e-12);
  double dq = 0, du = 0;
  for (size_t row = 0; row < ref.at("time").size(); ++row) {
    const double t = ref.at("time")[row];
    dq = std::max(
        dq, std::abs(HermiteAt(ours, "/jointset/pin1/r1_z/value", "/jointset/pin1/r1_z/speed", t) -
                     ref.at("r1_z")[row]));
    const std::vector<double>& time = ours.at("time");
    const size_t i = std::min<size_t>(std::lround(t / 0.01), time.size() - 1);
    ASSERT_NEAR(time[i], t, 1e-12);
    du = std::max(du, std::abs(ours.at("/jointset/pin1/r1_z/speed")[i] - ref.at("r1_z_u")[row]));
  }
  EXPECT_LT(dq, 1e-7);
  EXPECT_LT(du, 3e-7);
  // The controls and forces tables exist, with the model's (no) actuators.
  EXPECT_EQ(ReadStoColumns(Path("pin/SinglePin_controls.sto")).size(), 1u);  // time only
}

// pendulum.osim (10 kg point mass 0.5 m from a z pin, under gravity) and pendulum_no_gravity.osim
// with pendulum_external_load.xml (-98.0665 N at the mass) follow theta'' = -(g/L) sin(theta)
// from the default -0.1570796 rad for 1 s at the setups' tolerance 1e-5 (measured 3.0e-6 rad
// from an RK4 solution at 1e-4 s), and agree with each other to rounding (9.7e-17 rad;
// OpenSim's testForward accepts 1e-2).
TEST_F(ForwardTest, PendulumSetupsFollowThePendulumEquation) {
  ASSERT_EQ(Forward(kForward + "pendulum_Setup_Forward.xml", "g").exit_code, 0);
  const testing::CliRun ext = Forward(kForward + "pendulum_ext_gravity_Setup_Forward.xml", "ext");
  ASSERT_EQ(ext.exit_code, 0) << ext.err;
  // Its PointKinematics analysis is named as not run, and --strict refuses that.
  EXPECT_NE(ext.err.find("sinew: warning: " + kForward +
                         "pendulum_ext_gravity_Setup_Forward.xml:36: /pendulum_ext_gravity: "
                         "analysis PointKinematics is not run"),
            std::string::npos)
      << ext.err;
  const testing::CliRun strict =
      Forward(kForward + "pendulum_ext_gravity_Setup_Forward.xml", "strict", "--strict");
  EXPECT_EQ(strict.exit_code, 2);
  EXPECT_NE(strict.err.find("analysis PointKinematics is not run"), std::string::npos)
      << strict.err;
  const Columns g = ReadStoColumns(Path("g/pendulum_states.sto"));
  const Columns e = ReadStoColumns(Path("ext/pendulum_ext_gravity_states.sto"));
  const std::string value = PathLabel(g, "Pendulum_r1", "value");
  ASSERT_FALSE(value.empty());
  ASSERT_EQ(g.at("time").size(), e.at("time").size());
  double vs_exact = 0, vs_gravity = 0;
  for (size_t i = 0; i < g.at("time").size(); i += 10) {
    const double exact = ExactPendulumAngle(-0.1570796326795, 9.80665 / 0.5, g.at("time")[i]);
    vs_exact = std::max(vs_exact, std::abs(g.at(value)[i] - exact));
    vs_gravity = std::max(vs_gravity, std::abs(e.at(value)[i] - g.at(value)[i]));
  }
  EXPECT_LT(vs_exact, 1e-5);
  EXPECT_LT(vs_gravity, 1e-14);
  // The degrees table: the same states, the pin's angle and speed in degrees.
  const Columns degrees = ReadStoColumns(Path("g/pendulum_states_degrees.mot"));
  const std::string speed = PathLabel(g, "Pendulum_r1", "speed");
  ASSERT_EQ(degrees.at(value).size(), g.at(value).size());
  for (size_t i = 0; i < g.at(value).size(); ++i) {
    EXPECT_NEAR(degrees.at(value)[i], g.at(value)[i] * 180 / std::numbers::pi, 1e-12);
    EXPECT_NEAR(degrees.at(speed)[i], g.at(speed)[i] * 180 / std::numbers::pi, 1e-12);
  }
  // The external force is reported: -98.0665 N along y on the pendulum.
  const Columns forces = ReadStoColumns(Path("ext/pendulum_ext_gravity_forces.sto"));
  ASSERT_TRUE(forces.count("pendulum_gravity_Fy")) << "labels changed";
  EXPECT_NEAR(forces.at("pendulum_gravity_Fy").front(), -98.0665, 1e-9);
}

// The states file's row is the one OpenSim's Forward tool takes: the last at or before
// initial_time (the run then starts at that row's time), the first when initial_time precedes
// every row. Columns the file lacks keep the model's defaults, with a warning naming them.
TEST_F(ForwardTest, StatesFileRowIsTheClosestEarlierOne) {
  const std::string states = Write("states.sto",
                                   "states\nversion=1\nnRows=3\nnColumns=3\ninDegrees=no\n"
                                   "endheader\ntime\tr1_z\tr1_z_u\n"
                                   "0.2\t0.5\t0\n0.5\t1.0\t0.25\n0.9\t1.5\t0\n");
  const auto setup = [&](const std::string& name, double t0, const std::string& file,
                         double t1 = 1.0) {
    return Write(name + ".xml", "<OpenSimDocument Version=\"40000\"><ForwardTool name=\"" + name +
                                    "\"><model_file>" + kAnalyze +
                                    "SinglePin.osim</model_file><initial_time>" +
                                    std::to_string(t0) + "</initial_time><final_time>" +
                                    std::to_string(t1) + "</final_time><states_file>" + file +
                                    "</states_file></ForwardTool></OpenSimDocument>");
  };
  // Between rows: the earlier one (t = 0.5), and the run starts there.
  const testing::CliRun between = Forward(setup("between", 0.7, states), "between");
  ASSERT_EQ(between.exit_code, 0) << between.err;
  EXPECT_NE(between.err.find("no row at the initial time 0.7; the run starts at 0.5 s"),
            std::string::npos)
      << between.err;
  Columns out = ReadStoColumns(Path("between/between_states.sto"));
  EXPECT_EQ(out.at("time").front(), 0.5);
  EXPECT_EQ(out.at("/jointset/pin1/r1_z/value").front(), 1.0);
  EXPECT_EQ(out.at("/jointset/pin1/r1_z/speed").front(), 0.25);
  // Before every row: the first row (t = 0.2).
  const testing::CliRun before = Forward(setup("before", 0.0, states), "before");
  ASSERT_EQ(before.exit_code, 0) << before.err;
  EXPECT_NE(before.err.find("the initial time 0 precedes the first row"), std::string::npos)
      << before.err;
  out = ReadStoColumns(Path("before/before_states.sto"));
  EXPECT_EQ(out.at("time").front(), 0.2);
  EXPECT_EQ(out.at("/jointset/pin1/r1_z/value").front(), 0.5);
  // A file without the speed column: the speed keeps the model's default (0), with a warning.
  const std::string values_only =
      Write("values.sto",
            "s\nversion=1\nnRows=1\nnColumns=2\ninDegrees=no\nendheader\n"
            "time\tr1_z\n0\t0.75\n");
  const testing::CliRun missing = Forward(setup("missing", 0.0, values_only), "missing");
  ASSERT_EQ(missing.exit_code, 0) << missing.err;
  EXPECT_NE(missing.err.find("1 coordinate values or speeds are not in the file (r1_z (speed)): "
                             "they keep the model's defaults"),
            std::string::npos)
      << missing.err;
  out = ReadStoColumns(Path("missing/missing_states.sto"));
  EXPECT_EQ(out.at("/jointset/pin1/r1_z/value").front(), 0.75);
  EXPECT_EQ(out.at("/jointset/pin1/r1_z/speed").front(), 0.0);
  // A run that would start at or after final_time is an error naming the setup.
  const testing::CliRun late = Forward(setup("late", 0.0, states, 0.1), "late");
  EXPECT_EQ(late.exit_code, 2);
  EXPECT_NE(late.err.find("the run would start at 0.2 s (the states file's row), not before "
                          "final_time 0.1"),
            std::string::npos)
      << late.err;
}

// The ControlLinear nodes of `control` in a ControlSet file, parsed here independently of
// Sinew's reader: (t, value) pairs in file order.
std::vector<std::pair<double, double>> ControlNodes(const std::string& file,
                                                    const std::string& control) {
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t begin = text.find("<ControlLinear name=\"" + control + "\"");
  const size_t end = text.find("</ControlLinear>", begin);
  const std::string block = text.substr(begin, end - begin);
  const std::regex node(R"(<t>\s*([^<\s]+)\s*</t>\s*<value>\s*([^<\s]+)\s*</value>)");
  std::vector<std::pair<double, double>> nodes;
  for (auto it = std::sregex_iterator(block.begin(), block.end(), node);
       it != std::sregex_iterator(); ++it) {
    nodes.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
  }
  return nodes;
}

double Interpolate(const std::vector<std::pair<double, double>>& nodes, double t) {
  for (size_t i = 1; i < nodes.size(); ++i) {
    if (t <= nodes[i].first) {
      const double s = (t - nodes[i - 1].first) / (nodes[i].first - nodes[i - 1].first);
      return nodes[i - 1].second + s * (nodes[i].second - nodes[i - 1].second);
    }
  }
  return nodes.back().second;
}

// subject01_Setup_Forward.xml (gait2354, format 20302): CMC's 6 residual and 6 reserve
// actuators (the others are commented out in the file) are appended from
// gait2354_CMC_Actuators.xml, the ControlSetController's controls drive them, the ground reaction
// forces of subject01_GRFs.xml are applied, the run starts from the states file's row at 0.8 s; its
// 54 muscles are simulated (their excitations are controls too), so --strict accepts the run.
TEST_F(ForwardTest, Subject01AppendsActuatorsAndAppliesControlsAndLoads) {
  const std::string setup = kForward + "subject01_Setup_Forward.xml";
  const testing::CliRun run = Forward(setup, "s");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err.find("NOT simulated"), std::string::npos) << run.err;
  const Columns controls = ReadStoColumns(Path("s/subject01_controls.sto"));
  const Columns forces = ReadStoColumns(Path("s/subject01_forces.sto"));
  for (const char* actuator : {"FX", "FY", "FZ", "MX", "MY", "MZ", "ankle_angle_r_reserve",
                               "subtalar_angle_l_reserve", "mtp_angle_r_reserve"}) {
    EXPECT_TRUE(controls.count(actuator)) << actuator;
    EXPECT_TRUE(forces.count(actuator)) << actuator;
  }
  EXPECT_EQ(controls.size(), 1u + 54u + 12u);  // time + the muscles + the 12 appended actuators
  // FX's control is the controls file's ControlLinear through its nodes; its force is
  // optimal_force (100 N) times the control.
  const auto nodes = ControlNodes(kForward + "subject01_walk1_controls.xml", "FX.excitation");
  ASSERT_GT(nodes.size(), 10u);
  const std::vector<double>& time = controls.at("time");
  ASSERT_NEAR(time.front(), 0.8, 1e-12);
  ASSERT_NEAR(time.back(), 0.95, 1e-12);
  for (size_t i = 0; i < time.size(); ++i) {
    EXPECT_NEAR(controls.at("FX")[i], Interpolate(nodes, time[i]), 1e-12) << time[i];
    EXPECT_NEAR(forces.at("FX")[i], 100.0 * controls.at("FX")[i], 1e-9) << time[i];
  }
  // The right foot's ground reaction force is the data's at rows whose time is a sample time
  // (the spline through the samples passes through them).
  const Columns grf = ReadStoColumns(kForward + "subject01_walk1_grf.mot");
  const std::vector<double>& grf_time = grf.at("time");
  int matched = 0;
  for (size_t i = 0; i < time.size(); ++i) {
    const auto at = std::lower_bound(grf_time.begin(), grf_time.end(), time[i] - 1e-9);
    if (at == grf_time.end() || std::abs(*at - time[i]) > 1e-9) continue;
    const size_t row = at - grf_time.begin();
    EXPECT_NEAR(forces.at("calcn_r_RightForce_Fy")[i], grf.at("ground_force_vy")[row], 1e-6);
    EXPECT_NEAR(forces.at("calcn_l_LeftForce_Fy")[i], grf.at("l_ground_force_vy")[row], 1e-6);
    ++matched;
  }
  EXPECT_GT(matched, 5);
  // The first row is the states file's row at 0.8 s.
  const Columns states = ReadStoColumns(Path("s/subject01_states.sto"));
  const Columns ref = ReadStoColumns(kForward + "std_subject01_walk1_states.sto");
  EXPECT_EQ(states.at(PathLabel(states, "knee_angle_r", "value")).front(),
            ref.at("knee_angle_r").front());
  EXPECT_EQ(states.at(PathLabel(states, "pelvis_ty", "speed")).front(),
            ref.at("pelvis_ty_u").front());
  // --strict: nothing of the setup is left out or approximated.
  const testing::CliRun strict = Forward(setup, "strict", "--strict");
  EXPECT_EQ(strict.exit_code, 0) << strict.err;
}

// The OpenSim 4 label of an OpenSim 3 auxiliary state column "<force>.<variable>".
std::string StateVariableLabel(const std::string& label) {
  const size_t dot = label.rfind('.');
  return "/forceset/" + label.substr(0, dot) + "/" + label.substr(dot + 1);
}

// True when our table has the column matching reference column `label`.
bool HasColumnFor(const Columns& ours, const std::string& label) {
  if (label.find('.') != std::string::npos) return ours.count(StateVariableLabel(label)) != 0;
  if (label.ends_with("_u")) {
    return !PathLabel(ours, label.substr(0, label.size() - 2), "speed").empty();
  }
  return !PathLabel(ours, label, "value").empty();
}

// Column `column` of `table` at time t, interpolated linearly between its rows.
double LinearAt(const Columns& table, const std::string& column, double t) {
  const std::vector<double>& time = table.at("time");
  const std::vector<double>& y = table.at(column);
  size_t i = std::upper_bound(time.begin(), time.end(), t) - time.begin();
  i = std::clamp<size_t>(i, 1, time.size() - 1);
  const double s = (t - time[i - 1]) / (time[i] - time[i - 1]);
  return y[i - 1] + s * (y[i] - y[i - 1]);
}

// Our value of reference column `label` at time t: coordinate values by Hermite interpolation,
// speeds ("<coordinate>_u") and auxiliary states ("<force>.<variable>") linearly.
double OursAt(const Columns& ours, const std::string& label, double t) {
  if (label.find('.') != std::string::npos) return LinearAt(ours, StateVariableLabel(label), t);
  if (label.ends_with("_u")) {
    return LinearAt(ours, PathLabel(ours, label.substr(0, label.size() - 2), "speed"), t);
  }
  return HermiteAt(ours, PathLabel(ours, label, "value"), PathLabel(ours, label, "speed"), t);
}

// Largest and RMS difference of each reference column from ours, at our rows within the
// reference's time range (NaN for a column we do not have, so that a test comparing it fails
// naming it). The reference is interpolated linearly: its rows are OpenSim's integrator steps,
// dense exactly where the states change fast (arm26's first 0.2 ms, while fibers that do not
// start at equilibrium snap towards it), whereas our rows are the report interval apart.
struct ColumnError {
  double max = 0, rms = 0;
};
std::map<std::string, ColumnError> CompareStates(const Columns& ours, const Columns& ref) {
  std::map<std::string, ColumnError> errors;
  const double t0 = ref.at("time").front(), t1 = ref.at("time").back();
  const std::vector<double>& time = ours.at("time");
  for (const auto& [label, column] : ref) {
    if (label == "time") continue;
    ColumnError& e = errors[label];
    if (!HasColumnFor(ours, label)) {
      e.max = e.rms = std::nan("");
      continue;
    }
    int n = 0;
    for (size_t row = 0; row < time.size(); ++row) {
      const double t = time[row];
      if (t < t0 || t > t1) continue;
      const double d = std::abs(OursAt(ours, label, t) - LinearAt(ref, label, t));
      e.max = std::max(e.max, d);
      e.rms += d * d;
      ++n;
    }
    e.rms = std::sqrt(e.rms / std::max(n, 1));
  }
  return errors;
}

// OpenSim's testForward: subject01's run reproduces std_subject01_walk1_states.sto within RMS
// 0.035 rad on the coordinates and 1e-3 on activations and fiber lengths. OpenSim's test reads
// the model's Thelen2003Muscles as Thelen2003Muscle_Deprecated, and so does this one. (It
// matches since the CMC actuators of the bare ForceSet file act as OpenSim reads them: with
// their directions negated, docs/forward.md.)
TEST_F(ForwardTest, Subject01ReproducesOpenSim) {
  const testing::CliRun run =
      Forward(kForward + "subject01_Setup_Forward.xml", "s",
              "--rename-force-class Thelen2003Muscle=Thelen2003Muscle_Deprecated");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto errors = CompareStates(ReadStoColumns(Path("s/subject01_states.sto")),
                                    ReadStoColumns(kForward + "std_subject01_walk1_states.sto"));
  for (const auto& [label, error] : errors) {
    if (label.ends_with("_u")) continue;  // OpenSim's test compares coordinates and muscles
    EXPECT_LT(error.rms, label.find('.') != std::string::npos ? 1e-3 : 0.035) << label;
  }
}

// OpenSim's testForward: arm26 (6 muscles over wrap objects) from its initial states with its
// static-optimization controls reproduces std_arm26_states.sto within 5e-3 on every state,
// reading the Thelen2003Muscles as Thelen2003Muscle_Deprecated as OpenSim's test does. The file
// was written by OpenSim 2.x, whose cylinders refined their tangent points on every path:
// `--cylinder-refinement always` (docs/forward.md). Measured: 3.3e-3 rad/s (r_elbow_flex_u),
// every other state within 1.4e-3; with OpenSim 4.4's rule (the default) 3.24e-2 rad/s.
TEST_F(ForwardTest, Arm26ReproducesOpenSim) {
  const testing::CliRun run =
      Forward(kForward + "arm26_Setup_Forward.xml", "arm",
              "--rename-force-class Thelen2003Muscle=Thelen2003Muscle_Deprecated "
              "--cylinder-refinement always");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto errors = CompareStates(ReadStoColumns(Path("arm/arm26_states.sto")),
                                    ReadStoColumns(kForward + "std_arm26_states.sto"));
  for (const auto& [label, error] : errors) EXPECT_LT(error.max, 5e-3) << label;
}

// Settings that would change the results but are not supported are errors naming the setup's
// line and element; a setup without a model needs --model.
TEST_F(ForwardTest, UnsupportedSettingsAreErrorsWithTheirLine) {
  const testing::CliRun controller =
      Forward(kForward + "subject01_Setup_Forward_Controller.xml", "c");
  EXPECT_EQ(controller.exit_code, 2);
  EXPECT_NE(controller.err.find("subject01_Setup_Forward_Controller.xml:68: "
                                "/subject01/Correction_Controller: controller "
                                "<CorrectionController> is not supported"),
            std::string::npos)
      << controller.err;
  const testing::CliRun no_model = Forward(kAnalyze + "SinglePin_Setup_Forward.xml", "m");
  EXPECT_EQ(no_model.exit_code, 2);
  EXPECT_NE(no_model.err.find("<model_file> is empty): give one with --model"), std::string::npos)
      << no_model.err;
}

}  // namespace
}  // namespace sinew
