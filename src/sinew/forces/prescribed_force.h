// OpenSim's PrescribedForce: a force, its point of application and a torque on one frame, each
// given as three functions of time.
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/functions/function.h>
#include <sinew/math/transform.h>

#include <array>
#include <optional>
#include <string>

namespace sinew::forces {

/// Three functions of time giving a vector's x, y, z.
using VectorOfTime = std::array<functions::FunctionPtr, 3>;

/// What a PrescribedForce applies and how its vectors are expressed.
struct PrescribedForceParameters {
  std::optional<VectorOfTime> force;   ///< forceFunctions (N); none: no force
  std::optional<VectorOfTime> point;   ///< pointFunctions (m); none: the frame's origin
  std::optional<VectorOfTime> torque;  ///< torqueFunctions (N m); none: no torque
  bool force_is_global = true;         ///< forceIsGlobal: force and torque in G, else in the frame
  bool point_is_global = false;        ///< pointIsGlobal: point in G, else in the frame
};

/// Applies, at time t, the force F(t) at the point P(t) and the torque T(t) to the body the
/// frame (X_BF on `body`) is fixed to. With force_is_global false, F and T are expressed in the
/// frame and turned into G with its current orientation. With point_is_global false, P is a
/// point of the frame (moves with the body); with it true, P is given in G and the force acts
/// at the body's material point that is at P at that instant (OpenSim's
/// findStationLocationInAnotherFrame each evaluation).
class PrescribedForce final : public engine::ForceElement {
 public:
  PrescribedForce(std::string name, int body, const Transform& X_BF,
                  PrescribedForceParameters parameters);

  std::string name() const override { return name_; }
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  std::optional<engine::ForceSupport> Support() const override;

 private:
  std::string name_;
  int body_;
  Transform X_BF_;
  PrescribedForceParameters parameters_;
};

}  // namespace sinew::forces
