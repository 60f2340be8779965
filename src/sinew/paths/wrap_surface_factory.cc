#include <sinew/common/error.h>
#include <sinew/paths/wrap_cylinder.h>
#include <sinew/paths/wrap_cylinder_obst.h>
#include <sinew/paths/wrap_double_cylinder_obst.h>
#include <sinew/paths/wrap_ellipsoid.h>
#include <sinew/paths/wrap_quadrant.h>
#include <sinew/paths/wrap_sphere.h>
#include <sinew/paths/wrap_sphere_obst.h>
#include <sinew/paths/wrap_surface_factory.h>
#include <sinew/paths/wrap_torus.h>

#include <cmath>
#include <functional>
#include <map>
#include <sstream>

namespace sinew::paths {
namespace {

using Builder = std::function<std::unique_ptr<WrapSurface>(const model::WrapObjectSpec&)>;

[[noreturn]] void Fail(const model::WrapObjectSpec& spec, const std::string& message) {
  throw Error(spec.where, spec.name, spec.type + " " + message);
}

// One positive, finite length (m) named `key`, or `default_value` when the file has none.
double PositiveLength(const model::WrapObjectSpec& spec, const std::string& key,
                      double default_value) {
  const auto found = spec.dimensions.find(key);
  if (found == spec.dimensions.end()) return default_value;
  if (found->second.size() != 1) Fail(spec, key + " must be one number");
  const double value = found->second.front();
  if (!(value > 0.0) || !std::isfinite(value)) {
    std::ostringstream text;
    text << key << " must be positive and finite (got " << value << ")";
    Fail(spec, text.str());
  }
  return value;
}

// One positive, finite length (m) named `key` that the file must give (OpenSim has no default).
double RequiredPositiveLength(const model::WrapObjectSpec& spec, const std::string& key) {
  if (!spec.dimensions.contains(key)) Fail(spec, "has no " + key);
  return PositiveLength(spec, key, 0.0);
}

// Three positive, finite lengths (m) named `key`, or `default_value` when the file has none.
Vec3 PositiveLengths(const model::WrapObjectSpec& spec, const std::string& key,
                     const Vec3& default_value) {
  const auto found = spec.dimensions.find(key);
  if (found == spec.dimensions.end()) return default_value;
  if (found->second.size() != 3) Fail(spec, key + " must be three numbers");
  const Vec3 value(found->second[0], found->second[1], found->second[2]);
  if (!(value.minCoeff() > 0.0) || !value.allFinite()) {
    std::ostringstream text;
    text << key << " must be positive and finite (got " << value.transpose() << ")";
    Fail(spec, text.str());
  }
  return value;
}

// The object's quadrant; an unknown one is reported with the object's file and line.
WrapQuadrant Quadrant(const model::WrapObjectSpec& spec) {
  try {
    return ParseWrapQuadrant(spec.quadrant, spec.name);
  } catch (const Error& error) {
    Fail(spec, error.message());
  }
}

// OpenSim's torus: the tube's radius `inner_radius` below the ring's radius `outer_radius`.
std::unique_ptr<WrapSurface> MakeWrapTorus(const model::WrapObjectSpec& spec) {
  const double inner = RequiredPositiveLength(spec, "inner_radius");
  const double outer = RequiredPositiveLength(spec, "outer_radius");
  if (!(outer > inner)) {
    std::ostringstream text;
    text << "outer_radius (" << outer << ") must be greater than inner_radius (" << inner << ")";
    Fail(spec, text.str());
  }
  return std::make_unique<WrapTorus>(inner, outer, Quadrant(spec));
}

// An obstacle's wrap direction, which the reader keeps as dimensions[key]: +1 right-handed
// (also when absent), -1 left-handed. WrapCylinderObst's key is "wrap_direction",
// WrapDoubleCylinderObst's "wrap_ucyl_direction" and "wrap_vcyl_direction".
bool RightHanded(const model::WrapObjectSpec& spec, const std::string& key) {
  const auto found = spec.dimensions.find(key);
  if (found == spec.dimensions.end() || found->second == std::vector<double>{1.0}) return true;
  if (found->second == std::vector<double>{-1.0}) return false;
  Fail(spec, key + " must be +1 (righthand) or -1 (lefthand)");
}

WrapCylinderObst::Direction WrapDirection(const model::WrapObjectSpec& spec) {
  return RightHanded(spec, "wrap_direction") ? WrapCylinderObst::Direction::kRightHand
                                             : WrapCylinderObst::Direction::kLeftHand;
}

// An obstacle's length plays no part in its wrap, but OpenSim refuses one that is not positive.
void CheckObstacleLength(const model::WrapObjectSpec& spec, double default_value) {
  PositiveLength(spec, "length", default_value);
}

const std::map<std::string, Builder>& Registry() {
  static const std::map<std::string, Builder> registry{
      {"WrapSphere",
       [](const model::WrapObjectSpec& spec) -> std::unique_ptr<WrapSurface> {
         return std::make_unique<WrapSphere>(PositiveLength(spec, "radius", 0.05), Quadrant(spec));
       }},
      {"WrapCylinder",
       [](const model::WrapObjectSpec& spec) -> std::unique_ptr<WrapSurface> {
         return std::make_unique<WrapCylinder>(PositiveLength(spec, "radius", 1.0),
                                               PositiveLength(spec, "length", 1.0), Quadrant(spec));
       }},
      {"WrapEllipsoid",
       [](const model::WrapObjectSpec& spec) -> std::unique_ptr<WrapSurface> {
         return std::make_unique<WrapEllipsoid>(
             PositiveLengths(spec, "dimensions", Vec3(0.05, 0.05, 0.05)), Quadrant(spec));
       }},
      {"WrapTorus", MakeWrapTorus},
      {"WrapCylinderObst",
       [](const model::WrapObjectSpec& spec) -> std::unique_ptr<WrapSurface> {
         CheckObstacleLength(spec, 1.0);
         return std::make_unique<WrapCylinderObst>(PositiveLength(spec, "radius", 1.0),
                                                   WrapDirection(spec));
       }},
      {"WrapDoubleCylinderObst",
       [](const model::WrapObjectSpec& spec) -> std::unique_ptr<WrapSurface> {
         using Direction = WrapDoubleCylinderObst::Direction;
         const auto direction = [&](const std::string& key) {
           return RightHanded(spec, key) ? Direction::kRightHand : Direction::kLeftHand;
         };
         if (spec.second_body == model::kNone) {
           Fail(spec, "has no body for its V cylinder (wrapVcylHomeBodyName)");
         }
         CheckObstacleLength(spec, 1.0);
         return std::make_unique<WrapDoubleCylinderObst>(
             PositiveLength(spec, "radiusUcyl", 1.0), direction("wrap_ucyl_direction"),
             PositiveLength(spec, "radiusVcyl", 1.0), direction("wrap_vcyl_direction"));
       }},
      {"WrapSphereObst",
       [](const model::WrapObjectSpec& spec) -> std::unique_ptr<WrapSurface> {
         CheckObstacleLength(spec, 0.1);
         return std::make_unique<WrapSphereObst>(PositiveLength(spec, "radius", 0.05));
       }},
  };
  return registry;
}

}  // namespace

std::unique_ptr<WrapSurface> MakeWrapSurface(const model::WrapObjectSpec& spec) {
  const auto builder = Registry().find(spec.type);
  if (builder == Registry().end()) Fail(spec, "is not a wrap surface Sinew supports");
  return builder->second(spec);
}

bool IsWrapSurfaceSupported(const std::string& type) { return Registry().contains(type); }

std::vector<std::string> SupportedWrapSurfaceTypes() {
  std::vector<std::string> types;
  for (const auto& [type, builder] : Registry()) types.push_back(type);
  return types;
}

}  // namespace sinew::paths
