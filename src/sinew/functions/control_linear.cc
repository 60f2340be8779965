#include <sinew/common/error.h>
#include <sinew/functions/control_linear.h>

#include <algorithm>
#include <utility>

namespace sinew::functions {

ControlLinear::ControlLinear(std::vector<double> times, std::vector<double> values, bool use_steps,
                             bool extrapolate)
    : t_(std::move(times)),
      v_(std::move(values)),
      use_steps_(use_steps),
      extrapolate_(extrapolate) {
  if (t_.empty() || t_.size() != v_.size()) {
    throw Error("ControlLinear needs as many values as times, and at least one node");
  }
  for (size_t i = 1; i < t_.size(); ++i) {
    if (!(t_[i] > t_[i - 1])) throw Error("ControlLinear node times must increase");
  }
}

int ControlLinear::FindNode(double t) const {
  return static_cast<int>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1;
}

double ControlLinear::Slope(int a, int b) const { return (v_[b] - v_[a]) / (t_[b] - t_[a]); }

double ControlLinear::Line(int a, int b, double t) const {
  return v_[a] + Slope(a, b) * (t - t_[a]);
}

double ControlLinear::Calc(double t) const {
  const int n = static_cast<int>(t_.size());
  const int i = FindNode(t);
  // Steps are never extrapolated: they hold the end nodes' values (OpenSim's getControlValue).
  const bool extrapolate = extrapolate_ && !use_steps_;
  if (n == 1) return v_[0];
  if (i < 0) return extrapolate ? Line(0, 1, t) : v_[0];
  if (i >= n - 1) return extrapolate ? Line(n - 2, n - 1, t) : v_[n - 1];
  if (use_steps_) return t == t_[i] ? v_[i] : v_[i + 1];
  return Line(i, i + 1, t);
}

double ControlLinear::CalcDerivative(double t, int order) const {
  if (order == 0) return Calc(t);
  if (order != 1) return 0.0;
  const int n = static_cast<int>(t_.size());
  const int i = FindNode(t);
  const bool extrapolate = extrapolate_ && !use_steps_;
  if (n == 1) return 0.0;
  if (i < 0) return extrapolate ? Slope(0, 1) : 0.0;
  if (i >= n - 1) return extrapolate ? Slope(n - 2, n - 1) : 0.0;
  return use_steps_ ? 0.0 : Slope(i, i + 1);
}

}  // namespace sinew::functions
