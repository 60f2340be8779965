// OpenSim's Sine function.
#pragma once

#include <sinew/functions/function.h>

namespace sinew::functions {

/// f(x) = amplitude * sin(omega * x + phase) + offset (OpenSim properties `amplitude`, `omega`
/// in rad per unit of x, `phase` in rad, `offset`; defaults 1, 1, 0, 0).
class Sine final : public Function {
 public:
  Sine(double amplitude = 1.0, double omega = 1.0, double phase = 0.0, double offset = 0.0)
      : amplitude_(amplitude), omega_(omega), phase_(phase), offset_(offset) {}

  std::string TypeName() const override { return "Sine"; }
  double Calc(double x) const override;
  double CalcDerivative(double x, int order) const override;

  double amplitude() const { return amplitude_; }
  double omega() const { return omega_; }
  double phase() const { return phase_; }
  double offset() const { return offset_; }

 private:
  double amplitude_, omega_, phase_, offset_;
};

}  // namespace sinew::functions
