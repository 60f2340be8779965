// What a run did, in one place for Model.simulate (Result.statistics), Simulator.statistics and
// Batch.statistics: the integrator's counters and, for an NSC stepper, what its contact impulse
// solver did; and how NSC steps that stopped above the solver's tolerance are surfaced (a
// UserWarning, or sinew.Error for a model loaded with strict=True).
#pragma once

#include <pybind11/pybind11.h>
#include <sinew/engine/integrator.h>

#include <span>
#include <string>

#include "model_handle.h"
#include "stepped_copy.h"

namespace sinew::python {

namespace py = pybind11;

/// The statistics dict: "steps", "rejected", "evaluations" (engine::IntegratorStats) and, when
/// `integrator` is an NSC stepper, "nsc_solves" (steps with contacts), "nsc_unconverged_steps"
/// (solves stopped at the iteration limit above the tolerance), "nsc_most_iterations" and
/// "nsc_worst_residual" (m/s) (engine::NscSolveSummary), all since the integrator was made.
py::dict RunStatistics(const engine::Integrator& integrator);

/// NSC steps of `integrator` whose solve stopped above the tolerance (0 for another scheme).
long UnconvergedSteps(const engine::Integrator& integrator);

/// Tells Python that the NSC stepper `integrator` of `model` has steps whose solve stopped
/// above the tolerance: a UserWarning (py::error_already_set when warnings are errors), or with
/// strict=True a sinew::Error naming the model's file. `run` ("" for none) begins the message
/// and says which run it is.
void ReportUnconvergedSteps(const ModelHandle& model, const engine::Integrator& integrator,
                            const std::string& run);

/// After a step() of the stepping API `api` ("Simulator", "Batch"; `numbered`: the message
/// names copies by their index): reports (ReportUnconvergedSteps) the copies whose unconverged NSC
/// steps first appeared since their last reset, or with strict=True every copy whose count
/// grew, in one message naming them; every copy's reported_unconverged() is brought up to date
/// first.
void ReportNewUnconvergedSteps(const ModelHandle& model, std::span<SteppedCopy> copies,
                               const char* api, bool numbered);

}  // namespace sinew::python
