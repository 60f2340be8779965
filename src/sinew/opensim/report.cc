#include <sinew/opensim/report.h>

#include <iomanip>

namespace sinew::opensim {
namespace {

// Stores `info` under its name, or `name#k` for the k-th repeat; warns about repeats.
template <typename Info>
std::string AddUnique(std::map<std::string, Info>& items, Info info, const char* kind,
                      Diagnostics& warnings) {
  std::string key = info.name;
  for (int k = 2; items.count(key) > 0; ++k) key = info.name + "#" + std::to_string(k);
  if (key != info.name) {
    warnings.push_back({SourceLocation{}, info.name,
                        std::string("another ") + kind + " has this name; kept as '" + key + "'"});
  }
  items.emplace(key, std::move(info));
  return key;
}

template <typename Info>
const Info* Find(const std::map<std::string, Info>& items, const std::string& name) {
  auto it = items.find(name);
  return it == items.end() ? nullptr : &it->second;
}

}  // namespace

std::string Report::AddBody(BodyInfo info) {
  return AddUnique(bodies_, std::move(info), "body", warnings_);
}
std::string Report::AddJoint(JointInfo info) {
  return AddUnique(joints_, std::move(info), "joint", warnings_);
}
std::string Report::AddForce(ForceInfo info) {
  return AddUnique(forces_, std::move(info), "force", warnings_);
}
std::string Report::AddConstraint(ConstraintInfo info) {
  return AddUnique(constraints_, std::move(info), "constraint", warnings_);
}

const BodyInfo* Report::GetBody(const std::string& name) const { return Find(bodies_, name); }
const JointInfo* Report::GetJoint(const std::string& name) const { return Find(joints_, name); }
const ForceInfo* Report::GetForce(const std::string& name) const { return Find(forces_, name); }
const ConstraintInfo* Report::GetConstraint(const std::string& name) const {
  return Find(constraints_, name);
}

ForceInfo* Report::MutableForce(const std::string& name) {
  auto it = forces_.find(name);
  return it == forces_.end() ? nullptr : &it->second;
}

std::string JointFormName(engine::JointForm form) {
  switch (form) {
    case engine::JointForm::kParameterized:
      return "coordinate-parameterized";
    case engine::JointForm::kPin:
      return "revolute (direct)";
    case engine::JointForm::kBall:
      return "spherical (direct)";
    case engine::JointForm::kUniversal:
      return "universal (direct)";
    case engine::JointForm::kWeld:
      return "weld (direct)";
  }
  return "?";
}

void Report::Print(std::ostream& out) const {
  out << "Bodies (" << bodies_.size() << ")\n";
  for (const auto& [key, info] : bodies_) {
    out << "  " << std::left << std::setw(28) << key << " engine body " << info.body << "\n";
  }
  out << "Joints (" << joints_.size() << ")\n";
  for (const auto& [key, info] : joints_) {
    out << "  " << std::left << std::setw(27) << key << " " << std::setw(21) << info.type << " "
        << JointFormName(info.form) << (info.standin ? "  STAND-IN" : "") << "\n";
  }
  out << "Forces (" << forces_.size() << ")\n";
  for (const auto& [key, info] : forces_) {
    out << "  " << std::left << std::setw(27) << key << " " << std::setw(21) << info.type << " "
        << (info.load               ? "simulated"
            : info.disabled.empty() ? "not simulated"
                                    : "disabled (" + info.disabled + ")");
    if (info.actuator) out << ", excitation: " << info.excitation_source;
    out << "\n";
  }
  if (!constraints_.empty()) out << "Constraints (" << constraints_.size() << ")\n";
  for (const auto& [key, info] : constraints_) {
    out << "  " << std::left << std::setw(27) << key << " " << std::setw(21) << info.type << " "
        << (info.constraint ? "simulated" : "not simulated") << "\n";
  }
  if (!not_simulated_.empty()) {
    out << "Not simulated (" << not_simulated_.size() << ")\n";
    for (const std::string& what : not_simulated_) out << "  " << what << "\n";
  }
  if (!warnings_.empty()) {
    out << "Warnings (" << warnings_.size() << ")\n";
    for (const Diagnostic& w : warnings_) out << "  " << w.Format() << "\n";
  }
}

}  // namespace sinew::opensim
