// Issue #15's speed goal compares Sinew with Simbody, the engine under OpenSim, on the hung
// skeletons of hung_skeleton.h. This program times Simbody itself (Debian's libsimbody 3.7) on
// the same motion, on the same machine, so the ratio is measured, not carried over from another
// machine.
//
// The model is built with the mobilizers OpenSim gives the joints: a CustomJoint becomes a
// MobilizedBody::FunctionBased (three rotations about its axes in order, then three
// translations in the parent frame, each a function of the joint's coordinates), a PinJoint a
// Pin, a UniversalJoint a Universal; a joint whose coordinates are all locked (the pelvis, and
// Rajagopal2016's subtalar and mtp joints) is a Weld at its start pose (the cheapest form of a
// lock in Simbody); a CoordinateCouplerConstraint becomes a
// Constraint::CoordinateCoupler on scale * f(q_independent) - q_dependent. The axis functions
// are Sinew's (SimmSpline, LinearFunction, ...), called through SimTK::Function; everything
// else (the tree, the mass matrix, the integrator) is Simbody's. Start pose and speeds are the
// Sinew benchmark's.
//
// Reported: CPU time for one simulated second with Simbody's RungeKuttaMersonIntegrator
// (OpenSim's default; `merson`) or RungeKuttaFeldbergIntegrator (`feldberg`) at accuracy 10^-k
// (k = the argument); `err_rad`, the largest coordinate
// error at 1 s against a Simbody run at accuracy 1e-12; `vs_sinew_rad`, how far that Simbody
// reference lies from Sinew's own at 1e-12; `energy_change_J`, how much mechanical energy that
// reference gained (nothing but gravity acts: it should be zero to the integration's error);
// `steps`, the integrator's steps taken. CPU time at the accuracy whose error is
// 3e-6 rad is what the goal compares with `BM_Gait2354HungOneSecond`.
#include <benchmark/benchmark.h>
#include <sinew/common/error.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "hung_skeleton.h"
#include "simbody/hung_model.h"

namespace {

using sinew::model::JointSpec;
using sinew::model::JointType;
using sinew::model::ModelSpec;

std::array<double, 3> ToArray(const sinew::Vec3& v) { return {v.x(), v.y(), v.z()}; }

std::array<double, 9> ToArray(const sinew::Mat3& m) {
  std::array<double, 9> a;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a[3 * i + j] = m(i, j);
  }
  return a;
}

simbody_bench::Pose ToPose(const sinew::Transform& X) { return {ToArray(X.R), ToArray(X.p)}; }

// A Sinew function of the arguments in x (none for a Constant axis), or its partial derivative
// by the arguments listed in wrt.
simbody_bench::ScalarFunction Wrap(sinew::functions::FunctionPtr f) {
  return [f](const double* x, int n, const int* wrt, int num_wrt) {
    if (n == 0) return num_wrt == 0 ? f->Calc(0.0) : 0.0;
    const std::span<const double> args(x, n);
    return num_wrt == 0 ? f->CalcN(args)
                        : f->CalcPartialN(args, std::span<const int>(wrt, num_wrt));
  };
}

bool AllLocked(const ModelSpec& spec, const JointSpec& joint) {
  return !joint.coordinates.empty() &&
         std::all_of(joint.coordinates.begin(), joint.coordinates.end(),
                     [&](int c) { return spec.coordinates[c].locked; });
}

simbody_bench::Joint ToJoint(const ModelSpec& spec, const JointSpec& joint,
                             const sinew::engine::State& start) {
  using Kind = simbody_bench::Joint::Kind;
  simbody_bench::Joint out;
  out.parent = joint.parent_body;
  out.child = joint.child_body;
  out.X_PF = ToPose(joint.X_PF);
  out.X_BM = ToPose(joint.X_BM);
  if (joint.reverse) throw sinew::Error("simbody_hung: reversed joint '" + joint.name + "'");
  if (AllLocked(spec, joint)) {
    // Welded at the start's relative pose: the cheapest lock in Simbody.
    const auto pose = [&](int body) {
      const sinew::engine::BodyState& b = start.bodies[body];
      return sinew::Transform(b.quat_GB.toRotationMatrix(), b.p_GB);
    };
    out.kind = Kind::kWeld;
    out.X_PF = ToPose(pose(joint.parent_body).Inverse() * pose(joint.child_body));
    out.X_BM = simbody_bench::Pose();
    return out;
  }
  out.coordinates = joint.coordinates;
  switch (joint.kind) {
    case JointType::kPin:
      out.kind = Kind::kPin;
      break;
    case JointType::kUniversal:
      out.kind = Kind::kUniversal;
      break;
    case JointType::kWeld:
      out.kind = Kind::kWeld;
      break;
    case JointType::kCustom:
      out.kind = Kind::kFunctionBased;
      for (const sinew::model::TransformAxisSpec& axis : joint.spatial_transform) {
        simbody_bench::Axis a;
        a.f = Wrap(axis.function);
        a.axis = ToArray(axis.axis.normalized());
        for (int c : axis.coordinates) {
          const auto at = std::find(joint.coordinates.begin(), joint.coordinates.end(), c);
          a.arguments.push_back(static_cast<int>(at - joint.coordinates.begin()));
        }
        out.axes.push_back(std::move(a));
      }
      break;
    default:
      throw sinew::Error("simbody_hung: joint '" + joint.name + "' of type " + joint.type +
                         " has no Simbody counterpart here");
  }
  return out;
}

// The hung skeleton as Simbody input: its bodies, its joints parents first, its couplers, at
// the start state's coordinates and speeds.
simbody_bench::Model ToSimbody(const sinew_bench::HungSkeleton& hung) {
  const ModelSpec& spec = hung.spec;
  simbody_bench::Model model;
  model.gravity = ToArray(spec.gravity);
  for (const sinew::model::BodySpec& b : spec.bodies) {
    model.bodies.push_back({b.mass, ToArray(b.mass_center), ToArray(b.inertia)});
  }
  std::vector<bool> placed(spec.bodies.size(), false);
  placed[sinew::model::kGroundIndex] = true;
  for (size_t done = 0; done < spec.joints.size();) {
    const size_t before = done;
    for (const JointSpec& joint : spec.joints) {
      if (placed[joint.child_body] || !placed[joint.parent_body]) continue;
      model.joints.push_back(ToJoint(spec, joint, hung.start));
      placed[joint.child_body] = true;
      ++done;
    }
    if (done == before) throw sinew::Error("simbody_hung: a joint's parent is never placed");
  }
  for (const sinew::model::ConstraintSpec& c : spec.constraints) {
    if (!c.enabled) continue;
    if (c.type != "CoordinateCouplerConstraint") {
      throw sinew::Error("simbody_hung: constraint '" + c.name + "' of type " + c.type +
                         " has no Simbody counterpart here");
    }
    // OpenSim's form: scale * f(q_independent) - q_dependent = 0.
    const int n = static_cast<int>(c.independent_coordinates.size());
    const sinew::functions::FunctionPtr f = c.function;
    const double scale = c.scale_factor;
    simbody_bench::Coupler coupler;
    coupler.coordinates = c.independent_coordinates;
    coupler.coordinates.push_back(c.dependent_coordinate);
    coupler.f = [f, n, scale](const double* x, int, const int* wrt, int num_wrt) {
      const std::span<const double> independent(x, n);
      if (num_wrt == 0) return scale * f->CalcN(independent) - x[n];
      if (std::find(wrt, wrt + num_wrt, n) != wrt + num_wrt) return num_wrt == 1 ? -1.0 : 0.0;
      return scale * f->CalcPartialN(independent, std::span<const int>(wrt, num_wrt));
    };
    model.couplers.push_back(std::move(coupler));
  }
  model.q.assign(hung.start.q.data(), hung.start.q.data() + hung.start.q.size());
  model.u.assign(hung.start.u.data(), hung.start.u.data() + hung.start.u.size());
  return model;
}

double MaxDifference(const std::vector<double>& a, const Eigen::VectorXd& b) {
  double d = 0.0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[static_cast<int>(i)]));
  return d;
}

// A hung skeleton in Simbody with its references, made once per model.
struct SimbodyCase {
  explicit SimbodyCase(sinew_bench::HungSkeleton skeleton)
      : hung(std::move(skeleton)), simulation(ToSimbody(hung)) {
    reference = simulation.Run(simbody_bench::Simulation::Scheme::kRungeKuttaMerson, 1e-12, 1.0,
                               nullptr, &energy_change);
    vs_sinew = MaxDifference(reference, sinew_bench::RunHung(hung, "rk45", 1e-12, nullptr).q);
  }
  sinew_bench::HungSkeleton hung;
  simbody_bench::Simulation simulation;
  std::vector<double> reference;  // Simbody at accuracy 1e-12
  double energy_change = 0.0;     // of that reference run
  double vs_sinew = 0.0;          // its largest difference from Sinew's at 1e-12
};

void TimeSimbody(benchmark::State& bench, const SimbodyCase& model,
                 simbody_bench::Simulation::Scheme scheme) {
  const double accuracy = std::pow(10.0, -static_cast<double>(bench.range(0)));
  long steps = 0;
  std::vector<double> q;
  for (auto _ : bench) {
    q = model.simulation.Run(scheme, accuracy, 1.0, &steps);
    benchmark::DoNotOptimize(q.data());
  }
  const Eigen::VectorXd reference = Eigen::Map<const Eigen::VectorXd>(
      model.reference.data(), static_cast<Eigen::Index>(model.reference.size()));
  bench.counters["err_rad"] = MaxDifference(q, reference);
  bench.counters["vs_sinew_rad"] = model.vs_sinew;
  bench.counters["energy_change_J"] = model.energy_change;
  bench.counters["steps"] = static_cast<double>(steps);
}

using Scheme = simbody_bench::Simulation::Scheme;

void BM_SimbodyGait2354HungOneSecond(benchmark::State& bench, Scheme scheme) {
  static const SimbodyCase model(
      sinew_bench::MakeHungSkeleton(sinew_bench::kGait2354HungFile, false, -1.0));
  TimeSimbody(bench, model, scheme);
}
BENCHMARK_CAPTURE(BM_SimbodyGait2354HungOneSecond, merson, Scheme::kRungeKuttaMerson)
    ->DenseRange(5, 9)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SimbodyGait2354HungOneSecond, feldberg, Scheme::kRungeKuttaFeldberg)
    ->DenseRange(5, 11)
    ->Unit(benchmark::kMillisecond);

void BM_SimbodyRajagopal2016HungOneSecond(benchmark::State& bench, Scheme scheme) {
  static const SimbodyCase model(
      sinew_bench::MakeHungSkeleton(sinew_bench::kRajagopal2016HungFile, true, 1.0));
  TimeSimbody(bench, model, scheme);
}
BENCHMARK_CAPTURE(BM_SimbodyRajagopal2016HungOneSecond, merson, Scheme::kRungeKuttaMerson)
    ->DenseRange(5, 9)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SimbodyRajagopal2016HungOneSecond, feldberg, Scheme::kRungeKuttaFeldberg)
    ->DenseRange(5, 10)
    ->Unit(benchmark::kMillisecond);

}  // namespace
