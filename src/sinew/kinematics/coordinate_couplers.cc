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

// scale * df/dq_i for each independent coordinate i of coupler `c` at q.
std::vector<double> CoordinateCouplers::CalcSlopes(const Coupler& c, std::span<const double> q) {
  std::vector<double> x(c.independent.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = q[c.independent[i]];
  std::vector<double> slopes(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const int wrt[1] = {static_cast<int>(i)};
    slopes[i] = c.scale * c.function->CalcPartialN(x, wrt);
  }
  return slopes;
}

void CoordinateCouplers::ApplySpeeds(std::span<const double> q, std::span<double> u) const {
  for (const Coupler& c : couplers_) {
    const std::vector<double> slopes = CalcSlopes(c, q);
    double u_d = 0.0;
    for (size_t i = 0; i < slopes.size(); ++i) u_d += slopes[i] * u[c.independent[i]];
    u[c.dependent] = u_d;
  }
}

void CoordinateCouplers::AppendVelocityRows(std::span<const double> q,
                                            std::vector<std::vector<double>>& rows) const {
  for (const Coupler& c : couplers_) {
    const std::vector<double> slopes = CalcSlopes(c, q);
    std::vector<double> row(q.size(), 0.0);
    row[c.dependent] = 1.0;
    for (size_t i = 0; i < slopes.size(); ++i) row[c.independent[i]] -= slopes[i];
    rows.push_back(std::move(row));
  }
}

bool CoordinateCouplers::Drives(int c) const {
  return std::any_of(couplers_.begin(), couplers_.end(),
                     [c](const Coupler& p) { return p.dependent == c; });
}

bool CoordinateCouplers::Involves(int c) const {
  return std::any_of(couplers_.begin(), couplers_.end(), [c](const Coupler& p) {
    return p.dependent == c ||
           std::find(p.independent.begin(), p.independent.end(), c) != p.independent.end();
  });
}

}  // namespace sinew::kinematics
