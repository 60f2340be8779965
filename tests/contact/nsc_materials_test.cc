// NSC with per-shape materials: two balls of different friction and restitution on one floor
// (ContactSpheres and a ContactHalfSpace of a parsed model, through CollisionContactProvider),
// each following the closed forms of its own material combined with the floor's (the smaller
// friction, the smaller restitution, as SMC combines them).
#include <gtest/gtest.h>
#include <sinew/contact/collision_contact_provider.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace sinew::contact {
namespace {

constexpr double kG = 9.80665, kR = 0.1;

// Two 1 kg balls "a" and "b" (solid, I = 2/5 m r^2) on free joints 1 m apart in z, each with a
// ContactSphere ("sphere_a", "sphere_b") of radius kR, above a ground ContactHalfSpace "floor"
// (the solid y < 0); no contact force.
std::string TwoBallsModel() {
  std::ostringstream m;
  m.precision(17);
  m << R"(<OpenSimDocument Version="40000"><Model name="two_balls">
<gravity>0 )"
    << -kG << R"( 0</gravity><Ground name="ground"/><BodySet><objects>)";
  for (const char* b : {"a", "b"}) {
    m << "<Body name=\"" << b << "\"><mass>1</mass><inertia>" << 0.4 * kR * kR << " "
      << 0.4 * kR * kR << " " << 0.4 * kR * kR << " 0 0 0</inertia></Body>";
  }
  m << "</objects></BodySet><JointSet><objects>";
  for (const char* b : {"a", "b"}) {
    m << "<FreeJoint name=\"free_" << b << "\"><socket_parent_frame>/ground</socket_parent_frame>"
      << "<socket_child_frame>/bodyset/" << b << "</socket_child_frame><coordinates>";
    for (const char* q : {"rx", "ry", "rz", "tx", "ty", "tz"})
      m << "<Coordinate name=\"" << q << "_" << b << "\"/>";
    m << "</coordinates></FreeJoint>";
  }
  m << R"(</objects></JointSet><ContactGeometrySet><objects>
<ContactHalfSpace name="floor"><socket_frame>/ground</socket_frame>
<orientation>0 0 -1.5707963267948966</orientation></ContactHalfSpace>)";
  for (const char* b : {"a", "b"}) {
    m << "<ContactSphere name=\"sphere_" << b << "\"><socket_frame>/bodyset/" << b
      << "</socket_frame><radius>" << kR << "</radius></ContactSphere>";
  }
  m << "</objects></ContactGeometrySet></Model></OpenSimDocument>";
  return m.str();
}

struct Ball {
  const char* name;
  double friction, restitution;
};
// The floor's (default) material is the more slippery-proof and bouncy one, so each pair takes
// its ball's values.
constexpr Ball kBalls[2] = {{"a", 0.2, 0.5}, {"b", 0.5, 0.8}};

struct TwoBalls {
  std::unique_ptr<engine::System> system;
  std::unique_ptr<engine::NscIntegrator> integrator;
  engine::State state;
  int body[2] = {0, 0};
};

TwoBalls MakeTwoBalls(double step) {
  TwoBalls scene;
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  for (const Ball& b : kBalls) {
    CollisionMaterial material;
    material.friction = b.friction;
    material.restitution = b.restitution;
    parser.SetContactMaterial(std::string("sphere_") + b.name, material);
  }
  const model::ModelSpec spec = io::ReadOsimString(TwoBallsModel(), "two_balls.osim");
  scene.system = std::make_unique<engine::System>(spec.gravity);
  parser.ParseSpec(*scene.system, spec);
  scene.system->Finalize();
  scene.state = engine::MakeDefaultState(*scene.system);
  std::vector<Transform> X_GB;
  GatherBodyPoses(scene.state, X_GB);
  auto provider = std::make_shared<CollisionContactProvider>(
      parser.GetCollisionModel(), std::nullopt, NscMaterial{.friction = 1.0, .restitution = 1.0},
      X_GB);
  engine::IntegratorSettings settings;
  settings.step = step;
  engine::NscSettings nsc;
  nsc.solver.max_iterations = 1000;
  nsc.solver.tolerance = 1e-12;
  scene.integrator =
      std::make_unique<engine::NscIntegrator>(*scene.system, provider, settings, nsc);
  for (int i = 0; i < 2; ++i) {
    scene.body[i] = scene.system->FindBody(kBalls[i].name);
    engine::SetCoordinateValue(*scene.system, scene.state, std::string("tz_") + kBalls[i].name,
                               i == 0 ? -0.5 : 0.5);
  }
  return scene;
}

TEST(NscMaterialsTest, EachBallBouncesToItsOwnRestitutionSquared) {
  // Dropped from H = 1 m (lowest point): each rises to e^2 H with its own e. Step-size error as
  // in NscTest.DroppedBallBouncesToRestitutionSquaredOfItsHeight: e^2 H 2 g h / v + 2 h v.
  constexpr double kH0 = 1.0, kStep = 1e-5;
  TwoBalls scene = MakeTwoBalls(kStep);
  for (const Ball& b : kBalls)
    engine::SetCoordinateValue(*scene.system, scene.state, std::string("ty_") + b.name, kR + kH0);
  const double v = std::sqrt(2 * kG * kH0);
  double apex[2] = {0, 0}, lowest[2] = {1, 1};
  for (int n = 1; n * kStep < v / kG * 2.0 + 0.05; ++n) {
    scene.integrator->StepTo(scene.state, n * kStep);
    for (int i = 0; i < 2; ++i) {
      const double y = scene.state.bodies[scene.body[i]].p_GB.y() - kR;
      lowest[i] = std::min(lowest[i], y);
      if (n * kStep > v / kG + 0.01) apex[i] = std::max(apex[i], y);
    }
  }
  for (int i = 0; i < 2; ++i) {
    const double e = kBalls[i].restitution;
    const double tolerance = e * e * kH0 * 2 * kG * kStep / v + 2 * kStep * v;
    EXPECT_NEAR(apex[i], e * e * kH0, tolerance) << "ball " << kBalls[i].name;
    EXPECT_GT(lowest[i], -1e-12) << "ball " << kBalls[i].name << " enters the floor";
    std::cout << "nsc materials: ball " << kBalls[i].name << " (e = " << e << ") apex " << apex[i]
              << " m, closed form " << e * e * kH0 << " (error " << apex[i] - e * e * kH0
              << ", allowed " << tolerance << "); lowest " << lowest[i] << " m\n";
  }
}

TEST(NscMaterialsTest, EachBallRollsAfterItsOwnSlidingTime) {
  // Both resting on the floor, launched at v0 = 1 m/s without spin: each slides until
  // t* = 2 v0 / (7 mu g) with its own mu, then rolls at 5/7 v0. As in
  // NscTest.SlidingSphereRollsAtFiveSeventhsOfItsSpeed the sliding samples lie on the
  // continuous line (impulses m g h and mu m g h per step), so the line through them crosses
  // zero at t* to the solver's tolerance.
  constexpr double kV0 = 1.0, kStep = 1e-4;
  TwoBalls scene = MakeTwoBalls(kStep);
  for (const Ball& b : kBalls) {
    engine::SetCoordinateValue(*scene.system, scene.state, std::string("ty_") + b.name, kR);
    engine::SetCoordinateSpeed(*scene.system, scene.state, std::string("tx_") + b.name, kV0);
  }
  auto slip = [&](int i) {
    const engine::BodyState& s = scene.state.bodies[scene.body[i]];
    return s.v_GB.x() + s.w_GB.z() * kR;
  };
  double t_line[2] = {-1, -1}, previous[2] = {slip(0), slip(1)};
  bool rolling[2] = {false, false};
  for (int n = 1; n <= 3000; ++n) {
    scene.integrator->StepTo(scene.state, n * kStep);
    for (int i = 0; i < 2; ++i) {
      const double s = slip(i);
      if (!rolling[i] && std::abs(s) < 1e-9) {
        rolling[i] = true;
      } else if (!rolling[i]) {
        t_line[i] = n * kStep + s / ((previous[i] - s) / kStep);
      }
      previous[i] = s;
    }
  }
  for (int i = 0; i < 2; ++i) {
    const double t_star = 2.0 * kV0 / (7.0 * kBalls[i].friction * kG);
    const double v = scene.state.bodies[scene.body[i]].v_GB.x();
    EXPECT_TRUE(rolling[i]) << "ball " << kBalls[i].name;
    EXPECT_NEAR(t_line[i], t_star, 1e-9 * t_star) << "ball " << kBalls[i].name;
    EXPECT_NEAR(v, 5.0 / 7.0 * kV0, 1e-9 * kV0) << "ball " << kBalls[i].name;
    EXPECT_NEAR(scene.state.bodies[scene.body[i]].p_GB.y(), kR, 1e-12);
    std::cout << "nsc materials: ball " << kBalls[i].name << " (mu = " << kBalls[i].friction
              << ") sliding line ends at " << t_line[i] << " s, t* " << t_star << " s (relative "
              << t_line[i] / t_star - 1 << "); speed " << v << " m/s (relative "
              << v / (5.0 / 7.0 * kV0) - 1 << ")\n";
  }
}

}  // namespace
}  // namespace sinew::contact
