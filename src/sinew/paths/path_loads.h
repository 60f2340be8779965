// What a path under tension does to the model: a force at every path point along the path,
// and, for moving path points, a generalized force on the coordinates that move them. Its
// generalized force equals -tension * dL/du (power balance: the work the tension does is
// -tension * dL), which is how moment arms are computed, as OpenSim's MomentArmSolver does.
#pragma once

#include <sinew/paths/geometry_path.h>
#include <sinew/paths/speed_columns.h>

#include <span>
#include <vector>

namespace sinew::paths {

/// A force on a body at a point of it.
struct PointForce {
  int body = model::kGroundIndex;
  Vec3 p_BP = Vec3::Zero();  ///< Point in the body frame (m).
  Vec3 f_G = Vec3::Zero();   ///< Force in ground (N).
};

/// A generalized force on one coordinate (N m for rotational, N for translational).
struct CoordinateForce {
  int coordinate = model::kNone;
  double value = 0.0;
};

/// The loads of one path at one tension.
struct PathLoads {
  std::vector<PointForce> point_forces;
  std::vector<CoordinateForce> coordinate_forces;
};

/// The loads of `state` under `tension` (N; positive pulls the path's points together): at
/// point i the force tension * (e_i - e_(i-1)) (e the unit directions of the straight segments
/// on either side; none over a wrap surface), and at a moving point that same force dotted with
/// R_GB dp_BP/dq on each of its coordinates. Unlike OpenSim's GeometryPath::produceForces, the
/// forces of a segment between two points of one body are kept: they cancel on a rigid body,
/// and they carry a moving point's generalized force, which OpenSim drops there. A
/// FunctionBasedPath has no point forces: -tension dL/dq on each of its coordinates.
void CalcPathLoads(const PathState& state, std::span<const Transform> X_GB, double tension,
                   PathLoads& loads);

/// The generalized forces of `loads` (J^T F), one per coordinate, from the speed columns at the
/// same pose: Q_k = sum f_G . v_P^(k) + the coordinate forces. Adds to Q.
void AddGeneralizedForces(const PathLoads& loads, std::span<const Transform> X_GB,
                          const SpeedColumns& columns, std::span<double> Q);

/// dL/du_k for every coordinate speed (m per rad or m per m), analytic: minus the generalized
/// force of a unit tension (CalcPathLoads then AddGeneralizedForces, without storing the
/// loads). No heap use once its workspace is sized.
void CalcLengthGradient(const PathState& state, std::span<const Transform> X_GB,
                        const SpeedColumns& columns, std::span<double> dL_du);

/// OpenSim's moment arms where tangent points are stale (several wrap objects, docs/paths.md):
/// OpenSim's MomentArmSolver, like its GeometryPath::produceForces, pulls a tangent point along
/// the directions from the ground locations it read first (Sinew's e_G) but applies the force
/// where the point is now (PathPointState::p_BP_placed), and only along segments to points of
/// other bodies. This adds to `dL_du` (CalcLengthGradient's) the generalized force, at a
/// tension of -1, of moving each stale tangent point's forces from p_BP to p_BP_placed, so
/// that -c . dL_du becomes OpenSim's moment arm; it is then no longer a derivative of the
/// length. Adds nothing for a path without stale tangent points.
void AddStaleTangentPointShift(const PathState& state, std::span<const Transform> X_GB,
                               const SpeedColumns& columns, std::span<double> dL_du);

/// The lengthening speed dL/dt (m/s): the sum over straight segments of e_i . (v_(i+1) - v_i),
/// with each point's velocity in ground from its body's V_GB (kinematics::CalcBodyVelocities)
/// plus, for moving points, R_GB dp_BP/dq u of its coordinates. A FunctionBasedPath: its
/// lengthening_speed_function(q, u) if it has one, else sum_i dL/dq_i u_i (OpenSim uses qdot
/// there, which differs from u only for Ball and Free joint rotations).
double CalcLengtheningSpeed(const PathState& state, std::span<const Transform> X_GB,
                            std::span<const SpatialVec> V_GB, std::span<const double> u);

}  // namespace sinew::paths
