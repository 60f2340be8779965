// C++-only helpers for building excitation (control) signals u(t); they are not OpenSim classes
// and are never read from a file. Every OpenSim function type can be built from C++ as well,
// e.g. std::make_shared<SimmSpline>(times, values).
#pragma once

#include <sinew/functions/function.h>

#include <functional>

namespace sinew::functions {

/// A ramp starting at time `start` (s): u(t) = 0 for t < start and slope * (t - start) for
/// t >= start (`slope` in 1/s). The first derivative is 0 before `start` and `slope` from
/// `start` on (the right derivative at the kink); the second derivative is 0 everywhere.
/// Not clamped: combine with a MultiplierFunction or clamp downstream if u must stay <= 1.
class Ramp final : public Function {
 public:
  Ramp(double start, double slope) : start_(start), slope_(slope) {}

  std::string TypeName() const override { return "Ramp"; }
  double Calc(double t) const override;
  double CalcDerivative(double t, int order) const override;

  double start() const { return start_; }
  double slope() const { return slope_; }

 private:
  double start_, slope_;
};

/// u(t) = amplitude * sin(2 pi frequency_hz t + phase) + offset; `frequency_hz` in Hz (cycles
/// per second, not rad/s: compare Sine, whose omega is in rad/s), `phase` in rad.
class SineExcitation final : public Function {
 public:
  SineExcitation(double amplitude, double frequency_hz, double phase = 0.0, double offset = 0.0)
      : amplitude_(amplitude), frequency_hz_(frequency_hz), phase_(phase), offset_(offset) {}

  std::string TypeName() const override { return "SineExcitation"; }
  double Calc(double t) const override;
  double CalcDerivative(double t, int order) const override;

  double amplitude() const { return amplitude_; }
  double frequency_hz() const { return frequency_hz_; }
  double phase() const { return phase_; }
  double offset() const { return offset_; }

 private:
  double amplitude_, frequency_hz_, phase_, offset_;
};

/// Wraps any callable f(x). Derivatives are APPROXIMATED by central finite differences:
/// f' ~ (f(x+h1) - f(x-h1)) / (2 h1) with h1 = 6e-6 * max(1, |x|) and
/// f'' ~ (f(x+h2) - 2 f(x) + f(x-h2)) / h2^2 with h2 = 1.2e-4 * max(1, |x|)
/// (steps near the cube and fourth roots of machine epsilon: relative errors around 1e-10 and
/// 1e-7 for smooth f of unit scale). Near a kink or jump of f they are meaningless.
class CallableFunction final : public Function {
 public:
  /// `function` must be callable (throws sinew::Error otherwise); `name` is TypeName().
  explicit CallableFunction(std::function<double(double)> function,
                            std::string name = "CallableFunction");

  std::string TypeName() const override { return name_; }
  double Calc(double x) const override { return function_(x); }
  double CalcDerivative(double x, int order) const override;

 private:
  std::function<double(double)> function_;
  std::string name_;
};

}  // namespace sinew::functions

// The seed's spellings (ChFunction_Ramp and friends became sinew::Ramp, ...): programs written
// against the seed's API name these in namespace sinew.
namespace sinew {
using functions::CallableFunction;
using functions::Function;
using functions::FunctionPtr;
using functions::Ramp;
using functions::SineExcitation;
}  // namespace sinew
