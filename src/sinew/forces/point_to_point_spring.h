// OpenSim's PointToPointSpring: a linear spring between a point of one body and a point of
// another (Simbody's Force::TwoPointLinearSpring).
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/math/types.h>

#include <string>

namespace sinew::forces {

/// Tension T = stiffness (d - rest_length) along the line between point1 (on body1, in its
/// frame) and point2 (on body2): +T along the unit vector from point1 to point2 on body1, the
/// opposite on body2 (a stretched spring pulls the points together). Potential energy
/// stiffness (d - rest_length)^2 / 2. When the points coincide (d = 0) the direction is
/// undefined and no force is applied. Either body may be ground (0).
class PointToPointSpring final : public engine::ForceElement {
 public:
  PointToPointSpring(std::string name, int body1, const Vec3& point1, int body2, const Vec3& point2,
                     double stiffness, double rest_length);

  std::string name() const override { return name_; }
  /// The distance d between the points (m) for the context's state.
  double CalcLength(const engine::ForceContext& context) const;
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  std::optional<engine::ForceSupport> Support() const override;
  double CalcPotentialEnergy(const engine::ForceContext& context) const override;
  /// OpenSim's layout: per body (body1, then body2) "<name>.<body>.force.X|Y|Z" (the force on
  /// it, N, in G) and "<name>.<body>.point.X|Y|Z" (its point, m, in G).
  std::vector<std::string> RecordLabels(const engine::System& system) const override;
  void CalcRecordValues(const engine::ForceContext& context,
                        std::vector<double>& values) const override;

 private:
  /// The force on body1 (N, in G); body2 gets its opposite.
  Vec3 CalcForceOnBody1(const engine::State& state) const;

  std::string name_;
  int body1_, body2_;
  Vec3 point1_, point2_;
  double stiffness_, rest_length_;
};

}  // namespace sinew::forces
