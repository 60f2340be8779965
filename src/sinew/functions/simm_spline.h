// OpenSim's SimmSpline: the cubic spline of Forsythe, Malcolm & Moler.
#pragma once

#include <sinew/functions/function.h>

#include <vector>

namespace sinew::functions {

/// The interpolating cubic spline OpenSim uses for joint couplings and moving path points
/// (Forsythe, Malcolm & Moler, "Computer Methods for Mathematical Computations", 1977):
/// - end conditions: the third derivative at each end equals that of the cubic through the
///   first (last) four knots (built from divided differences), so cubic data are reproduced
///   exactly; with 3 knots the end rows make the spline the parabola through them; 2 knots
///   give the straight line;
/// - outside [x[0], x[n-1]] it extrapolates LINEARLY with the end slopes (second derivative 0
///   there), as OpenSim does;
/// - knot spacings below 1e-7 are raised to 1e-7 as in OpenSim (duplicate knots do not divide
///   by zero).
/// Within [x[k], x[k+1]]: f = y[k] + b[k] dx + c[k] dx^2 + d[k] dx^3, dx = x - x[k].
/// NaturalCubicSpline in old files is read as this class.
class SimmSpline final : public Function {
 public:
  /// Knots `x` (non-decreasing, >= 2 points) and values `y`; throws sinew::Error otherwise.
  SimmSpline(std::vector<double> x, std::vector<double> y);

  std::string TypeName() const override { return "SimmSpline"; }
  double Calc(double x) const override;
  double CalcDerivative(double x, int order) const override;
  /// Its inner knots and its ends (past which it extrapolates linearly); none for a line.
  std::vector<double> Breakpoints() const override;

  /// The knots and the data values, as given.
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  /// Polynomial coefficients per knot (see the class comment).
  const std::vector<double>& b() const { return b_; }
  const std::vector<double>& c() const { return c_; }
  const std::vector<double>& d() const { return d_; }

 private:
  void CalcCoefficients();

  std::vector<double> x_, y_, b_, c_, d_;
};

}  // namespace sinew::functions
