// No heap allocation per evaluation: a counting global operator new (this test program's
// only), switched on around evaluations made after a first one has sized the workspace.
// Its own program so that the replaced operator new touches no other test.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/build_system.h>
#include <sinew/opensim/parser.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <new>
#include <string>

#include "engine/chain_model.h"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
std::atomic<long> g_mallocs{0};  // malloc/calloc/realloc calls while g_counting (see below)
}  // namespace

// Eigen's dynamic-size matrices and SUNDIALS allocate with malloc, not operator new: on glibc
// (without a sanitizer, whose runtime owns malloc) this program's malloc, calloc and realloc
// count too and forward to glibc's.
#if defined(__SANITIZE_ADDRESS__)
#define SINEW_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define SINEW_SANITIZED 1
#endif
#endif
#if defined(__GLIBC__) && !defined(SINEW_SANITIZED)
#define SINEW_COUNTS_MALLOC 1
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* malloc(std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) ++g_mallocs;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) ++g_mallocs;
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) ++g_mallocs;
  return __libc_realloc(p, size);
}
}
#endif

// GCC cannot see that this new and delete pair up (both are malloc/free here).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

void* operator new(std::size_t size) {
  if (g_counting.load()) ++g_allocations;
  void* p = std::malloc(size == 0 ? 1 : size);
  if (!p) throw std::bad_alloc();
  return p;
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace sinew::engine {
namespace {

// Heap allocations (operator new, and malloc where it is counted) made by `n` evaluations of
// `state` after a first one.
long AllocationsPerEvaluations(const System& system, const State& state, int n) {
  Data data(system);
  CalcAccelerations(system, state, nullptr, data);  // sizes every buffer
  g_allocations = 0;
  g_mallocs = 0;
  g_counting = true;
  for (int i = 0; i < n; ++i) CalcAccelerations(system, state, nullptr, data);
  g_counting = false;
  return g_allocations.load() + g_mallocs.load();
}

TEST(EvaluationAllocationTest, Gait2354SkeletonEvaluatesWithoutHeapUse) {
  // Direct pins, parameterized CustomJoints with spline couplings, a locked-free mix.
  const model::ModelSpec spec =
      io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) +
                   "/opensim-org/opensim-core/OpenSim/Simulation/Test/gait2354_simbody.osim");
  const auto system = opensim::BuildSystem(spec);
  State state = MakeDefaultState(*system);
  for (int c = 0; c < system->num_coordinates(); ++c) state.u[c] = std::sin(c + 1.0);
  PlaceBodies(*system, state);
  EXPECT_EQ(AllocationsPerEvaluations(*system, state, 10), 0);
}

TEST(EvaluationAllocationTest, ChainWithCouplersEvaluatesWithoutHeapUse) {
  // Extra constraints go through the Schur complement: its buffers are reused too.
  const System system = testing::MakeChain(20, JointForm::kParameterized, 3);
  const State state = MakeDefaultState(system);
  EXPECT_EQ(AllocationsPerEvaluations(system, state, 10), 0);
}

// arm26's six Thelen2003Muscles on their paths without the PathWraps (wrapping still allocates:
// 310 allocations over 10 evaluations of arm26's 7 PathWraps; docs/muscles.md).
std::unique_ptr<System> MakeArm26WithoutWraps() {
  const std::string file =
      std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-models/Models/Arm26/arm26.osim";
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (size_t at = text.find("<PathWrapSet"); at != std::string::npos;
       at = text.find("<PathWrapSet", at)) {
    const std::string end = "</PathWrapSet>";
    const size_t close = text.find(end, at);
    const size_t self_closing = text.find("/>", at);
    const size_t stop = self_closing < text.find('>', at) + 1 ? self_closing + 2
                        : close == std::string::npos          ? text.size()
                                                              : close + end.size();
    text.erase(at, stop - at);
  }
  EXPECT_EQ(text.find("<PathWrap "), std::string::npos);
  const model::ModelSpec spec = io::ReadOsimString(text, file);
  opensim::OpenSimParser parser;
  auto system = std::make_unique<System>(spec.gravity);
  parser.ParseSpec(*system, spec);
  system->Finalize();
  return system;
}

TEST(EvaluationAllocationTest, MusclesOnPathsEvaluateWithoutHeapUse) {
  // Each evaluation computes the muscles' paths (thread-local buffers) and tensions, and their
  // state derivatives.
  const auto system = MakeArm26WithoutWraps();
  ASSERT_EQ(system->num_state_variables(), 12);
  State state = MakeDefaultState(*system);
  state.u.setConstant(0.5);
  PlaceBodies(*system, state);
  state.inputs.setConstant(0.3);
  VecX zdot(system->num_state_variables());
  CalcStateVariableDerivatives(*system, state, zdot);
  EXPECT_EQ(AllocationsPerEvaluations(*system, state, 10), 0);
  g_allocations = 0;
  g_mallocs = 0;
  g_counting = true;
  for (int i = 0; i < 10; ++i) CalcStateVariableDerivatives(*system, state, zdot);
  g_counting = false;
  EXPECT_EQ(g_allocations.load() + g_mallocs.load(), 0);
}

TEST(EvaluationAllocationTest, CvodeRightHandSideDoesNotAllocate) {
  // CVODE's right-hand side (unpack into the scratch State, evaluate, write CVODE's vector in
  // place), the block-diagonal preconditioner (setup and solve) and each step's bookkeeping
  // reuse their buffers: after a few steps that size them, 20 further steps make no
  // operator-new allocation. malloc (Eigen's temporaries) is still called per
  // step, 8 times on this model, by the position and velocity projections (CalcPositionErrors,
  // ProjectVelocities, KktSolver::Solve) and GatherVelocities; the evaluations themselves do
  // not: the three linear solvers make different numbers of evaluations in those steps and
  // the same number of mallocs.
  const auto system = MakeArm26WithoutWraps();
#ifdef SINEW_COUNTS_MALLOC
  long first_mallocs = -1, first_evaluations = -1;
#endif
  for (const char* name : {"cvode", "cvode-gmres", "cvode-gmres-bd"}) {
    State state = MakeDefaultState(*system);
    state.inputs.setConstant(0.3);  // held (no controller): the muscles pull
    auto integrator = MakeIntegrator(name, *system, {.accuracy = 1e-6});
    for (int i = 0; i < 5; ++i) integrator->Advance(state, 1.0);
    const long evaluations = integrator->stats().evaluations;
    g_allocations = 0;
    g_mallocs = 0;
    g_counting = true;
    for (int i = 0; i < 20; ++i) integrator->Advance(state, 1.0);
    g_counting = false;
    const long window = integrator->stats().evaluations - evaluations;
    EXPECT_GT(window, 20) << name;
    EXPECT_EQ(g_allocations.load(), 0) << name;
#ifdef SINEW_COUNTS_MALLOC
    if (first_mallocs < 0) {
      first_mallocs = g_mallocs.load();
      first_evaluations = window;
    } else {
      EXPECT_NE(window, first_evaluations) << name;  // else the comparison shows nothing
      EXPECT_EQ(g_mallocs.load(), first_mallocs) << name;
    }
#endif
  }
}

TEST(EvaluationAllocationTest, ContactForcesEvaluateWithoutHeapUse) {
  // OpenSim's three bouncing balls resting in contact: Hunt-Crossley, elastic foundation on a
  // 720-face mesh, smoothed sphere/half-space.
  for (const char* file : {"BouncingBall_HuntCrossley.osim", "BouncingBallModelEF.osim",
                           "BouncingBall_SmoothSphereHalfSpace.osim"}) {
    opensim::OpenSimParser parser;
    const auto system = parser.Parse(std::string(SINEW_TEST_DATA_DIR) +
                                     "/opensim-org/opensim-core/OpenSim/Simulation/Test/" + file);
    State state = MakeDefaultState(*system);
    SetCoordinateValue(*system, state, "ball_ty", 0.4995);
    EXPECT_EQ(AllocationsPerEvaluations(*system, state, 10), 0) << file;
  }
}

TEST(EvaluationAllocationTest, TheCounterCounts) {
  // The counting operator new is really the one in use (so the zeros above mean something).
  g_allocations = 0;
  g_counting = true;
  auto* p = new std::string(100, 'x');
  g_counting = false;
  delete p;
  EXPECT_GE(g_allocations.load(), 1);
#ifdef SINEW_COUNTS_MALLOC
  // And the counting malloc, through a dynamic-size Eigen vector.
  g_mallocs = 0;
  g_counting = true;
  VecX* v = new VecX(1000);
  g_counting = false;
  delete v;
  EXPECT_GE(g_mallocs.load(), 2);  // the object (operator new) and Eigen's storage
#endif
}

}  // namespace
}  // namespace sinew::engine
