#include <sinew/contact/contact_force.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/state.h>

#include <algorithm>
#include <utility>

namespace sinew::contact {
namespace {

// Adds each contact's force and its torque about the body origin to the loads of both bodies
// (ground's loads are left alone: it does not move).
class LoadsSink final : public ContactSink {
 public:
  LoadsSink(const engine::State& state, engine::Loads& loads) : state_(state), loads_(loads) {}
  void Add(const ContactLoad& c) override {
    Apply(c.body2, c.p_G, c.f_G);
    Apply(c.body1, c.p_G, -c.f_G);
  }

 private:
  void Apply(int body, const Vec3& p_G, const Vec3& f_G) {
    if (body == 0) return;
    loads_.AddForceAtOrigin(body, f_G);
    loads_.AddTorque(body, (p_G - state_.bodies[body].p_GB).cross(f_G));
  }
  const engine::State& state_;
  engine::Loads& loads_;
};

// Sums the loads on each record group's body, torques about that body's origin.
class GroupSink final : public ContactSink {
 public:
  GroupSink(const engine::State& state, const std::vector<ContactForce::RecordGroup>& groups)
      : state_(state), groups_(groups), loads_(groups.size(), Vec6::Zero()) {}
  void Add(const ContactLoad& c) override {
    for (size_t g = 0; g < groups_.size(); ++g) {
      if (groups_[g].body == c.body2) Apply(g, c.p_G, c.f_G);
      if (groups_[g].body == c.body1) Apply(g, c.p_G, -c.f_G);
    }
  }
  std::vector<Vec6>& loads() { return loads_; }

 private:
  void Apply(size_t g, const Vec3& p_G, const Vec3& f_G) {
    const Vec3 p_GBo = state_.bodies[groups_[g].body].p_GB;
    loads_[g].head<3>() += f_G;
    loads_[g].tail<3>() += (p_G - p_GBo).cross(f_G);
  }
  const engine::State& state_;
  const std::vector<ContactForce::RecordGroup>& groups_;
  std::vector<Vec6> loads_;
};

class CountSink final : public ContactSink {
 public:
  void Add(const ContactLoad& c) override { count += c.active ? 1 : 0; }
  int count = 0;
};

}  // namespace

ContactForce::ContactForce(std::string name, std::vector<RecordGroup> groups,
                           std::vector<PairGroup> pairs)
    : name_(std::move(name)), groups_(std::move(groups)), pairs_(std::move(pairs)) {}

void ContactForce::AddLoads(const engine::ForceContext& context, engine::Loads& loads) const {
  LoadsSink sink(context.state, loads);
  VisitContacts(context.state, sink);
}

std::optional<engine::ForceSupport> ContactForce::Support() const {
  engine::ForceSupport support;
  for (const RecordGroup& g : groups_) {
    if (g.body != 0 &&
        std::find(support.bodies.begin(), support.bodies.end(), g.body) == support.bodies.end())
      support.bodies.push_back(g.body);
  }
  return support;
}

std::vector<std::string> ContactForce::RecordLabels(const engine::System& /*system*/) const {
  std::vector<std::string> labels;
  for (const RecordGroup& g : groups_) {
    for (const char* kind : {".force.", ".torque."}) {
      for (const char* axis : {"X", "Y", "Z"})
        labels.push_back(name_ + "." + g.label + kind + axis);
    }
  }
  return labels;
}

std::vector<Vec6> ContactForce::CalcGroupLoads(const engine::State& state) const {
  GroupSink sink(state, groups_);
  VisitContacts(state, sink);
  return std::move(sink.loads());
}

void ContactForce::CalcRecordValues(const engine::ForceContext& context,
                                    std::vector<double>& values) const {
  for (const Vec6& load : CalcGroupLoads(context.state))
    values.insert(values.end(), load.begin(), load.end());
}

double ContactForce::CalcPotentialEnergy(const engine::ForceContext& context) const {
  class Ignore final : public ContactSink {
   public:
    void Add(const ContactLoad&) override {}
  } sink;
  return VisitContacts(context.state, sink);
}

int ContactForce::CountActiveContacts(const engine::State& state) const {
  CountSink sink;
  VisitContacts(state, sink);
  return sink.count;
}

std::vector<int> ContactForce::CountActiveContactsPerPair(const engine::State& state) const {
  class PairCountSink final : public ContactSink {
   public:
    explicit PairCountSink(const std::vector<PairGroup>& pairs)
        : pairs_(pairs), counts(pairs.size(), 0) {}
    void Add(const ContactLoad& c) override {
      if (!c.active) return;
      for (size_t k = 0; k < pairs_.size(); ++k) {
        const PairGroup& p = pairs_[k];
        if ((p.body1 == c.body1 && p.body2 == c.body2) ||
            (p.body1 == c.body2 && p.body2 == c.body1))
          ++counts[k];
      }
    }
    const std::vector<PairGroup>& pairs_;
    std::vector<int> counts;
  } sink(pairs_);
  VisitContacts(state, sink);
  return sink.counts;
}

}  // namespace sinew::contact
