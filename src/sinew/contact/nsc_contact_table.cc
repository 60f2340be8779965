#include <sinew/contact/nsc_contact_table.h>

#include <algorithm>
#include <set>

namespace sinew::contact {

NscContactTable::NscContactTable(const engine::System& system,
                                 const engine::NscIntegrator& integrator,
                                 const CollisionContactProvider& provider)
    : integrator_(integrator), pairs_(provider.BodyPairs()) {
  std::set<int> bodies;
  for (const auto& [a, b] : pairs_) bodies.insert(a), bodies.insert(b);
  bodies_.assign(bodies.begin(), bodies.end());
  const std::string prefix = std::string(kNscTableName) + ".";
  const auto name = [&](int b) { return system.bodies()[b].name; };
  for (const int b : bodies_) {
    for (const char* what : {".force.", ".torque."}) {
      for (const char* axis : {"X", "Y", "Z"}) labels_.push_back(prefix + name(b) + what + axis);
    }
  }
  labels_.push_back(prefix + "active_contacts");
  for (const auto& [a, b] : pairs_)
    labels_.push_back(prefix + name(a) + "-" + name(b) + ".active_contacts");
  for (const char* solver : {"solver_iterations", "solver_residual", "unconverged_steps"})
    labels_.push_back(prefix + solver);
}

void NscContactTable::Row(std::vector<double>& row) const {
  row.clear();
  integrator_.LastBodyImpulses(impulses_);
  const double h = integrator_.last_step().step;
  const double per_second = h > 0.0 ? 1.0 / h : 0.0;
  for (const int b : bodies_) {
    for (const Vec3& v : {impulses_[b].linear, impulses_[b].angular}) {
      for (int k = 0; k < 3; ++k) row.push_back(v[k] * per_second);
    }
  }
  const std::vector<engine::UnilateralContact>& contacts = integrator_.last_contacts();
  const VecX gamma = integrator_.last_impulses();
  std::vector<int> per_pair(pairs_.size(), 0);
  int active = 0;
  for (size_t i = 0; i < contacts.size(); ++i) {
    if (!(gamma[3 * static_cast<Eigen::Index>(i)] > 0.0)) continue;
    ++active;
    const std::pair<int, int> pair = std::minmax(contacts[i].body1, contacts[i].body2);
    const auto it = std::lower_bound(pairs_.begin(), pairs_.end(), pair);
    if (it != pairs_.end() && *it == pair) ++per_pair[it - pairs_.begin()];
  }
  row.push_back(active);
  for (const int count : per_pair) row.push_back(count);
  row.push_back(integrator_.last_step().iterations);
  row.push_back(integrator_.last_step().residual);
  row.push_back(static_cast<double>(integrator_.solve_summary().unconverged));
}

}  // namespace sinew::contact
