// OpenSim's ControlLinear: a control curve through (time, value) nodes, as stored in ControlSet
// files (e.g. the Static Optimization controls that drive a forward simulation).
#pragma once

#include <sinew/functions/function.h>

#include <vector>

namespace sinew::functions {

/// Control value of time through nodes (t_i, v_i), t strictly increasing.
/// Between nodes: linear interpolation, or with `use_steps` the value of the next node
/// (the one at or after t). Outside the nodes: with `extrapolate` (and not `use_steps`) the line
/// through the two end nodes, else the end node's value, as OpenSim's ControlLinear.
class ControlLinear : public Function {
 public:
  ControlLinear(std::vector<double> times, std::vector<double> values, bool use_steps,
                bool extrapolate);

  std::string TypeName() const override { return "ControlLinear"; }
  double Calc(double t) const override;
  /// Slope of the piece at t (0 for steps and held ends); second derivative 0.
  double CalcDerivative(double t, int order) const override;

 private:
  // Index of the last node with time <= t, or -1 before the first node.
  int FindNode(double t) const;
  double Line(int a, int b, double t) const;
  double Slope(int a, int b) const;

  std::vector<double> t_;
  std::vector<double> v_;
  bool use_steps_;
  bool extrapolate_;
};

}  // namespace sinew::functions
