// Simbody as an independent reference engine: a skeleton built in Simbody from plain data, for
// the tests that compare Sinew's dynamics with Simbody's (tests/simbody) and the benchmarks that
// time Simbody on the same motions (benchmarks/simbody_hung.cc). Compiled as C++17 on its own:
// Simbody 3.7's headers do not compile as C++20 (their index types' comparison operators become
// ambiguous), and Sinew's headers need C++20, so this interface mentions neither.
// simbody/from_spec.h makes its input from a Sinew ModelSpec.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace simbody_reference {

/// A pose: rotation R (row-major) and translation p of a frame in its parent.
struct Pose {
  std::array<double, 9> R{1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::array<double, 3> p{0, 0, 0};
};

/// f(x) (n arguments) for num_wrt = 0, else the partial derivative of f by the arguments
/// listed in wrt. Called on every evaluation: it must not allocate.
using ScalarFunction = std::function<double(const double* x, int n, const int* wrt, int num_wrt)>;
/// The most arguments a ScalarFunction may take.
inline constexpr int kMaxArguments = 8;

struct Body {
  double mass = 0;
  std::array<double, 3> mass_center{0, 0, 0};  ///< in the body frame
  std::array<double, 9> inertia{};             ///< about the mass centre, body axes (row-major)
};

/// One axis of a function-based mobilizer: a rotation about, or translation along, `axis`
/// by f(the joint's coordinates listed in `arguments`, as indices into Joint::coordinates).
struct Axis {
  ScalarFunction f;
  std::vector<int> arguments;
  std::array<double, 3> axis{1, 0, 0};
};

/// A joint as a Simbody mobilizer. Ball, Free, Gimbal and Ellipsoid take body-fixed X-Y-Z
/// angles (the State uses Euler angles, as OpenSim's does); their speeds are Simbody's (the
/// angular velocity in F for Ball, Free and Ellipsoid; the angles' rates for Gimbal).
struct Joint {
  enum class Kind {
    kPin,
    kSlider,
    kUniversal,
    kGimbal,
    kBall,
    kEllipsoid,
    kFree,
    kPlanar,
    kWeld,
    kFunctionBased
  };
  Kind kind = Kind::kWeld;
  /// Body indices (0: ground): frame F is fixed to `parent`, M to `child`. The body nearer to
  /// ground must come first: `parent`, or `child` when `reversed` (a joint whose parent hangs
  /// from its child: Simbody's reverse mobilizer, whose q and u keep their meaning from F to M).
  int parent = 0, child = 0;
  bool reversed = false;
  Pose X_PF, X_BM;
  std::vector<int> coordinates;  ///< model coordinate indices, in the mobilizer's q order
  std::vector<Axis> axes;        ///< kFunctionBased: three rotations, then three translations
  std::array<double, 3> radii{1, 1, 1};  ///< kEllipsoid
};

/// f(q_independent..., q_dependent) = 0.
struct Coupler {
  ScalarFunction f;
  std::vector<int> coordinates;  ///< model coordinate indices, the function's arguments
};

struct Model {
  std::array<double, 3> gravity{0, -9.80665, 0};
  std::vector<Body> bodies;  ///< [0] is ground (ignored)
  std::vector<Joint> joints;
  std::vector<Coupler> couplers;
  std::vector<int> locked;   ///< model coordinates held at their start value
  std::vector<double> q, u;  ///< start coordinates and speeds, per model coordinate
};

/// The model in Simbody, ready to integrate from its start state.
class Simulation {
 public:
  explicit Simulation(const Model& model);
  ~Simulation();
  /// Simbody's error-controlled explicit integrators.
  enum class Scheme { kRungeKuttaMerson, kRungeKuttaFeldberg };
  /// What a run did.
  struct RunStats {
    long steps = 0;            ///< steps taken
    long attempted = 0;        ///< steps attempted (taken and rejected)
    long realizations = 0;     ///< evaluations: realizations to the acceleration stage
    double energy_change = 0;  ///< mechanical energy (kinetic + gravity's potential) gained, J
  };
  /// The coordinates at t_final after Simbody's `scheme` at `accuracy` (coordinates no
  /// mobilizer holds keep their start values); what the run did into *stats when not null.
  std::vector<double> Run(Scheme scheme, double accuracy, double t_final,
                          RunStats* stats = nullptr) const;
  /// One evaluation at the start state: everything from the positions on is recomputed
  /// (kinematics, mass properties, forces, the accelerations). Returns the first generalized
  /// acceleration. For timing; not thread-safe (it reuses one working state).
  double EvaluateAccelerations() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace simbody_reference
