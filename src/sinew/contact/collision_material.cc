#include <sinew/contact/collision_material.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace sinew::contact {

PairMaterial CombineMaterials(const CollisionMaterial& a, const CollisionMaterial& b) {
  PairMaterial m;
  m.friction = std::min(a.friction, b.friction);
  m.restitution = std::min(a.restitution, b.restitution);
  m.effective_modulus = 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.young_modulus +
                               (1.0 - b.poisson_ratio * b.poisson_ratio) / b.young_modulus);
  m.kn = 0.5 * (a.kn + b.kn);
  m.gn = 0.5 * (a.gn + b.gn);
  m.kt = 0.5 * (a.kt + b.kt);
  m.gt = 0.5 * (a.gt + b.gt);
  return m;
}

std::optional<std::string> FindMaterialProblem(const CollisionMaterial& m) {
  const auto say = [](const char* what, double value, const char* rule) {
    std::ostringstream s;
    s << what << " " << value << " " << rule;
    return s.str();
  };
  if (!(m.friction >= 0.0) || !std::isfinite(m.friction))
    return say("friction", m.friction, "must be >= 0");
  if (!(m.restitution >= 0.0 && m.restitution <= 1.0))
    return say("restitution", m.restitution, "must be in [0, 1]");
  if (!(m.young_modulus > 0.0) || !std::isfinite(m.young_modulus))
    return say("young_modulus", m.young_modulus, "must be > 0");
  if (!(m.poisson_ratio >= 0.0 && m.poisson_ratio < 0.5))
    return say("poisson_ratio", m.poisson_ratio, "must be in [0, 0.5)");
  for (const auto& [name, value] : {std::pair{"kn", m.kn}, std::pair{"gn", m.gn},
                                    std::pair{"kt", m.kt}, std::pair{"gt", m.gt}}) {
    if (!(value >= 0.0) || !std::isfinite(value)) return say(name, value, "must be >= 0");
  }
  return std::nullopt;
}

void CheckMaterial(const CollisionMaterial& m, const SourceLocation& where,
                   const std::string& component) {
  if (const std::optional<std::string> problem = FindMaterialProblem(m))
    throw Error(where, component, "contact material: " + *problem);
}

}  // namespace sinew::contact
