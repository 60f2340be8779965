#include <sinew/kinematics/body_kinematics.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/math/rotation.h>

#include <numbers>

namespace sinew::kinematics {
namespace {
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// Appends a vector's entries; adding +0.0 turns -0.0 into 0.0, so files never show "-0".
void Append(std::vector<double>& row, const Vec3& v) {
  row.insert(row.end(), {v.x() + 0.0, v.y() + 0.0, v.z() + 0.0});
}
}  // namespace

std::vector<std::string> BodyKinematicsLabels(const model::ModelSpec& spec) {
  std::vector<std::string> labels;
  for (const model::BodySpec& b : spec.bodies) {
    for (const char* suffix : {"_X", "_Y", "_Z", "_Ox", "_Oy", "_Oz"}) {
      labels.push_back(b.name + suffix);
    }
  }
  for (const char* suffix : {"_X", "_Y", "_Z"})
    labels.push_back(std::string("center_of_mass") + suffix);
  return labels;
}

std::vector<double> CalcBodyKinematicsRow(const model::ModelSpec& spec,
                                          std::span<const Transform> X_GB) {
  std::vector<double> row;
  row.reserve(spec.bodies.size() * 6 + 3);
  Vec3 weighted = Vec3::Zero();
  double total_mass = 0.0;
  for (size_t b = 0; b < spec.bodies.size(); ++b) {
    const Vec3 p = X_GB[b] * spec.bodies[b].mass_center;
    const Vec3 angles = BodyFixedXYZFromRotation(X_GB[b].R) * kDegreesPerRadian;
    Append(row, p);
    Append(row, angles);
    weighted += spec.bodies[b].mass * p;
    total_mass += spec.bodies[b].mass;
  }
  const Vec3 com = total_mass > 0 ? Vec3(weighted / total_mass) : Vec3::Zero();
  Append(row, com);
  return row;
}

std::vector<double> CalcBodyVelocityRow(const model::ModelSpec& spec,
                                        std::span<const Transform> X_GB,
                                        std::span<const SpatialVec> V_GB) {
  std::vector<double> row;
  row.reserve(spec.bodies.size() * 6 + 3);
  Vec3 weighted = Vec3::Zero();
  double total_mass = 0.0;
  for (size_t b = 0; b < spec.bodies.size(); ++b) {
    const Vec3 v = CalcStationVelocity(X_GB[b], V_GB[b], spec.bodies[b].mass_center);
    const Vec3 w = V_GB[b].head<3>() * kDegreesPerRadian;
    Append(row, v);
    Append(row, w);
    weighted += spec.bodies[b].mass * v;
    total_mass += spec.bodies[b].mass;
  }
  const Vec3 com = total_mass > 0 ? Vec3(weighted / total_mass) : Vec3::Zero();
  Append(row, com);
  return row;
}

std::vector<std::string> MarkerLocationLabels(const model::ModelSpec& spec) {
  std::vector<std::string> labels;
  for (const model::MarkerSpec& m : spec.markers) {
    for (const char* suffix : {"_tx", "_ty", "_tz"}) labels.push_back(m.name + suffix);
  }
  return labels;
}

std::vector<double> CalcMarkerLocationRow(const model::ModelSpec& spec,
                                          std::span<const Transform> X_GB) {
  std::vector<double> row;
  row.reserve(spec.markers.size() * 3);
  for (const Vec3& p : CalcMarkerLocations(spec, X_GB)) Append(row, p);
  return row;
}

}  // namespace sinew::kinematics
