// OpenSim's MultiplierFunction.
#pragma once

#include <sinew/functions/function.h>

namespace sinew::functions {

/// f(x) = scale * g(x), where g is the inner function (OpenSim properties `function` and
/// `scale`). Scaled OpenSim models wrap most joint and path-point functions in these.
/// Has as many arguments as g.
class MultiplierFunction final : public Function {
 public:
  /// `function` must not be null (throws sinew::Error).
  MultiplierFunction(FunctionPtr function, double scale);

  std::string TypeName() const override { return "MultiplierFunction"; }
  int NumArguments() const override { return function_->NumArguments(); }
  double Calc(double x) const override { return scale_ * function_->Calc(x); }
  double CalcDerivative(double x, int order) const override {
    return scale_ * function_->CalcDerivative(x, order);
  }
  double CalcN(std::span<const double> x) const override { return scale_ * function_->CalcN(x); }
  double CalcPartialN(std::span<const double> x, std::span<const int> wrt) const override {
    return scale_ * function_->CalcPartialN(x, wrt);
  }
  std::vector<double> Breakpoints() const override { return function_->Breakpoints(); }

  const FunctionPtr& function() const { return function_; }
  double scale() const { return scale_; }

 private:
  FunctionPtr function_;
  double scale_;
};

}  // namespace sinew::functions
