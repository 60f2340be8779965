#include <sinew/common/error.h>
#include <sinew/engine/direct_joint.h>
#include <sinew/engine/joint_constraints.h>
#include <sinew/engine/state.h>
#include <sinew/engine/system.h>
#include <sinew/kinematics/joint_tree_order.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>

namespace sinew::engine {

System::System(const Vec3& gravity) : gravity_(gravity) {
  Body ground;
  ground.name = "ground";
  bodies_.push_back(ground);
}

void System::RequireNotFinalized() const {
  if (finalized_) throw Error("engine::System: cannot add to a finalized system");
}

int System::AddBody(const Body& body) {
  RequireNotFinalized();
  if (!(body.mass >= 0.0) || !std::isfinite(body.mass)) {
    throw Error({}, body.name, "body mass must be finite and >= 0");
  }
  if (!body.I_Bcm_B.allFinite() || !body.I_Bcm_B.isApprox(body.I_Bcm_B.transpose(), 1e-9) ||
      !body.p_BCm.allFinite()) {
    throw Error({}, body.name, "body inertia must be finite and symmetric");
  }
  bodies_.push_back(body);
  return num_bodies() - 1;
}

int System::AddJoint(const std::string& name, int parent, const Transform& X_PF, int child,
                     const Transform& X_BM, JointForm form,
                     std::shared_ptr<const kinematics::JointModel> model,
                     const std::vector<CoordinateDesc>& coordinates) {
  RequireNotFinalized();
  if (parent < 0 || parent >= num_bodies() || child < 0 || child >= num_bodies() ||
      parent == child) {
    throw Error({}, name, "joint connects invalid bodies");
  }
  const int expected =
      form == JointForm::kParameterized ? (model ? model->nq() : -1) : NumDirectCoordinates(form);
  if (expected < 0) throw Error({}, name, "a parameterized joint needs a JointModel");
  if (expected != static_cast<int>(coordinates.size())) {
    throw Error({}, name,
                "joint has " + std::to_string(coordinates.size()) + " coordinates, expected " +
                    std::to_string(expected));
  }
  Joint joint;
  joint.name = name;
  joint.parent = parent;
  joint.child = child;
  joint.X_PF = X_PF;
  joint.X_BM = X_BM;
  joint.form = form;
  joint.model = std::move(model);
  const int joint_index = static_cast<int>(joints_.size());
  for (size_t i = 0; i < coordinates.size(); ++i) {
    const CoordinateDesc& d = coordinates[i];
    Coordinate c;
    c.name = d.name;
    c.joint = joint_index;
    c.index_in_joint = static_cast<int>(i);
    c.default_value = d.default_value;
    c.default_speed = d.default_speed;
    c.motion = d.motion;
    c.prescribed = d.prescribed;
    c.assembly_weight = d.assembly_weight;
    if (!(d.assembly_weight >= 0.0) || !std::isfinite(d.assembly_weight)) {
      throw Error({}, name + "/" + d.name, "assembly weight must be finite and >= 0");
    }
    if (c.motion == CoordinateMotion::kPrescribed && !c.prescribed) {
      throw Error({}, name + "/" + d.name, "prescribed coordinate without a function");
    }
    if (c.motion != CoordinateMotion::kFree && form != JointForm::kParameterized) {
      throw Error({}, name + "/" + d.name,
                  "locked or prescribed coordinates need the parameterized joint form");
    }
    joint.coordinates.push_back(num_coordinates());
    coordinates_.push_back(c);
  }
  joints_.push_back(std::move(joint));
  return joint_index;
}

void System::AddConstraint(std::shared_ptr<const Constraint> constraint) {
  RequireNotFinalized();
  extra_constraints_.push_back(std::move(constraint));
}

int System::AddForceElement(std::shared_ptr<const ForceElement> force) {
  RequireNotFinalized();
  if (!force) throw Error("engine::System: null force element");
  const std::vector<std::string> z_names = force->StateVariableNames();
  const std::vector<std::string> input_names = force->InputNames();
  force_layout_.push_back({num_state_variables(), static_cast<int>(z_names.size()), num_inputs(),
                           static_cast<int>(input_names.size())});
  const std::string prefix =
      force->name().empty() ? "force" + std::to_string(forces_.size()) : force->name();
  for (const std::string& v : z_names) z_names_.push_back(prefix + "/" + v);
  for (const std::string& v : input_names) input_names_.push_back(prefix + "/" + v);
  if (force->HasDiscreteData()) discrete_forces_.push_back(static_cast<int>(forces_.size()));
  forces_.push_back(std::move(force));
  return static_cast<int>(forces_.size()) - 1;
}

void System::Finalize() {
  RequireNotFinalized();
  // Tree: walking the joints outward from ground places every body exactly once. A joint whose
  // child is nearer to ground is used reversed (the constraint itself is the same); a joint
  // between two bodies placed by others closes a loop: it stays a constraint (solved with the
  // others) but places no body.
  std::vector<std::array<int, 2>> bodies_of_joint;
  for (const Joint& joint : joints_) bodies_of_joint.push_back({joint.parent, joint.child});
  kinematics::JointTreeOrder order = kinematics::OrderJointTree(num_bodies(), bodies_of_joint);
  tree_order_ = std::move(order.order);
  reversed_ = std::move(order.reversed);
  loop_ = std::move(order.loop);
  joint_of_body_ = std::move(order.joint_of_body);
  const std::vector<bool>& placed_body = order.placed;
  bool any_mass = false;
  for (int b = 1; b < num_bodies(); ++b) {
    if (!placed_body[b]) {
      throw Error({}, bodies_[b].name, "no chain of joints connects the body to ground");
    }
    any_mass = any_mass || bodies_[b].mass > 0.0;
  }
  // With every body placed, every joint either placed one or closes a loop.
  if (num_bodies() > 1 && !any_mass) {
    throw Error(
        "every body has zero mass: forward dynamics is singular (a kinematics-only "
        "model cannot be simulated)");
  }
  for (const auto* names : {&z_names_, &input_names_}) {
    std::set<std::string_view> seen;
    for (const std::string& n : *names) {
      if (!seen.insert(n).second) {
        throw Error({}, n,
                    "two force elements declare this state variable or input: give them "
                    "different names");
      }
    }
  }
  // Speeds of parameterized joints are integrated unknowns.
  u_column_.assign(coordinates_.size(), -1);
  num_integrated_ = 0;
  for (const Joint& joint : joints_) {
    if (joint.form != JointForm::kParameterized) continue;
    for (int c : joint.coordinates) u_column_[c] = num_integrated_++;
  }
  // Constraints: joints, coordinate motions, extra.
  finalized_ = true;
  constraints_.clear();
  held_by_tree_placement_.clear();
  for (size_t j = 0; j < joints_.size(); ++j) {
    constraints_.push_back(MakeJointConstraint(*this, static_cast<int>(j)));
    held_by_tree_placement_.push_back(!loop_[j]);
  }
  for (int c = 0; c < num_coordinates(); ++c) {
    const Coordinate& coordinate = coordinates_[c];
    if (coordinate.motion == CoordinateMotion::kFree) continue;
    constraints_.push_back(MakeCoordinateMotionConstraint(*this, c));
    held_by_tree_placement_.push_back(coordinate.motion == CoordinateMotion::kLocked);
  }
  for (const auto& c : extra_constraints_) {
    constraints_.push_back(c);
    held_by_tree_placement_.push_back(false);
  }
  CollectBreakpoints();
}

void System::CollectBreakpoints() {
  breakpoints_.clear();
  for (const Joint& joint : joints_) {
    if (joint.form != JointForm::kParameterized || !joint.model) continue;
    for (const auto& [local, value] : joint.model->Breakpoints()) {
      breakpoints_.emplace_back(joint.coordinates[local], value);
    }
  }
  for (const auto& c : extra_constraints_) {
    const std::vector<std::pair<int, double>> points = c->Breakpoints();
    breakpoints_.insert(breakpoints_.end(), points.begin(), points.end());
  }
  // Only where the coordinate moves freely (a locked or prescribed one crosses nothing the
  // integrator could step to), each once.
  std::erase_if(breakpoints_, [this](const std::pair<int, double>& point) {
    return coordinates_[point.first].motion != CoordinateMotion::kFree;
  });
  std::sort(breakpoints_.begin(), breakpoints_.end());
  breakpoints_.erase(std::unique(breakpoints_.begin(), breakpoints_.end()), breakpoints_.end());
}

int System::FindBody(std::string_view name) const {
  for (int i = 0; i < num_bodies(); ++i) {
    if (bodies_[i].name == name) return i;
  }
  return -1;
}

int System::FindJoint(std::string_view name) const {
  for (size_t i = 0; i < joints_.size(); ++i) {
    if (joints_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int System::FindCoordinate(std::string_view name) const {
  for (int i = 0; i < num_coordinates(); ++i) {
    if (coordinates_[i].name == name) return i;
  }
  return -1;
}

namespace {
int FindName(const std::vector<std::string>& names, std::string_view name) {
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  return -1;
}
}  // namespace

int System::FindStateVariable(std::string_view name) const { return FindName(z_names_, name); }
int System::FindInput(std::string_view name) const { return FindName(input_names_, name); }

double ForceContext::z(int i) const { return state.z[z_begin + i]; }
double ForceContext::input(int i) const { return state.inputs[input_begin + i]; }

void System::UpdateDiscreteData(State& state, bool only_missing) const {
  for (const int k : discrete_forces_) {
    const ForceElement* owner = forces_[k].get();
    if (only_missing && FindDiscreteData(state, owner) != nullptr) continue;
    std::shared_ptr<const DiscreteData> data =
        owner->UpdateDiscreteData(MakeForceContext(k, state));
    auto entry = std::find_if(state.discrete.begin(), state.discrete.end(),
                              [owner](const DiscreteDataEntry& e) { return e.owner == owner; });
    if (entry == state.discrete.end()) {
      state.discrete.push_back({owner, std::move(data)});
    } else {
      entry->data = std::move(data);
    }
  }
}

}  // namespace sinew::engine
