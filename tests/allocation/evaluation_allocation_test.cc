// No heap allocation per evaluation: a counting global operator new (this test program's
// only), switched on around evaluations made after a first one has sized the workspace.
// Its own program so that the replaced operator new touches no other test.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
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
}  // namespace

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

// Heap allocations made by `n` evaluations of `state` after a first one.
long AllocationsPerEvaluations(const System& system, const State& state, int n) {
  Data data(system);
  CalcAccelerations(system, state, nullptr, data);  // sizes every buffer
  g_allocations = 0;
  g_counting = true;
  for (int i = 0; i < n; ++i) CalcAccelerations(system, state, nullptr, data);
  g_counting = false;
  return g_allocations.load();
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

TEST(EvaluationAllocationTest, MusclesOnPathsEvaluateWithoutHeapUse) {
  // arm26's six Thelen2003Muscles on their paths without the PathWraps: each evaluation
  // computes their paths (thread-local buffers) and tensions, and the muscles' state
  // derivatives. The wrap objects are left out here because wrapping still allocates (measured
  // with them: 310 allocations over 10 evaluations of arm26's 7 PathWraps; docs/muscles.md).
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
                        : close == std::string::npos ? text.size() : close + end.size();
    text.erase(at, stop - at);
  }
  ASSERT_EQ(text.find("<PathWrap "), std::string::npos);
  const model::ModelSpec spec = io::ReadOsimString(text, file);
  opensim::OpenSimParser parser;
  auto system = std::make_unique<System>(spec.gravity);
  parser.ParseSpec(*system, spec);
  system->Finalize();
  ASSERT_EQ(system->num_state_variables(), 12);
  State state = MakeDefaultState(*system);
  state.u.setConstant(0.5);
  PlaceBodies(*system, state);
  state.inputs.setConstant(0.3);
  VecX zdot(system->num_state_variables());
  CalcStateVariableDerivatives(*system, state, zdot);
  EXPECT_EQ(AllocationsPerEvaluations(*system, state, 10), 0);
  g_allocations = 0;
  g_counting = true;
  for (int i = 0; i < 10; ++i) CalcStateVariableDerivatives(*system, state, zdot);
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0);
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
}

}  // namespace
}  // namespace sinew::engine
