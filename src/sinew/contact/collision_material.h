// Contact materials of collision shapes (the seed's contact material: friction, restitution,
// Young's modulus, Poisson ratio, and the SMC coefficients kn, gn, kt, gt), their defaults,
// how two shapes' materials combine into the material of their contact, and their checks.
#pragma once

#include <sinew/common/error.h>

#include <optional>
#include <string>

namespace sinew::contact {

/// One shape's contact material. Defaults: friction 0.6 and restitution 0.4 (Chrono's
/// material defaults), Young's modulus 1e7 Pa (rubber-like; stiffer than Chrono's 2e5 Pa so
/// that a skeleton does not sink centimetres into its floor), Poisson ratio 0.3; kn, gn, kt, gt
/// 0, meaning "from the modulus, Poisson ratio and restitution" (docs/contact.md).
struct CollisionMaterial {
  double friction = 0.6;       ///< Coulomb coefficient (static = dynamic), >= 0
  double restitution = 0.4;    ///< in [0, 1]
  double young_modulus = 1e7;  ///< Pa, > 0
  double poisson_ratio = 0.3;  ///< in [0, 0.5)
  double kn = 0.0;             ///< Pa (N/m^2): normal stiffness of the Hertz law when > 0
  double gn = 0.0;             ///< 1/(m s): normal damping per unit effective mass when kn > 0
  double kt = 0.0;  ///< Pa: > 0 makes SMC's friction a tangential spring kept per contact
  double gt = 0.0;  ///< N s/m: slope of the regularized friction at zero slip when > 0; with
                    ///< kt > 0 the spring's damping
};

/// The material of a contact between two shapes: friction and restitution the smaller of the
/// two (Chrono's default composition), the Hertz effective modulus
/// E* = 1 / ((1 - nu1^2) / E1 + (1 - nu2^2) / E2), kn, gn, kt, gt the means of the two.
struct PairMaterial {
  double friction = 0.0;
  double restitution = 0.0;
  double effective_modulus = 0.0;  ///< Pa
  double kn = 0.0, gn = 0.0, kt = 0.0, gt = 0.0;
};

PairMaterial CombineMaterials(const CollisionMaterial& a, const CollisionMaterial& b);

/// The first problem with `m` ("friction -0.1 is negative", ...), or nullopt when it is valid.
std::optional<std::string> FindMaterialProblem(const CollisionMaterial& m);

/// Throws sinew::Error(where, component, problem) when `m` is not valid.
void CheckMaterial(const CollisionMaterial& m, const SourceLocation& where,
                   const std::string& component);

}  // namespace sinew::contact
