#include <sinew/engine/state.h>
#include <sinew/muscles/path_spring.h>

#include <algorithm>
#include <utility>

namespace sinew::muscles {

PathSpring::PathSpring(std::string name, EnginePath path, double resting_length, double stiffness,
                       double dissipation)
    : name_(std::move(name)),
      path_(std::move(path)),
      resting_length_(resting_length),
      stiffness_(stiffness),
      dissipation_(dissipation) {}

double PathSpring::CalcTension(const PathKinematics& path) const {
  const double stretch = std::max(path.length - resting_length_, 0.0);
  return stiffness_ * stretch * (1.0 + dissipation_ * path.lengthening_speed);
}

void PathSpring::AddLoads(const engine::ForceContext& context, engine::Loads& loads) const {
  PathScratch& scratch = EnginePath::Scratch();
  const double tension = CalcTension(path_.Calc(context.state, scratch));
  path_.AddTensionLoads(context.state, tension, scratch, loads);
}

double PathSpring::CalcPotentialEnergy(const engine::ForceContext& context) const {
  const double stretch =
      std::max(path_.Calc(context.state, EnginePath::Scratch()).length - resting_length_, 0.0);
  return 0.5 * stiffness_ * stretch * stretch;
}

std::vector<std::string> PathSpring::RecordLabels(const engine::System& /*system*/) const {
  return {name_};
}

void PathSpring::CalcRecordValues(const engine::ForceContext& context,
                                  std::vector<double>& values) const {
  values.push_back(CalcTension(path_.Calc(context.state, EnginePath::Scratch())));
}

}  // namespace sinew::muscles
