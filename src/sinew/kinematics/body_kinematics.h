// Rows in the layout of OpenSim's BodyKinematics analysis and of its model marker locations,
// so Sinew's results can be compared column by column with OpenSim's.
#pragma once

#include <sinew/math/transform.h>
#include <sinew/model/model_spec.h>

#include <span>
#include <string>
#include <vector>

namespace sinew::kinematics {

/// BodyKinematics position labels (time excluded): `<body>_X _Y _Z _Ox _Oy _Oz` for every body,
/// ground first, then `center_of_mass_X _Y _Z`.
std::vector<std::string> BodyKinematicsLabels(const model::ModelSpec& spec);

/// One BodyKinematics position row (time excluded) in the order of BodyKinematicsLabels:
/// mass-centre positions in G (m), body-fixed X-Y-Z angles of R_GB (degrees), and the whole
/// model's mass centre (m; zeros when the model has no mass).
std::vector<double> CalcBodyKinematicsRow(const model::ModelSpec& spec,
                                          std::span<const Transform> X_GB);

/// BodyKinematics velocity row, same labels: mass-centre velocities in G (m/s), angular
/// velocities w_GB in G (deg/s), whole-model mass-centre velocity (m/s). V_GB from
/// CalcBodyVelocities.
std::vector<double> CalcBodyVelocityRow(const model::ModelSpec& spec,
                                        std::span<const Transform> X_GB,
                                        std::span<const SpatialVec> V_GB);

/// Marker location labels (time excluded): `<marker>_tx _ty _tz`.
std::vector<std::string> MarkerLocationLabels(const model::ModelSpec& spec);

/// Marker positions in G (m), in the order of MarkerLocationLabels.
std::vector<double> CalcMarkerLocationRow(const model::ModelSpec& spec,
                                          std::span<const Transform> X_GB);

}  // namespace sinew::kinematics
