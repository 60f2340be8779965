// The enforced CoordinateCouplerConstraints of a model applied to a set of coordinate values:
// each dependent coordinate takes the value scale_factor f(independent coordinates), as
// OpenSim's assembly gives it. Used wherever poses are made from coordinates that a table or
// the defaults give (kinematics, export, render), so coupler-driven bodies (Rajagopal's
// patellae) follow their drivers instead of staying at their defaults.
#pragma once

#include <sinew/functions/function.h>
#include <sinew/model/model_spec.h>

#include <span>
#include <vector>

namespace sinew::kinematics {

/// A model's enforced couplers, ordered so that a coupler driven by another's dependent
/// coordinate comes after it.
class CoordinateCouplers {
 public:
  /// Throws sinew::Error (file, line, constraint) for a cycle of couplers.
  explicit CoordinateCouplers(const model::ModelSpec& spec);

  /// Sets every dependent coordinate of `q` (ModelSpec::coordinates order) from its
  /// independent ones.
  void Apply(std::span<double> q) const;
  /// Sets every dependent coordinate's speed in `u` from its independent ones at `q` (the
  /// time derivative of Apply: u_d = scale_factor sum_i df/dq_i u_i). Both in
  /// ModelSpec::coordinates order; the speeds of coupled coordinates are their qdot.
  void ApplySpeeds(std::span<const double> q, std::span<double> u) const;
  /// Adds one row per coupler to `rows` (each of size num_coordinates): the velocity
  /// constraint row . u = 0 at `q`, i.e. u_d - scale_factor sum_i df/dq_i u_i = 0.
  void AppendVelocityRows(std::span<const double> q, std::vector<std::vector<double>>& rows) const;
  /// True when coordinate `c` is set by a coupler.
  bool Drives(int c) const;
  /// True when coordinate `c` is a coupler's dependent or one of its independent coordinates
  /// (it appears in AppendVelocityRows' rows).
  bool Involves(int c) const;
  bool empty() const { return couplers_.empty(); }

 private:
  struct Coupler {
    int dependent;
    std::vector<int> independent;
    functions::FunctionPtr function;
    double scale;
  };
  static std::vector<double> CalcSlopes(const Coupler& c, std::span<const double> q);
  std::vector<Coupler> couplers_;
};

}  // namespace sinew::kinematics
