// OpenSim's ExternalForce: a force, its point of application and a torque given as functions
// of time (the columns of a data file), each expressed in a chosen body, applied to another
// body. Read from an ExternalLoads file or a model's ForceSet (opensim/force_registry.cc).
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/functions/function.h>
#include <sinew/math/types.h>

#include <array>
#include <string>

namespace sinew::forces {

/// The three functions of time of each part of an ExternalForce; a part whose functions are
/// null is not applied (force, torque) or not specified (point: the body origin).
struct ExternalForceFunctions {
  std::array<functions::FunctionPtr, 3> force;   ///< N, expressed in the force body E
  std::array<functions::FunctionPtr, 3> point;   ///< m, a station of the point body P
  std::array<functions::FunctionPtr, 3> torque;  ///< N m, expressed in the force body E
};

/// Which bodies an ExternalForce uses (engine body indices; 0 is ground).
struct ExternalForceBodies {
  int applied_to = 0;  ///< B: the body the force and torque act on
  int force_in = 0;    ///< E: the body the force and torque vectors are expressed in
  int point_in = 0;    ///< P: the body the point is expressed in
};

/// At time t: f_G = R_GE f(t) at the point Q of B that is at p(t) in P (p_BQ = X_GB^-1 X_GP
/// p(t); Bo when no point is given), and torque tau_G = R_GE tau(t) on B (OpenSim's
/// ExternalForce::computeForce). B, E and P may all differ; E and P move with their bodies.
class ExternalForce final : public engine::ForceElement {
 public:
  /// `body_label` is the applied_to_body text as written (OpenSim's record labels use it).
  /// Throws sinew::Error when neither a force nor a torque is given, or a point without a
  /// force.
  ExternalForce(std::string name, std::string body_label, const ExternalForceBodies& bodies,
                ExternalForceFunctions functions);

  std::string name() const override { return name_; }
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  /// B, E and P (those that are not ground).
  std::optional<engine::ForceSupport> Support() const override;
  /// OpenSim's layout: "<body>_<name>_Fx|Fy|Fz" (force in G), "..._px|py|pz" (the point in B)
  /// when a point is given, "..._Tx|Ty|Tz" (torque in G); only the parts given.
  std::vector<std::string> RecordLabels(const engine::System& system) const override;
  void CalcRecordValues(const engine::ForceContext& context,
                        std::vector<double>& values) const override;

  bool applies_force() const { return functions_.force[0] != nullptr; }
  bool specifies_point() const { return functions_.point[0] != nullptr; }
  bool applies_torque() const { return functions_.torque[0] != nullptr; }

  /// What is applied at the context's state.
  struct Applied {
    Vec3 f_G = Vec3::Zero();    ///< force (N, in G)
    Vec3 p_BQ = Vec3::Zero();   ///< its point, in B (m)
    Vec3 tau_G = Vec3::Zero();  ///< torque (N m, in G)
  };
  Applied Calc(const engine::ForceContext& context) const;

 private:
  std::string name_;
  std::string body_label_;
  ExternalForceBodies bodies_;
  ExternalForceFunctions functions_;
};

}  // namespace sinew::forces
