#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/assemble_state.h>
#include <sinew/engine/direct_joint.h>
#include <sinew/engine/pose.h>

#include <array>
#include <span>
#include <string>
#include <vector>

namespace sinew::engine {
namespace {

std::vector<double> Gather(const VecX& x, const std::vector<int>& indices) {
  std::vector<double> out;
  out.reserve(indices.size());
  for (int i : indices) out.push_back(x[i]);
  return out;
}

int RequireCoordinate(const System& system, std::string_view name) {
  const int c = system.FindCoordinate(name);
  if (c < 0) throw Error("no coordinate named '" + std::string(name) + "'");
  return c;
}

}  // namespace

State MakeDefaultState(const System& system, double t) {
  State state;
  state.t = t;
  state.bodies.assign(system.num_bodies(), BodyState{});
  state.q = VecX::Zero(system.num_coordinates());
  state.u = VecX::Zero(system.num_coordinates());
  for (int c = 0; c < system.num_coordinates(); ++c) {
    const Coordinate& coordinate = system.coordinates()[c];
    if (coordinate.motion == CoordinateMotion::kPrescribed) {
      state.q[c] = coordinate.prescribed->Calc(t);
      state.u[c] = coordinate.prescribed->CalcDerivative(t, 1);
    } else {
      state.q[c] = coordinate.default_value;
      state.u[c] = coordinate.motion == CoordinateMotion::kLocked ? 0.0 : coordinate.default_speed;
    }
  }
  state.inputs = VecX::Zero(system.num_inputs());
  state.z = VecX::Zero(system.num_state_variables());
  PlaceBodies(system, state);
  // Joints that close loops were not used to place bodies, and extra constraints (couplers,
  // welds, ...) need not hold at the default values: assemble them as OpenSim does.
  if (system.HasLoops() || system.HasExtraConstraints()) AssembleState(system, state);
  for (int k = 0; k < static_cast<int>(system.force_elements().size()); ++k) {
    const int n = system.NumStateVariables(k);
    if (n > 0) {
      system.force_elements()[k]->SetDefaultStateVariables(
          state.z.segment(system.StateVariableBegin(k), n));
    }
  }
  InitializeStateVariables(system, state);
  return state;
}

void InitializeStateVariables(const System& system, State& state) {
  CheckState(system, state);
  for (int k = 0; k < static_cast<int>(system.force_elements().size()); ++k) {
    const int n = system.NumStateVariables(k);
    if (n == 0) continue;
    // The element reads a copy of the state, so what it writes cannot alias what it reads.
    const State before = state;
    system.force_elements()[k]->InitializeStateVariables(
        system.MakeForceContext(k, before), state.z.segment(system.StateVariableBegin(k), n));
  }
}

void CheckState(const System& system, const State& state) {
  if (static_cast<int>(state.bodies.size()) != system.num_bodies() ||
      state.q.size() != system.num_coordinates() || state.u.size() != system.num_coordinates() ||
      state.z.size() != system.num_state_variables() ||
      state.inputs.size() != system.num_inputs()) {
    throw Error("engine: the state does not belong to this system (" +
                std::to_string(state.bodies.size()) + " bodies, " + std::to_string(state.q.size()) +
                " coordinates, " + std::to_string(state.z.size()) + " state variables, " +
                std::to_string(state.inputs.size()) + " inputs; the system has " +
                std::to_string(system.num_bodies()) + ", " +
                std::to_string(system.num_coordinates()) + ", " +
                std::to_string(system.num_state_variables()) + " and " +
                std::to_string(system.num_inputs()) + ")");
  }
}

void PlaceBodies(const System& system, State& state) {
  CheckState(system, state);
  for (int j : system.tree_order()) {
    const Joint& joint = system.joints()[j];
    const std::vector<double> q = Gather(state.q, joint.coordinates);
    const std::vector<double> u = Gather(state.u, joint.coordinates);
    Transform X_FM;
    Mat6X H;
    if (joint.form == JointForm::kParameterized) {
      X_FM = joint.model->CalcX_FM(q);
      H = joint.model->CalcH_FM(q);
    } else {
      X_FM = CalcDirectX_FM(joint.form, q);
      H = CalcDirectH_FM(joint.form, q);
    }
    SpatialVec V_FM_F = SpatialVec::Zero();
    if (H.cols() > 0) V_FM_F = H * Eigen::Map<const VecX>(u.data(), u.size());
    const JointFrames frames = PlaceBodyThroughJoint(system, j, X_FM, state);
    BodyState& P = state.bodies[joint.parent];
    BodyState& B = state.bodies[joint.child];
    const Vec3 w_FM_G = frames.X_GF.R * V_FM_F.head<3>();
    const Vec3 v_FM_G = frames.X_GF.R * V_FM_F.tail<3>();
    const Vec3& p_GM = frames.X_GM.p;
    if (!system.IsReversed(j)) {
      B.w_GB = P.w_GB + w_FM_G;
      const Vec3 v_M = PointVelocity(P, p_GM) + v_FM_G;
      B.v_GB = v_M + B.w_GB.cross(B.p_GB - p_GM);
    } else {
      P.w_GB = B.w_GB - w_FM_G;
      const Vec3 v_M = PointVelocity(B, p_GM) - v_FM_G;
      P.v_GB = v_M + P.w_GB.cross(P.p_GB - p_GM);
    }
  }
}

JointFrames PlaceBodyThroughJoint(const System& system, int j, const Transform& X_FM,
                                  State& state) {
  const Joint& joint = system.joints()[j];
  JointFrames frames;
  Transform X_GB;
  BodyState* placed = nullptr;
  if (!system.IsReversed(j)) {
    frames.X_GF = PoseOf(state.bodies[joint.parent]) * joint.X_PF;
    frames.X_GM = frames.X_GF * X_FM;
    X_GB = frames.X_GM * joint.X_BM.Inverse();
    placed = &state.bodies[joint.child];
  } else {
    // The parent is placed: X_GP = X_GB X_BM inverse(X_FM) inverse(X_PF).
    frames.X_GM = PoseOf(state.bodies[joint.child]) * joint.X_BM;
    frames.X_GF = frames.X_GM * X_FM.Inverse();
    X_GB = frames.X_GF * joint.X_PF.Inverse();
    placed = &state.bodies[joint.parent];
  }
  placed->p_GB = X_GB.p;
  placed->quat_GB = Quat(X_GB.R).normalized();
  return frames;
}

Transform CalcJointTransform(const System& system, const State& state, int j) {
  const Joint& joint = system.joints()[j];
  return (PoseOf(state.bodies[joint.parent]) * joint.X_PF).Inverse() *
         PoseOf(state.bodies[joint.child]) * joint.X_BM;
}

SpatialVec CalcJointVelocity(const System& system, const State& state, int j) {
  const Joint& joint = system.joints()[j];
  const BodyState& P = state.bodies[joint.parent];
  const BodyState& B = state.bodies[joint.child];
  const Transform X_GF = PoseOf(P) * joint.X_PF;
  const Vec3 p_GM = PoseOf(B) * joint.X_BM.p;
  const Mat3 Rt = X_GF.R.transpose();
  SpatialVec V;
  V.head<3>() = Rt * (B.w_GB - P.w_GB);
  V.tail<3>() = Rt * (PointVelocity(B, p_GM) - PointVelocity(P, p_GM));
  return V;
}

void UpdateDirectCoordinates(const System& system, State& state) {
  for (size_t j = 0; j < system.joints().size(); ++j) {
    const Joint& joint = system.joints()[j];
    if (joint.form == JointForm::kParameterized || joint.coordinates.empty()) continue;
    const Transform X_FM = CalcJointTransform(system, state, static_cast<int>(j));
    // A direct joint has at most 3 coordinates (a Ball); no heap use, as this runs every step.
    std::array<double, 3> q_buffer{}, u_buffer{};
    const size_t n = joint.coordinates.size();
    if (n > q_buffer.size()) throw Error("joint '" + joint.name + "': too many coordinates");
    const std::span<double> q(q_buffer.data(), n), u(u_buffer.data(), n);
    for (size_t i = 0; i < n; ++i) q[i] = state.q[joint.coordinates[i]];
    ReadDirectCoordinates(joint.form, X_FM, CalcJointVelocity(system, state, static_cast<int>(j)),
                          q, u);
    for (size_t i = 0; i < n; ++i) {
      state.q[joint.coordinates[i]] = q[i];
      state.u[joint.coordinates[i]] = u[i];
    }
  }
}

double GetCoordinateValue(const System& system, const State& state, std::string_view name) {
  return state.q[RequireCoordinate(system, name)];
}

double GetCoordinateSpeed(const System& system, const State& state, std::string_view name) {
  return state.u[RequireCoordinate(system, name)];
}

void SetCoordinateValue(const System& system, State& state, std::string_view name, double q) {
  state.q[RequireCoordinate(system, name)] = q;
  PlaceBodies(system, state);
}

void SetCoordinateSpeed(const System& system, State& state, std::string_view name, double u) {
  state.u[RequireCoordinate(system, name)] = u;
  PlaceBodies(system, state);
}

}  // namespace sinew::engine
