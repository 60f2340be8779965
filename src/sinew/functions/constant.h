// OpenSim's Constant function.
#pragma once

#include <sinew/functions/function.h>

namespace sinew::functions {

/// f(x) = value for every x (OpenSim property `value`). Derivatives are 0. Takes any number of
/// arguments (OpenSim's Constant ignores them); NumArguments() reports `num_arguments`.
class Constant final : public Function {
 public:
  explicit Constant(double value, int num_arguments = 1)
      : value_(value), num_arguments_(num_arguments) {}

  std::string TypeName() const override { return "Constant"; }
  int NumArguments() const override { return num_arguments_; }
  double Calc(double /*x*/) const override { return value_; }
  double CalcDerivative(double x, int order) const override;
  double CalcN(std::span<const double> /*x*/) const override { return value_; }
  double CalcPartialN(std::span<const double> x, std::span<const int> wrt) const override;

  double value() const { return value_; }

 private:
  double value_;
  int num_arguments_;
};

}  // namespace sinew::functions
