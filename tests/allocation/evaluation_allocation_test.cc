// No heap allocation per evaluation: a counting global operator new (this test program's
// only), switched on around evaluations made after a first one has sized the workspace.
// Its own program so that the replaced operator new touches no other test.
#include <gtest/gtest.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/kkt.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/build_system.h>
#include <sinew/opensim/parser.h>
#include <sinew/paths/wrap_cylinder.h>
#include <sinew/paths/wrap_cylinder_obst.h>
#include <sinew/paths/wrap_double_cylinder_obst.h>
#include <sinew/paths/wrap_ellipsoid.h>
#include <sinew/paths/wrap_sphere.h>
#include <sinew/paths/wrap_sphere_obst.h>
#include <sinew/paths/wrap_torus.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "contact/contact_models.h"
#include "contact/skeleton_drop.h"
#include "contact/skeleton_on_ground.h"
#include "contact/sphere_contact_provider.h"
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

TEST(EvaluationAllocationTest, UnitLoadResponsesThroughCouplersWithoutHeapUse) {
  // NSC contact's Delassus blocks: the tree-path responses and the Schur complement's
  // correction for the levers reuse their buffers.
  const System system = testing::MakeChain(20, JointForm::kParameterized, 3);
  KktSolver kkt(system);
  kkt.Factorize(MakeDefaultState(system));
  ASSERT_EQ(kkt.num_extra_equations(), 3);
  const std::vector<int> targets = {2, 11, 20, 5};
  MatX out(6 * targets.size(), 6);
  ASSERT_TRUE(kkt.SolveUnitLoadResponses(4, targets, out));  // sizes the buffers
  g_allocations = 0;
  g_mallocs = 0;
  g_counting = true;
  for (int source : {4, 11, 20, 1}) kkt.SolveUnitLoadResponses(source, targets, out);
  g_counting = false;
  EXPECT_EQ(g_allocations.load() + g_mallocs.load(), 0);
}

// arm26: six Thelen2003Muscles on paths wrapped by 7 PathWraps over 2 cylinders and 2
// ellipsoids.
std::unique_ptr<System> MakeArm26() {
  opensim::OpenSimParser parser;
  return parser.Parse(std::string(SINEW_TEST_DATA_DIR) +
                      "/opensim-org/opensim-models/Models/Arm26/arm26.osim");
}

TEST(EvaluationAllocationTest, MusclesOnPathsEvaluateWithoutHeapUse) {
  // Each evaluation computes the muscles' paths (thread-local buffers) and tensions, and their
  // state derivatives.
  const auto system = MakeArm26();
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

TEST(EvaluationAllocationTest, WrappedMusclePathsEvaluateWithoutHeapUse) {
  // At the default pose and with the elbow flexed, arm26's paths wrap and unwrap.
  const auto system = MakeArm26();
  for (const double elbow : {0.0, 1.2, 2.2}) {
    State state = MakeDefaultState(*system);
    SetCoordinateValue(*system, state, "r_elbow_flex", elbow);
    PlaceBodies(*system, state);
    state.u.setConstant(0.5);
    state.inputs.setConstant(0.3);
    EXPECT_EQ(AllocationsPerEvaluations(*system, state, 10), 0) << "elbow " << elbow;
  }
}

TEST(EvaluationAllocationTest, EveryWrapSurfaceWrapsWithoutHeapUse) {
  // Each surface type wraps a segment that crosses it (arc points, for drawing, are not asked
  // for); the cylinder also with OpenSim's tangency refinement (a path with several wraps).
  using namespace paths;
  const Vec3 p(-0.05, 0.01, 0.01), s(0.05, 0.01, -0.01);  // crosses every surface at 1 cm
  const WrapCylinder cylinder(0.02, 0.2, {});
  const WrapSphere sphere(0.02, {});
  const WrapEllipsoid ellipsoid({0.02, 0.03, 0.04}, {});
  const WrapTorus torus(0.035, 0.08, {});  // P and S straddle its tube at (0.08, 0, 0)
  const WrapCylinderObst cylinder_obstacle(0.02, WrapCylinderObst::Direction::kLeftHand);
  const WrapSphereObst sphere_obstacle(0.02);
  const struct {
    const char* name;
    const WrapSurface& surface;
    Vec3 p, s;
    bool single_wrap;
  } cases[] = {{"WrapCylinder", cylinder, p, s, true},
               {"WrapCylinder refined", cylinder, p, s, false},
               {"WrapSphere", sphere, p, s, true},
               {"WrapEllipsoid", ellipsoid, p, s, true},
               {"WrapTorus", torus, {0.07, 0.0, -0.06}, {0.07, 0.0, 0.06}, true},
               {"WrapCylinderObst", cylinder_obstacle, p, s, true},
               {"WrapSphereObst", sphere_obstacle, p, s, true}};
  for (const auto& c : cases) {
    WrapOptions options;
    options.single_wrap = c.single_wrap;
    g_allocations = 0;
    g_mallocs = 0;
    g_counting = true;
    const WrapResult result = c.surface.Wrap(c.p, c.s, options);
    g_counting = false;
    EXPECT_TRUE(result.wrapped) << c.name;
    EXPECT_GT(result.arc_length, 0.0) << c.name;
    EXPECT_EQ(g_allocations.load() + g_mallocs.load(), 0) << c.name;
  }
  // WrapDoubleCylinderObst over both its cylinders (Newton's method on the crossing line).
  const WrapDoubleCylinderObst two(0.02, WrapDoubleCylinderObst::Direction::kRightHand, 0.02,
                                   WrapDoubleCylinderObst::Direction::kRightHand);
  WrapOptions options;
  options.X_WV = Transform::Translation(Vec3(0.1, 0.0, 0.0));
  g_allocations = 0;
  g_mallocs = 0;
  g_counting = true;
  const WrapResult result = two.Wrap({-0.05, -0.01, 0.0}, {0.15, -0.01, 0.0}, options);
  g_counting = false;
  EXPECT_TRUE(result.on_first && result.on_second);
  EXPECT_EQ(g_allocations.load() + g_mallocs.load(), 0) << "WrapDoubleCylinderObst";
}

// Heap allocations made by `steps` further steps of `integrator` (each Advance is one step).
long AllocationsPerSteps(Integrator& integrator, State& state, int steps) {
  g_allocations = 0;
  g_mallocs = 0;
  g_counting = true;
  for (int i = 0; i < steps; ++i) integrator.Advance(state, state.t + 1.0);
  g_counting = false;
  return g_allocations.load() + g_mallocs.load();
}

TEST(EvaluationAllocationTest, CvodeStepsWithoutHeapUse) {
  // CVODE's right-hand side (unpack into the scratch State, evaluate, write CVODE's vector in
  // place), the block-diagonal preconditioner (setup and solve), the projections onto the
  // constraints and each step's bookkeeping reuse their buffers: after a few steps that size
  // them, 20 further steps allocate nothing.
  const auto system = MakeArm26();
  for (const char* name : {"cvode", "cvode-gmres", "cvode-gmres-bd"}) {
    State state = MakeDefaultState(*system);
    state.inputs.setConstant(0.3);  // held (no controller): the muscles pull
    auto integrator = MakeIntegrator(name, *system, {.accuracy = 1e-6});
    for (int i = 0; i < 5; ++i) integrator->Advance(state, 1.0);
    const long evaluations = integrator->stats().evaluations;
    EXPECT_EQ(AllocationsPerSteps(*integrator, state, 20), 0) << name;
    EXPECT_GT(integrator->stats().evaluations - evaluations, 20) << name;
  }
}

TEST(EvaluationAllocationTest, EulerStepsWithoutHeapUse) {
  // Semi-implicit Euler's step (evaluation, velocity solve, position and velocity
  // projections) on arm26's muscles and on a chain whose couplers need projecting.
  const auto arm26 = MakeArm26();
  const System chain = testing::MakeChain(20, JointForm::kParameterized, 3);
  for (const System* system : {static_cast<const System*>(arm26.get()), &chain}) {
    State state = MakeDefaultState(*system);
    state.inputs.setConstant(0.3);
    auto integrator = MakeIntegrator("euler", *system, {.step = 1e-3});
    for (int i = 0; i < 5; ++i) integrator->Advance(state, 1.0);
    EXPECT_EQ(AllocationsPerSteps(*integrator, state, 20), 0) << system->num_bodies();
    EXPECT_EQ(integrator->stats().steps, 25);
  }
}

TEST(EvaluationAllocationTest, NscStepsWithoutHeapUse) {
  // The NSC stepper's own buffers (the free step, the State, the contact rows, the Delassus
  // operator and APGD's workspace) are reused: a ball resting on the floor, one contact per
  // step, and a block standing on three spheres, three; with either impulse solver.
  const auto system = sinew::testing::ParseContactModel(
      sinew::testing::FreeBodyContactModel(1.0, Vec3::Constant(0.004), Vec3(0, -9.80665, 0), 0.1,
                                           {Vec3::Zero()}, ""),
      "nsc_ball.osim");
  const std::vector<sinew::testing::TestSphere> ball = {{1, Vec3::Zero(), 0.1}};
  const std::vector<sinew::testing::TestSphere> feet = {{1, Vec3(0.1, -0.09, 0), 0.01},
                                                        {1, Vec3(-0.05, -0.09, 0.087), 0.01},
                                                        {1, Vec3(-0.05, -0.09, -0.087), 0.01}};
  for (const auto method : {ContactSolverMethod::kGaussSeidel, ContactSolverMethod::kApgd}) {
    for (const auto* spheres : {&ball, &feet}) {
      auto provider =
          std::make_shared<sinew::testing::SphereContactProvider>(*spheres, true, 0.4, 0.0, 1e-3);
      NscSettings nsc;
      nsc.solver.method = method;
      NscIntegrator integrator(*system, provider, {.step = 1e-3}, nsc);
      State state = MakeDefaultState(*system);
      SetCoordinateValue(*system, state, "ty", 0.1);
      for (int i = 0; i < 5; ++i) integrator.Advance(state, 1.0);
      const bool apgd = method == ContactSolverMethod::kApgd;
      EXPECT_EQ(AllocationsPerSteps(integrator, state, 20), 0) << apgd << " " << spheres->size();
      // It rests on the floor throughout.
      EXPECT_EQ(integrator.last_contacts().size(), spheres->size()) << apgd;
    }
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

TEST(EvaluationAllocationTest, SkeletonOnTheGroundStepsWithoutHeapUse) {
  // The SMC skeleton-on-ground scene (the seed's cylinders, Bullet's detection each evaluation):
  // once landed, with contacts coming and going as it folds, 50 further Euler steps allocate
  // nothing (Bullet's pair caches and manifolds keep their memory once grown).
  const sinew::testing::SkeletonDrop scene = sinew::testing::MakeSkeletonDrop(0.05);
  State state = MakeDefaultState(*scene.system);
  IntegratorSettings settings;
  settings.step = 1e-3;
  auto integrator = MakeIntegrator("euler", *scene.system, settings);
  integrator->StepTo(state, 0.3);  // landed: contacts active
  EXPECT_EQ(AllocationsPerSteps(*integrator, state, 50), 0);
}

TEST(EvaluationAllocationTest, NscSkeletonOnTheGroundStepsWithoutHeapUse) {
  // The NSC scene of issue 14 through Bullet's detection (CollisionContactProvider): once the
  // skeleton lies on the ground and its buffers have grown to its contacts, 50 further steps
  // allocate nothing.
  sinew::testing::SkeletonOnGround scene = sinew::testing::MakeSkeletonOnGround(0.05);
  NscIntegrator integrator(*scene.system, scene.provider, {.step = 1e-3}, {});
  integrator.StepTo(scene.state, 2.0);
  EXPECT_EQ(AllocationsPerSteps(integrator, scene.state, 50), 0);
  EXPECT_GT(integrator.last_contacts().size(), 10u);  // lying on the ground
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
