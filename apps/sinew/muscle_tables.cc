#include "apps/sinew/muscle_tables.h"

#include <sinew/common/error.h>
#include <sinew/io/storage_writer.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace sinew::cli {
namespace {

// The column of a muscle's state variable: OpenSim 4's or OpenSim 3's label, or -1.
int FindStateColumn(const io::Storage& states, const std::string& muscle,
                    const std::string& variable) {
  const int c = states.FindColumn("/forceset/" + muscle + "/" + variable);
  return c >= 0 ? c : states.FindColumn(muscle + "." + variable);
}

}  // namespace

MuscleTables::MuscleTables(const model::ModelSpec& spec, const io::Storage& states,
                           const std::vector<std::string>& path_names) {
  opensim::OpenSimParser parser;
  try {
    system_ = std::make_unique<engine::System>(spec.gravity);
    parser.ParseSpec(*system_, spec);
    system_->Finalize();
  } catch (const Error& error) {
    std::cerr << "sinew: warning: no muscle tables: the model cannot be built (" << error.what()
              << ")\n";
    return;
  }
  for (const auto& element : system_->force_elements()) {
    const auto* actuator = dynamic_cast<const muscles::PathActuator*>(element.get());
    if (!actuator || actuator->StateVariableNames().empty()) continue;
    const auto path = std::find(path_names.begin(), path_names.end(), actuator->name());
    const int activation = FindStateColumn(states, actuator->name(), "activation");
    const int fiber = FindStateColumn(states, actuator->name(), "fiber_length");
    if (path == path_names.end() || activation < 0 || fiber < 0) continue;
    muscles_.push_back({actuator, static_cast<int>(path - path_names.begin()), activation, fiber});
    used_labels_.push_back(states.labels[activation]);
    used_labels_.push_back(states.labels[fiber]);
  }
  for (const char* name :
       {"FiberLength", "TendonLength", "ActiveFiberForce", "PassiveFiberForce", "TendonForce"}) {
    io::Storage table;
    table.name = name;
    for (const Muscle& m : muscles_) table.labels.push_back(m.actuator->name());
    tables_.push_back(std::move(table));
  }
}

void MuscleTables::AppendRow(const io::Storage& states, int r, const std::vector<double>& lengths,
                             const std::vector<double>& speeds) {
  std::vector<std::vector<double>> rows(tables_.size());
  VecX z(2);
  for (const Muscle& m : muscles_) {
    z << states.Value(r, m.activation), states.Value(r, m.fiber_length);
    // The excitation does not enter a muscle's forces, only its activation's rate.
    const muscles::MuscleQuantities q =
        m.actuator->model().Calc(z, 0.0, {lengths[m.path], speeds[m.path]});
    rows[0].push_back(q.fiber_length);
    rows[1].push_back(q.tendon_length);
    rows[2].push_back(q.active_fiber_force);
    rows[3].push_back(q.passive_fiber_force);
    rows[4].push_back(q.tendon_force);
  }
  for (size_t k = 0; k < tables_.size(); ++k) tables_[k].AppendRow(states.time[r], rows[k]);
}

void MuscleTables::Write(const std::string& dir) const {
  for (const io::Storage& table : tables_) {
    io::WriteStorage(table, (std::filesystem::path(dir) / (table.name + ".sto")).string());
  }
}

}  // namespace sinew::cli
