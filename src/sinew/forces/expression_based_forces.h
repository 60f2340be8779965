// OpenSim's expression-based forces: ExpressionBasedCoordinateForce (a formula in q and qdot),
// ExpressionBasedPointToPointForce (in d and ddot) and the stiffness law of
// ExpressionBasedBushingForce (in theta_x, theta_y, theta_z, delta_x, delta_y, delta_z).
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/forces/bushing_force.h>
#include <sinew/forces/expression.h>
#include <sinew/math/types.h>

#include <array>
#include <memory>
#include <string>

namespace sinew::forces {

/// Generalized force f = expression(q, qdot) on `coordinate` (qdot is the coordinate's speed u).
class ExpressionBasedCoordinateForce final : public engine::ForceElement {
 public:
  /// `expression` must be made with the variables {"q", "qdot"}.
  ExpressionBasedCoordinateForce(std::string name, int coordinate,
                                 std::shared_ptr<const Expression> expression);

  std::string name() const override { return name_; }
  /// The generalized force for the context's state.
  double CalcForce(const engine::ForceContext& context) const;
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  std::optional<engine::ForceSupport> Support() const override;

 private:
  std::string name_;
  int coordinate_;
  std::shared_ptr<const Expression> expression_;
};

/// A force of magnitude F = expression(d, ddot) along the line between point1 (on body1, in
/// its frame) and point2 (on body2): +F along the unit vector from point1 to point2 on body1,
/// the opposite on body2 (a positive F pulls the points together), d their distance and ddot
/// its rate. No force when the points coincide (OpenSim divides by d = 0 there).
class ExpressionBasedPointToPointForce final : public engine::ForceElement {
 public:
  /// `expression` must be made with the variables {"d", "ddot"}.
  ExpressionBasedPointToPointForce(std::string name, int body1, const Vec3& point1, int body2,
                                   const Vec3& point2,
                                   std::shared_ptr<const Expression> expression);

  std::string name() const override { return name_; }
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  std::optional<engine::ForceSupport> Support() const override;

 private:
  std::string name_;
  int body1_, body2_;
  Vec3 point1_, point2_;
  std::shared_ptr<const Expression> expression_;
};

/// ExpressionBasedBushingForce's stiffness: fk_i = expression_i(theta_x, theta_y, theta_z,
/// delta_x, delta_y, delta_z) for Mx, My, Mz, Fx, Fy, Fz. No potential energy (as OpenSim).
class ExpressionBushingStiffness final : public BushingStiffness {
 public:
  /// The variable names, in the order of FrameDeflection::q.
  static const std::vector<std::string>& VariableNames();
  /// Each expression must be made with VariableNames().
  explicit ExpressionBushingStiffness(std::array<std::shared_ptr<const Expression>, 6> expressions)
      : expressions_(std::move(expressions)) {}
  Vec6 Calc(const Vec6& q) const override;

 private:
  std::array<std::shared_ptr<const Expression>, 6> expressions_;
};

}  // namespace sinew::forces
