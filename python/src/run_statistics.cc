#include "run_statistics.h"

#include <sinew/common/error.h>
#include <sinew/engine/nsc_integrator.h>

#include <sstream>
#include <vector>

namespace sinew::python {

py::dict RunStatistics(const engine::Integrator& integrator) {
  const engine::IntegratorStats stats = integrator.stats();
  py::dict statistics(py::arg("steps") = stats.steps, py::arg("rejected") = stats.rejected,
                      py::arg("evaluations") = stats.evaluations,
                      py::arg("breakpoints_crossed") = stats.breakpoints_crossed);
  if (const auto* nsc = dynamic_cast<const engine::NscIntegrator*>(&integrator)) {
    const engine::NscSolveSummary& solves = nsc->solve_summary();
    statistics["nsc_solves"] = solves.solves;
    statistics["nsc_unconverged_steps"] = solves.unconverged;
    statistics["nsc_most_iterations"] = solves.most_iterations;
    statistics["nsc_worst_residual"] = solves.worst_residual;
  }
  return statistics;
}

long UnconvergedSteps(const engine::Integrator& integrator) {
  const auto* nsc = dynamic_cast<const engine::NscIntegrator*>(&integrator);
  return nsc ? nsc->solve_summary().unconverged : 0;
}

void ReportUnconvergedSteps(const ModelHandle& model, const engine::Integrator& integrator,
                            const std::string& run) {
  const auto& nsc = dynamic_cast<const engine::NscIntegrator&>(integrator);
  const engine::NscSolveSummary& solves = nsc.solve_summary();
  std::ostringstream message;
  if (!run.empty()) message << run << ": ";
  message << "NSC's contact impulse solver did NOT reach its tolerance of "
          << nsc.nsc_settings().solver.tolerance << " m/s in " << solves.unconverged << " of "
          << solves.solves << " steps with contacts (it stopped at its limit of "
          << nsc.nsc_settings().solver.max_iterations << " iterations, residual up to "
          << solves.worst_residual
          << " m/s): those steps' contact impulses are approximate; raise nsc_iterations or "
             "loosen nsc_tolerance in sinew.load";
  // strict: no silent approximation (as `sinew simulate --strict`).
  if (model.options().strict) throw Error({model.path(), 0}, "", message.str() + " (strict)");
  if (PyErr_WarnEx(PyExc_UserWarning, message.str().c_str(), 1) != 0) {
    throw py::error_already_set();
  }
}

void ReportNewUnconvergedSteps(const ModelHandle& model, std::span<SteppedCopy> copies,
                               const char* api, bool numbered) {
  const bool strict = model.options().strict;
  std::vector<size_t> news;
  for (size_t i = 0; i < copies.size(); ++i) {
    const long now = UnconvergedSteps(copies[i].integrator());
    const long before = copies[i].reported_unconverged();
    if (now > before && (strict || before == 0)) news.push_back(i);
    copies[i].set_reported_unconverged(now);
  }
  if (news.empty()) return;
  const SteppedCopy& first = copies[news.front()];
  std::ostringstream run;
  run << api;
  if (numbered) {
    run << " copy " << news.front();
    if (news.size() > 1) run << " (and " << news.size() - 1 << " more copies)";
  }
  run << " at t = " << first.state().t << " s (counts since the last reset)";
  ReportUnconvergedSteps(model, first.integrator(), run.str());
}

}  // namespace sinew::python
