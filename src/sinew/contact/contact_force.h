// What OpenSim's contact forces share as engine force elements: each contact is a force at a
// point between two bodies; the base class applies them, reports them per body in OpenSim's
// ForceReporter layout, and counts the active contacts.
#pragma once

#include <sinew/engine/force_element.h>
#include <sinew/math/types.h>

#include <string>
#include <vector>

namespace sinew::engine {
struct State;
}

namespace sinew::contact {

/// One contact's load: force `f_G` (N, in G) on `body2` at the point `p_G` (in G), and its
/// opposite on `body1` at the same point.
struct ContactLoad {
  int body1 = 0;
  int body2 = 0;
  Vec3 p_G = Vec3::Zero();
  Vec3 f_G = Vec3::Zero();
  bool active = true;  ///< Counted as an active contact (smoothed forces act when apart too).
};

/// Receives the loads of a contact force one contact at a time (no allocation per evaluation).
class ContactSink {
 public:
  virtual ~ContactSink() = default;
  virtual void Add(const ContactLoad& load) = 0;
};

/// A contact force element. Derived classes find their contacts (VisitContacts); this class
/// turns them into loads, records and energy.
class ContactForce : public engine::ForceElement {
 public:
  /// A group of record columns: "<label>.force.X|Y|Z", "<label>.torque.X|Y|Z", the net force
  /// and the torque about the origin of `body` (ground included), in G.
  struct RecordGroup {
    std::string label;
    int body = 0;
  };

  /// A pair of bodies whose active contacts are counted ("<label>.active_contacts").
  struct PairGroup {
    std::string label;
    int body1 = 0;
    int body2 = 0;
  };

  ContactForce(std::string name, std::vector<RecordGroup> groups,
               std::vector<PairGroup> pairs = {});

  std::string name() const override { return name_; }
  void AddLoads(const engine::ForceContext& context, engine::Loads& loads) const override;
  std::optional<engine::ForceSupport> Support() const override;
  std::vector<std::string> RecordLabels(const engine::System& system) const override;
  void CalcRecordValues(const engine::ForceContext& context,
                        std::vector<double>& values) const override;
  double CalcPotentialEnergy(const engine::ForceContext& context) const override;

  /// Passes every contact's load at `state` to `sink`; returns the potential energy stored
  /// in the contacts (J).
  virtual double VisitContacts(const engine::State& state, ContactSink& sink) const = 0;
  /// The number of contacts that apply a load at `state` (for contacts.sto).
  int CountActiveContacts(const engine::State& state) const;
  /// Per record group, [force; torque about the body origin] on its body (N, N m, in G).
  std::vector<Vec6> CalcGroupLoads(const engine::State& state) const;
  /// Per pair group, the number of active contacts between its two bodies (either order).
  std::vector<int> CountActiveContactsPerPair(const engine::State& state) const;
  const std::vector<RecordGroup>& record_groups() const { return groups_; }
  const std::vector<PairGroup>& pair_groups() const { return pairs_; }

 private:
  std::string name_;
  std::vector<RecordGroup> groups_;
  std::vector<PairGroup> pairs_;
};

}  // namespace sinew::contact
