#include <sinew/contact/contact_force.h>
#include <sinew/contact/contact_table.h>

namespace sinew::contact {
namespace {

template <class Visit>
void ForEachContactForce(const engine::System& system, Visit visit) {
  for (const auto& element : system.force_elements()) {
    if (const auto* c = dynamic_cast<const ContactForce*>(element.get())) visit(*c);
  }
}

}  // namespace

std::vector<std::string> ContactTableLabels(const engine::System& system) {
  std::vector<std::string> labels;
  ForEachContactForce(system, [&](const ContactForce& c) {
    const std::vector<std::string> own = c.RecordLabels(system);
    labels.insert(labels.end(), own.begin(), own.end());
    labels.push_back(c.name() + ".active_contacts");
    for (const ContactForce::PairGroup& p : c.pair_groups())
      labels.push_back(c.name() + "." + p.label + ".active_contacts");
  });
  return labels;
}

void ContactTableRow(const engine::System& system, const engine::State& state,
                     std::vector<double>& row) {
  row.clear();
  ForEachContactForce(system, [&](const ContactForce& c) {
    for (const Vec6& load : c.CalcGroupLoads(state))
      row.insert(row.end(), load.begin(), load.end());
    row.push_back(c.CountActiveContacts(state));
    if (c.pair_groups().empty()) return;
    for (const int count : c.CountActiveContactsPerPair(state)) row.push_back(count);
  });
}

}  // namespace sinew::contact
