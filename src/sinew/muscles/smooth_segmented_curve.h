// OpenSim's SmoothSegmentedFunction: a C2-continuous curve y(x) made of quintic Bezier
// segments, extended linearly beyond its ends. Millard2012's muscle curves are built from it.
#pragma once

#include <array>
#include <vector>

namespace sinew::muscles {

/// One quintic Bezier segment in the plane: (x(u), y(u)) for u in [0, 1], from its six control
/// points. x(u) must increase with u (every curve built here satisfies that).
struct QuinticBezierSegment {
  std::array<double, 6> x{};
  std::array<double, 6> y{};
};

/// The segment OpenSim calls a quintic Bezier corner: from (x0, y0) with slope dydx0 to (x1, y1)
/// with slope dydx1, its control points pulled towards the intersection C of the two end
/// tangents by `curviness` in [0, 1] (points 1 and 2 at P0 + curviness (C - P0), points 3 and 4
/// at P1 + curviness (C - P1)). When the slopes are equal (within sqrt(machine epsilon)) C is
/// taken at the middle x. Throws sinew::Error when curviness is outside [0, 1] or when C does
/// not make a corner (it must be closer to each end than the ends are to each other).
QuinticBezierSegment MakeQuinticBezierCorner(double x0, double y0, double dydx0, double x1,
                                             double y1, double dydx1, double curviness);

/// OpenSim's mapping of a user curviness in [0, 1] to the corner's: 0.1 + 0.8 curviness.
double ScaleCurviness(double curviness);

/// A curve y(x) from consecutive Bezier segments (each starting where the previous ends), and the
/// straight lines that continue it: y0 + dydx0 (x - x0) left of x0, y1 + dydx1 (x - x1) right
/// of x1, as OpenSim extrapolates (its first derivative there is the end slope, its second 0).
class SmoothSegmentedCurve {
 public:
  /// An empty curve; evaluating it throws sinew::Error.
  SmoothSegmentedCurve() = default;
  /// `segments` in increasing x; x0/x1 are the ends of the Bezier part, y0/y1 and dydx0/dydx1
  /// the values and slopes the lines continue with. Throws sinew::Error for no segments or
  /// segments that do not join.
  SmoothSegmentedCurve(std::vector<QuinticBezierSegment> segments, double x0, double x1, double y0,
                       double y1, double dydx0, double dydx1);

  /// y(x).
  double Value(double x) const;
  /// dy/dx (order 1) or d2y/dx2 (order 2); order 0 is the value. Throws for other orders.
  double Derivative(double x, int order) const;
  /// The value and the first derivative at once (one parameter solve).
  struct ValueAndSlope {
    double value = 0.0;
    double slope = 0.0;
  };
  ValueAndSlope ValueAndDerivative(double x) const;
  /// The integral of y from x0 to x (negative for x < x0), exact within the Bezier part (Gauss
  /// quadrature of a degree-9 polynomial in u) and along the lines. OpenSim integrates
  /// numerically and fits a spline to the result, so its values differ in the last digits.
  double Integral(double x) const;

  double x0() const { return x0_; }
  double x1() const { return x1_; }
  const std::vector<QuinticBezierSegment>& segments() const { return segments_; }

 private:
  // The segment holding x (x0 <= x <= x1) and the parameter u at which its x(u) equals x.
  struct SegmentParameter {
    int segment = 0;
    double u = 0.0;
  };
  SegmentParameter Locate(double x) const;
  // Throws sinew::Error for a default-constructed (empty) curve.
  void CheckBuilt() const;
  // The integral of y dx over segment s from u = 0 to u.
  double SegmentIntegral(int s, double u) const;

  // A segment in monomial form (x(u) and y(u) as polynomials in u, evaluated by Horner's rule),
  // with u and du/dx tabulated at evenly spaced x for Newton's first guess (cubic Hermite
  // interpolation between them).
  static constexpr int kGuessPoints = 33;
  struct Polynomials {
    std::array<double, 6> x{}, y{};
    std::array<double, kGuessPoints> u_at_x{};
    std::array<double, kGuessPoints> du_dx{};  ///< 1 / x'(u) there (0 where x' vanishes)
  };

  std::vector<QuinticBezierSegment> segments_;
  std::vector<Polynomials> polynomials_;
  double x0_ = 0.0, x1_ = 0.0, y0_ = 0.0, y1_ = 0.0, dydx0_ = 0.0, dydx1_ = 0.0;
};

}  // namespace sinew::muscles
