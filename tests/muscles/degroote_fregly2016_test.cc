// DeGrooteFregly2016Muscle: the published curves' defining values (the paper normalizes
// fal(1) = fv(0) = 1 and fv(-1) = 0; OpenSim's strains put fpe and fT at 1 where they say),
// derivatives and integrals against finite differences and Simpson's rule, the explicit and
// implicit forms of the tendon dynamics against each other, equilibrium, activation dynamics.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/muscles/degroote_fregly2016_muscle.h>
#include <sinew/muscles/degroote_fregly2016_spec.h>

#include <cmath>
#include <functional>
#include <string>

namespace sinew::muscles {
namespace {

// Central difference of g at x with step 1e-6 (truncation h^2 g'''/6 below 1e-9 for these
// smooth exponentials, rounding about 1e-10).
double Slope(const std::function<double(double)>& g, double x) {
  const double h = 1e-6;
  return (g(x + h) - g(x - h)) / (2 * h);
}

// Simpson's rule over [a, b] with 20000 intervals: its error (b - a)^5 max g(4) / (180 n^4)
// stays below 1e-13 here (the passive curve's g(4) = (kPE / e0)^4 g reaches 1e5 at 1.8).
double Simpson(const std::function<double(double)>& g, double a, double b) {
  const int n = 20000;
  double sum = g(a) + g(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * g(a + (b - a) * i / n);
  return sum * (b - a) / (3.0 * n);
}

TEST(DeGrooteFregly2016CurvesTest, PublishedNormalizationsHold) {
  const DeGrooteFregly2016Curves c;  // OpenSim's defaults
  EXPECT_NEAR(c.ActiveForceLength(1.0), 1.0, 1e-15);
  EXPECT_NEAR(DeGrooteFregly2016Curves::ForceVelocity(0.0), 1.0, 1e-15);
  EXPECT_NEAR(DeGrooteFregly2016Curves::ForceVelocity(-1.0), 0.0, 1e-15);
  EXPECT_NEAR(c.PassiveForceLength(0.2), 0.0, 1e-16);
  EXPECT_NEAR(c.PassiveForceLength(1.6), 1.0, 1e-15);
  EXPECT_NEAR(c.TendonForceLength(1.0), 0.0, 1e-16);
  EXPECT_NEAR(c.TendonForceLength(1.049), 1.0, 1e-14);
  EXPECT_NEAR(c.tendon_stiffness_parameter(), std::log(6.0) / 0.049, 1e-12);
  // The width scale stretches the active curve about l~ = 1.
  const DeGrooteFregly2016Curves wide(2.0);
  EXPECT_NEAR(wide.ActiveForceLength(1.4), c.ActiveForceLength(1.2), 1e-15);
  const DeGrooteFregly2016Curves no_passive(1.0, 0.6, 0.049, true);
  EXPECT_EQ(no_passive.PassiveForceLength(1.5), 0.0);
  EXPECT_THROW(DeGrooteFregly2016Curves(0.5), Error);
}

TEST(DeGrooteFregly2016CurvesTest, DerivativesInversesAndIntegralsAgree) {
  const DeGrooteFregly2016Curves c(1.2, 0.5, 0.06);
  for (double l = 0.4; l <= 1.8; l += 0.01) {
    EXPECT_NEAR(c.ActiveForceLengthDerivative(l),
                Slope([&](double x) { return c.ActiveForceLength(x); }, l), 1e-8);
    EXPECT_NEAR(c.PassiveForceLengthDerivative(l),
                Slope([&](double x) { return c.PassiveForceLength(x); }, l), 1e-8);
    EXPECT_NEAR(c.PassiveForceLengthIntegral(l),
                Simpson([&](double x) { return c.PassiveForceLength(x); }, 0.2, l), 1e-12);
  }
  for (double v = -1.2; v <= 1.2; v += 0.01) {
    const double f = DeGrooteFregly2016Curves::ForceVelocity(v);
    EXPECT_NEAR(DeGrooteFregly2016Curves::ForceVelocityInverse(f), v, 1e-13);
    EXPECT_NEAR(DeGrooteFregly2016Curves::ForceVelocityDerivative(v),
                Slope(DeGrooteFregly2016Curves::ForceVelocity, v), 1e-8);
  }
  for (double lt = 0.98; lt <= 1.08; lt += 0.001) {
    const double f = c.TendonForceLength(lt);
    EXPECT_NEAR(c.TendonForceLengthInverse(f), lt, 1e-14);
    EXPECT_NEAR(c.TendonForceLengthDerivative(lt),
                Slope([&](double x) { return c.TendonForceLength(x); }, lt),
                1e-8 * c.TendonForceLengthDerivative(lt));
    EXPECT_NEAR(c.TendonForceLengthIntegral(lt),
                Simpson([&](double x) { return c.TendonForceLength(x); }, 1.0, lt), 1e-12);
  }
}

DeGrooteFregly2016Parameters Pennated() {
  DeGrooteFregly2016Parameters p;
  p.name = "/forceset/dg";
  p.max_isometric_force = 1000.0;
  p.optimal_fiber_length = 0.1;
  p.tendon_slack_length = 0.2;
  p.pennation_angle_at_optimal = 0.3;
  p.fiber_damping = 0.01;
  return p;
}

// The explicit form's state derivative, given to the implicit form, zeroes its residual: the
// two forms describe the same dynamics (without fiber damping; see the next test).
TEST(DeGrooteFregly2016MuscleTest, ExplicitAndImplicitFormsAgree) {
  DeGrooteFregly2016Parameters p = Pennated();
  p.fiber_damping = 0.0;
  const DeGrooteFregly2016Muscle m(p);
  for (double force : {0.2, 0.6, 1.1}) {
    for (double speed : {-0.3, 0.0, 0.2}) {
      const DeGrooteFregly2016Dynamics d =
          CalcDeGrooteFregly2016Dynamics(m, 0.7, force, 0.3, speed);
      // fT~ = (a fal fv + fpe + beta v~) cos(phi) holds by construction of the explicit form.
      EXPECT_NEAR(d.fiber_force_along_tendon / 1000.0, force, 1e-9);
      EXPECT_NEAR(CalcDeGrooteFregly2016EquilibriumResidual(
                      m, 0.7, force, d.norm_tendon_force_derivative, 0.3, speed),
                  0.0, 1e-12);
      // The parallelogram: constant width, fiber along tendon plus tendon equals the path.
      EXPECT_NEAR(d.fiber_length * d.sin_pennation, 0.1 * std::sin(0.3), 1e-15);
      EXPECT_NEAR(d.fiber_length_along_tendon + d.tendon_length, 0.3, 1e-15);
      EXPECT_NEAR(d.fiber_velocity_along_tendon + d.tendon_velocity, speed, 1e-14);
    }
  }
  EXPECT_THROW(CalcDeGrooteFregly2016Dynamics(m, 0.0, 0.5, 0.3, 0.0), Error);
}

// OpenSim's explicit form solves a fal fv + fpe = fT~ / cos(phi) for the velocity, leaving the
// fiber damping out, so with damping the fiber force along the tendon exceeds the tendon force
// by exactly the damping force along the tendon. Sinew reproduces that.
TEST(DeGrooteFregly2016MuscleTest, ExplicitFormLeavesFiberDampingOutAsOpenSimDoes) {
  const DeGrooteFregly2016Muscle m(Pennated());  // fiber_damping 0.01
  const DeGrooteFregly2016Dynamics d = CalcDeGrooteFregly2016Dynamics(m, 0.7, 0.6, 0.3, 0.1);
  EXPECT_NE(d.passive_damping_fiber_force, 0.0);
  EXPECT_NEAR(d.fiber_force_along_tendon - d.tendon_force,
              d.passive_damping_fiber_force * d.cos_pennation, 1e-10);
}

TEST(DeGrooteFregly2016MuscleTest, EquilibriumBalancesFiberAndTendon) {
  const DeGrooteFregly2016Muscle m(Pennated());
  for (double path : {0.28, 0.3, 0.31}) {
    const double force = SolveDeGrooteFregly2016Equilibrium(m, 0.8, path, 0.0);
    // Bisection to an interval of 1e-10 in normalized force: the residual is within that times
    // its slope (below 1 + fiber stiffness / tendon stiffness, about 2 here).
    EXPECT_NEAR(CalcDeGrooteFregly2016EquilibriumResidual(m, 0.8, force, 0.0, path, 0.0), 0.0,
                3e-10);
    // At equilibrium and rest the explicit form keeps the tendon force still: a residual r
    // moves fv by r / (cos a fal), the velocity by that over fv'(0), the tendon force at
    // fT~' vmax / (cos lts) per unit normalized fiber velocity.
    const DeGrooteFregly2016Dynamics d = CalcDeGrooteFregly2016Dynamics(m, 0.8, force, path, 0.0);
    const double fv_error = 3e-10 / (d.cos_pennation * 0.8 * d.active_force_length_multiplier);
    const double rate = fv_error / DeGrooteFregly2016Curves::ForceVelocityDerivative(0.0) * 1.0 /
                        (d.cos_pennation * 0.2) *
                        m.curves().TendonForceLengthDerivative(d.norm_tendon_length);
    EXPECT_NEAR(d.norm_tendon_force_derivative, 0.0, rate);
  }
  // A path too long for the tendon to hold within five times the maximum force.
  EXPECT_THROW(SolveDeGrooteFregly2016Equilibrium(m, 0.8, 1.0, 0.0), Error);
}

TEST(DeGrooteFregly2016MuscleTest, RigidTendonFiberFollowsThePath) {
  DeGrooteFregly2016Parameters p = Pennated();
  p.ignore_tendon_compliance = true;
  const DeGrooteFregly2016Muscle m(p);
  const DeGrooteFregly2016Dynamics d = CalcDeGrooteFregly2016Dynamics(m, 0.5, 0.0, 0.29, -0.1);
  EXPECT_NEAR(d.fiber_length, std::hypot(0.09, 0.1 * std::sin(0.3)), 1e-15);
  EXPECT_NEAR(d.fiber_velocity, 0.09 / d.fiber_length * -0.1, 1e-15);
  EXPECT_NEAR(d.tendon_force, d.fiber_force * d.cos_pennation, 1e-12);
  EXPECT_EQ(SolveDeGrooteFregly2016Equilibrium(m, 0.5, 0.29, 0.0), 0.0);
}

TEST(DeGrooteFregly2016MuscleTest, SteepSmoothingGivesFirstOrderActivation) {
  DeGrooteFregly2016Parameters p = Pennated();
  p.activation_dynamics_smoothing = 1e6;  // tanh becomes the sign
  const DeGrooteFregly2016Muscle steep(p);
  EXPECT_NEAR(CalcDeGrooteFregly2016ActivationDerivative(steep, 0.5, 1.0), 0.5 / (0.015 * 1.25),
              1e-9);
  EXPECT_NEAR(CalcDeGrooteFregly2016ActivationDerivative(steep, 0.5, 0.1), -0.4 * 1.25 / 0.060,
              1e-9);
  // The default smoothing (0.1) blends the two time constants: halfway at u = a.
  const DeGrooteFregly2016Muscle smooth(Pennated());
  const double a = 0.5, u = 0.5 + 1e-8;
  EXPECT_NEAR(CalcDeGrooteFregly2016ActivationDerivative(smooth, a, u) / (u - a),
              0.5 / (0.015 * 1.25) + 0.5 * 1.25 / 0.060, 1e-6);
}

model::ModelSpec ModelFile() {
  model::ModelSpec spec;
  spec.file = "m.osim";
  spec.version = 40000;
  return spec;
}

model::ForceSpec DeGrooteElement() {
  model::ForceSpec force;
  force.name = "dg";
  force.path = "/forceset/dg";
  force.type = "DeGrooteFregly2016Muscle";
  force.element.tag = force.type;
  force.element.line = 12;
  force.element.children = {{"max_isometric_force", "", "800", 13, {}},
                            {"optimal_fiber_length", "", "0.12", 14, {}},
                            {"tendon_slack_length", "", "0.3", 15, {}},
                            {"tendon_strain_at_one_norm_force", "", "0.04", 16, {}}};
  return force;
}

TEST(DeGrooteFregly2016SpecTest, ReadsPropertiesAndRefusesWhatOpenSimRefuses) {
  const DeGrooteFregly2016Muscle m = ReadDeGrooteFregly2016Muscle(ModelFile(), DeGrooteElement());
  EXPECT_EQ(m.parameters().max_isometric_force, 800.0);
  EXPECT_EQ(m.parameters().activation_time_constant, 0.015);
  EXPECT_EQ(m.parameters().passive_fiber_strain_at_one_norm_force, 0.6);
  EXPECT_NEAR(m.curves().TendonForceLength(1.04), 1.0, 1e-14);
  model::ForceSpec force = DeGrooteElement();
  force.element.children.push_back({"optimal_force", "", "2", 17, {}});
  EXPECT_THROW(ReadDeGrooteFregly2016Muscle(ModelFile(), force), Error);
  force = DeGrooteElement();
  force.element.children.push_back({"active_force_width_scale", "", "0.5", 18, {}});
  try {
    ReadDeGrooteFregly2016Muscle(ModelFile(), force);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "m.osim");
    EXPECT_EQ(e.where().line, 12);
    EXPECT_EQ(e.component(), "/forceset/dg");
    EXPECT_NE(e.message().find("active_force_width_scale"), std::string::npos);
  }
}

}  // namespace
}  // namespace sinew::muscles
