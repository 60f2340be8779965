// OpenSim's bushings: BushingForce (linear, Simbody's Force::LinearBushing),
// FunctionBasedBushingForce and ExpressionBasedBushingForce. All three restore the deflection
// of a frame M (on body 2) from a frame F (on body 1) and differ only in the stiffness law.
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/forces/two_frame_linker.h>
#include <sinew/functions/function.h>
#include <sinew/math/types.h>

#include <array>
#include <memory>
#include <string>

namespace sinew::forces {

/// The elastic part of a bushing: fk(q) for the deflection q = [theta_x, theta_y, theta_z,
/// delta_x, delta_y, delta_z] (FrameDeflection::q); the bushing applies -fk.
class BushingStiffness {
 public:
  virtual ~BushingStiffness() = default;
  /// fk(q): three generalized moments on the angles (N m) and three forces along F's axes (N).
  virtual Vec6 Calc(const Vec6& q) const = 0;
  /// The potential energy V with -dV/dq = -fk, or 0 when the law has none (J).
  virtual double CalcPotentialEnergy(const Vec6& q) const {
    (void)q;
    return 0.0;
  }
};

/// BushingForce: fk = k .* q with k = [rotational_stiffness; translational_stiffness]
/// (N m/rad, N/m), V = sum k_i q_i^2 / 2 (as Simbody's LinearBushing).
class LinearBushingStiffness final : public BushingStiffness {
 public:
  explicit LinearBushingStiffness(const Vec6& k) : k_(k) {}
  Vec6 Calc(const Vec6& q) const override { return k_.cwiseProduct(q); }
  double CalcPotentialEnergy(const Vec6& q) const override {
    return 0.5 * q.dot(k_.cwiseProduct(q));
  }

 private:
  Vec6 k_;
};

/// FunctionBasedBushingForce: fk_i = f_i(q_i), each axis through its own function of its own
/// deflection (m_x_theta_x_function, ..., f_z_delta_z_function). OpenSim reports no potential
/// energy for it, and neither does Sinew.
class FunctionBushingStiffness final : public BushingStiffness {
 public:
  explicit FunctionBushingStiffness(std::array<functions::FunctionPtr, 6> functions)
      : functions_(std::move(functions)) {}
  Vec6 Calc(const Vec6& q) const override;

 private:
  std::array<functions::FunctionPtr, 6> functions_;
};

/// A bushing: internal force f = -fk(q) - c .* qdot on M from F (c = [rotational_damping;
/// translational_damping]), applied through OpenSim's TwoFrameLinker basis (the moments act
/// through the body-fixed X-Y-Z Euler-angle Jacobian, so they are singular where theta_y is
/// +-90 degrees, as in OpenSim).
class BushingForce final : public engine::ForceElement {
 public:
  BushingForce(std::string name, const LinkedFrames& frames,
               std::shared_ptr<const BushingStiffness> stiffness, const Vec6& damping);

  std::string name() const override { return name_; }
  /// The internal force f in the deflection basis for the context's state.
  Vec6 CalcInternalForce(const engine::ForceContext& context) const;
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  std::optional<engine::ForceSupport> Support() const override { return frames_.Support(); }
  double CalcPotentialEnergy(const engine::ForceContext& context) const override;

 private:
  Vec6 InternalForce(const FrameDeflection& deflection) const;

  std::string name_;
  LinkedFrames frames_;
  std::shared_ptr<const BushingStiffness> stiffness_;
  Vec6 damping_;
};

}  // namespace sinew::forces
