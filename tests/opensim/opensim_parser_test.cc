// The seed's parser API on the seed's own models: actuators against analytic solutions, the
// Report, stand-ins, strict mode, controls files, and parsing more than once.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/functions/excitations.h>
#include <sinew/functions/linear_function.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace sinew {
namespace {

const std::string kChronoDir =
    std::string(SINEW_TEST_DATA_DIR) + "/projectchrono/chrono/data/opensim/";

// Both actuator models: rod1 (m = 1 kg, Izz = 1 kg m^2 about its mass centre at its origin)
// hangs from a z pin 0.5 m above its origin; q1 starts at -0.78539816 rad, gravity is 0.
constexpr double kQ0 = -0.78539816;
constexpr double kPinInertia = 1.0 + 1.0 * 0.5 * 0.5;  // parallel axis: Izz + m d^2

// Accuracy of the reference runs: the local error per step is ~1e-11, so q is good to ~1e-9;
// the tests allow 1e-7 rad, far below any modelling error they look for (0.1 rad and up).
constexpr double kAccuracy = 1e-11;
constexpr double kAngleTolerance = 1e-7;

// Simulates `system` from its default state, its excitations set by the controller of
// `parser`, to each time in `times`, returning q1 there.
std::vector<double> SimulateQ1(const engine::System& system, const opensim::OpenSimParser& parser,
                               const std::vector<double>& times) {
  engine::IntegratorSettings settings;
  settings.accuracy = kAccuracy;
  auto integrator = engine::MakeIntegrator("rk45", system, settings);
  integrator->SetController(parser.GetController());
  engine::State state = engine::MakeDefaultState(system);
  std::vector<double> q;
  for (double t : times) {
    integrator->StepTo(state, t);
    q.push_back(engine::GetCoordinateValue(system, state, "q1"));
  }
  return q;
}

TEST(OpenSimParserTest, TorqueActuatorWithConstantExcitationGivesParabola) {
  // The model's own PrescribedController excites "grav" with the constant 1: a torque of
  // -9.8 N m about z on rod1 (bodyB), so q'' = -9.8 / I and q = q0 - 4.9 t^2 / I.
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kChronoDir + "torque-actuator.osim");
  EXPECT_EQ(parser.GetReport().GetForce("grav")->excitation_source,
            "PrescribedController prescribedcontroller_");
  const std::vector<double> times = {0.25, 0.5, 1.0};
  const std::vector<double> q = SimulateQ1(*system, parser, times);
  for (size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    EXPECT_NEAR(q[i], kQ0 - 0.5 * 9.8 / kPinInertia * t * t, kAngleTolerance) << "t = " << t;
  }
}

// A ForceSet file is read with its own format version: a bare <ForceSet> is version 10500, as
// OpenSim assumes, and OpenSim's TorqueActuator (like its PointActuator) negates the axis read
// from any document older than 1.9.5. So one TorqueActuator on rod1 about +z (optimal force
// 9.8 N m, excitation 1, "grav" left out) turns rod1 by q = q0 + 4.9 t^2 / I from an
// OpenSimDocument of version 40000, and by q0 - 4.9 t^2 / I from a bare file. (OpenSim's
// gait2354_CMC_Actuators.xml is such a bare file: its residuals act opposite to what it says.)
TEST(OpenSimParserTest, ActuatorsOfABareForceSetFileActOppositeToTheirWrittenAxis) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "sinew_force_set_version";
  std::filesystem::create_directories(dir);
  const std::string set =
      "<ForceSet name=\"extra\"><objects><TorqueActuator name=\"twist\"><bodyA>rod1</bodyA>"
      "<bodyB>ground</bodyB><axis>0 0 1</axis><optimal_force>9.8</optimal_force>"
      "</TorqueActuator></objects></ForceSet>";
  const std::string bare = (dir / "bare.xml").string();
  const std::string wrapped = (dir / "wrapped.xml").string();
  std::ofstream(bare) << set;
  std::ofstream(wrapped) << "<OpenSimDocument Version=\"40000\">" << set << "</OpenSimDocument>";
  for (const auto& [file, sign] : {std::pair{wrapped, 1.0}, std::pair{bare, -1.0}}) {
    const model::ModelSpec spec =
        io::ReadOsim(kChronoDir + "torque-actuator.osim", io::ForceSetFiles{{file}, false});
    EXPECT_EQ(spec.forces.back().version, sign > 0 ? 40000 : 10500);
    opensim::OpenSimParser parser;
    parser.DisableForce("grav");
    engine::System system(spec.gravity);
    parser.ParseSpec(system, spec);
    system.Finalize();
    parser.SetExcitationFunction("twist", std::make_shared<functions::LinearFunction>(0.0, 1.0));
    EXPECT_NEAR(SimulateQ1(system, parser, {1.0})[0], kQ0 + sign * 4.9 / kPinInertia,
                kAngleTolerance)
        << file;
  }
  // A bad value in the ForceSet file is reported at that file's line, not the model's.
  std::ofstream(bare)
      << "<ForceSet name=\"extra\"><objects>\n<TorqueActuator name=\"twist\">\n"
         "<bodyA>rod1</bodyA><bodyB>ground</bodyB><optimal_force>strong</optimal_force>\n"
         "</TorqueActuator></objects></ForceSet>\n";
  const model::ModelSpec spec =
      io::ReadOsim(kChronoDir + "torque-actuator.osim", io::ForceSetFiles{{bare}, false});
  opensim::OpenSimParser parser;
  engine::System system(spec.gravity);
  try {
    parser.ParseSpec(system, spec);
    ADD_FAILURE() << "a non-numeric optimal_force was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(bare + ":3: /forceset/twist"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(OpenSimParserTest, TorqueActuatorWithRampExcitationGivesCubic) {
  // Listing 1 of the seed: excitation e(t) = t, so q'' = -9.8 t / I and q = q0 - 9.8 t^3 / 6I.
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kChronoDir + "torque-actuator.osim");
  parser.SetExcitationFunction("grav", std::make_shared<functions::Ramp>(0.0, 1.0));
  EXPECT_EQ(parser.GetReport().GetForce("grav")->excitation_source, "set by user");
  const std::vector<double> times = {0.5, 1.0};
  const std::vector<double> q = SimulateQ1(*system, parser, times);
  for (size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    EXPECT_NEAR(q[i], kQ0 - 9.8 / (6 * kPinInertia) * t * t * t, kAngleTolerance);
  }
}

TEST(OpenSimParserTest, ControlsFileDrivesItsActuator) {
  // The ControlSet ramps "grav.excitation" through (0, 0) and (0.5, 0.5), extrapolated: e = t.
  opensim::OpenSimParser parser;
  parser.SetControlsFile(std::string(SINEW_TEST_DATA_DIR) + "/sinew/grav_ramp_controls.xml");
  auto system = parser.Parse(kChronoDir + "torque-actuator.osim");
  EXPECT_EQ(parser.GetReport().GetForce("grav")->excitation_source, "controls file");
  const double q = SimulateQ1(*system, parser, {1.0})[0];
  EXPECT_NEAR(q, kQ0 - 9.8 / (6 * kPinInertia), kAngleTolerance);
}

// OpenSim adds the controls of all the controllers of an actuator; Sinew takes the controls
// file's and says so in the Report (an error with strict), never silently.
TEST(OpenSimParserTest, ControlsFileReplacingAPrescribedControllerIsAWarning) {
  const std::string controls = ::testing::TempDir() + "/sinew_lift_controls.xml";
  std::ofstream(controls) << "<ControlSet><objects><ControlConstant name=\"lift_force\">"
                             "<value>0.2</value></ControlConstant></objects></ControlSet>\n";
  opensim::OpenSimParser parser;
  parser.SetControlsFile(controls);
  parser.Parse(std::string(SINEW_TEST_DATA_DIR) + "/sinew/sliders.osim");
  EXPECT_EQ(parser.GetReport().GetForce("lift_force")->excitation_source, "controls file");
  bool warned = false;
  for (const Diagnostic& w : parser.GetReport().warnings()) {
    warned |= w.message.find(
                  "replaces the PrescribedController lift_controller of "
                  "'lift_force' (OpenSim would add the two controls)") != std::string::npos;
  }
  EXPECT_TRUE(warned);
  std::remove(controls.c_str());
}

// K(k), the complete elliptic integral of the first kind, by the arithmetic-geometric mean
// (quadratic convergence: 30 steps reach the last bit many times over).
double EllipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 30; ++i) {
    const double next_a = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next_a;
  }
  return std::numbers::pi / (2.0 * a);
}

TEST(OpenSimParserTest, PointActuatorWithConstantExcitationIsAnExactPendulum) {
  // The controller excites "grav" with 9.8: a force of 9.8 N along -y (ground) at (0, -1, 0) in
  // rod1, 1.5 m below the pin, so I q'' = -1.5 * 9.8 * sin q: a pendulum released at rest
  // from q0. It passes q = 0 at a quarter period and reaches -q0 at half a period, where the
  // period is 4 K(sin(|q0|/2)) / w with w = sqrt(1.5 * 9.8 / I).
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kChronoDir + "point-actuator.osim");
  const double w = std::sqrt(1.5 * 9.8 / kPinInertia);
  const double period = 4.0 * EllipticK(std::sin(std::abs(kQ0) / 2)) / w;
  const std::vector<double> q = SimulateQ1(*system, parser, {period / 4, period / 2, period});
  EXPECT_NEAR(q[0], 0.0, kAngleTolerance);
  EXPECT_NEAR(q[1], -kQ0, kAngleTolerance);
  EXPECT_NEAR(q[2], kQ0, kAngleTolerance);
}

TEST(OpenSimParserTest, PointActuatorWithRampExcitationMatchesItsEquationOfMotion) {
  // With e(t) = t the equation I q'' = -1.5 t sin q has no closed form: compare with a
  // classical Runge-Kutta solution of that scalar equation (step 1e-4 s, error ~1e-14).
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kChronoDir + "point-actuator.osim");
  parser.SetExcitationFunction("grav", std::make_shared<functions::LinearFunction>(1.0, 0.0));
  const double q_sinew = SimulateQ1(*system, parser, {2.0})[0];

  auto accel = [](double t, double q) { return -1.5 * t * std::sin(q) / kPinInertia; };
  double t = 0, q = kQ0, u = 0;
  const double h = 1e-4;
  for (int i = 0; i < 20000; ++i) {
    const double k1q = u, k1u = accel(t, q);
    const double k2q = u + 0.5 * h * k1u, k2u = accel(t + 0.5 * h, q + 0.5 * h * k1q);
    const double k3q = u + 0.5 * h * k2u, k3u = accel(t + 0.5 * h, q + 0.5 * h * k2q);
    const double k4q = u + h * k3u, k4u = accel(t + h, q + h * k3q);
    q += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
    u += h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u);
    t += h;
  }
  EXPECT_NEAR(q_sinew, q, kAngleTolerance);
  EXPECT_GT(std::abs(q - kQ0), 0.1);  // the actuator really moved the pendulum
}

TEST(OpenSimParserTest, DefaultExcitationIsZeroAndActivateActuatorsMakesItOne) {
  // Without the model's controller (excitation overridden by the user with 0) nothing moves;
  // ActivateActuators(true) gives the constant 1 (4.9 t^2 / I as with the controller).
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kChronoDir + "torque-actuator.osim");
  parser.SetExcitationFunction("grav", nullptr);
  EXPECT_NEAR(SimulateQ1(*system, parser, {1.0})[0], kQ0, 1e-12);

  opensim::OpenSimParser active;
  active.ActivateActuators(true);
  auto system2 = active.Parse(kChronoDir + "torque-actuator.osim");
  EXPECT_EQ(active.GetReport().GetForce("grav")->excitation_source, "ActivateActuators");
  EXPECT_NEAR(SimulateQ1(*system2, active, {1.0})[0], kQ0 - 4.9 / kPinInertia, kAngleTolerance);
}

TEST(OpenSimParserTest, EverySeedModelParsesWithAFullReportAndNoStandIns) {
  for (const auto& entry : std::filesystem::directory_iterator(kChronoDir)) {
    SCOPED_TRACE(entry.path().string());
    opensim::OpenSimParser parser;
    auto system = parser.Parse(entry.path().string());
    const model::ModelSpec& spec = parser.GetSpec();
    const opensim::Report& report = parser.GetReport();
    EXPECT_EQ(report.bodies().size(), spec.bodies.size() - 1);  // ground is not listed
    EXPECT_EQ(report.joints().size(), spec.joints.size());
    EXPECT_EQ(report.forces().size(), spec.forces.size());
    for (const model::BodySpec& b : spec.bodies) {
      if (b.name != "ground") {
        EXPECT_NE(report.GetBody(b.name), nullptr) << b.name;
      }
    }
    for (const auto& [key, joint] : report.joints()) {
      EXPECT_FALSE(joint.standin) << key << " (" << joint.type << ")";
      EXPECT_GE(joint.joint, 0);
    }
    for (const model::ForceSpec& f : spec.forces) EXPECT_NE(report.GetForce(f.name), nullptr);
  }
}

TEST(OpenSimParserTest, RepeatedJointNamesAreKeptAndReported) {
  // newton_cradle.osim names five joints `sph1`: all five are built, under the unique names
  // the reader gives their paths, and each repeat is a warning.
  opensim::OpenSimParser parser;
  parser.Parse(kChronoDir + "newton_cradle.osim");
  const opensim::Report& report = parser.GetReport();
  for (const char* key : {"sph1", "sph1_2", "sph1_3", "sph1_4", "sph1_5"}) {
    ASSERT_NE(report.GetJoint(key), nullptr) << key;
    EXPECT_EQ(report.GetJoint(key)->type, "BallJoint");
  }
  int repeats = 0;
  for (const Diagnostic& w : report.warnings()) {
    repeats += w.message.find("duplicate joint name 'sph1'") != std::string::npos;
  }
  EXPECT_EQ(repeats, 4);
}

// A 4.x model whose joint has a type Sinew does not know (a plugin's).
std::string WriteUnknownJointModel() {
  const std::string path =
      (std::filesystem::temp_directory_path() / "sinew_unknown_joint.osim").string();
  std::ofstream(path) << R"(<?xml version="1.0" encoding="UTF-8"?>
<OpenSimDocument Version="40000">
  <Model name="plugin">
    <Ground name="ground"/>
    <BodySet name="bodyset"><objects>
      <Body name="link">
        <mass>2</mass><mass_center>0 -0.5 0</mass_center><inertia>0.1 0.1 0.1 0 0 0</inertia>
      </Body>
    </objects></BodySet>
    <JointSet name="jointset"><objects>
      <MyPluginJoint name="odd">
        <socket_parent_frame>ground_offset</socket_parent_frame>
        <socket_child_frame>link_offset</socket_child_frame>
        <coordinates><Coordinate name="odd_q"><default_value>0.3</default_value></Coordinate></coordinates>
        <frames>
          <PhysicalOffsetFrame name="ground_offset"><socket_parent>/ground</socket_parent>
            <translation>0 1 0</translation><orientation>0 0 0</orientation></PhysicalOffsetFrame>
          <PhysicalOffsetFrame name="link_offset"><socket_parent>/bodyset/link</socket_parent>
            <translation>0 0 0</translation><orientation>0 0 0</orientation></PhysicalOffsetFrame>
        </frames>
      </MyPluginJoint>
    </objects></JointSet>
  </Model>
</OpenSimDocument>
)";
  return path;
}

TEST(OpenSimParserTest, UnknownJointBecomesAFlaggedSphericalStandIn) {
  const std::string path = WriteUnknownJointModel();
  opensim::OpenSimParser parser;
  auto system = parser.Parse(path);
  const opensim::JointInfo* joint = parser.GetReport().GetJoint("odd");
  ASSERT_NE(joint, nullptr);
  EXPECT_TRUE(joint->standin);
  EXPECT_EQ(joint->type, "MyPluginJoint");
  EXPECT_EQ(joint->form, engine::JointForm::kBall);
  bool warned = false;
  for (const Diagnostic& w : parser.GetReport().warnings()) {
    warned |= w.component == "/jointset/odd" && w.message.find("stand-in") != std::string::npos;
  }
  EXPECT_TRUE(warned);
  // The stand-in's frames coincide at the start: the link's origin is at the pivot (0, 1, 0).
  const engine::State state = engine::MakeDefaultState(*system);
  const int link = parser.GetReport().GetBody("link")->body;
  EXPECT_TRUE(state.bodies[link].p_GB.isApprox(Vec3(0, 1, 0), 1e-12));

  opensim::OpenSimParser strict;
  strict.SetStrict(true);
  EXPECT_THROW(strict.Parse(path), Error);
}

TEST(OpenSimParserTest, KnownModelsPassStrictModeOnlyWhenNothingIsLeftOut) {
  opensim::OpenSimParser strict;
  strict.SetStrict(true);
  EXPECT_NO_THROW(strict.Parse(kChronoDir + "torque-actuator.osim"));
  EXPECT_NO_THROW(strict.Parse(kChronoDir + "double_pendulum.osim"));
}

TEST(OpenSimParserTest, SameFileTwiceAndTwoFilesIntoOneSystem) {
  opensim::OpenSimParser parser;
  engine::System system;
  parser.Parse(system, kChronoDir + "double_pendulum.osim");
  const int after_first = system.num_bodies();
  parser.Parse(system, kChronoDir + "torque-actuator.osim");
  EXPECT_EQ(system.num_bodies(), after_first + 1);  // rod1 added beside the pendulum
  system.Finalize();
  engine::State state = engine::MakeDefaultState(system);
  EXPECT_EQ(static_cast<int>(state.bodies.size()), system.num_bodies());

  // Parsing the same file twice with one parser gives identical, independent systems.
  auto a = parser.Parse(kChronoDir + "double_pendulum.osim");
  auto b = parser.Parse(kChronoDir + "double_pendulum.osim");
  EXPECT_EQ(a->num_bodies(), b->num_bodies());
  EXPECT_NE(a.get(), b.get());
}

TEST(OpenSimParserTest, CollisionFamiliesAlternateWithTreeDepth) {
  opensim::OpenSimParser parser;
  parser.EnableCollision(1, 2);
  parser.Parse(kChronoDir + "triple_revolute.osim");
  const contact::CollisionModel& collision = parser.GetCollisionModel();
  const model::ModelSpec& spec = parser.GetSpec();
  EXPECT_FALSE(collision.shapes.empty());
  for (const model::JointSpec& j : spec.joints) {
    if (j.parent_body == model::kGroundIndex) {
      EXPECT_EQ(collision.family[j.child_body], 1);
    } else {
      EXPECT_FALSE(collision.CanCollide(j.parent_body, j.child_body)) << j.name;
    }
  }
}

TEST(OpenSimParserTest, VisualizationTypeChoosesTheVisualAssets) {
  // PRIMITIVES: every body gets parts (a sphere and its segments); NONE: no parts at all.
  opensim::OpenSimParser parser;
  parser.SetVisualizationType(opensim::VisType::kPrimitives);
  parser.Parse(kChronoDir + "triple_revolute.osim");
  const viz::VisualScene& scene = parser.GetVisualScene();
  ASSERT_EQ(scene.bodies.size(), parser.GetSpec().bodies.size());
  for (size_t b = 1; b < scene.bodies.size(); ++b) EXPECT_FALSE(scene.bodies[b].parts.empty());

  // MESH: the model names mesh files (cylinder.vtp, sphere.vtp) not shipped beside it: each is
  // a warning naming the file, and the body falls back to primitives.
  opensim::OpenSimParser mesh;
  mesh.SetVisualizationType(opensim::VisType::kMesh);
  mesh.Parse(kChronoDir + "double_pendulum.osim");
  bool missing_mesh_warned = false;
  for (const Diagnostic& w : mesh.GetReport().warnings()) {
    missing_mesh_warned |= w.message.find("not found") != std::string::npos;
  }
  EXPECT_TRUE(missing_mesh_warned);
  for (size_t b = 1; b < mesh.GetVisualScene().bodies.size(); ++b) {
    EXPECT_FALSE(mesh.GetVisualScene().bodies[b].parts.empty());
  }

  opensim::OpenSimParser none;
  none.Parse(kChronoDir + "triple_revolute.osim");
  for (const viz::VisualBody& body : none.GetVisualScene().bodies) EXPECT_TRUE(body.parts.empty());
}

TEST(OpenSimParserTest, UnknownActuatorNameIsAnError) {
  opensim::OpenSimParser parser;
  parser.Parse(kChronoDir + "torque-actuator.osim");
  EXPECT_THROW(parser.SetExcitationFunction("no_such_actuator", nullptr), Error);
}

}  // namespace
}  // namespace sinew
