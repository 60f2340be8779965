// The Report of the OpenSim parser (the seed's ChParserOpenSim::Report): what was built for
// every body, joint, force and constraint of the
// file, by name, and every decision worth knowing.
#pragma once

#include <sinew/common/error.h>
#include <sinew/engine/system.h>

#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace sinew::forces {
class Actuator;
}  // namespace sinew::forces

namespace sinew::opensim {

/// A body read from the file and the engine body made for it.
struct BodyInfo {
  std::string name;  ///< The name in the file.
  int body = -1;     ///< Index into engine::System::bodies().
};

/// A joint read from the file and the engine joint made for it.
struct JointInfo {
  std::string name;  ///< The name in the file.
  std::string type;  ///< The OpenSim class, as written in the file.
  int joint = -1;    ///< Index into engine::System::joints().
  engine::JointForm form = engine::JointForm::kParameterized;  ///< How the engine imposes it.
  bool standin = false;  ///< True when a joint the engine cannot model was replaced by a ball
                         ///< joint (opensim::ReplaceWithStandIns).
};

/// A force (actuator, spring, muscle, ...) read from the file and what was made of it.
struct ForceInfo {
  std::string name;  ///< The name in the file.
  std::string type;  ///< The OpenSim class, as written in the file.
  /// The engine force element made for it; null when the type is not simulated (yet).
  std::shared_ptr<const engine::ForceElement> load;
  /// For actuators: the same object as `load`; else null.
  std::shared_ptr<const forces::Actuator> actuator;
  /// For actuators: the index of its excitation in engine::State::inputs; else -1.
  int input = -1;
  /// Where the actuator's excitation comes from ("default 0", "ActivateActuators",
  /// "PrescribedController <name>", "controls file", "set by user").
  std::string excitation_source;
  /// Why the force is not applied although it could be: "appliesForce false in the file" or
  /// "disabled by name" (OpenSimParser::DisableForce); "" when it is not disabled.
  std::string disabled = {};
};

/// A constraint read from the file and what was made of it.
struct ConstraintInfo {
  std::string name;  ///< The name in the file.
  std::string type;  ///< The OpenSim class, as written in the file.
  /// The engine constraint made for it; null when the type is not simulated (yet) or the
  /// constraint is not enforced (isEnforced false).
  std::shared_ptr<const engine::Constraint> constraint;
};

/// Everything one Parse call built, by name. A name repeated within a kind (chrono's
/// newton_cradle.osim names five joints `sph1`) is reported under the unique path name the
/// reader gave it (`sph1`, `sph1_2`, ... with a warning from the reader); should two entries
/// still share a key, the later ones are kept as `name#2`, `name#3`, ... with a warning.
class Report {
 public:
  /// Prints a readable table of bodies, joints, forces and warnings.
  void Print(std::ostream& out) const;

  /// The entry for `name`, or nullptr.
  const BodyInfo* GetBody(const std::string& name) const;
  const JointInfo* GetJoint(const std::string& name) const;
  const ForceInfo* GetForce(const std::string& name) const;
  const ConstraintInfo* GetConstraint(const std::string& name) const;

  const std::map<std::string, BodyInfo>& bodies() const { return bodies_; }
  const std::map<std::string, JointInfo>& joints() const { return joints_; }
  const std::map<std::string, ForceInfo>& forces() const { return forces_; }
  const std::map<std::string, ConstraintInfo>& constraints() const { return constraints_; }
  /// Approximations, substitutions, renamed duplicates, ignored elements.
  const Diagnostics& warnings() const { return warnings_; }
  /// Elements read from the file that the simulation does not include.
  const std::vector<std::string>& not_simulated() const { return not_simulated_; }

  // Filled by the parser. Each Add* returns the key under which the entry is stored.
  std::string AddBody(BodyInfo info);
  std::string AddJoint(JointInfo info);
  std::string AddForce(ForceInfo info);
  std::string AddConstraint(ConstraintInfo info);
  ForceInfo* MutableForce(const std::string& name);
  void AddWarning(Diagnostic warning) { warnings_.push_back(std::move(warning)); }
  void AddNotSimulated(std::string what) { not_simulated_.push_back(std::move(what)); }

 private:
  std::map<std::string, BodyInfo> bodies_;
  std::map<std::string, JointInfo> joints_;
  std::map<std::string, ForceInfo> forces_;
  std::map<std::string, ConstraintInfo> constraints_;
  Diagnostics warnings_;
  std::vector<std::string> not_simulated_;
};

/// The readable name of an engine joint form ("revolute (direct)", "coordinate-parameterized").
std::string JointFormName(engine::JointForm form);

}  // namespace sinew::opensim
