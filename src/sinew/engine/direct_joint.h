// The direct Cartesian joint forms (Pin, Ball, Universal, Weld): their transforms X_FM(q) and
// velocity maps, used to place bodies, and the read-off of their coordinates from body poses.
#pragma once

#include <sinew/engine/system.h>
#include <sinew/math/transform.h>

#include <span>

namespace sinew::engine {

/// Number of coordinates of a direct joint form (Pin 1, Ball 3, Universal 2, Weld 0).
int NumDirectCoordinates(JointForm form);

/// X_FM(q) of a direct form: Pin Rz(q); Ball body-fixed X-Y-Z angles; Universal Rx(q0) Ry(q1).
Transform CalcDirectX_FM(JointForm form, std::span<const double> q);

/// H_FM(q) (6 x n, [angular; linear] in F): V_FM_F = H u. For all direct forms qdot = u except
/// Ball, whose u is w_FM_F.
Mat6X CalcDirectH_FM(JointForm form, std::span<const double> q);

/// Reads q and u of a direct joint from X_FM and V_FM_F (spatial velocity of M in F, in F).
/// On entry `q` holds the previous values: angles are unwrapped to stay continuous with them.
void ReadDirectCoordinates(JointForm form, const Transform& X_FM, const SpatialVec& V_FM_F,
                           std::span<double> q, std::span<double> u);

}  // namespace sinew::engine
