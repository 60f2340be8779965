// Function evaluation costs. Forward kinematics of a full-body model evaluates ~37 joints with a
// few spline couplings each per pose; the goal is well under 5 us for all of them.
#include <benchmark/benchmark.h>
#include <sinew/functions/gcv_spline.h>
#include <sinew/functions/multiplier_function.h>
#include <sinew/functions/simm_spline.h>
#include <sinew/io/storage.h>

#include <cmath>
#include <memory>
#include <vector>

namespace {

// Knee translation spline from OpenSim's gait models (12 knots).
const std::vector<double> kKneeX = {-2.0943951,  -1.99997279, -1.57079633, -1.45752446,
                                    -1.3962634,  -1.04719755, -0.78539816, -0.52359878,
                                    -0.34906585, -0.17453293, 0.0,         0.17453293};
const std::vector<double> kKneeY = {0.0082733,  0.01068662, 0.02020416, 0.02235298,
                                    0.02345827, 0.02927151, 0.03267044, 0.03493239,
                                    0.03583779, 0.03625744, 0.03616478, 0.03549306};

void BM_SimmSplineCalc(benchmark::State& state) {
  sinew::functions::SimmSpline spline(kKneeX, kKneeY);
  double x = -2.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(spline.Calc(x));
    x += 0.001;
    if (x > 0.1) x = -2.0;
  }
}
BENCHMARK(BM_SimmSplineCalc);

void BM_SimmSplineValueAndDerivatives(benchmark::State& state) {
  sinew::functions::SimmSpline spline(kKneeX, kKneeY);
  double x = -2.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(spline.Calc(x));
    benchmark::DoNotOptimize(spline.CalcDerivative(x, 1));
    benchmark::DoNotOptimize(spline.CalcDerivative(x, 2));
    x += 0.001;
    if (x > 0.1) x = -2.0;
  }
}
BENCHMARK(BM_SimmSplineValueAndDerivatives);

// One pose of a full-body model: 37 joints x 3 scaled spline couplings (MultiplierFunction
// around a SimmSpline, as in scaled models), value + first + second derivative each, through
// the virtual Function interface.
void BM_FullBodyPoseSplines(benchmark::State& state) {
  std::vector<sinew::functions::FunctionPtr> functions;
  for (int i = 0; i < 37 * 3; ++i) {
    functions.push_back(std::make_shared<sinew::functions::MultiplierFunction>(
        std::make_shared<sinew::functions::SimmSpline>(kKneeX, kKneeY), 1.0 + 0.001 * i));
  }
  double x = -2.0;
  for (auto _ : state) {
    double sum = 0.0;
    for (const sinew::functions::FunctionPtr& f : functions) {
      sum += f->Calc(x) + f->CalcDerivative(x, 1) + f->CalcDerivative(x, 2);
    }
    benchmark::DoNotOptimize(sum);
    x += 0.001;
    if (x > 0.1) x = -2.0;
  }
}
BENCHMARK(BM_FullBodyPoseSplines);

void BM_SimmSplineConstruct(benchmark::State& state) {
  for (auto _ : state) {
    sinew::functions::SimmSpline spline(kKneeX, kKneeY);
    benchmark::DoNotOptimize(spline.b().data());
  }
}
BENCHMARK(BM_SimmSplineConstruct);

// GCVSpline fit (sparse solve) for a control with many points, and its evaluation.
void BM_GCVSplineFit(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<double> x(n), y(n);
  for (int i = 0; i < n; ++i) {
    x[i] = 0.01 * i;
    y[i] = 0.5 + 0.4 * std::sin(3.0 * x[i]);
  }
  for (auto _ : state) {
    sinew::functions::GCVSpline spline(3, x, y);
    benchmark::DoNotOptimize(spline.Calc(0.5));
  }
}
BENCHMARK(BM_GCVSplineFit)->Arg(100)->Arg(1000);

// Smoothing fit with a known error variance: ~100 criterion evaluations, each with n solves for
// the influence-matrix trace.
void BM_GCVSplineSmoothingFit(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<double> x(n), y(n);
  for (int i = 0; i < n; ++i) {
    x[i] = 0.01 * i;
    y[i] = 0.5 + 0.4 * std::sin(3.0 * x[i]) + 0.01 * std::sin(97.0 * i);
  }
  for (auto _ : state) {
    sinew::functions::GCVSpline spline(3, x, y, 0.0001);
    benchmark::DoNotOptimize(spline.Calc(0.5));
  }
}
BENCHMARK(BM_GCVSplineSmoothingFit)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_GCVSplineCalc(benchmark::State& state) {
  std::vector<double> x(1000), y(1000);
  for (int i = 0; i < 1000; ++i) {
    x[i] = 0.01 * i;
    y[i] = 0.5 + 0.4 * std::sin(3.0 * x[i]);
  }
  sinew::functions::GCVSpline spline(3, x, y);
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(spline.Calc(t));
    t += 0.0137;
    if (t > 9.9) t = 0.0;
  }
}
BENCHMARK(BM_GCVSplineCalc);

// Reading a real states file (SinglePin_states.sto, 302 rows x 3 columns, 26 kB).
void BM_ReadStorage(benchmark::State& state) {
  const std::string file =
      std::string(SINEW_TEST_DATA_DIR) +
      "/opensim-org/opensim-core/Applications/Analyze/tests/resources/SinglePin_states.sto";
  for (auto _ : state) {
    sinew::io::Storage s = sinew::io::ReadStorage(file);
    benchmark::DoNotOptimize(s.values.data());
  }
}
BENCHMARK(BM_ReadStorage);

}  // namespace
