#include <sinew/common/error.h>
#include <sinew/kinematics/coordinate_couplers.h>

#include <algorithm>

namespace sinew::kinematics {

CoordinateCouplers::CoordinateCouplers(const model::ModelSpec& spec) {
  std::vector<Coupler> pending;
  std::vector<const model::ConstraintSpec*> sources;
  for (const model::ConstraintSpec& c : spec.constraints) {
    if (c.type != "CoordinateCouplerConstraint" || !c.enabled || !c.function ||
        c.dependent_coordinate == model::kNone) {
      continue;
    }
    pending.push_back(
        {c.dependent_coordinate, c.independent_coordinates, c.function, c.scale_factor});
    sources.push_back(&c);
  }
  // Order: a coupler is ready once none of its independent coordinates is still to be set.
  while (!pending.empty()) {
    bool progress = false;
    for (size_t i = 0; i < pending.size();) {
      const bool ready =
          std::none_of(pending[i].independent.begin(), pending[i].independent.end(), [&](int q) {
            return std::any_of(pending.begin(), pending.end(),
                               [q](const Coupler& p) { return p.dependent == q; });
          });
      if (ready) {
        couplers_.push_back(std::move(pending[i]));
        pending.erase(pending.begin() + static_cast<long>(i));
        sources.erase(sources.begin() + static_cast<long>(i));
        progress = true;
      } else {
        ++i;
      }
    }
    if (!progress) {
      const model::ConstraintSpec& c = *sources.front();
      throw Error(c.where, c.path, "coupler constraints drive each other in a cycle");
    }
  }
}

void CoordinateCouplers::Apply(std::span<double> q) const {
  for (const Coupler& c : couplers_) {
    std::vector<double> x(c.independent.size());
    for (size_t i = 0; i < x.size(); ++i) x[i] = q[c.independent[i]];
    q[c.dependent] = c.scale * c.function->CalcN(x);
  }
}

bool CoordinateCouplers::Drives(int c) const {
  return std::any_of(couplers_.begin(), couplers_.end(),
                     [c](const Coupler& p) { return p.dependent == c; });
}

}  // namespace sinew::kinematics
