// CoordinateCouplerConstraint: two sliders coupled linearly under gravity against the closed
// form of the coupled motion; a pendulum driving a slider through a spline, its Jacobian and
// acceleration right-hand side against finite differences of phi, its residual and energy
// along the motion; and the default state assembled onto the coupler.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/system.h>
#include <sinew/forces/coordinate_coupler_constraint.h>
#include <sinew/functions/linear_function.h>
#include <sinew/functions/simm_spline.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "engine/test_models.h"

namespace sinew::forces {
namespace {

using engine::testing::Coord;
using engine::testing::MakeBody;

constexpr double kG = 9.80665;
constexpr double kM1 = 2.0, kM2 = 0.5;
// x1 = s f(x2) with f(x) = 1.5 x + 0.2 and s = 2: x1 = 3 x2 + 0.4.
constexpr double kSlope = 1.5, kIntercept = 0.2, kScale = 2.0;

// Two sliders along ground x (1 m apart in y), gravity along -x, x1 = s f(x2). The defaults
// (x1 = 0, x2 = 0.1, u = 0.2 both) do not satisfy the coupler: MakeDefaultState projects.
std::unique_ptr<engine::System> MakeCoupledSliders() {
  auto system = std::make_unique<engine::System>(Vec3(-kG, 0, 0));
  const Mat3 I = 0.01 * Mat3::Identity();
  const int b1 = system->AddBody(MakeBody("b1", kM1, Vec3::Zero(), I));
  const int b2 = system->AddBody(MakeBody("b2", kM2, Vec3::Zero(), I));
  const auto slider = std::make_shared<engine::testing::SliderModel>();
  system->AddJoint("s1", 0, Transform(), b1, Transform(), engine::JointForm::kParameterized, slider,
                   {Coord("x1", 0.0, 0.2)});
  system->AddJoint("s2", 0, Transform::Translation(Vec3(0, 1, 0)), b2, Transform(),
                   engine::JointForm::kParameterized, slider, {Coord("x2", 0.1, 0.2)});
  system->AddConstraint(std::make_shared<CoordinateCouplerConstraint>(
      "coupler", std::vector<int>{1}, 0,
      std::make_shared<functions::LinearFunction>(kSlope, kIntercept), kScale));
  system->Finalize();
  return system;
}

TEST(CoordinateCouplerTest, LinearCouplingOfTwoSlidersIsTheClosedForm) {
  const auto system = MakeCoupledSliders();
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-10;
  engine::State state = engine::MakeDefaultState(*system);
  const auto coupler = system->constraints().back();
  VecX phi(1);
  coupler->CalcPositionError(*system, state, phi);
  EXPECT_LT(std::abs(phi[0]), 1e-10);  // the default state is projected onto the coupler
  EXPECT_NEAR(state.u[0], kScale * kSlope * state.u[1], 1e-12);
  // With x1 = r x2 + c (r = s slope) the kinetic energy is (m1 r^2 + m2) x2'^2 / 2 and
  // gravity's generalized force on x2 is -g (m2 + r m1): x2'' is constant.
  const double r = kScale * kSlope;
  const double a = -kG * (kM2 + r * kM1) / (kM1 * r * r + kM2);
  const double x0 = state.q[1], v0 = state.u[1];
  engine::Data data(*system);
  const engine::KktSolver& kkt = data.kkt;
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  double worst = 0.0;
  for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    integrator->StepTo(state, t);
    const engine::Accelerations acc = engine::CalcAccelerations(*system, state, nullptr, data);
    EXPECT_NEAR(acc.vdot[kkt.SpeedColumn(1)], a, 1e-12 * kG) << t;
    EXPECT_NEAR(acc.vdot[kkt.SpeedColumn(0)], r * a, 1e-12 * kG) << t;
    // x2'' is constant, so the error grows at most linearly with the steps taken.
    const double steps = std::max(1.0, static_cast<double>(integrator->stats().steps));
    const double x2 = x0 + v0 * t + 0.5 * a * t * t;
    EXPECT_NEAR(state.q[1], x2, 2.0 * steps * settings.accuracy) << t;
    EXPECT_NEAR(state.q[0], r * state.q[1] + kScale * kIntercept, 1e-10) << t;
    worst = std::max(worst, std::abs(state.q[1] - x2));
  }
  std::cout << "coupled sliders: x2 error " << worst << " m\n";
}

// A pendulum (pin about ground z, 1 kg at 0.5 m) drives a 3 kg slider along x through
// x = s f(theta), f a SimmSpline through 6 knots (a bent, non-polynomial curve).
std::unique_ptr<engine::System> MakeSplineCoupled() {
  auto system = std::make_unique<engine::System>(Vec3(0, -kG, 0));
  const int arm =
      system->AddBody(MakeBody("arm", 1.0, Vec3(0, -0.5, 0), Vec3(0.02, 0.001, 0.02).asDiagonal()));
  const int slider = system->AddBody(MakeBody("block", 3.0, Vec3::Zero(), 0.01 * Mat3::Identity()));
  system->AddJoint("pin", 0, Transform(), arm, Transform(), engine::JointForm::kParameterized,
                   std::make_shared<engine::testing::RevoluteModel>(Vec3::UnitZ()),
                   {Coord("theta", 0.9, 0.0)});
  system->AddJoint("slide", 0, Transform::Translation(Vec3(0, 2, 0)), slider, Transform(),
                   engine::JointForm::kParameterized,
                   std::make_shared<engine::testing::SliderModel>(), {Coord("x", 0.0, 0.0)});
  auto spline = std::make_shared<functions::SimmSpline>(
      std::vector<double>{-1.5, -0.8, -0.2, 0.4, 1.0, 1.6},
      std::vector<double>{0.3, -0.1, 0.05, 0.2, -0.15, 0.1});
  system->AddConstraint(std::make_shared<CoordinateCouplerConstraint>(
      "spline_coupler", std::vector<int>{0}, 1, spline, 0.7));
  system->Finalize();
  return system;
}

TEST(CoordinateCouplerTest, JacobianAndAccelerationTermAreDerivativesOfPhi) {
  const auto system = MakeSplineCoupled();
  const auto coupler = system->constraints().back();
  engine::State state = engine::MakeDefaultState(*system);
  state.u[0] = 1.3;
  state.u[1] = 0.4;  // any speeds: J and b do not assume the velocity constraint holds
  MatX J(1, 2);
  VecX b(1), phi_p(1), phi_m(1), phi_0(1);
  coupler->CalcJacobian(*system, state, J);
  coupler->CalcAccelerationRhs(*system, state, b);
  // d phi / dt along q(t) = q + t u: (phi(+h) - phi(-h)) / 2h = J u; the second difference
  // (with udot = 0) is d/dt (J u) = Jdot u = -b. Central differences: errors h^2 phi''' ~ 1e-8
  // for the first, h^2 phi'''' / 12 and the rounding 1e-16 / h^2 ~ 1e-8 for the second.
  const double h = 1e-4;
  engine::State plus = state, minus = state;
  plus.q += h * state.u;
  minus.q -= h * state.u;
  coupler->CalcPositionError(*system, plus, phi_p);
  coupler->CalcPositionError(*system, minus, phi_m);
  coupler->CalcPositionError(*system, state, phi_0);
  EXPECT_NEAR((phi_p[0] - phi_m[0]) / (2 * h), (J * state.u)[0], 1e-7);
  EXPECT_NEAR((phi_p[0] - 2 * phi_0[0] + phi_m[0]) / (h * h), -b[0], 1e-5 * (1 + std::abs(b[0])));
  EXPECT_GT(std::abs(b[0]), 0.01);  // the spline's curvature is felt
}

TEST(CoordinateCouplerTest, SplineCouplingHoldsAndConservesEnergyAlongTheMotion) {
  const auto system = MakeSplineCoupled();
  const auto coupler = system->constraints().back();
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-9;
  engine::State state = engine::MakeDefaultState(*system);
  VecX phi(1);
  coupler->CalcPositionError(*system, state, phi);
  EXPECT_LT(std::abs(phi[0]), 1e-10);
  const double e0 = engine::CalcMechanicalEnergy(*system, state);
  auto integrator = engine::MakeIntegrator("rk45", *system, settings);
  double worst_phi = 0.0, worst_energy = 0.0, theta_min = 1.0;
  for (int k = 1; k <= 40; ++k) {
    integrator->StepTo(state, 0.05 * k);
    coupler->CalcPositionError(*system, state, phi);
    worst_phi = std::max(worst_phi, std::abs(phi[0]));
    worst_energy =
        std::max(worst_energy, std::abs(engine::CalcMechanicalEnergy(*system, state) - e0));
    theta_min = std::min(theta_min, state.q[0]);
  }
  // The coupler is workless: the energy changes only by the integration error, at most
  // accuracy x (energy scale ~ m g l = 5 J) per step.
  const double steps = static_cast<double>(integrator->stats().steps);
  EXPECT_LT(worst_phi, 1e-8);
  EXPECT_LT(worst_energy, steps * settings.accuracy * 5.0);
  EXPECT_LT(theta_min, 0.0);  // it swung through the bottom, across several spline knots
  std::cout << "spline coupler: residual " << worst_phi << ", energy drift " << worst_energy
            << " J over " << steps << " steps\n";
}

TEST(CoordinateCouplerTest, RefusesMismatchedArgumentsAndRepeatedCoordinates) {
  auto f = std::make_shared<functions::LinearFunction>(1.0, 0.0);
  EXPECT_THROW(CoordinateCouplerConstraint("c", {0, 1}, 2, f, 1.0), Error);
  EXPECT_THROW(CoordinateCouplerConstraint("c", {0}, 0, f, 1.0), Error);
  EXPECT_THROW(CoordinateCouplerConstraint("c", {0}, 1, nullptr, 1.0), Error);
}

}  // namespace
}  // namespace sinew::forces
