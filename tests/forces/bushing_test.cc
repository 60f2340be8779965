// OpenSim's bushings (BushingForce, FunctionBasedBushingForce, ExpressionBasedBushingForce):
// OpenSim's own bushing models against their closed-form motions, the loads against the
// gradient of the potential (finite differences) and hand computations, the damping against
// the rates of the deflection, and energy conservation of a free body on a bushing.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/system.h>
#include <sinew/forces/bushing_force.h>
#include <sinew/io/osim_reader.h>
#include <sinew/math/rotation.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include "engine/test_models.h"

namespace sinew::forces {
namespace {

using engine::testing::Coord;
using engine::testing::MakeBody;

const std::string kData = SINEW_TEST_DATA_DIR;
const std::string kOpenSimTests = kData + "/opensim-org/opensim-core/OpenSim/Simulation/Test/";

// Integrates the model's slider coordinate `ball_h` from `h0` and returns the largest
// difference from `closed_form(t)` at 40 times over 2 s (rk45 at accuracy 1e-10).
template <class ClosedForm>
double WorstSliderError(const std::string& file, double h0, ClosedForm closed_form) {
  opensim::OpenSimParser parser;
  auto system = parser.Parse(file);
  EXPECT_TRUE(parser.GetReport().not_simulated().empty());
  EXPECT_NE(parser.GetReport().GetForce("bushing")->load, nullptr);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  engine::State state = engine::MakeDefaultState(*system);
  engine::SetCoordinateValue(*system, state, "ball_h", h0);
  double worst = 0.0;
  for (int k = 1; k <= 40; ++k) {
    const double t = 0.05 * k;
    integrator->StepTo(state, t);
    worst = std::max(
        worst, std::abs(engine::GetCoordinateValue(*system, state, "ball_h") - closed_form(t)));
  }
  return worst;
}

TEST(BushingForceTest, OpenSimsBushingModelOscillatesAsTheClosedForm) {
  // BushingForceModel_30000.osim: a 1 kg ball on a vertical slider (the slider's x axis is
  // turned onto ground's y by both joint frames), a bushing between the ground and ball origins
  // with translational stiffness k = 10 N/m and nothing else, gravity g = -9.8065 m/s^2 along y.
  // m h'' = -k h + m g: h(t) = (h0 - dh) cos(sqrt(k/m) t) + dh with dh = m g / k (OpenSim's
  // testBushingForce, which starts at h0 = 0.5 m and accepts 1e-4).
  constexpr double kM = 1.0, kK = 10.0, kG = -9.8065, kH0 = 0.5;
  const double w = std::sqrt(kK / kM), dh = kM * kG / kK;
  const double worst =
      WorstSliderError(kOpenSimTests + "BushingForceModel_30000.osim", kH0,
                       [&](double t) { return (kH0 - dh) * std::cos(w * t) + dh; });
  // rk45 at accuracy 1e-10 over ~3 periods: 1.1e-10 m measured (OpenSim's test accepts 1e-4).
  EXPECT_LT(worst, 1e-9);
  std::cout << "BushingForceModel_30000: worst error " << worst << " m\n";
}

TEST(BushingForceTest, OpenSimsOffsetBushingModelIsTheDampedClosedForm) {
  // BushingForceOffsetModel_30000.osim: the same ball and slider, with the bushing's frame F at
  // p = (1, 2, 3) on ground turned by body-fixed XYZ angles (-0.5, 0, 0.5), its frame M at
  // (4, 5, 6) on the ball turned by (0.1, 0.2, 0.3), translational stiffness 10 N/m on every
  // axis, translational damping c = (0.2, 0.3, 0.4) N s/m along F's axes, rotational stiffness
  // and damping. The ball cannot turn, so R_FM is constant: the moments are taken by the slider
  // and only the force moves the ball. With the ball at (0, h, 0): p_FM = (3, 3 + h, 3) in
  // ground, the isotropic spring pulls with -10 (3 + h) along y, and the damping, diagonal in
  // F, resists the velocity (0, h', 0) with c_yy = sum_i c_i (R_GF)_yi^2, where F's axes seen
  // from ground have y components (R_GF)_y = (cos a sin c, cos a cos c, -sin a), a = -0.5,
  // c = 0.5. So h'' + c_yy h' + 10 h = -30 + g: a damped oscillator about h_eq = -3 + g / 10,
  // from h = 0 at rest.
  constexpr double kG = -9.8065, kA = -0.5, kC = 0.5;
  const double r_y[3] = {std::cos(kA) * std::sin(kC), std::cos(kA) * std::cos(kC), -std::sin(kA)};
  const double c_yy = 0.2 * r_y[0] * r_y[0] + 0.3 * r_y[1] * r_y[1] + 0.4 * r_y[2] * r_y[2];
  const double h_eq = -3.0 + kG / 10.0;
  const double sigma = c_yy / 2.0, wd = std::sqrt(10.0 - sigma * sigma);
  const double a = 0.0 - h_eq, b = sigma * a / wd;
  const double worst =
      WorstSliderError(kOpenSimTests + "BushingForceOffsetModel_30000.osim", 0.0, [&](double t) {
        return h_eq + std::exp(-sigma * t) * (a * std::cos(wd * t) + b * std::sin(wd * t));
      });
  EXPECT_LT(worst, 1e-9);  // 2.5e-10 m measured at accuracy 1e-10
  std::cout << "BushingForceOffsetModel_30000: worst error " << worst << " m (c_yy " << c_yy
            << " N s/m)\n";
}

// Two free bodies (1 and 2; posed by the test, not through joints) and one force element
// between them, for pose-level checks.
struct TwoBodies {
  engine::System system{Vec3::Zero()};
  engine::State state;
};

std::unique_ptr<TwoBodies> MakeTwoBodies(std::shared_ptr<engine::ForceElement> element) {
  auto m = std::make_unique<TwoBodies>();
  for (const char* name : {"a", "b"}) {
    const int body = m->system.AddBody(MakeBody(name, 1.0, Vec3::Zero(), Mat3::Identity()));
    const std::string n(name);
    m->system.AddJoint("free_" + n, 0, Transform(), body, Transform(),
                       engine::JointForm::kParameterized,
                       std::make_shared<engine::testing::FreeModel>(),
                       {Coord("rx" + n), Coord("ry" + n), Coord("rz" + n), Coord("tx" + n),
                        Coord("ty" + n), Coord("tz" + n)});
  }
  m->system.AddForceElement(std::move(element));
  m->system.Finalize();
  m->state = engine::MakeDefaultState(m->system);
  // A pose and twist of each body with no special structure.
  engine::BodyState& sa = m->state.bodies[1];
  sa.p_GB = Vec3(0.2, -0.1, 0.3);
  sa.quat_GB = Quat(RotationFromBodyFixedXYZ(Vec3(0.4, -0.3, 0.2)));
  sa.w_GB = Vec3(0.5, -1.2, 0.7);
  sa.v_GB = Vec3(-0.3, 0.2, 0.9);
  engine::BodyState& sb = m->state.bodies[2];
  sb.p_GB = Vec3(0.5, 0.3, 0.1);
  sb.quat_GB = Quat(RotationFromBodyFixedXYZ(Vec3(0.9, 0.1, 0.6)));
  sb.w_GB = Vec3(-0.8, 0.4, 1.1);
  sb.v_GB = Vec3(0.6, -0.5, 0.2);
  return m;
}

// Frames with offsets on both bodies (body-fixed XYZ angles, translations).
LinkedFrames OffsetFrames() {
  return {1, Transform(RotationFromBodyFixedXYZ(Vec3(0.3, 0.2, -0.4)), Vec3(0.1, 0.2, -0.3)), 2,
          Transform(RotationFromBodyFixedXYZ(Vec3(-0.2, 0.5, 0.1)), Vec3(-0.2, 0.1, 0.25))};
}

Vec6 Stiffness() {
  Vec6 k;
  k << 20, 30, 40, 200, 300, 400;
  return k;
}

engine::Loads LoadsOf(const TwoBodies& m) {
  engine::Loads loads(m.system.num_bodies(), m.system.num_coordinates());
  m.system.force_elements()[0]->AddLoads(m.system.MakeForceContext(0, m.state), loads);
  return loads;
}

double PotentialOf(const TwoBodies& m, const engine::State& state) {
  return m.system.force_elements()[0]->CalcPotentialEnergy(m.system.MakeForceContext(0, state));
}

// The state with body `body` turned by `amount` about G's axis `axis` (about Bo) or, for axis
// 3..5, moved by `amount` along G's axis axis - 3.
engine::State Displaced(const engine::State& state, int body, int axis, double amount) {
  engine::State s = state;
  engine::BodyState& b = s.bodies[body];
  if (axis < 3) {
    b.quat_GB = Quat(Eigen::AngleAxisd(amount, Vec3::Unit(axis))) * b.quat_GB;
  } else {
    b.p_GB[axis - 3] += amount;
  }
  return s;
}

TEST(BushingForceTest, LoadsAreMinusTheGradientOfThePotential) {
  // Stiffness only: the load on each body, [torque about Bo; force] in G, must be minus the
  // derivative of V = sum k_i q_i^2 / 2 with respect to turning the body about Bo (about G's
  // axes) and moving it (along G's axes): central differences of V, whose error at step 1e-6 is
  // ~1e-12 V''' plus rounding ~1e-16 V / 1e-6, both far below 1e-7.
  const auto m = MakeTwoBodies(std::make_shared<BushingForce>(
      "b", OffsetFrames(), std::make_shared<LinearBushingStiffness>(Stiffness()), Vec6::Zero()));
  const engine::Loads loads = LoadsOf(*m);
  constexpr double kStep = 1e-6;
  double largest = 0.0;
  for (int body : {1, 2}) {
    for (int axis = 0; axis < 6; ++axis) {
      const double dV = (PotentialOf(*m, Displaced(m->state, body, axis, kStep)) -
                         PotentialOf(*m, Displaced(m->state, body, axis, -kStep))) /
                        (2 * kStep);
      EXPECT_NEAR(loads.body[body][axis], -dV, 1e-7) << "body " << body << " axis " << axis;
      largest = std::max(largest, std::abs(dV));
    }
  }
  EXPECT_GT(largest, 10.0);  // a real deflection, not a trivial zero
}

TEST(BushingForceTest, DampingFollowsTheRatesOfTheDeflection) {
  // Damping only. (1) The deflection rate qdot the force uses equals the central difference of
  // the deflection q along the bodies' motion (poses advanced with their twists). (2) The
  // loads' power is f . qdot = -sum c_i qdot_i^2: the moment goes through the transpose of the
  // map from angular velocity to angle rates.
  Vec6 c;
  c << 0.3, 0.5, 0.7, 2.0, 3.0, 4.0;
  const LinkedFrames frames = OffsetFrames();
  const auto m = MakeTwoBodies(std::make_shared<BushingForce>(
      "b", frames, std::make_shared<LinearBushingStiffness>(Vec6::Zero()), c));
  auto advanced = [&](double h) {
    engine::State s = m->state;
    for (int body : {1, 2}) {
      engine::BodyState& b = s.bodies[body];
      b.p_GB += h * b.v_GB;
      b.quat_GB = Quat(Eigen::AngleAxisd(h * b.w_GB.norm(), b.w_GB.normalized())) * b.quat_GB;
    }
    return s;
  };
  constexpr double kStep = 1e-6;
  const FrameDeflection d = CalcFrameDeflection(m->state, frames);
  const Vec6 rate = (CalcFrameDeflection(advanced(kStep), frames).q -
                     CalcFrameDeflection(advanced(-kStep), frames).q) /
                    (2 * kStep);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(d.qdot[i], rate[i], 1e-8) << i;
  const double expected_power = -d.qdot.dot(c.cwiseProduct(d.qdot));
  EXPECT_NEAR(engine::CalcForcePower(m->system, m->state, 0), expected_power, 1e-12);
  EXPECT_LT(expected_power, -0.1);
}

TEST(BushingForceTest, SingleAxisDeflectionsGiveTheHandComputedLoads) {
  // F = body 1's frame at the origin, unturned; M = body 2's frame, body 2 turned about x by
  // 0.7 rad and moved to (0.1, -0.2, 0.3): q = (0.7, 0, 0, 0.1, -0.2, 0.3) and, with no second
  // or third angle, the angle rates are the angular velocity, so the moment on body 2 is
  // -k_x 0.7 about x and the force -k .* p. Body 1 gets the opposite force at M's origin and
  // the opposite moment.
  const auto m = MakeTwoBodies(std::make_shared<BushingForce>(
      "b", LinkedFrames{1, Transform(), 2, Transform()},
      std::make_shared<LinearBushingStiffness>(Stiffness()), Vec6::Zero()));
  for (int body : {1, 2}) m->state.bodies[body] = engine::BodyState{};
  m->state.bodies[2].p_GB = Vec3(0.1, -0.2, 0.3);
  m->state.bodies[2].quat_GB = Quat(Eigen::AngleAxisd(0.7, Vec3::UnitX()));
  engine::Loads loads = LoadsOf(*m);
  const Vec3 force(-20.0, 60.0, -120.0);
  EXPECT_TRUE(loads.body[2].head<3>().isApprox(Vec3(-14.0, 0, 0), 1e-14));
  EXPECT_TRUE(loads.body[2].tail<3>().isApprox(force, 1e-14));
  EXPECT_TRUE(loads.body[1].tail<3>().isApprox(-force, 1e-14));
  EXPECT_TRUE(loads.body[1].head<3>().isApprox(
      Vec3(14.0, 0, 0) + Vec3(0.1, -0.2, 0.3).cross(-force), 1e-14));
  // Turned about y by 0.5 rad instead: q = (0, 0.5, 0, ...); the moment on the angles is
  // (0, -15, 0) and N(0, 0.5, 0)^T maps it to (0, -15, 0) about M's y, which is G's y.
  m->state.bodies[2].quat_GB = Quat(Eigen::AngleAxisd(0.5, Vec3::UnitY()));
  loads = LoadsOf(*m);
  EXPECT_TRUE(loads.body[2].head<3>().isApprox(Vec3(0, -15.0, 0), 1e-14));
}

TEST(BushingForceTest, FreeBodyOnABushingConservesEnergy) {
  // tests/data/sinew/bushings.osim: a 2 kg body with a full inertia on a FreeJoint, hung from
  // ground by a linear BushingForce between two PhysicalOffsetFrames (4.x layout, relative
  // socket paths), started turning and moving, no damping: T + V_gravity + V_bushing is
  // constant. rk45 at accuracy A changes it by at most ~A x the energy scale (~10 J) per step.
  opensim::OpenSimParser parser;
  auto system = parser.Parse(kData + "/sinew/bushings.osim");
  ASSERT_TRUE(parser.GetReport().not_simulated().empty());
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  engine::State state = engine::MakeDefaultState(*system);
  const double e0 = engine::CalcMechanicalEnergy(*system, state);
  double worst = 0.0, v_min = 1e9, v_max = 0.0;
  for (int k = 1; k <= 40; ++k) {
    integrator->StepTo(state, 0.05 * k);
    worst = std::max(worst, std::abs(engine::CalcMechanicalEnergy(*system, state) - e0));
    const double v = engine::CalcForcePotentialEnergy(*system, state);
    v_min = std::min(v_min, v);
    v_max = std::max(v_max, v);
  }
  const double steps = static_cast<double>(integrator->stats().steps);
  EXPECT_LT(worst, 2e-7);  // 5.3e-8 J measured
  EXPECT_LT(worst, 10.0 * steps * settings.accuracy);
  EXPECT_GT(v_max - v_min, 0.1);  // the bushing did exchange energy
  std::cout << "free body on a bushing: energy drift " << worst << " J over " << steps
            << " steps, bushing energy in [" << v_min << ", " << v_max << "] J\n";
}

}  // namespace
}  // namespace sinew::forces
