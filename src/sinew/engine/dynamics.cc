#include <sinew/common/text.h>
#include <sinew/engine/direct_joint.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/joint_values.h>
#include <sinew/engine/pose.h>
#include <sinew/math/finite.h>

#include <string>
#include <vector>

namespace sinew::engine {

void MapDirectJointForces(const System& system, const State& state, Loads& loads) {
  for (const Joint& joint : system.joints()) {
    if (joint.form == JointForm::kParameterized || joint.coordinates.empty()) continue;
    bool any = false;
    for (int c : joint.coordinates) any = any || loads.mobility[c] != 0.0;
    if (!any) continue;
    const JointValues q(state.q, joint.coordinates);
    const Mat6X H = CalcDirectH_FM(joint.form, q);
    const Mat3 R_GF = (PoseOf(state.bodies[joint.parent]) * joint.X_PF).R;
    for (size_t i = 0; i < joint.coordinates.size(); ++i) {
      const Vec3 tau_G = R_GF * H.col(i).head<3>() * loads.mobility[joint.coordinates[i]];
      loads.AddTorqueBetween(joint.parent, joint.child, tau_G);
    }
  }
}

namespace {
// Throws NonFiniteForceError naming force element k unless its state-variable derivatives are
// finite.
void CheckStateVariableDerivatives(const System& system, const State& state, int k,
                                   Eigen::Ref<const VecX> zdot) {
  if (!zdot.allFinite()) {
    throw NonFiniteForceError(
        {}, system.force_elements()[k]->name(),
        "its state-variable derivatives are not finite at t = " + FormatNumber(state.t) + " s");
  }
}
}  // namespace

void CalcLoads(const System& system, const State& state, const Loads* external, Loads& loads,
               Eigen::Ref<VecX>* zdot) {
  if (static_cast<int>(loads.body.size()) == system.num_bodies() &&
      loads.mobility.size() == system.num_coordinates()) {
    loads.SetZero();  // reused: no heap use
  } else {
    loads = Loads(system.num_bodies(), system.num_coordinates());
  }
  for (int b = 1; b < system.num_bodies(); ++b) {
    const Body& body = system.bodies()[b];
    if (body.mass == 0.0) continue;
    const Vec3 c_G = state.bodies[b].quat_GB.normalized() * body.p_BCm;
    const Vec3 f_G = body.mass * system.gravity();
    loads.body[b].head<3>() += c_G.cross(f_G);
    loads.body[b].tail<3>() += f_G;
  }
  const auto& forces = system.force_elements();
  for (size_t k = 0; k < forces.size(); ++k) {
    const int element = static_cast<int>(k);
    const ForceContext context = system.MakeForceContext(element, state);
    const int n = zdot ? system.NumStateVariables(element) : 0;
    if (n == 0) {
      forces[k]->AddLoads(context, loads);
      continue;
    }
    auto element_zdot = zdot->segment(system.StateVariableBegin(element), n);
    forces[k]->AddLoadsAndStateVariableDerivatives(context, loads, element_zdot);
    CheckStateVariableDerivatives(system, state, element, element_zdot);
  }
  if (external) {
    for (int b = 0; b < system.num_bodies(); ++b) loads.body[b] += external->body[b];
    loads.mobility += external->mobility;
  }
  MapDirectJointForces(system, state, loads);
}

void CalcStateVariableDerivatives(const System& system, const State& state, Eigen::Ref<VecX> zdot) {
  const auto& forces = system.force_elements();
  for (size_t k = 0; k < forces.size(); ++k) {
    const int element = static_cast<int>(k);
    const int n = system.NumStateVariables(element);
    if (n == 0) continue;
    auto element_zdot = zdot.segment(system.StateVariableBegin(element), n);
    forces[k]->CalcStateVariableDerivatives(system.MakeForceContext(element, state), element_zdot);
    CheckStateVariableDerivatives(system, state, element, element_zdot);
  }
}

Data::Data(const System& system, KktSolver::Method method)
    : kkt(system, method), loads(system.num_bodies(), system.num_coordinates()) {
  rhs = VecX::Zero(kkt.num_velocities() + kkt.num_equations());
  solution = rhs;
  accelerations.vdot = VecX::Zero(kkt.num_velocities());
  accelerations.lambda = VecX::Zero(kkt.num_equations());
}

namespace {
// Names the first source of a right-hand side that is not finite at `state`: a force element
// (each evaluated alone, only on this failure path), else the state, a constraint or the
// external loads.
[[noreturn]] void ThrowNonFiniteLoads(const System& system, const State& state,
                                      const Loads* external) {
  const std::string at = " at t = " + FormatNumber(state.t) + " s";
  const auto& forces = system.force_elements();
  for (size_t k = 0; k < forces.size(); ++k) {
    Loads alone(system.num_bodies(), system.num_coordinates());
    forces[k]->AddLoads(system.MakeForceContext(static_cast<int>(k), state), alone);
    bool finite = alone.mobility.allFinite();
    for (const SpatialVec& load : alone.body) finite = finite && load.allFinite();
    if (!finite) throw NonFiniteForceError({}, forces[k]->name(), "its loads are not finite" + at);
  }
  throw NonFiniteForceError("engine: the equations of motion are not finite" + at +
                            ", though every force element's loads are: the state, a constraint" +
                            (external ? " or the external loads" : "") + " is not finite");
}

}  // namespace

void CalcForceRhs(const System& system, const State& state, const Loads* external, const Data& data,
                  Eigen::Ref<VecX> rhs) {
  const Loads& loads = data.loads;
  const KktSolver& kkt = data.kkt;
  rhs.setZero();
  // Body rows: applied loads minus the velocity-dependent (gyroscopic, centripetal) terms of
  // the Newton-Euler equations about the body origin.
  for (int b = 1; b < system.num_bodies(); ++b) {
    const Body& body = system.bodies()[b];
    const BodyState& s = state.bodies[b];
    const Mat3 R = s.quat_GB.normalized().toRotationMatrix();
    const Vec3 c = R * body.p_BCm;
    const Mat3 I_G = R * body.I_Bcm_B * R.transpose();
    const Vec3& w = s.w_GB;
    const Vec3 centripetal = body.mass * w.cross(w.cross(c));
    SpatialVec bias;
    bias.head<3>() = w.cross(I_G * w) + c.cross(centripetal);
    bias.tail<3>() = centripetal;
    rhs.segment<6>(kkt.BodyColumn(b)) = loads.body[b] - bias;
  }
  for (int c = 0; c < system.num_coordinates(); ++c) {
    if (system.IsIntegrated(c)) rhs[kkt.SpeedColumn(c)] = loads.mobility[c];
  }
  if (!AllFinite(rhs)) ThrowNonFiniteLoads(system, state, external);
}

void CalcForceRhsReusingFactorization(const System& system, const State& state,
                                      const Loads* external, Data& data, Eigen::Ref<VecX> rhs,
                                      Eigen::Ref<VecX>* zdot) {
  CalcLoads(system, state, external, data.loads, zdot);
  if (!data.kkt.IsFactorizedAt(state)) data.kkt.Factorize(state);
  CalcForceRhs(system, state, external, data, rhs);
}

namespace {
// The accelerations for data.loads with data.kkt factorized at `state`.
const Accelerations& SolveAccelerations(const System& system, const State& state,
                                        const Loads* external, Data& data) {
  const KktSolver& kkt = data.kkt;
  const int nv = kkt.num_velocities();
  VecX& rhs = data.rhs;
  CalcForceRhs(system, state, external, data, rhs.head(nv));
  const auto& constraints = system.constraints();
  for (size_t k = 0; k < constraints.size(); ++k) {
    constraints[k]->CalcAccelerationRhs(
        system, state, rhs.segment(nv + kkt.EquationRow(k), constraints[k]->NumEquations()));
  }
  // The loads' rows were checked by CalcForceRhs.
  if (!AllFinite(rhs.tail(kkt.num_equations()))) ThrowNonFiniteLoads(system, state, external);
  kkt.Solve(rhs, data.solution);
  data.accelerations.vdot = data.solution.head(nv);
  data.accelerations.lambda = data.solution.tail(kkt.num_equations());
  return data.accelerations;
}
}  // namespace

const Accelerations& CalcAccelerations(const System& system, const State& state,
                                       const Loads* external, Data& data) {
  CalcLoads(system, state, external, data.loads);
  data.kkt.Factorize(state);
  return SolveAccelerations(system, state, external, data);
}

const Accelerations& CalcAccelerationsReusingFactorization(const System& system, const State& state,
                                                           const Loads* external, Data& data,
                                                           Eigen::Ref<VecX>* zdot) {
  CalcLoads(system, state, external, data.loads, zdot);
  if (!data.kkt.IsFactorizedAt(state)) data.kkt.Factorize(state);
  return SolveAccelerations(system, state, external, data);
}

}  // namespace sinew::engine
