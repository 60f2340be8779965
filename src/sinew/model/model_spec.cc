#include <sinew/model/model_spec.h>

namespace sinew::model {
namespace {

template <typename T>
int FindByName(const std::vector<T>& items, std::string_view name) {
  for (size_t i = 0; i < items.size(); ++i) {
    if (items[i].name == name) return static_cast<int>(i);
  }
  return kNone;
}

}  // namespace

int ModelSpec::FindBody(std::string_view body_name) const { return FindByName(bodies, body_name); }
int ModelSpec::FindJoint(std::string_view joint_name) const {
  return FindByName(joints, joint_name);
}
int ModelSpec::FindCoordinate(std::string_view coordinate_name) const {
  return FindByName(coordinates, coordinate_name);
}

}  // namespace sinew::model
