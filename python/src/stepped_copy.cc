#include "stepped_copy.h"

#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/opensim/run_integrator.h>

#include <algorithm>
#include <cmath>

namespace sinew::python {

SteppedCopy::SteppedCopy(const engine::System& system, const opensim::OpenSimParser& parser,
                         const std::string& integrator, const engine::IntegratorSettings& settings,
                         double interval)
    : system_(system),
      parser_(parser),
      integrator_name_(integrator),
      settings_(settings),
      interval_(interval) {
  if (!(interval > 0.0) || !std::isfinite(interval)) {
    throw Error("step must be a finite time > 0 (s), not " + std::to_string(interval));
  }
  integrator_ = opensim::MakeRunIntegrator(integrator_name_, system_, parser_, settings_);
}

void SteppedCopy::Reset(const engine::State& state) {
  engine::CheckState(system_, state);
  integrator_ = opensim::MakeRunIntegrator(integrator_name_, system_, parser_, settings_);
  state_ = state;
  t_start_ = state.t;
  steps_ = 0;
  reported_unconverged_ = 0;
}

void SteppedCopy::Step(const double* controls) {
  if (controls) std::copy(controls, controls + state_.inputs.size(), state_.inputs.data());
  integrator_->StepTo(state_, t_start_ + static_cast<double>(steps_ + 1) * interval_);
  ++steps_;
}

}  // namespace sinew::python
