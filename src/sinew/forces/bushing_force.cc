#include <sinew/engine/state.h>
#include <sinew/forces/bushing_force.h>

#include <utility>

namespace sinew::forces {

Vec6 FunctionBushingStiffness::Calc(const Vec6& q) const {
  Vec6 fk;
  for (int i = 0; i < 6; ++i) fk[i] = functions_[i]->Calc(q[i]);
  return fk;
}

BushingForce::BushingForce(std::string name, const LinkedFrames& frames,
                           std::shared_ptr<const BushingStiffness> stiffness, const Vec6& damping)
    : name_(std::move(name)),
      frames_(frames),
      stiffness_(std::move(stiffness)),
      damping_(damping) {}

Vec6 BushingForce::InternalForce(const FrameDeflection& d) const {
  return -stiffness_->Calc(d.q) - damping_.cwiseProduct(d.qdot);
}

Vec6 BushingForce::CalcInternalForce(const engine::ForceContext& context) const {
  return InternalForce(CalcFrameDeflection(context.state, frames_));
}

void BushingForce::AddLoads(const engine::ForceContext& context, engine::Loads& loads) const {
  const FrameDeflection d = CalcFrameDeflection(context.state, frames_);
  AddInternalForce(context.state, frames_, d, InternalForce(d), loads);
}

double BushingForce::CalcPotentialEnergy(const engine::ForceContext& context) const {
  return stiffness_->CalcPotentialEnergy(CalcFrameDeflection(context.state, frames_).q);
}

}  // namespace sinew::forces
