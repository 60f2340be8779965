#include <sinew/common/error.h>
#include <sinew/engine/force_reporter.h>

namespace sinew::engine {

ForceReporter::ForceReporter(const System& system) : system_(system) {
  for (const auto& element : system.force_elements()) {
    std::vector<std::string> labels = element->RecordLabels(system);
    counts_.push_back(labels.size());
    labels_.insert(labels_.end(), labels.begin(), labels.end());
  }
}

void ForceReporter::CalcRow(const State& state, std::vector<double>& row) const {
  row.clear();
  row.reserve(labels_.size());
  const auto& elements = system_.force_elements();
  for (size_t k = 0; k < elements.size(); ++k) {
    const size_t before = row.size();
    elements[k]->CalcRecordValues(system_.MakeForceContext(static_cast<int>(k), state), row);
    if (row.size() - before != counts_[k]) {
      throw Error("force element '" + elements[k]->name() + "' reported " +
                  std::to_string(row.size() - before) + " values for " +
                  std::to_string(counts_[k]) + " labels");
    }
  }
}

}  // namespace sinew::engine
