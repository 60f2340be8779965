// Checks on the assembled spec that no single element can make: every body reachable from ground
// through joints, cycles of joints that never reach ground, closed loops (kept, with a note).
#include <sinew/io/internal/osim_context.h>

#include <map>
#include <string>
#include <vector>

namespace sinew::io::internal {

void ValidateSpec(ReadContext& ctx, const pugi::xml_node& model) {
  const model::ModelSpec& spec = ctx.spec();
  const XmlDocument& doc = ctx.doc();
  const int n = static_cast<int>(spec.bodies.size());

  std::vector<std::vector<int>> joints_of(n);      // joints touching each body
  std::vector<std::vector<int>> parent_joints(n);  // joints whose child is the body
  for (size_t j = 0; j < spec.joints.size(); ++j) {
    const model::JointSpec& joint = spec.joints[j];
    if (joint.parent_body == joint.child_body) {
      throw Error(joint.where, joint.path,
                  "joint connects body '" + spec.bodies[joint.parent_body].name + "' to itself");
    }
    joints_of[joint.parent_body].push_back(static_cast<int>(j));
    joints_of[joint.child_body].push_back(static_cast<int>(j));
    parent_joints[joint.child_body].push_back(static_cast<int>(j));
  }

  // Reachability from ground, joints taken in either direction (OpenSim reverses a joint in its
  // multibody tree when needed).
  std::vector<bool> reached(n, false);
  std::vector<int> stack = {model::kGroundIndex};
  reached[model::kGroundIndex] = true;
  while (!stack.empty()) {
    const int b = stack.back();
    stack.pop_back();
    for (int j : joints_of[b]) {
      const int other =
          spec.joints[j].parent_body == b ? spec.joints[j].child_body : spec.joints[j].parent_body;
      if (!reached[other]) {
        reached[other] = true;
        stack.push_back(other);
      }
    }
  }
  for (int b = 1; b < n; ++b) {
    if (reached[b]) continue;
    // Follow parents: a cycle explains why ground is never reached.
    std::vector<int> seen_at(n, -1);
    std::vector<int> chain;
    int body = b;
    while (body != model::kNone && seen_at[body] < 0 && !parent_joints[body].empty()) {
      seen_at[body] = static_cast<int>(chain.size());
      const int j = parent_joints[body][0];
      chain.push_back(j);
      body = spec.joints[j].parent_body;
    }
    if (body != model::kNone && seen_at[body] >= 0) {
      std::string cycle;
      for (size_t i = static_cast<size_t>(seen_at[body]); i < chain.size(); ++i) {
        const model::JointSpec& j = spec.joints[chain[i]];
        cycle += (cycle.empty() ? "" : ", ") + j.name + " (" + spec.bodies[j.parent_body].name +
                 " -> " + spec.bodies[j.child_body].name + ")";
      }
      const model::JointSpec& first = spec.joints[chain[seen_at[body]]];
      throw Error(first.where, first.path,
                  "joints form a cycle that never reaches ground: " + cycle);
    }
    throw Error(spec.bodies[b].where, spec.bodies[b].path,
                "body '" + spec.bodies[b].name + "' is not connected to ground by any joint");
  }

  // A joint between bodies already connected closes a kinematic loop: legal in OpenSim (its
  // graph maker cuts the loop), noted for the engine. Union-find over the joints in file order.
  std::vector<int> root(n);
  for (int b = 0; b < n; ++b) root[b] = b;
  auto find = [&root](int b) {
    while (root[b] != b) b = root[b] = root[root[b]];
    return b;
  };
  for (const model::JointSpec& joint : spec.joints) {
    const int a = find(joint.parent_body), b = find(joint.child_body);
    if (a == b) {
      ctx.spec().warnings.push_back({joint.where, joint.path,
                                     "joint closes a kinematic loop between '" +
                                         spec.bodies[joint.parent_body].name + "' and '" +
                                         spec.bodies[joint.child_body].name + "'"});
    } else {
      root[a] = b;
    }
  }

  // Zero mass everywhere: fine for kinematics, singular for forward dynamics (say so once).
  bool any_mass = false;
  for (int b = 1; b < n; ++b) any_mass = any_mass || spec.bodies[b].mass > 0;
  if (n > 1 && !any_mass) {
    ctx.Warn(model, "/bodyset",
             "every body has zero mass: kinematics only, forward dynamics would be singular");
  }

  // Coordinate names used twice: fine until something refers to one by name (that fails).
  std::map<std::string, int> uses;
  for (const model::CoordinateSpec& c : spec.coordinates) ++uses[c.name];
  std::string repeated;
  int count = 0;
  for (const auto& [name, times] : uses) {
    if (times < 2) continue;
    if (++count <= 8) repeated += (repeated.empty() ? "" : ", ") + name;
  }
  if (count > 0) {
    if (count > 8) repeated += ", ...";
    ctx.Warn(model, "/jointset",
             std::to_string(count) + " coordinate name" + (count == 1 ? " is" : "s are") +
                 " used more than once (" + repeated + "); references by name are ambiguous");
  }
  (void)doc;
}

}  // namespace sinew::io::internal
