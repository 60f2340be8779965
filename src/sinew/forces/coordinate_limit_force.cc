#include <sinew/common/error.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/state.h>
#include <sinew/forces/coordinate_limit_force.h>

#include <cmath>
#include <utility>

namespace sinew::forces {
namespace {

// Simbody's smooth step 10x^3 - 15x^4 + 6x^5 on [0, 1], 0 below, 1 above, and its derivative.
double Step(double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  return x * x * x * (10.0 + x * (-15.0 + 6.0 * x));
}
double StepDerivative(double x) {
  if (x <= 0.0 || x >= 1.0) return 0.0;
  return 30.0 * x * x * (1.0 - x) * (1.0 - x);
}

// Energy stored at penetration `depth` (>= 0) into a limit of stiffness K with band dq.
double LimitEnergy(double K, double depth, double dq) {
  if (depth >= dq) return K * (0.5 * depth * depth - dq * dq / 7.0);
  const double x = depth / dq;
  return K * x * x * x * (2.0 - 2.5 * x + (6.0 / 7.0) * x * x) * depth * depth;
}

}  // namespace

CoordinateLimitForce::CoordinateLimitForce(std::string name, int coordinate, bool rotational,
                                           const CoordinateLimitParameters& p)
    : name_(std::move(name)), coordinate_(coordinate) {
  const double w = rotational ? M_PI / 180.0 : 1.0;
  if (!(p.transition > 0.0)) throw Error(SourceLocation{}, name_, "transition must be > 0");
  if (p.upper_stiffness < 0.0 || p.lower_stiffness < 0.0 || p.damping < 0.0) {
    throw Error(SourceLocation{}, name_, "stiffnesses and damping must be >= 0");
  }
  q_up_ = w * p.upper_limit;
  q_lo_ = w * p.lower_limit;
  dq_ = w * p.transition;
  k_up_ = p.upper_stiffness / w;
  k_lo_ = p.lower_stiffness / w;
  c_ = p.damping / w;
}

CoordinateLimitForce::Stiffness CoordinateLimitForce::CalcStiffness(double q) const {
  const double x_up = (q - q_up_) / dq_, x_lo = (q_lo_ - q) / dq_;
  return {k_up_ * Step(x_up), k_lo_ * Step(x_lo), k_up_ * StepDerivative(x_up) / dq_,
          -k_lo_ * StepDerivative(x_lo) / dq_};
}

double CoordinateLimitForce::DampingFactor(const Stiffness& k) const {
  return c_ * ((k_up_ > 0.0 ? k.up / k_up_ : 0.0) + (k_lo_ > 0.0 ? k.lo / k_lo_ : 0.0));
}

double CoordinateLimitForce::DampingFactorDerivative(const Stiffness& k) const {
  return c_ * ((k_up_ > 0.0 ? k.dup / k_up_ : 0.0) + (k_lo_ > 0.0 ? k.dlo / k_lo_ : 0.0));
}

double CoordinateLimitForce::CalcForce(double q, double u) const {
  const Stiffness k = CalcStiffness(q);
  return -k.up * (q - q_up_) + k.lo * (q_lo_ - q) - DampingFactor(k) * u;
}

double CoordinateLimitForce::CalcPotentialEnergy(double q) const {
  if (q > q_up_) return LimitEnergy(k_up_, q - q_up_, dq_);
  if (q < q_lo_) return LimitEnergy(k_lo_, q_lo_ - q, dq_);
  return 0.0;
}

void CoordinateLimitForce::AddLoads(const engine::ForceContext& context,
                                    engine::Loads& loads) const {
  const engine::State& s = context.state;
  loads.AddGeneralizedForce(coordinate_, CalcForce(s.q[coordinate_], s.u[coordinate_]));
}

std::vector<std::string> CoordinateLimitForce::RecordLabels(
    const engine::System& /*system*/) const {
  return {name_, "PotentialEnergy"};
}

void CoordinateLimitForce::CalcRecordValues(const engine::ForceContext& context,
                                            std::vector<double>& values) const {
  const engine::State& s = context.state;
  values.push_back(CalcForce(s.q[coordinate_], s.u[coordinate_]));
  values.push_back(CalcPotentialEnergy(s.q[coordinate_]));
}

std::optional<engine::ForceSupport> CoordinateLimitForce::Support() const {
  return engine::ForceSupport{{}, {coordinate_}};
}

bool CoordinateLimitForce::CalcLoadJacobians(const engine::ForceContext& context,
                                             Eigen::Ref<MatX> K, Eigen::Ref<MatX> D) const {
  const double q = context.state.q[coordinate_], u = context.state.u[coordinate_];
  const Stiffness k = CalcStiffness(q);
  K(0, 0) =
      -k.dup * (q - q_up_) - k.up + k.dlo * (q_lo_ - q) - k.lo - DampingFactorDerivative(k) * u;
  D(0, 0) = -DampingFactor(k);
  return true;
}

double CoordinateLimitForce::CalcPotentialEnergy(const engine::ForceContext& context) const {
  return CalcPotentialEnergy(context.state.q[coordinate_]);
}

}  // namespace sinew::forces
