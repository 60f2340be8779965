// The Constraint interface: a set of holonomic equations phi(positions, t) = 0 between bodies
// and coordinates, given with its velocity Jacobian J, velocity right-hand side c(t) and the
// acceleration right-hand side b = -Jdot v + dc/dt.
#pragma once

#include <sinew/math/types.h>

#include <string>
#include <utility>
#include <vector>

namespace sinew::engine {

class System;
struct State;

/// Equations phi(x, t) = 0 with J(x) v = c(t) and J(x) vdot = b(x, v, t). The velocity unknowns
/// v are, in order: for each body of Bodies() its twist [w_GB; v_GB] (in G, 6 entries), then
/// for each coordinate of Coordinates() its speed u. Ground may appear among Bodies(): its
/// columns are ignored.
class Constraint {
 public:
  virtual ~Constraint() = default;

  /// The constraint's name, for messages (empty when it has none).
  virtual std::string name() const { return {}; }

  /// Number of scalar equations.
  virtual int NumEquations() const = 0;
  /// The bodies whose twists enter the equations (indices into System::bodies()).
  virtual std::vector<int> Bodies() const = 0;
  /// The coordinates whose speeds enter the equations (indices into System::coordinates());
  /// only coordinates with integrated speeds (System::IsIntegrated) may appear.
  virtual std::vector<int> Coordinates() const { return {}; }

  /// phi (NumEquations entries). Its derivative along any motion must be J v - c.
  virtual void CalcPositionError(const System& system, const State& state,
                                 Eigen::Ref<VecX> phi) const = 0;
  /// J: NumEquations() rows, 6 * Bodies().size() + Coordinates().size() columns.
  virtual void CalcJacobian(const System& system, const State& state, Eigen::Ref<MatX> J) const = 0;
  /// c(t), the velocity right-hand side (zero for scleronomic constraints).
  virtual void CalcVelocityRhs(const System& system, const State& state, Eigen::Ref<VecX> c) const {
    (void)system, (void)state;
    c.setZero();
  }
  /// b = -Jdot v + dc/dt, the acceleration right-hand side.
  virtual void CalcAccelerationRhs(const System& system, const State& state,
                                   Eigen::Ref<VecX> b) const = 0;
  /// The values of coordinates (indices into System::coordinates(), value) where b or its rate of
  /// change jumps (a function's functions::Function::Breakpoints).
  virtual std::vector<std::pair<int, double>> Breakpoints() const { return {}; }
};

}  // namespace sinew::engine
