// The default record of a force element (ForceElement::RecordLabels, CalcRecordValues): the
// loads AddLoads applies, on the bodies and coordinates of the element's support.
#include <sinew/engine/force_element.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/system.h>

#include <numeric>

namespace sinew::engine {
namespace {

// The bodies and coordinates an element's default record covers: its support, or, without
// one, every body but ground and every coordinate.
ForceSupport RecordedSupport(const ForceElement& element, const System& system) {
  if (std::optional<ForceSupport> support = element.Support()) return *support;
  ForceSupport all;
  all.bodies.resize(system.num_bodies() - 1);
  std::iota(all.bodies.begin(), all.bodies.end(), 1);
  all.coordinates.resize(system.num_coordinates());
  std::iota(all.coordinates.begin(), all.coordinates.end(), 0);
  return all;
}

}  // namespace

std::vector<std::string> ForceElement::RecordLabels(const System& system) const {
  const ForceSupport support = RecordedSupport(*this, system);
  const std::string prefix = name();
  std::vector<std::string> labels;
  for (int b : support.bodies) {
    for (const char* kind : {".force.", ".torque."}) {
      for (const char* axis : {"X", "Y", "Z"}) {
        labels.push_back(prefix + "." + system.bodies()[b].name + kind + axis);
      }
    }
  }
  if (support.bodies.empty() && support.coordinates.size() == 1) return {prefix};
  for (int c : support.coordinates) labels.push_back(prefix + "." + system.coordinates()[c].name);
  return labels;
}

void ForceElement::CalcRecordValues(const ForceContext& context,
                                    std::vector<double>& values) const {
  const System& system = context.system;
  const ForceSupport support = RecordedSupport(*this, system);
  Loads loads(system.num_bodies(), system.num_coordinates());
  AddLoads(context, loads);
  for (int b : support.bodies) {
    const SpatialVec& load = loads.body[b];  // [torque about Bo; force], in G
    for (int i = 3; i < 6; ++i) values.push_back(load[i]);
    for (int i = 0; i < 3; ++i) values.push_back(load[i]);
  }
  for (int c : support.coordinates) values.push_back(loads.mobility[c]);
}

}  // namespace sinew::engine
