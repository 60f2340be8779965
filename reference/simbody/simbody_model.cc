#include "simbody/simbody_model.h"

#include <Simbody.h>

#include <array>
#include <stdexcept>
#include <utility>

namespace simbody_reference {
namespace {

SimTK::Vec3 ToVec3(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

SimTK::Mat33 ToMat33(const std::array<double, 9>& m) {
  SimTK::Mat33 R;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) R(i, j) = m[3 * i + j];
  }
  return R;
}

SimTK::Transform ToTransform(const Pose& X) {
  return {SimTK::Rotation(ToMat33(X.R), true), ToVec3(X.p)};
}

// A ScalarFunction of n arguments as a SimTK::Function (owned by the mobilizer or constraint
// it is given to, as Simbody does).
class Callback final : public SimTK::Function {
 public:
  Callback(ScalarFunction f, int n) : f_(std::move(f)), n_(n) {
    if (n > kMaxArguments) throw std::runtime_error("simbody_reference: too many arguments");
  }
  double calcValue(const SimTK::Vector& x) const override {
    std::array<double, kMaxArguments> a;
    for (int i = 0; i < n_; ++i) a[i] = x[i];
    return f_(a.data(), n_, nullptr, 0);
  }
  double calcDerivative(const SimTK::Array_<int>& wrt, const SimTK::Vector& x) const override {
    std::array<double, kMaxArguments> a;
    for (int i = 0; i < n_; ++i) a[i] = x[i];
    return f_(a.data(), n_, wrt.data(), static_cast<int>(wrt.size()));
  }
  int getArgumentSize() const override { return n_; }
  int getMaxDerivativeOrder() const override { return 2; }

 private:
  ScalarFunction f_;
  int n_;
};

// Where a model coordinate lives: its mobilized body and q index there.
struct Slot {
  SimTK::MobilizedBodyIndex body;
  int q = -1;
};

}  // namespace

struct Simulation::Impl {
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter{system};
  SimTK::GeneralForceSubsystem forces{system};
  std::vector<Slot> slots;
  std::vector<double> q0;
  SimTK::State start;
  mutable SimTK::State work;  // EvaluateAccelerations' state
  mutable bool work_made = false;
};

Simulation::Simulation(const Model& model) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  SimTK::Force::UniformGravity(s.forces, s.matter, ToVec3(model.gravity));
  s.slots.resize(model.q.size());
  s.q0 = model.q;
  std::vector<SimTK::MobilizedBody> mobods(model.bodies.size());
  mobods[0] = s.matter.Ground();
  for (const Joint& joint : model.joints) {
    // The mobilizer's inboard body and frame, its outboard body and frame.
    const int inboard = joint.reversed ? joint.child : joint.parent;
    const int outboard = joint.reversed ? joint.parent : joint.child;
    if (!mobods.at(inboard).getMobilizedBodyIndex().isValid()) {
      throw std::runtime_error("simbody_reference: a joint comes before its inboard body's");
    }
    const Body& b = model.bodies.at(outboard);
    const SimTK::Vec3 com = ToVec3(b.mass_center);
    const SimTK::Inertia central{SimTK::SymMat33(ToMat33(b.inertia))};
    const SimTK::Body::Rigid body(
        SimTK::MassProperties(b.mass, com, central.shiftFromMassCenter(com, b.mass)));
    const SimTK::Transform X_PF = ToTransform(joint.reversed ? joint.X_BM : joint.X_PF);
    const SimTK::Transform X_BM = ToTransform(joint.reversed ? joint.X_PF : joint.X_BM);
    const auto direction =
        joint.reversed ? SimTK::MobilizedBody::Reverse : SimTK::MobilizedBody::Forward;
    SimTK::MobilizedBody& parent = mobods[inboard];
    SimTK::MobilizedBody& made = mobods[outboard];
    switch (joint.kind) {
      case Joint::Kind::kPin:
        made = SimTK::MobilizedBody::Pin(parent, X_PF, body, X_BM, direction);
        break;
      case Joint::Kind::kSlider:
        made = SimTK::MobilizedBody::Slider(parent, X_PF, body, X_BM, direction);
        break;
      case Joint::Kind::kUniversal:
        made = SimTK::MobilizedBody::Universal(parent, X_PF, body, X_BM, direction);
        break;
      case Joint::Kind::kGimbal:
        made = SimTK::MobilizedBody::Gimbal(parent, X_PF, body, X_BM, direction);
        break;
      case Joint::Kind::kBall:
        made = SimTK::MobilizedBody::Ball(parent, X_PF, body, X_BM, direction);
        break;
      case Joint::Kind::kEllipsoid:
        made = SimTK::MobilizedBody::Ellipsoid(parent, X_PF, body, X_BM, ToVec3(joint.radii),
                                               direction);
        break;
      case Joint::Kind::kFree:
        made = SimTK::MobilizedBody::Free(parent, X_PF, body, X_BM, direction);
        break;
      case Joint::Kind::kPlanar:
        made = SimTK::MobilizedBody::Planar(parent, X_PF, body, X_BM, direction);
        break;
      case Joint::Kind::kWeld:
        made = SimTK::MobilizedBody::Weld(parent, X_PF, body, X_BM);
        break;
      case Joint::Kind::kFunctionBased: {
        SimTK::Array_<const SimTK::Function*> functions;
        SimTK::Array_<SimTK::Array_<int>> arguments;
        SimTK::Array_<SimTK::Vec3> axes;
        for (const Axis& axis : joint.axes) {
          functions.push_back(new Callback(axis.f, static_cast<int>(axis.arguments.size())));
          arguments.push_back(SimTK::Array_<int>(axis.arguments.begin(), axis.arguments.end()));
          axes.push_back(SimTK::UnitVec3(ToVec3(axis.axis)));
        }
        made = SimTK::MobilizedBody::FunctionBased(parent, X_PF, body, X_BM,
                                                   static_cast<int>(joint.coordinates.size()),
                                                   functions, arguments, axes, direction);
        break;
      }
    }
    for (size_t i = 0; i < joint.coordinates.size(); ++i) {
      s.slots.at(joint.coordinates[i]) = {made.getMobilizedBodyIndex(), static_cast<int>(i)};
    }
  }
  for (const Coupler& c : model.couplers) {
    SimTK::Array_<SimTK::MobilizedBodyIndex> bodies;
    SimTK::Array_<SimTK::MobilizerQIndex> qs;
    for (int k : c.coordinates) {
      bodies.push_back(s.slots.at(k).body);
      qs.push_back(SimTK::MobilizerQIndex(s.slots.at(k).q));
    }
    SimTK::Constraint::CoordinateCoupler(
        s.matter, new Callback(c.f, static_cast<int>(c.coordinates.size())), bodies, qs);
  }
  for (int k : model.locked) {
    SimTK::MobilizedBody& m = s.matter.updMobilizedBody(s.slots.at(k).body);
    SimTK::Constraint::ConstantCoordinate(m, SimTK::MobilizerQIndex(s.slots.at(k).q),
                                          model.q.at(k));
  }
  s.system.realizeTopology();
  s.start = s.system.getDefaultState();
  // Ball, Free and Ellipsoid coordinates as angles, as OpenSim sets them.
  s.matter.setUseEulerAngles(s.start, true);
  s.system.realizeModel(s.start);
  for (size_t c = 0; c < s.slots.size(); ++c) {
    if (!s.slots[c].body.isValid()) continue;
    const SimTK::MobilizedBody& m = s.matter.getMobilizedBody(s.slots[c].body);
    m.setOneQ(s.start, s.slots[c].q, model.q[c]);
    m.setOneU(s.start, s.slots[c].q, model.u[c]);
  }
}

Simulation::~Simulation() = default;

double Simulation::EvaluateAccelerations() const {
  const Impl& s = *impl_;
  if (!s.work_made) s.work = s.start, s.work_made = true;
  // A new position each time (alternating by 1e-12): nothing cached can be reused.
  s.work.updQ()[0] = s.start.getQ()[0] + ((s.work.getQ()[0] == s.start.getQ()[0]) ? 1e-12 : 0.0);
  s.system.realize(s.work, SimTK::Stage::Acceleration);
  return s.work.getUDot().size() > 0 ? s.work.getUDot()[0] : 0.0;
}

std::vector<double> Simulation::Run(Scheme scheme, double accuracy, double t_final,
                                    RunStats* stats) const {
  const Impl& s = *impl_;
  std::unique_ptr<SimTK::Integrator> made;
  if (scheme == Scheme::kRungeKuttaMerson) {
    made = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(s.system);
  } else {
    made = std::make_unique<SimTK::RungeKuttaFeldbergIntegrator>(s.system);
  }
  SimTK::Integrator& integrator = *made;
  integrator.setAccuracy(accuracy);
  integrator.initialize(s.start);
  // stepTo also returns at events (the start of the continuous interval first).
  while (integrator.getTime() < t_final) {
    if (integrator.stepTo(t_final) == SimTK::Integrator::EndOfSimulation) {
      throw std::runtime_error(
          "simbody_reference: Simbody's integrator ended the simulation early");
    }
  }
  if (stats != nullptr) {
    stats->steps = integrator.getNumStepsTaken();
    stats->attempted = integrator.getNumStepsAttempted();
    stats->realizations = integrator.getNumRealizations();
    SimTK::State start = s.start;
    s.system.realize(start, SimTK::Stage::Dynamics);
    s.system.realize(integrator.getState(), SimTK::Stage::Dynamics);
    stats->energy_change = s.system.calcEnergy(integrator.getState()) - s.system.calcEnergy(start);
  }
  std::vector<double> q = s.q0;
  for (size_t c = 0; c < s.slots.size(); ++c) {
    if (!s.slots[c].body.isValid()) continue;
    q[c] = s.matter.getMobilizedBody(s.slots[c].body).getOneQ(integrator.getState(), s.slots[c].q);
  }
  return q;
}

}  // namespace simbody_reference
