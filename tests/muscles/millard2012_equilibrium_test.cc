// Millard2012EquilibriumMuscle's fiber velocity, forces, equilibrium and activation dynamics
// against the equations that define them, and its errors.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/muscles/millard2012_equilibrium.h>
#include <sinew/muscles/millard2012_spec.h>

#include <cmath>
#include <string>

namespace sinew::muscles {
namespace {

// A pennated muscle with OpenSim's default curves.
Millard2012Parameters Pennated() {
  Millard2012Parameters p;
  p.name = "/forceset/test_muscle";
  p.max_isometric_force = 1000.0;
  p.optimal_fiber_length = 0.1;
  p.tendon_slack_length = 0.2;
  p.pennation_angle_at_optimal = 0.3;
  return p;
}

TEST(Millard2012EquilibriumTest, DampedFiberVelocityBalancesFiberAndTendonForces) {
  const Millard2012Muscle m(Pennated());
  ASSERT_TRUE(m.uses_fiber_damping());
  const double fiso = 1000.0, beta = 0.1;
  // Away from equilibrium: a stretched tendon pulls the fiber out.
  for (double lce : {0.09, 0.1, 0.11}) {
    const Millard2012Dynamics d = CalcMillard2012Dynamics(m, 0.6, lce, 0.305, 0.0);
    const double fse = m.tendon_force_length().Value(d.norm_tendon_length);
    // a fal fv(v~) + fpe + beta v~ = fse / cos(phi), solved to OpenSim's 1e-10 Fiso.
    const double balance =
        0.6 * d.active_force_length_multiplier * m.force_velocity().Value(d.norm_fiber_velocity) +
        d.passive_force_length_multiplier + beta * d.norm_fiber_velocity;
    EXPECT_NEAR(fiso * balance * d.cos_pennation, fiso * fse, 1e-10 * fiso) << lce;
    EXPECT_DOUBLE_EQ(d.fiber_velocity, d.norm_fiber_velocity * 10.0 * 0.1);
    EXPECT_NEAR(d.tendon_force, d.fiber_force_along_tendon, 1e-10 * fiso);
    EXPECT_NEAR(d.passive_damping_fiber_force, fiso * beta * d.norm_fiber_velocity, 1e-12);
    // The fixed-width parallelogram: lce sin(phi) is the height, lce cos(phi) + tendon = path.
    EXPECT_NEAR(lce * d.sin_pennation, 0.1 * std::sin(0.3), 1e-15);
    EXPECT_NEAR(d.fiber_length_along_tendon + d.tendon_length, 0.305, 1e-15);
  }
}

TEST(Millard2012EquilibriumTest, UndampedFiberVelocityComesFromTheInverseCurve) {
  Millard2012Parameters p = Pennated();
  p.fiber_damping = 0.0;
  const Millard2012Muscle m(p);
  ASSERT_FALSE(m.uses_fiber_damping());
  // OpenSim's adjustments for the classic model: active-force-length floor 0.1, slopes at vmax
  // at least half those near vmax.
  EXPECT_EQ(m.parameters().active_force_length.minimum_value, 0.1);
  EXPECT_EQ(m.parameters().force_velocity.concentric_slope_at_vmax, 0.125);
  EXPECT_EQ(m.parameters().force_velocity.eccentric_slope_at_vmax, 0.075);
  EXPECT_EQ(m.adjustments().size(), 2u);  // the default floor is 0.1 already
  const Millard2012Dynamics d = CalcMillard2012Dynamics(m, 0.6, 0.1, 0.305, 0.0);
  const double fse = m.tendon_force_length().Value(d.norm_tendon_length);
  const double fv = (fse / d.cos_pennation - d.passive_force_length_multiplier) /
                    (0.6 * d.active_force_length_multiplier);
  EXPECT_NEAR(d.force_velocity_multiplier, fv, 1e-14);
  EXPECT_NEAR(m.force_velocity().Value(d.norm_fiber_velocity), fv, 1e-12);
  EXPECT_EQ(d.passive_damping_fiber_force, 0.0);
  // Minimum activation below 0.01 makes the classic model singular: refused.
  p.minimum_activation = 0.0;
  EXPECT_THROW(Millard2012Muscle{p}, Error);
}

TEST(Millard2012EquilibriumTest, RigidTendonFiberFollowsThePath) {
  Millard2012Parameters p = Pennated();
  p.ignore_tendon_compliance = true;
  const Millard2012Muscle m(p);
  const double height = 0.1 * std::sin(0.3);
  for (double path : {0.27, 0.3, 0.33}) {
    const double speed = -0.2;
    const Millard2012Dynamics d = CalcMillard2012Dynamics(m, 0.8, 0.0, path, speed);
    const double along = path - 0.2;
    EXPECT_NEAR(d.fiber_length, std::hypot(height, along), 1e-15);
    // d/dt sqrt(h^2 + (L - Ls)^2) = (L - Ls) / lce * dL/dt.
    EXPECT_NEAR(d.fiber_velocity, along / d.fiber_length * speed, 1e-15);
    EXPECT_NEAR(d.tendon_force, d.fiber_force * d.cos_pennation, 1e-12);
    EXPECT_EQ(d.tendon_length, 0.2 + (path - 0.2 - d.fiber_length_along_tendon));
    const Millard2012Equilibrium eq = SolveMillard2012Equilibrium(m, 0.8, path, 0.0);
    EXPECT_EQ(eq.fiber_length, CalcMillard2012Dynamics(m, 0.8, 0.0, path, 0.0).fiber_length);
  }
}

// A muscle at equilibrium stays there under constant activation: its fiber velocity is the
// damping of the solver's residual, and integrating it for 1 s (RK4, 1 ms) moves the fiber less
// than that velocity bound allows.
TEST(Millard2012EquilibriumTest, EquilibriumStaysPutUnderConstantActivation) {
  const Millard2012Muscle m(Pennated());
  const double fiso = 1000.0, a = 0.7, path = 0.3;
  const Millard2012Equilibrium eq = SolveMillard2012Equilibrium(m, a, path, 0.0);
  ASSERT_EQ(eq.status, Millard2012Equilibrium::Status::kConverged);
  EXPECT_LE(std::abs(eq.solution_error), 1e-8 * fiso);
  auto velocity = [&](double lce) {
    return CalcMillard2012Dynamics(m, a, lce, path, 0.0).fiber_velocity;
  };
  const Millard2012Dynamics d0 = CalcMillard2012Dynamics(m, a, eq.fiber_length, path, 0.0);
  // |v~| <= |residual| / (Fiso beta cos(phi)), since a fal fv' >= 0 adds to the damping.
  const double speed_bound =
      std::abs(eq.solution_error) / (fiso * 0.1 * d0.cos_pennation) * 10.0 * 0.1;
  EXPECT_LE(std::abs(d0.fiber_velocity), speed_bound * (1 + 1e-6) + 1e-15);
  double lce = eq.fiber_length;
  const double h = 1e-3;
  for (int step = 0; step < 1000; ++step) {
    const double k1 = velocity(lce), k2 = velocity(lce + 0.5 * h * k1);
    const double k3 = velocity(lce + 0.5 * h * k2), k4 = velocity(lce + h * k3);
    lce += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  EXPECT_LE(std::abs(lce - eq.fiber_length), speed_bound * 1.0 + 1e-15);
  EXPECT_EQ(CalcMillard2012ActivationDerivative(m, a, a), 0.0);
}

// The stored energies are potentials of the elastic forces: d(fiber energy)/d(lce) is the
// passive elastic fiber force and d(tendon energy)/d(tendon length) the tendon force (central
// differences, step 1e-7 m: truncation below 1e-6 N for these curves).
TEST(Millard2012EquilibriumTest, PotentialEnergiesArePotentialsOfTheElasticForces) {
  const Millard2012Muscle m(Pennated());
  const double h = 1e-7;
  for (double lce : {0.11, 0.13, 0.15}) {
    auto fiber_energy = [&](double l) {
      return CalcMillard2012PotentialEnergy(m, CalcMillard2012Dynamics(m, 0.5, l, 0.36, 0.0)).fiber;
    };
    const Millard2012Dynamics d = CalcMillard2012Dynamics(m, 0.5, lce, 0.36, 0.0);
    EXPECT_NEAR((fiber_energy(lce + h) - fiber_energy(lce - h)) / (2 * h),
                d.passive_elastic_fiber_force, 1e-6 * std::max(1.0, d.passive_elastic_fiber_force));
  }
  // The tendon's energy as a function of its length: move the path with the fiber fixed.
  for (double path : {0.3, 0.305, 0.31}) {
    auto tendon_energy = [&](double l) {
      return CalcMillard2012PotentialEnergy(m, CalcMillard2012Dynamics(m, 0.5, 0.1, l, 0.0)).tendon;
    };
    const Millard2012Dynamics d = CalcMillard2012Dynamics(m, 0.5, 0.1, path, 0.0);
    EXPECT_NEAR((tendon_energy(path + h) - tendon_energy(path - h)) / (2 * h), d.tendon_force,
                1e-6 * std::max(1.0, d.tendon_force));
  }
}

TEST(Millard2012EquilibriumTest, ActivationDynamicsUsesMillardsTimeConstants) {
  const Millard2012Muscle m(Pennated());  // 0.010 s and 0.040 s, minimum 0.01
  // Rising: tau = 0.010 (0.5 + 1.5 a); falling: tau = 0.040 / (0.5 + 1.5 a).
  EXPECT_NEAR(CalcMillard2012ActivationDerivative(m, 0.5, 1.0), 0.5 / (0.010 * 1.25), 1e-12);
  EXPECT_NEAR(CalcMillard2012ActivationDerivative(m, 0.5, 0.1), -0.4 / (0.040 / 1.25), 1e-12);
  // Below the minimum the activation is taken at the minimum.
  EXPECT_NEAR(CalcMillard2012ActivationDerivative(m, 0.0, 0.0), -0.01 / (0.040 / 0.515), 1e-12);
  EXPECT_EQ(m.ClampActivation(-1.0), 0.01);
  EXPECT_EQ(m.ClampActivation(2.0), 1.0);
}

TEST(Millard2012EquilibriumTest, NoEquilibriumAboveTheMinimumLeavesTheFiberThere) {
  // Undamped: the active-force-length floor (0.1) keeps the fiber pulling when the tendon is
  // slack, so no equilibrium exists above the minimum fiber length.
  Millard2012Parameters p = Pennated();
  p.fiber_damping = 0.0;
  const Millard2012Muscle m(p);
  const Millard2012Equilibrium eq = SolveMillard2012Equilibrium(m, 1.0, 0.21, 0.0);
  EXPECT_EQ(eq.status, Millard2012Equilibrium::Status::kFiberAtLowerBound);
  EXPECT_EQ(eq.fiber_length, m.minimum_fiber_length());
  EXPECT_EQ(eq.tendon_force, 0.0);
}

TEST(Millard2012EquilibriumTest, BadInputNamesTheMuscle) {
  const Millard2012Muscle m(Pennated());
  try {
    SolveMillard2012Equilibrium(m, 0.5, std::nan(""), 0.0);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/forceset/test_muscle"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("path length nan"), std::string::npos) << e.what();
  }
}

// A model file's spec (4.x format) as far as the muscle readers look at it.
model::ModelSpec ModelFile() {
  model::ModelSpec spec;
  spec.file = "model.osim";
  spec.version = 40000;
  return spec;
}

// A Millard2012EquilibriumMuscle element as the reader keeps it.
model::ForceSpec MuscleElement() {
  model::ForceSpec force;
  force.name = "vas";
  force.path = "/forceset/vas";
  force.type = "Millard2012EquilibriumMuscle";
  force.version = 40000;
  force.element.tag = force.type;
  force.element.line = 40;
  auto add = [](model::Element& parent, const std::string& tag, const std::string& text,
                int line) -> model::Element& {
    parent.children.push_back({tag, "", text, line, {}});
    return parent.children.back();
  };
  add(force.element, "max_isometric_force", "5000", 41);
  add(force.element, "optimal_fiber_length", "0.09", 42);
  add(force.element, "tendon_slack_length", "0.22", 43);
  add(force.element, "pennation_angle_at_optimal", "0.05", 44);
  model::Element& tendon = add(force.element, "TendonForceLengthCurve", "", 45);
  add(tendon, "strain_at_one_norm_force", "0.06", 46);
  add(tendon, "curviness", "", 47);  // empty: absent, as OpenSim writes unset optionals
  return force;
}

TEST(Millard2012SpecTest, ReadsPropertiesWithOpenSimsDefaults) {
  const Millard2012Muscle m = ReadMillard2012Muscle(ModelFile(), MuscleElement());
  const Millard2012Parameters& p = m.parameters();
  EXPECT_EQ(p.max_isometric_force, 5000.0);
  EXPECT_EQ(p.tendon_force_length.strain_at_one_norm_force, 0.06);
  EXPECT_FALSE(p.tendon_force_length.curviness.has_value());
  EXPECT_EQ(p.fiber_damping, 0.1);
  EXPECT_EQ(p.max_contraction_velocity, 10.0);
  EXPECT_EQ(p.minimum_activation, 0.01);
  EXPECT_FALSE(p.ignore_tendon_compliance);
  // The damped model's adjustment of the default active-force-length floor (0.1 -> 0).
  EXPECT_EQ(p.active_force_length.minimum_value, 0.0);
  EXPECT_NEAR(m.tendon_force_length().Value(1.06), 1.0, 1e-12);
}

// OpenSim drops a min_control of 0 from files older than format 30513 (it was written whatever
// the minimum activation); in newer files it is kept, and then below the default minimum
// activation 0.01 it is refused.
TEST(Millard2012SpecTest, OldFilesMinControlOfZeroIsDropped) {
  model::ForceSpec force = MuscleElement();
  force.element.children.push_back({"min_control", "", "0", 48, {}});
  force.version = 30000;
  EXPECT_FALSE(ReadMillard2012Parameters(ModelFile(), force).min_control.has_value());
  EXPECT_NO_THROW(ReadMillard2012Muscle(ModelFile(), force));
  force.version = 40000;
  EXPECT_EQ(ReadMillard2012Parameters(ModelFile(), force).min_control, 0.0);
  EXPECT_THROW(ReadMillard2012Muscle(ModelFile(), force), Error);
}

TEST(Millard2012SpecTest, BadPropertiesNameFileLineAndMuscle) {
  model::ForceSpec force = MuscleElement();
  force.element.children[4].children[1].text = "0.4";  // curviness without the other optionals
  try {
    ReadMillard2012Muscle(ModelFile(), force);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "model.osim");
    EXPECT_EQ(e.where().line, 40);
    EXPECT_EQ(e.component(), "/forceset/vas");
    EXPECT_NE(e.message().find("TendonForceLengthCurve"), std::string::npos) << e.what();
  }
  force = MuscleElement();
  force.element.children[1].text = "short";
  try {
    ReadMillard2012Muscle(ModelFile(), force);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 42);
    EXPECT_EQ(e.component(), "/forceset/vas");
  }
}

}  // namespace
}  // namespace sinew::muscles
