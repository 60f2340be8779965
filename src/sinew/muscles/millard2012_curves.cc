// Each curve below places the same corner points, slopes and curvinesses as OpenSim's
// SmoothSegmentedFunctionFactory for the same properties, and checks the same conditions.
#include <sinew/common/error.h>
#include <sinew/muscles/millard2012_curves.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

namespace sinew::muscles {

namespace {

// Throws sinew::Error "<curve>: <what>" when `holds` is false.
void Require(bool holds, const char* curve, const std::string& what) {
  if (!holds) throw Error(std::string(curve) + ": " + what);
}

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", value);
  return text;
}

// The curve through the given corners, continued by lines with the end slopes.
SmoothSegmentedCurve Join(std::vector<QuinticBezierSegment> segments, double dydx0, double dydx1) {
  const double x0 = segments.front().x[0], y0 = segments.front().y[0];
  const double x1 = segments.back().x[5], y1 = segments.back().y[5];
  return SmoothSegmentedCurve(std::move(segments), x0, x1, y0, y1, dydx0, dydx1);
}

// The four corners of the force-velocity curve, x the normalized velocity: (-1, 0), the point
// near concentric vmax (x = -0.9), (0, 1), near eccentric vmax (x = 0.9), (1, fmaxE).
std::vector<QuinticBezierSegment> ForceVelocityCorners(const ForceVelocityCurveParameters& p) {
  const double c_conc = ScaleCurviness(p.concentric_curviness);
  const double c_ecc = ScaleCurviness(p.eccentric_curviness);
  const double fmax = p.max_eccentric_velocity_force_multiplier;
  const double x_near_c = -0.9;
  const double y_near_c =
      0.5 * (p.concentric_slope_near_vmax + p.concentric_slope_at_vmax) * (x_near_c + 1.0);
  const double x_near_e = 0.9;
  const double y_near_e =
      fmax + 0.5 * (p.eccentric_slope_near_vmax + p.eccentric_slope_at_vmax) * (x_near_e - 1.0);
  return {MakeQuinticBezierCorner(-1.0, 0.0, p.concentric_slope_at_vmax, x_near_c, y_near_c,
                                  p.concentric_slope_near_vmax, c_conc),
          MakeQuinticBezierCorner(x_near_c, y_near_c, p.concentric_slope_near_vmax, 0.0, 1.0,
                                  p.isometric_slope, c_conc),
          MakeQuinticBezierCorner(0.0, 1.0, p.isometric_slope, x_near_e, y_near_e,
                                  p.eccentric_slope_near_vmax, c_ecc),
          MakeQuinticBezierCorner(x_near_e, y_near_e, p.eccentric_slope_near_vmax, 1.0, fmax,
                                  p.eccentric_slope_at_vmax, c_ecc)};
}

void CheckForceVelocityShape(const ForceVelocityCurveParameters& p, const char* curve) {
  const double fmax = p.max_eccentric_velocity_force_multiplier;
  Require(fmax > 1.0, curve, "max_eccentric_velocity_force_multiplier must be greater than 1");
  Require(p.concentric_slope_near_vmax > p.concentric_slope_at_vmax &&
              p.concentric_slope_near_vmax <= 1.0,
          curve, "concentric_slope_near_vmax must exceed concentric_slope_at_vmax and be <= 1");
  Require(p.concentric_slope_at_vmax >= 0.0 && p.concentric_slope_at_vmax < 1.0, curve,
          "concentric_slope_at_vmax must be in [0, 1)");
  Require(p.isometric_slope > 1.0, curve, "isometric_slope must be greater than 1");
  Require(p.eccentric_slope_at_vmax >= 0.0 && p.eccentric_slope_at_vmax < fmax - 1.0, curve,
          "eccentric_slope_at_vmax must be in [0, " + Number(fmax - 1.0) + ")");
  Require(
      p.eccentric_slope_near_vmax >= p.eccentric_slope_at_vmax &&
          p.eccentric_slope_near_vmax < fmax - 1.0,
      curve,
      "eccentric_slope_near_vmax must be in [eccentric_slope_at_vmax, " + Number(fmax - 1.0) + ")");
  Require(p.concentric_curviness >= 0.0 && p.concentric_curviness <= 1.0, curve,
          "concentric_curviness must be in [0, 1]");
  Require(p.eccentric_curviness >= 0.0 && p.eccentric_curviness <= 1.0, curve,
          "eccentric_curviness must be in [0, 1]");
}

// The optional properties of a curve are all given or all absent (OpenSim refuses a mix).
template <typename... Optionals>
bool AllGiven(const char* curve, const char* names, const Optionals&... optionals) {
  const int given = (static_cast<int>(optionals.has_value()) + ...);
  Require(given == 0 || given == static_cast<int>(sizeof...(optionals)), curve,
          std::string("the optional properties ") + names +
              " must either all be given or all be absent");
  return given > 0;
}

}  // namespace

SmoothSegmentedCurve MakeActiveForceLengthCurve(const ActiveForceLengthCurveParameters& p) {
  constexpr const char* kCurve = "ActiveForceLengthCurve";
  const double x0 = p.min_norm_active_fiber_length, x1 = p.transition_norm_fiber_length;
  const double x2 = 1.0, x3 = p.max_norm_active_fiber_length;
  const double ylow = p.minimum_value, dydx = p.shallow_ascending_slope;
  const double root_eps = std::sqrt(std::numeric_limits<double>::epsilon());
  Require(x0 >= 0.0 && x1 > x0 + root_eps && x2 > x1 + root_eps && x3 > x2 + root_eps, kCurve,
          "need 0 <= min_norm_active_fiber_length < transition_norm_fiber_length < 1 < "
          "max_norm_active_fiber_length");
  Require(ylow >= 0.0, kCurve, "minimum_value must be >= 0");
  const double slope_bound = (1.0 - ylow) / (x2 - x1);
  Require(dydx >= 0.0 && dydx < slope_bound, kCurve,
          "shallow_ascending_slope must be in [0, " + Number(slope_bound) + ")");
  const double c = ScaleCurviness(1.0);
  // Corners: the start of the ascending limb, its middle, the shallow ascent (ending half a
  // sarcomere width, 0.05, before the plateau), the plateau at 1, the descending limb's middle.
  const double x_delta = 0.05 * x2;
  const double xs = x2 - x_delta;
  const double y1 = 1.0 - dydx * (xs - x1);
  const double dydx01 = 1.25 * y1 / (x1 - x0);
  const double x01 = x0 + 0.5 * (x1 - x0), y01 = 0.5 * y1;
  const double x1s = x1 + 0.5 * (xs - x1), y1s = y1 + 0.5 * (1.0 - y1);
  const double x23 = (x2 + x_delta) + 0.5 * (x3 - (x2 + x_delta)), y23 = 0.5;
  const double dydx23 = -1.0 / ((x3 - x_delta) - (x2 + x_delta));
  return Join({MakeQuinticBezierCorner(x0, ylow, 0.0, x01, y01, dydx01, c),
               MakeQuinticBezierCorner(x01, y01, dydx01, x1s, y1s, dydx, c),
               MakeQuinticBezierCorner(x1s, y1s, dydx, x2, 1.0, 0.0, c),
               MakeQuinticBezierCorner(x2, 1.0, 0.0, x23, y23, dydx23, c),
               MakeQuinticBezierCorner(x23, y23, dydx23, x3, ylow, 0.0, c)},
              0.0, 0.0);
}

SmoothSegmentedCurve MakeForceVelocityCurve(const ForceVelocityCurveParameters& p) {
  CheckForceVelocityShape(p, "ForceVelocityCurve");
  return Join(ForceVelocityCorners(p), p.concentric_slope_at_vmax, p.eccentric_slope_at_vmax);
}

ForceVelocityCurveParameters DefaultForceVelocityInverseCurveParameters() {
  ForceVelocityCurveParameters p;
  p.concentric_slope_at_vmax = 0.1;
  p.eccentric_slope_at_vmax = 0.1;
  return p;
}

SmoothSegmentedCurve MakeForceVelocityInverseCurve(const ForceVelocityCurveParameters& p) {
  constexpr const char* kCurve = "ForceVelocityInverseCurve";
  CheckForceVelocityShape(p, kCurve);
  Require(p.concentric_slope_at_vmax > 0.0 && p.eccentric_slope_at_vmax > 0.0, kCurve,
          "the slopes at vmax must be greater than 0 for the curve to be invertible");
  std::vector<QuinticBezierSegment> segments = ForceVelocityCorners(p);
  for (QuinticBezierSegment& s : segments) std::swap(s.x, s.y);
  return Join(std::move(segments), 1.0 / p.concentric_slope_at_vmax,
              1.0 / p.eccentric_slope_at_vmax);
}

SmoothSegmentedCurve MakeFiberForceLengthCurve(const FiberForceLengthCurveParameters& p) {
  constexpr const char* kCurve = "FiberForceLengthCurve";
  const double e0 = p.strain_at_zero_force, e1 = p.strain_at_one_norm_force;
  Require(e1 > e0, kCurve, "strain_at_one_norm_force must exceed strain_at_zero_force");
  const bool given =
      AllGiven(kCurve, "stiffness_at_low_force, stiffness_at_one_norm_force and curviness",
               p.stiffness_at_low_force, p.stiffness_at_one_norm_force, p.curviness);
  const double k_iso = given ? *p.stiffness_at_one_norm_force : 2.0 / (e1 - e0);
  const double k_low = given ? *p.stiffness_at_low_force : 0.2;
  const double curviness = given ? *p.curviness : 0.75;
  Require(k_iso > 1.0 / (e1 - e0), kCurve,
          "stiffness_at_one_norm_force must exceed " + Number(1.0 / (e1 - e0)));
  Require(k_low > 0.0 && k_low < 1.0 / (e1 - e0), kCurve,
          "stiffness_at_low_force must be in (0, " + Number(1.0 / (e1 - e0)) + ")");
  Require(curviness >= 0.0 && curviness <= 1.0, kCurve, "curviness must be in [0, 1]");
  const double c = ScaleCurviness(curviness);
  const double x_zero = 1.0 + e0, x_iso = 1.0 + e1;
  const double delta_x = std::min(0.1 / k_iso, 0.1 * (x_iso - x_zero));
  const double x_low = x_zero + delta_x;
  const double x_foot = x_zero + 0.5 * (x_low - x_zero);
  const double y_low = k_low * (x_low - x_foot);
  return Join({MakeQuinticBezierCorner(x_zero, 0.0, 0.0, x_low, y_low, k_low, c),
               MakeQuinticBezierCorner(x_low, y_low, k_low, x_iso, 1.0, k_iso, c)},
              0.0, k_iso);
}

SmoothSegmentedCurve MakeTendonForceLengthCurve(const TendonForceLengthCurveParameters& p) {
  constexpr const char* kCurve = "TendonForceLengthCurve";
  const double e_iso = p.strain_at_one_norm_force;
  Require(e_iso > 0.0, kCurve, "strain_at_one_norm_force must be greater than 0");
  const bool given =
      AllGiven(kCurve, "stiffness_at_one_norm_force, norm_force_at_toe_end and curviness",
               p.stiffness_at_one_norm_force, p.norm_force_at_toe_end, p.curviness);
  const double k_iso = given ? *p.stiffness_at_one_norm_force : 1.375 / e_iso;
  const double f_toe = given ? *p.norm_force_at_toe_end : 2.0 / 3.0;
  const double curviness = given ? *p.curviness : 0.5;
  Require(f_toe > 0.0 && f_toe < 1.0, kCurve, "norm_force_at_toe_end must be in (0, 1)");
  Require(k_iso > 1.0 / e_iso, kCurve,
          "stiffness_at_one_norm_force must exceed 1/strain_at_one_norm_force (" +
              Number(1.0 / e_iso) + ")");
  Require(curviness >= 0.0 && curviness <= 1.0, kCurve, "curviness must be in [0, 1]");
  const double c = ScaleCurviness(curviness);
  // The toe ends where the linear part (slope k_iso through (1 + e_iso, 1)) reaches f_toe.
  const double x_iso = 1.0 + e_iso;
  const double x_toe = (f_toe - 1.0) / k_iso + x_iso;
  const double x_foot = 1.0 + (x_toe - 1.0) / 10.0;
  const double y_toe_mid = 0.5 * f_toe;
  const double x_toe_mid = (y_toe_mid - 1.0) / k_iso + x_iso;
  const double dydx_toe_mid = y_toe_mid / (x_toe_mid - x_foot);
  const double x_toe_ctrl = x_foot + 0.5 * (x_toe_mid - x_foot);
  const double y_toe_ctrl = dydx_toe_mid * (x_toe_ctrl - x_foot);
  return Join(
      {MakeQuinticBezierCorner(1.0, 0.0, 0.0, x_toe_ctrl, y_toe_ctrl, dydx_toe_mid, c),
       MakeQuinticBezierCorner(x_toe_ctrl, y_toe_ctrl, dydx_toe_mid, x_toe, f_toe, k_iso, c)},
      0.0, k_iso);
}

SmoothSegmentedCurve MakeFiberCompressiveForceLengthCurve(
    const FiberCompressiveForceLengthCurveParameters& p) {
  constexpr const char* kCurve = "FiberCompressiveForceLengthCurve";
  const double l_max = p.norm_length_at_zero_force;
  Require(l_max > 0.0, kCurve, "norm_length_at_zero_force must be greater than 0");
  const bool given = AllGiven(kCurve, "stiffness_at_zero_length and curviness",
                              p.stiffness_at_zero_length, p.curviness);
  const double k = given ? *p.stiffness_at_zero_length : -2.0 / l_max;
  const double curviness = given ? *p.curviness : 0.5;
  Require(k < -1.0 / l_max, kCurve,
          "stiffness_at_zero_length must be less than " + Number(-1.0 / l_max));
  Require(curviness >= 0.0 && curviness <= 1.0, kCurve, "curviness must be in [0, 1]");
  return Join({MakeQuinticBezierCorner(0.0, 1.0, k, l_max, 0.0, 0.0, ScaleCurviness(curviness))}, k,
              0.0);
}

SmoothSegmentedCurve MakeFiberCompressiveForceCosPennationCurve(
    const FiberCompressiveForceCosPennationCurveParameters& p) {
  constexpr const char* kCurve = "FiberCompressiveForceCosPennationCurve";
  const double cos_phi0 = std::cos(p.engagement_angle_in_degrees * std::numbers::pi / 180.0);
  Require(cos_phi0 > 0.0 && cos_phi0 < 1.0, kCurve,
          "engagement_angle_in_degrees must be in (0, 90)");
  const bool given = AllGiven(kCurve, "stiffness_at_perpendicular and curviness",
                              p.stiffness_at_perpendicular, p.curviness);
  const double k = given ? *p.stiffness_at_perpendicular : -2.0 / cos_phi0;
  const double curviness = given ? *p.curviness : 0.1;
  Require(k < -1.0 / cos_phi0, kCurve,
          "stiffness_at_perpendicular must be less than " + Number(-1.0 / cos_phi0));
  Require(curviness >= 0.0 && curviness <= 1.0, kCurve, "curviness must be in [0, 1]");
  return Join({MakeQuinticBezierCorner(0.0, 1.0, k, cos_phi0, 0.0, 0.0, ScaleCurviness(curviness))},
              k, 0.0);
}

}  // namespace sinew::muscles
