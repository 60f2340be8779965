// A ForwardTool setup's run, decided in one place for `sinew forward` and Python's
// sinew.forward: the model file, the states table's row it starts from and when, how long it
// runs, and the integrator's settings (docs/forward.md).
#pragma once

#include <sinew/common/error.h>
#include <sinew/engine/integrator.h>
#include <sinew/io/forward_setup.h>
#include <sinew/io/storage.h>

#include <optional>
#include <string>

namespace sinew::opensim {

/// How a front end runs a setup.
struct ForwardRunOptions {
  std::string model_path;  ///< replaces the setup's model_file when not empty
  /// How a user gives a model ("--model", "model="), for the error when none is named.
  std::string model_option = "--model";
  bool strict = false;                     ///< a setup warning is then an error
  std::string strict_option = "--strict";  ///< named in that error
};

/// A setup's run, decided.
struct ForwardRun {
  io::ForwardSetup setup;
  std::string model_path;  ///< the model given, else the setup's model_file
  /// The setup's states_file as read (none without one; angles as the file has them, the
  /// reader's notes in its `notes`).
  std::optional<io::Storage> states;
  /// The row of `states` the run starts from: the one OpenSim's Forward tool takes for the
  /// setup's initial_time (ForwardStartRow); 0 without a states file.
  int start_row = 0;
  double start_time = 0.0;  ///< s: that row's time, else the setup's initial_time
  /// What a front end tells as notes: the setup's notes and, when the run does not start at
  /// initial_time, where it starts and why.
  Diagnostics notes;
  /// What a front end warns of: the setup's warnings (OpenSim would act on them, Sinew does
  /// not). Empty when strict, where they are errors.
  Diagnostics warnings;

  double duration() const { return setup.final_time - start_time; }  ///< s
  /// The setup's error tolerance as the accuracy, and its step bounds.
  engine::IntegratorSettings integrator_settings() const;
};

/// Reads the ForwardTool setup `setup_file` and its states file, and decides its run. Throws
/// sinew::Error naming the file and the tool for a bad setup (io::ReadForwardSetup), for a
/// setup warning when strict, when neither the options nor the setup name a model, for an
/// unreadable or empty states file, and for a run that would start at or after final_time.
ForwardRun PlanForwardRun(const std::string& setup_file, const ForwardRunOptions& options);

}  // namespace sinew::opensim
