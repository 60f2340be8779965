#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/force_jacobian.h>
#include <sinew/engine/projection.h>

#include <algorithm>

namespace sinew::engine {
namespace {

// Step of the central differences: the loads are smooth on this scale, and the truncation
// (eps^2) and rounding (1e-16 / eps) errors are both ~1e-10 relative.
constexpr double kStep = 1e-6;

void AddBodyColumns(const KktSolver& kkt, int b, std::vector<int>& columns) {
  if (b == 0) return;
  const int first = kkt.BodyColumn(b);
  if (std::find(columns.begin(), columns.end(), first) != columns.end()) return;
  for (int i = 0; i < 6; ++i) columns.push_back(first + i);
}

// True when element k's analytic blocks may be used: a declared support whose coordinates are
// all integrated (so its columns follow Support() one to one).
bool HasPlainSupport(const System& system, int k) {
  const auto support = system.force_elements()[k]->Support();
  if (!support) return false;
  for (int c : support->coordinates) {
    if (!system.IsIntegrated(c)) return false;
  }
  for (int b : support->bodies) {
    if (b == 0) return false;
  }
  return true;
}

}  // namespace

std::vector<int> CalcSupportColumns(const System& system, const KktSolver& kkt, int k) {
  const auto support = system.force_elements()[k]->Support();
  std::vector<int> columns;
  if (!support) {
    for (int i = 0; i < kkt.num_velocities(); ++i) columns.push_back(i);
    return columns;
  }
  for (int b : support->bodies) AddBodyColumns(kkt, b, columns);
  for (int c : support->coordinates) {
    if (system.IsIntegrated(c)) {
      columns.push_back(kkt.SpeedColumn(c));
    } else {
      const Joint& joint = system.joints()[system.coordinates()[c].joint];
      AddBodyColumns(kkt, joint.parent, columns);
      AddBodyColumns(kkt, joint.child, columns);
    }
  }
  return columns;
}

VecX CalcForceLoadVector(const System& system, const KktSolver& kkt, const State& state, int k) {
  Loads loads(system.num_bodies(), system.num_coordinates());
  system.force_elements()[k]->AddLoads(system.MakeForceContext(k, state), loads);
  MapDirectJointForces(system, state, loads);
  VecX f = VecX::Zero(kkt.num_velocities());
  for (int b = 1; b < system.num_bodies(); ++b) f.segment<6>(kkt.BodyColumn(b)) = loads.body[b];
  for (int c = 0; c < system.num_coordinates(); ++c) {
    if (system.IsIntegrated(c)) f[kkt.SpeedColumn(c)] = loads.mobility[c];
  }
  return f;
}

void CalcForceJacobiansByFiniteDifference(const System& system, const KktSolver& kkt,
                                          const State& state, int k,
                                          const std::vector<int>& columns, MatX& K, MatX& D) {
  const int n = static_cast<int>(columns.size());
  K.setZero(n, n);
  D.setZero(n, n);
  const VecX v0 = GatherVelocities(system, kkt, state);
  auto restrict_rows = [&](const VecX& f) {
    VecX out(n);
    for (int i = 0; i < n; ++i) out[i] = f[columns[i]];
    return out;
  };
  VecX f[2];
  for (int j = 0; j < n; ++j) {
    for (int side = 0; side < 2; ++side) {
      const double delta = side == 0 ? kStep : -kStep;
      State moved = state;
      VecX v = v0;
      v[columns[j]] += delta;
      ScatterVelocities(system, kkt, v, moved);
      UpdateDirectCoordinates(system, moved);  // elements may read direct joints' q and u
      f[side] = restrict_rows(CalcForceLoadVector(system, kkt, moved, k));
    }
    D.col(j) = (f[0] - f[1]) / (2 * kStep);
    for (int side = 0; side < 2; ++side) {
      State moved = state;
      VecX dx = VecX::Zero(kkt.num_velocities());
      dx[columns[j]] = side == 0 ? kStep : -kStep;
      ApplyPositionDisplacement(system, kkt, dx, moved);
      UpdateDirectCoordinates(system, moved);
      f[side] = restrict_rows(CalcForceLoadVector(system, kkt, moved, k));
    }
    K.col(j) = (f[0] - f[1]) / (2 * kStep);
  }
}

void CalcLoadJacobians(const System& system, const KktSolver& kkt, const State& state, MatX& K,
                       MatX& D) {
  const int nv = kkt.num_velocities();
  K.setZero(nv, nv);
  D.setZero(nv, nv);
  // Gravity: the torque c x (m g) about Bo turns with the body: a rotation dtheta moves c by
  // dtheta x c, so d(torque) = (dtheta x c) x f = [f]x [c]x dtheta.
  for (int b = 1; b < system.num_bodies(); ++b) {
    const Body& body = system.bodies()[b];
    if (body.mass == 0.0) continue;
    const Vec3 c = state.bodies[b].quat_GB.normalized() * body.p_BCm;
    const Vec3 f = body.mass * system.gravity();
    const int col = kkt.BodyColumn(b);
    K.block<3, 3>(col, col) += Skew(f) * Skew(c);
  }
  MatX Kk, Dk;
  for (int k = 0; k < static_cast<int>(system.force_elements().size()); ++k) {
    const std::vector<int> columns = CalcSupportColumns(system, kkt, k);
    const int n = static_cast<int>(columns.size());
    bool analytic = false;
    if (HasPlainSupport(system, k)) {
      Kk.setZero(n, n);
      Dk.setZero(n, n);
      analytic =
          system.force_elements()[k]->CalcLoadJacobians(system.MakeForceContext(k, state), Kk, Dk);
    }
    if (!analytic) CalcForceJacobiansByFiniteDifference(system, kkt, state, k, columns, Kk, Dk);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        K(columns[i], columns[j]) += Kk(i, j);
        D(columns[i], columns[j]) += Dk(i, j);
      }
    }
  }
}

}  // namespace sinew::engine
