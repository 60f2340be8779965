#include <sinew/common/error.h>
#include <sinew/engine/state.h>
#include <sinew/muscles/blankevoort_ligament.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <utility>

namespace sinew::muscles {
namespace {

// Quintic smooth step from 0 at x = 0 to 1 at x = 1, flat to second order at both ends
// (Simbody's Function::Step, which OpenSim uses to fade the damping in).
double SmoothStep(double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  return x * x * x * (10.0 + x * (6.0 * x - 15.0));
}

// OpenSim fades the damping in over strains 0..0.01.
constexpr double kDampingFadeStrain = 0.01;

}  // namespace

std::optional<BadParameter> FindBadParameter(const BlankevoortParameters& p) {
  const struct {
    const char* property;
    double value;
    bool allow_zero;
  } checks[] = {{"linear_stiffness", p.linear_stiffness, true},
                {"transition_strain", p.transition_strain, false},
                {"damping_coefficient", p.damping_coefficient, true},
                {"slack_length", p.slack_length, false}};
  for (const auto& check : checks) {
    if (check.value > 0.0 || (check.allow_zero && check.value == 0.0)) continue;
    std::ostringstream message;
    message << check.property << " is " << check.value << "; it must be "
            << (check.allow_zero ? "zero or positive" : "positive");
    return BadParameter{check.property, message.str()};
  }
  return std::nullopt;
}

double BlankevoortSpringForce(const BlankevoortParameters& p, double strain) {
  const double k = p.linear_stiffness, e_t = p.transition_strain;
  if (strain <= 0.0) return 0.0;
  if (strain < e_t) return 0.5 * k * strain * strain / e_t;
  return k * (strain - 0.5 * e_t);
}

double BlankevoortPotentialEnergy(const BlankevoortParameters& p, double strain) {
  const double k = p.linear_stiffness, e_t = p.transition_strain, l0 = p.slack_length;
  if (strain <= 0.0) return 0.0;
  if (strain < e_t) return l0 * k * strain * strain * strain / (6.0 * e_t);
  // The toe region's energy up to e_t, then the linear region's from e_t to the strain.
  return l0 * k * (e_t * e_t / 6.0 + 0.5 * strain * (strain - e_t));
}

LigamentForces CalcBlankevoortForces(const BlankevoortParameters& p, const PathKinematics& path) {
  LigamentForces f;
  f.strain = path.length / p.slack_length - 1.0;
  f.strain_rate = path.lengthening_speed / p.slack_length;
  f.spring = BlankevoortSpringForce(p, f.strain);
  if (f.strain > 0.0 && f.strain_rate > 0.0) {
    f.damping = p.damping_coefficient * f.strain_rate * SmoothStep(f.strain / kDampingFadeStrain);
  }
  // The ligament only pulls.
  f.total = std::max(f.spring + f.damping, 0.0);
  return f;
}

BlankevoortLigament::BlankevoortLigament(std::string name, EnginePath path,
                                         const BlankevoortParameters& parameters)
    : name_(std::move(name)), path_(std::move(path)), parameters_(parameters) {
  if (const auto bad = FindBadParameter(parameters)) throw Error(name_ + ": " + bad->message);
}

void BlankevoortLigament::AddLoads(const engine::ForceContext& context,
                                   engine::Loads& loads) const {
  PathScratch& scratch = EnginePath::Scratch();
  const double tension =
      CalcBlankevoortForces(parameters_, path_.Calc(context.state, scratch)).total;
  path_.AddTensionLoads(context.state, tension, scratch, loads);
}

double BlankevoortLigament::CalcPotentialEnergy(const engine::ForceContext& context) const {
  const double length = path_.Calc(context.state, EnginePath::Scratch()).length;
  return BlankevoortPotentialEnergy(parameters_, length / parameters_.slack_length - 1.0);
}

std::vector<std::string> BlankevoortLigament::RecordLabels(const engine::System& /*system*/) const {
  std::vector<std::string> labels;
  for (const char* column : {".force_spring", ".force_damping", ".force_total", ".length",
                             ".lengthening_speed", ".strain", ".strain_rate"}) {
    labels.push_back(name_ + column);
  }
  return labels;
}

void BlankevoortLigament::CalcRecordValues(const engine::ForceContext& context,
                                           std::vector<double>& values) const {
  const PathKinematics path = path_.Calc(context.state, EnginePath::Scratch());
  const LigamentForces f = CalcBlankevoortForces(parameters_, path);
  values.insert(values.end(), {f.spring, f.damping, f.total, path.length, path.lengthening_speed,
                               f.strain, f.strain_rate});
}

}  // namespace sinew::muscles
