// OpenSim's StepFunction.
#pragma once

#include <sinew/functions/function.h>

namespace sinew::functions {

/// A smooth step from `start_value` to `end_value` as x goes from `transition_start_time` x0 to
/// `transition_end_time` x1 (OpenSim defaults 0.99, 1.01, 0, 1), as Simbody's Function::Step:
/// with s = (x - x0) / (x1 - x0),
///   f = y0 + (y1 - y0) * (10 s^3 - 15 s^4 + 6 s^5)   for s in (0, 1),
/// f = y0 before x0 and y1 after x1 (x0 > x1 is allowed: the step then runs backwards). The
/// first and second derivatives are continuous and vanish at both ends. x0 == x1 throws.
class StepFunction final : public Function {
 public:
  StepFunction(double transition_start_time, double transition_end_time, double start_value,
               double end_value);

  std::string TypeName() const override { return "StepFunction"; }
  double Calc(double x) const override { return CalcDerivative(x, 0); }
  double CalcDerivative(double x, int order) const override;

  double transition_start_time() const { return x0_; }
  double transition_end_time() const { return x1_; }
  double start_value() const { return y0_; }
  double end_value() const { return y1_; }

 private:
  double x0_, x1_, y0_, y1_;
};

}  // namespace sinew::functions
