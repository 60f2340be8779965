// OpenSim's LinearFunction.
#pragma once

#include <sinew/functions/function.h>

namespace sinew::functions {

/// f(x) = slope * x + intercept. OpenSim stores `coefficients` = [slope, intercept]; the default
/// (a missing property) is [1, 0], the identity.
class LinearFunction final : public Function {
 public:
  LinearFunction(double slope = 1.0, double intercept = 0.0)
      : slope_(slope), intercept_(intercept) {}

  std::string TypeName() const override { return "LinearFunction"; }
  double Calc(double x) const override { return slope_ * x + intercept_; }
  double CalcDerivative(double x, int order) const override;

  double slope() const { return slope_; }
  double intercept() const { return intercept_; }

 private:
  double slope_;
  double intercept_;
};

}  // namespace sinew::functions
