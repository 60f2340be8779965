// OpenSim's ForwardTool setup files (`*_Setup_Forward.xml`, every layout from 1.9 to 4.x): what
// a forward run reads, with each path resolved relative to the setup file, as OpenSim resolves
// them (it changes into the setup's folder first).
#pragma once

#include <sinew/common/error.h>

#include <string>
#include <vector>

namespace sinew::io {

/// What a ForwardTool setup says. Defaults are OpenSim's (AbstractTool::setNull and
/// ForwardTool::setNull) for properties the file leaves out.
struct ForwardSetup {
  std::string file;  ///< The setup file read.
  std::string name;  ///< The ForwardTool's name: outputs are `<name>_states.sto`, ...
  int version = 0;   ///< OpenSimDocument Version (0 when absent).

  std::string model_file;          ///< Resolved; "" when the setup names none (give one instead).
  bool replace_force_set = false;  ///< Replace (true) or append to the ForceSet.
  std::vector<std::string> force_set_files;  ///< ForceSet files, resolved, in order.
  std::string results_directory;             ///< Resolved; the setup's folder when empty.
  int output_precision = 8;                  ///< Significant digits OpenSim would print.
  double initial_time = 0.0;                 ///< s
  double final_time = 1.0;                   ///< s, > initial_time
  bool solve_for_equilibrium_for_auxiliary_states = false;
  int maximum_number_of_integrator_steps = 20000;
  double maximum_integrator_step_size = 1.0;   ///< s
  double minimum_integrator_step_size = 1e-8;  ///< s
  double integrator_error_tolerance = 1e-5;    ///< the integrator's accuracy
  /// The controls file of the enabled ControlSetController (or of the 1.9 top-level
  /// `controls_file`), resolved; "" when there is none.
  std::string controls_file;
  std::string external_loads_file;  ///< Resolved; "" when empty or "Unassigned".
  std::string states_file;          ///< Resolved; "" when empty.
  /// What OpenSim would act on but Sinew does not, each naming file:line and element: analyses
  /// of the AnalysisSet (they observe, the motion is the same) and unknown settings. A front
  /// end prints them as warnings (errors when strict).
  Diagnostics warnings;
  /// What is read and, as OpenSim does, not acted on: disabled controllers, corrective spring
  /// settings (ignored since 1.9.4), the kinematics options OpenSim 4 ignores, actuator_list.
  Diagnostics notes;
};

/// Reads a ForwardTool setup file. Throws sinew::Error naming the file, line and element for a
/// malformed file and for settings that would change the results but that Sinew cannot honour:
/// controllers other than ControlSetController (e.g. CorrectionController), more than one
/// enabled ControlSetController, `use_specified_dt` true, the pre-1.9.4 corrective springs, an
/// external loads file that is not .xml (pre-2.0),
/// final_time not after initial_time, and numbers out of range.
ForwardSetup ReadForwardSetup(const std::string& file);

/// As ReadForwardSetup, from the XML text of a setup file; `file` names it in messages and
/// paths are resolved relative to its folder.
ForwardSetup ParseForwardSetup(std::string text, const std::string& file);

}  // namespace sinew::io
