// The force interface against closed forms and conservation laws: auxiliary state variables z
// integrated under error control, inputs read at every evaluation (also from two threads
// sharing one System), the initialization hook, and the potential energy and power of a spring.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/controller.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/energy.h>
#include <sinew/engine/force_jacobian.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/pose.h>
#include <sinew/engine/projection.h>
#include <sinew/engine/system.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

using testing::Coord;
using testing::MakeBody;

// A first-order lag x' = (r - x) / tau towards its input r, pushing coordinate 0 with the
// generalized force k x. x starts at x0 unless `follow_q` (then at q of coordinate 0).
class Lag final : public ForceElement {
 public:
  Lag(std::string name, double tau, double k, double x0, bool follow_q = false)
      : name_(std::move(name)), tau_(tau), k_(k), x0_(x0), follow_q_(follow_q) {}
  std::string name() const override { return name_; }
  std::vector<std::string> StateVariableNames() const override { return {"x"}; }
  std::vector<std::string> InputNames() const override { return {"target"}; }
  void SetDefaultStateVariables(Eigen::Ref<VecX> z) const override { z[0] = x0_; }
  void InitializeStateVariables(const ForceContext& context, Eigen::Ref<VecX> z) const override {
    if (follow_q_) z[0] = context.state.q[0];
  }
  void CalcStateVariableDerivatives(const ForceContext& context,
                                    Eigen::Ref<VecX> zdot) const override {
    zdot[0] = (context.input(0) - context.z(0)) / tau_;
  }
  void AddLoads(const ForceContext& context, Loads& loads) const override {
    loads.AddGeneralizedForce(0, k_ * context.z(0));
  }

 private:
  std::string name_;
  double tau_, k_, x0_;
  bool follow_q_;
};

// A slider of mass 1 kg without gravity, starting at q = 0.1 m at rest, pushed by a Lag.
System MakeLaggedSlider(double tau, double k, double x0) {
  System system(Vec3::Zero());
  const int b = system.AddBody(MakeBody("block", 1.0, Vec3::Zero(), 0.1 * Mat3::Identity()));
  system.AddJoint("slider", 0, Transform::Identity(), b, Transform::Identity(),
                  JointForm::kParameterized, std::make_shared<testing::SliderModel>(),
                  {Coord("x", 0.1)});
  system.AddForceElement(std::make_shared<Lag>("lag", tau, k, x0));
  system.Finalize();
  return system;
}

// Closed forms for x' = (r - x) / tau, x(0) = x0, and q'' = k x, q(0) = q0, q'(0) = 0.
double LagValue(double t, double tau, double x0, double r) {
  return r + (x0 - r) * std::exp(-t / tau);
}
double LaggedPosition(double t, double tau, double k, double x0, double r, double q0) {
  return q0 + k * (0.5 * r * t * t + (x0 - r) * tau * (t - tau * (1.0 - std::exp(-t / tau))));
}

TEST(ForceInterfaceTest, StateVariablesAndInputsAreNamedAndLaidOut) {
  System system = MakeLaggedSlider(0.2, 3.0, 0.5);
  EXPECT_EQ(system.state_variable_names(), std::vector<std::string>{"lag/x"});
  EXPECT_EQ(system.input_names(), std::vector<std::string>{"lag/target"});
  EXPECT_EQ(system.FindStateVariable("lag/x"), 0);
  EXPECT_EQ(system.FindInput("lag/target"), 0);
  EXPECT_EQ(system.FindInput("lag/x"), -1);
  const State state = MakeDefaultState(system);
  ASSERT_EQ(state.z.size(), 1);
  EXPECT_EQ(state.z[0], 0.5);  // the element's default
  EXPECT_EQ(state.inputs, VecX::Zero(1));

  // Two elements that declare the same names cannot be told apart in a states file.
  System twice(Vec3::Zero());
  const int b = twice.AddBody(MakeBody("block", 1.0, Vec3::Zero(), Mat3::Identity()));
  twice.AddJoint("slider", 0, Transform::Identity(), b, Transform::Identity(),
                 JointForm::kParameterized, std::make_shared<testing::SliderModel>(), {Coord("x")});
  twice.AddForceElement(std::make_shared<Lag>("lag", 1, 1, 0));
  twice.AddForceElement(std::make_shared<Lag>("lag", 1, 1, 0));
  EXPECT_THROW(twice.Finalize(), Error);

  // A state of another layout is refused.
  State wrong = state;
  wrong.z.resize(0);
  EXPECT_THROW(CheckState(system, wrong), Error);
}

TEST(ForceInterfaceTest, StateVariableIsIntegratedUnderErrorControl) {
  const double tau = 0.2, k = 3.0, x0 = 0.5, r = -1.0, q0 = 0.1;
  const System system = MakeLaggedSlider(tau, k, x0);
  State state = MakeDefaultState(system);
  state.inputs[0] = r;  // held: no controller
  IntegratorSettings settings;
  settings.accuracy = 1e-10;
  auto integrator = MakeIntegrator("rk45", system, settings);
  double worst_x = 0.0, worst_q = 0.0;
  for (double t : {0.1, 0.3, 0.6, 1.0}) {
    integrator->StepTo(state, t);
    worst_x = std::max(worst_x, std::abs(state.z[0] - LagValue(t, tau, x0, r)));
    worst_q = std::max(worst_q, std::abs(state.q[0] - LaggedPosition(t, tau, k, x0, r, q0)));
  }
  // rk45 keeps each step's local error below accuracy (unit floor): the global error of the
  // contracting lag stays below steps x accuracy; q integrates it twice over at most 1 s.
  const double bound = static_cast<double>(integrator->stats().steps) * settings.accuracy;
  EXPECT_LT(worst_x, bound);
  EXPECT_LT(worst_q, 3.0 * bound);
  // The state variable is error-controlled: a looser accuracy must take fewer steps and
  // still stay within its own bound.
  State loose = MakeDefaultState(system);
  loose.inputs[0] = r;
  settings.accuracy = 1e-6;
  auto coarse = MakeIntegrator("rk45", system, settings);
  coarse->StepTo(loose, 1.0);
  EXPECT_LT(coarse->stats().steps, integrator->stats().steps);
  EXPECT_LT(std::abs(loose.z[0] - LagValue(1.0, tau, x0, r)),
            static_cast<double>(coarse->stats().steps) * settings.accuracy);
}

TEST(ForceInterfaceTest, CvodeIntegratesAStiffLagInFewSteps) {
  // tau = 0.1 ms against a 1 s run: stiff. rk45's stability interval on the negative real axis
  // ends near -3.3, so it cannot take steps longer than about 3.3 tau once the lag has settled
  // (>= 3,000 steps); the implicit BDF's steps are bounded by accuracy only.
  const double tau = 1e-4, k = 3.0, x0 = 0.5, r = -1.0, q0 = 0.1;
  const System system = MakeLaggedSlider(tau, k, x0);
  IntegratorSettings settings;
  settings.accuracy = 1e-8;
  State explicit_state = MakeDefaultState(system);
  explicit_state.inputs[0] = r;
  auto rk45 = MakeIntegrator("rk45", system, settings);
  rk45->StepTo(explicit_state, 1.0);
  EXPECT_GT(rk45->stats().steps, static_cast<long>(1.0 / (3.3 * tau)));
  for (const char* name : {"cvode", "cvode-gmres", "cvode-gmres-bd"}) {
    State state = MakeDefaultState(system);
    state.inputs[0] = r;
    auto integrator = MakeIntegrator(name, system, settings);
    double worst_x = 0.0, worst_q = 0.0;
    for (double t : {1e-4, 1e-3, 0.01, 0.1, 0.5}) {
      integrator->StepTo(state, t);
      worst_x = std::max(worst_x, std::abs(state.z[0] - LagValue(t, tau, x0, r)));
      worst_q = std::max(worst_q, std::abs(state.q[0] - LaggedPosition(t, tau, k, x0, r, q0)));
    }
    // One more step, then the dense output inside it (CVODE's interpolating polynomial).
    integrator->Advance(state, 1.0);
    const double t_end = state.t, t_mid = 0.5 * (0.5 + t_end);
    State mid = state;
    integrator->Interpolate(t_mid, mid);
    const double mid_q_error = std::abs(mid.q[0] - LaggedPosition(t_mid, tau, k, x0, r, q0));
    integrator->StepTo(state, 1.0);
    worst_x = std::max(worst_x, std::abs(state.z[0] - LagValue(1.0, tau, x0, r)));
    worst_q = std::max(worst_q, std::abs(state.q[0] - LaggedPosition(1.0, tau, k, x0, r, q0)));
    // CVODE keeps each step's local error estimate below accuracy in the RMS norm of its
    // 16-component vector (so a component's below 4 x accuracy, unit floor); global errors as
    // in the rk45 test above: steps x local error, q integrating x twice over at most 1 s.
    const long steps = integrator->stats().steps;
    const double bound = 4.0 * static_cast<double>(steps) * settings.accuracy;
    EXPECT_LT(worst_x, bound) << name;
    EXPECT_LT(worst_q, 3.0 * bound) << name;
    EXPECT_LT(mid_q_error, 3.0 * bound) << name;
    EXPECT_LT(steps, 300) << name;
    std::printf(
        "stiff lag over 1 s: %s %ld steps, %ld evaluations (x error %.2g, q %.2g); "
        "rk45 %ld steps, %ld evaluations\n",
        name, steps, integrator->stats().evaluations, worst_x, worst_q, rk45->stats().steps,
        rk45->stats().evaluations);
  }
}

TEST(ForceInterfaceTest, CvodeRestartsFromAStateChangedBetweenSteps) {
  // The input jumps from r1 to r2 at t1 (set in the state between two StepTo calls, no
  // controller): x follows the piecewise closed form, so cvode did not keep integrating the
  // old input from its own history.
  const double tau = 0.05, k = 1.0, x0 = 0.0, r1 = 1.0, r2 = -2.0, t1 = 0.3;
  const System system = MakeLaggedSlider(tau, k, x0);
  const double x1 = LagValue(t1, tau, x0, r1);
  for (const char* name : {"cvode", "cvode-gmres", "cvode-gmres-bd"}) {
    State state = MakeDefaultState(system);
    state.inputs[0] = r1;
    auto integrator = MakeIntegrator(name, system, {.accuracy = 1e-9});
    integrator->StepTo(state, t1);
    state.inputs[0] = r2;
    integrator->StepTo(state, 1.0);
    const double bound = 4.0 * static_cast<double>(integrator->stats().steps) * 1e-9;
    EXPECT_LT(std::abs(state.z[0] - LagValue(1.0 - t1, tau, x1, r2)), bound) << name;
  }
}

TEST(ForceInterfaceTest, FixedStepSchemesIntegrateStateVariablesToFirstOrder) {
  const double tau = 0.2, k = 3.0, x0 = 0.5, r = -1.0;
  const System system = MakeLaggedSlider(tau, k, x0);
  for (const char* name : {"euler", "implicit-euler"}) {
    double error[2];
    for (int i = 0; i < 2; ++i) {
      IntegratorSettings settings;
      settings.step = i == 0 ? 2e-3 : 1e-3;
      State state = MakeDefaultState(system);
      state.inputs[0] = r;
      MakeIntegrator(name, system, settings)->StepTo(state, 0.5);
      error[i] = std::abs(state.z[0] - LagValue(0.5, tau, x0, r));
    }
    // Explicit Euler in z: the error halves with the step.
    EXPECT_NEAR(error[0] / error[1], 2.0, 0.1) << name;
    EXPECT_LT(error[1], 1e-2) << name;
  }
}

TEST(ForceInterfaceTest, InitializationHookSetsStateVariablesFromTheState) {
  System system(Vec3::Zero());
  const int b = system.AddBody(MakeBody("block", 1.0, Vec3::Zero(), Mat3::Identity()));
  system.AddJoint("slider", 0, Transform::Identity(), b, Transform::Identity(),
                  JointForm::kParameterized, std::make_shared<testing::SliderModel>(),
                  {Coord("x", 0.25)});
  system.AddForceElement(std::make_shared<Lag>("follower", 1.0, 1.0, 9.0, true));
  system.Finalize();
  State state = MakeDefaultState(system);
  EXPECT_EQ(state.z[0], 0.25);  // from q, not the default 9
  SetCoordinateValue(system, state, "x", -0.75);
  InitializeStateVariables(system, state);
  EXPECT_EQ(state.z[0], -0.75);
}

// The controller r(t) = sin(w t).
class SineController final : public Controller {
 public:
  explicit SineController(double w) : w_(w) {}
  void CalcInputs(const System&, const State& state, Eigen::Ref<VecX> inputs) const override {
    inputs[0] = std::sin(w_ * state.t);
  }

 private:
  double w_;
};

TEST(ForceInterfaceTest, ControllerSetsInputsAtEveryEvaluation) {
  // A lag so fast it follows its input closely is not needed: with k = 1 and tau = 1 the
  // closed form of x' = sin(w t) - x, x(0) = 0 is
  //   x = (sin(w t) - w cos(w t) + w e^-t) / (1 + w^2).
  // Inputs held over a step instead of read per stage would be off by O(h) there.
  const double w = 5.0;
  const System system = MakeLaggedSlider(1.0, 1.0, 0.0);
  // rk45 bounds each component's local error by accuracy, cvode their RMS (4 x per component).
  for (const auto& [name, norm_factor] :
       {std::pair{"rk45", 1.0}, std::pair{"cvode", 4.0}, std::pair{"cvode-gmres", 4.0},
        std::pair{"cvode-gmres-bd", 4.0}}) {
    State state = MakeDefaultState(system);
    IntegratorSettings settings;
    settings.accuracy = 1e-10;
    auto integrator = MakeIntegrator(name, system, settings);
    integrator->SetController(std::make_shared<SineController>(w));
    integrator->StepTo(state, 1.0);
    const double exact = (std::sin(w) - w * std::cos(w) + w * std::exp(-1.0)) / (1 + w * w);
    EXPECT_LT(std::abs(state.z[0] - exact),
              norm_factor * static_cast<double>(integrator->stats().steps) * settings.accuracy)
        << name;
    EXPECT_EQ(state.inputs[0], std::sin(w * 1.0)) << name;  // the controller's value at the end
  }
}

TEST(ForceInterfaceTest, TwoThreadsShareOneSystemWithDifferentInputs) {
  const System system = MakeLaggedSlider(0.2, 3.0, 0.5);
  IntegratorSettings settings;
  settings.accuracy = 1e-9;
  auto run = [&](double r, State& out) {
    State state = MakeDefaultState(system);
    state.inputs[0] = r;
    MakeIntegrator("rk45", system, settings)->StepTo(state, 1.0);
    out = state;
  };
  State sequential[2], threaded[2];
  run(2.0, sequential[0]);
  run(-3.0, sequential[1]);
  std::thread a([&] { run(2.0, threaded[0]); });
  std::thread b([&] { run(-3.0, threaded[1]); });
  a.join();
  b.join();
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(threaded[i].q, sequential[i].q);
    EXPECT_EQ(threaded[i].u, sequential[i].u);
    EXPECT_EQ(threaded[i].z, sequential[i].z);
  }
  EXPECT_GT(std::abs(sequential[0].q[0] - sequential[1].q[0]), 0.1);  // inputs mattered
}

// A linear spring of stiffness k and rest length L0 between point p_BQ of body b and the
// ground point p_GP.
class Spring final : public ForceElement {
 public:
  Spring(int b, const Vec3& p_BQ, const Vec3& p_GP, double k, double L0)
      : b_(b), p_BQ_(p_BQ), p_GP_(p_GP), k_(k), L0_(L0) {}
  void AddLoads(const ForceContext& context, Loads& loads) const override {
    const Vec3 d = p_GP_ - PoseOf(context.state.bodies[b_]) * p_BQ_;  // from Q to P
    const double L = d.norm();
    loads.AddForceAtPoint(context.state, b_, p_BQ_, k_ * (L - L0_) * d / L);
  }
  double CalcPotentialEnergy(const ForceContext& context) const override {
    const double L = (p_GP_ - PoseOf(context.state.bodies[b_]) * p_BQ_).norm();
    return 0.5 * k_ * (L - L0_) * (L - L0_);
  }

 private:
  int b_;
  Vec3 p_BQ_, p_GP_;
  double k_, L0_;
};

// A pendulum (pin about z at the origin, rod 1 kg, mass centre 0.5 m below) tied by a spring
// from its tip to the ground point (0.6, -0.4, 0): gravity and the spring are both
// conservative.
System MakeSpringPendulum(JointForm form) {
  System system(Vec3(0, -9.80665, 0));
  const int rod = system.AddBody(MakeBody("rod", 1.0, Vec3(0, -0.5, 0), 0.02 * Mat3::Identity()));
  system.AddJoint("pin", 0, Transform::Identity(), rod, Transform::Identity(), form,
                  std::make_shared<testing::RevoluteModel>(Vec3::UnitZ()),
                  {Coord("angle", 0.9, 0.5)});
  system.AddForceElement(
      std::make_shared<Spring>(rod, Vec3(0, -1.0, 0), Vec3(0.6, -0.4, 0), 40.0, 0.2));
  system.Finalize();
  return system;
}

TEST(ForceInterfaceTest, SpringEnergyIsConservedWithItsPotential) {
  for (JointForm form : {JointForm::kParameterized, JointForm::kPin}) {
    const System system = MakeSpringPendulum(form);
    State state = MakeDefaultState(system);
    const double e0 = CalcMechanicalEnergy(system, state);
    const double v0 = CalcForcePotentialEnergy(system, state);
    IntegratorSettings settings;
    settings.accuracy = 1e-10;
    auto integrator = MakeIntegrator("rk45", system, settings);
    double drift = 0.0, swing = 0.0;
    for (int i = 1; i <= 20; ++i) {
      integrator->StepTo(state, 0.1 * i);
      drift = std::max(drift, std::abs(CalcMechanicalEnergy(system, state) - e0));
      swing = std::max(swing, std::abs(CalcForcePotentialEnergy(system, state) - v0));
    }
    // Energies of order 10 J; each step's local error is below 1e-10 of the unknowns.
    const double bound = 10.0 * static_cast<double>(integrator->stats().steps) * settings.accuracy;
    EXPECT_LT(drift, bound);
    EXPECT_GT(swing, 0.5);  // the spring's energy really changes: leaving it out would show
  }
}

TEST(ForceInterfaceTest, SpringPowerIsMinusTheRateOfItsPotential) {
  const System system = MakeSpringPendulum(JointForm::kParameterized);
  const State state = MakeDefaultState(system);
  KktSolver kkt(system);
  const VecX v = GatherVelocities(system, kkt, state);
  // dV/dt along the motion by a central difference of V over a displacement +-dt v.
  const double dt = 1e-6;
  State ahead = state, behind = state;
  ApplyPositionDisplacement(system, kkt, dt * v, ahead);
  ApplyPositionDisplacement(system, kkt, -dt * v, behind);
  const double rate =
      (CalcForcePotentialEnergy(system, ahead) - CalcForcePotentialEnergy(system, behind)) /
      (2 * dt);
  const double power = CalcForcePower(system, state, 0);
  EXPECT_GT(std::abs(power), 0.1);  // the spring does work here
  EXPECT_NEAR(power, -rate, 1e-6 * std::abs(power));
}

// Generalized spring-damper -k q - c u on coordinate `coordinate`, with its analytic Jacobian
// (K = -k, D = -c) unless `analytic` is false; with `declared` false it names no support.
class CoordinateSpringDamper final : public ForceElement {
 public:
  CoordinateSpringDamper(int coordinate, double k, double c, bool analytic, bool declared)
      : coordinate_(coordinate), k_(k), c_(c), analytic_(analytic), declared_(declared) {}
  void AddLoads(const ForceContext& context, Loads& loads) const override {
    loads.AddGeneralizedForce(
        coordinate_, -k_ * context.state.q[coordinate_] - c_ * context.state.u[coordinate_]);
  }
  std::optional<ForceSupport> Support() const override {
    if (!declared_) return std::nullopt;
    return ForceSupport{{}, {coordinate_}};
  }
  bool CalcLoadJacobians(const ForceContext&, Eigen::Ref<MatX> K,
                         Eigen::Ref<MatX> D) const override {
    if (!analytic_) return false;
    K(0, 0) = -k_;
    D(0, 0) = -c_;
    return true;
  }

 private:
  int coordinate_;
  double k_, c_;
  bool analytic_, declared_;
};

System MakeDampedSpringPendulum(bool analytic, bool declared) {
  System system(Vec3(0, -9.80665, 0));
  const int rod = system.AddBody(MakeBody("rod", 1.0, Vec3(0, -0.5, 0), 0.02 * Mat3::Identity()));
  system.AddJoint(
      "pin", 0, Transform::Identity(), rod, Transform::Identity(), JointForm::kParameterized,
      std::make_shared<testing::RevoluteModel>(Vec3::UnitZ()), {Coord("angle", 0.9, 0.5)});
  system.AddForceElement(
      std::make_shared<CoordinateSpringDamper>(0, 30.0, 0.7, analytic, declared));
  system.Finalize();
  return system;
}

TEST(ForceInterfaceTest, AnalyticJacobianBlocksEqualFiniteDifferences) {
  const System system = MakeDampedSpringPendulum(true, true);
  const State state = MakeDefaultState(system);
  KktSolver kkt(system);
  const std::vector<int> columns = CalcSupportColumns(system, kkt, 0);
  ASSERT_EQ(columns, std::vector<int>{kkt.SpeedColumn(0)});
  MatX K(1, 1), D(1, 1), K_fd, D_fd;
  ASSERT_TRUE(
      system.force_elements()[0]->CalcLoadJacobians(system.MakeForceContext(0, state), K, D));
  CalcForceJacobiansByFiniteDifference(system, kkt, state, 0, columns, K_fd, D_fd);
  // Central differences of a linear force: exact up to rounding of f / step (~1e-10).
  EXPECT_NEAR(K_fd(0, 0), K(0, 0), 1e-7 * 30.0);
  EXPECT_NEAR(D_fd(0, 0), D(0, 0), 1e-7 * 30.0);
}

TEST(ForceInterfaceTest, JacobiansFromSupportEqualThoseOverEveryUnknown) {
  // The same element, once with its support and analytic blocks, once with its support and
  // finite differences, once with no support (differenced over every unknown): the assembled
  // K and D agree; gravity's analytic block is in all three.
  MatX K[3], D[3];
  int i = 0;
  for (auto [analytic, declared] : {std::pair{true, true}, {false, true}, {false, false}}) {
    const System system = MakeDampedSpringPendulum(analytic, declared);
    const State state = MakeDefaultState(system);
    KktSolver kkt(system);
    CalcLoadJacobians(system, kkt, state, K[i], D[i]);
    ++i;
  }
  for (int j = 1; j < 3; ++j) {
    EXPECT_LT((K[j] - K[0]).lpNorm<Eigen::Infinity>(), 1e-6) << j;
    EXPECT_LT((D[j] - D[0]).lpNorm<Eigen::Infinity>(), 1e-6) << j;
  }
}

TEST(ForceInterfaceTest, GravityJacobianEqualsFiniteDifferencesOfTheLoads) {
  // A body hung off-centre, turned: gravity's torque about its origin changes with its
  // orientation, as the analytic block [f]x [c]x says.
  System system(Vec3(0, -9.80665, 0));
  const int b = system.AddBody(MakeBody("b", 2.0, Vec3(0.3, -0.4, 0.2), Mat3::Identity()));
  system.AddJoint("ball", 0, Transform::Identity(), b, Transform::Identity(), JointForm::kBall,
                  nullptr, {Coord("x", 0.3), Coord("y", -0.2), Coord("z", 0.5)});
  system.Finalize();
  const State state = MakeDefaultState(system);
  KktSolver kkt(system);
  MatX K, D;
  CalcLoadJacobians(system, kkt, state, K, D);
  const double step = 1e-6;
  for (int j = 0; j < 3; ++j) {
    Loads plus, minus;
    State moved = state;
    VecX dx = VecX::Zero(kkt.num_velocities());
    dx[kkt.BodyColumn(b) + j] = step;
    ApplyPositionDisplacement(system, kkt, dx, moved);
    CalcLoads(system, moved, nullptr, plus);
    moved = state;
    dx[kkt.BodyColumn(b) + j] = -step;
    ApplyPositionDisplacement(system, kkt, dx, moved);
    CalcLoads(system, moved, nullptr, minus);
    const SpatialVec column = (plus.body[b] - minus.body[b]) / (2 * step);
    EXPECT_LT((column - K.block<6, 1>(kkt.BodyColumn(b), kkt.BodyColumn(b) + j))
                  .lpNorm<Eigen::Infinity>(),
              1e-7 * 2.0 * 9.81)
        << "rotation about axis " << j;
  }
  EXPECT_GT(K.lpNorm<Eigen::Infinity>(), 1.0);  // the block is not trivially zero
  EXPECT_EQ(D.lpNorm<Eigen::Infinity>(), 0.0);  // gravity does not depend on velocities
}

}  // namespace
}  // namespace sinew::engine
