// OpenSim's Function family: real functions of one (usually) or more arguments, with first and
// second derivatives. Immutable once built; shared by pointer between a model and its users.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace sinew::functions {

/// A real function y = f(x) (or f(x0, x1, ...)) with derivatives, named by its OpenSim class.
/// Single-argument functions implement Calc and CalcDerivative; multi-argument ones override
/// NumArguments, CalcN and CalcPartialN (whose defaults forward to the single-argument forms).
class Function {
 public:
  virtual ~Function() = default;

  /// The OpenSim class name, e.g. "SimmSpline", "LinearFunction".
  virtual std::string TypeName() const = 0;
  /// How many arguments the function takes (1 for most types).
  virtual int NumArguments() const { return 1; }

  /// f(x).
  virtual double Calc(double x) const = 0;
  /// d^order f / dx^order at x, for order 1 or 2 (0 gives f).
  virtual double CalcDerivative(double x, int order) const = 0;

  /// f(x0, x1, ...); x has NumArguments() entries.
  virtual double CalcN(std::span<const double> x) const { return Calc(x[0]); }
  /// The partial derivative of f by the arguments listed in `wrt` (one entry: first partial,
  /// two entries: second partial), as Simbody's calcDerivative(derivComponents, x).
  virtual double CalcPartialN(std::span<const double> x, std::span<const int> wrt) const {
    return CalcDerivative(x[0], static_cast<int>(wrt.size()));
  }

  /// The arguments (of a one-argument function), ascending, where its polynomial pieces meet
  /// with f and f' continuous but f'' or f''' jumping: a cubic spline's inner knots (f''') and
  /// its ends, past which it extrapolates linearly (f'', or f''' where the end is not curved). A
  /// coordinate crossing one makes the accelerations, or their rate of change, jump there; rk45
  /// ends a failing step at it (engine::System::breakpoints).
  virtual std::vector<double> Breakpoints() const { return {}; }
};

using FunctionPtr = std::shared_ptr<const Function>;

}  // namespace sinew::functions
