// Rotations: body-fixed (intrinsic) X-Y-Z angle sequences as OpenSim uses them, axis-angle.
#pragma once

#include <sinew/math/types.h>

namespace sinew {

/// R = Rx(a.x) * Ry(a.y) * Rz(a.z): body-fixed X-Y-Z angles in radians (OpenSim `orientation`).
Mat3 RotationFromBodyFixedXYZ(const Vec3& angles);

/// The body-fixed X-Y-Z angles (radians) of R; y in [-pi/2, pi/2]. Inverse of the above
/// away from the gimbal-lock configurations.
Vec3 BodyFixedXYZFromRotation(const Mat3& R);

/// N with qdot = N w_M: the rates of the body-fixed X-Y-Z angles `angles` of a frame M from
/// its angular velocity w_M expressed in M. Singular when cos(angles.y) = 0 (gimbal lock). Its
/// transpose maps generalized forces on the angles to the moment on M, in M (m_M = N^T f).
Mat3 BodyFixedXYZRatesFromAngularVelocity(const Vec3& angles);

/// Rotation by `angle` radians about the unit vector `axis` (right-hand rule).
Mat3 RotationAboutAxis(const Vec3& axis, double angle);

}  // namespace sinew
