#include <sinew/kinematics/body_depths.h>

#include <queue>

namespace sinew::kinematics {

std::vector<int> CalcBodyDepths(const model::ModelSpec& spec) {
  const int n = static_cast<int>(spec.bodies.size());
  std::vector<std::vector<int>> neighbours(n);
  for (const model::JointSpec& j : spec.joints) {
    if (j.parent_body < 0 || j.parent_body >= n || j.child_body < 0 || j.child_body >= n) continue;
    neighbours[j.parent_body].push_back(j.child_body);
    neighbours[j.child_body].push_back(j.parent_body);
  }
  std::vector<int> depth(n, -1);
  if (n == 0) return depth;
  std::queue<int> frontier;
  depth[model::kGroundIndex] = 0;
  frontier.push(model::kGroundIndex);
  while (!frontier.empty()) {
    const int b = frontier.front();
    frontier.pop();
    for (int next : neighbours[b]) {
      if (depth[next] >= 0) continue;
      depth[next] = depth[b] + 1;
      frontier.push(next);
    }
  }
  return depth;
}

}  // namespace sinew::kinematics
