// engine::System: the immutable description of a Cartesian multibody system (bodies, joints as
// constraints, coordinates, extra constraints, force elements, gravity). Its changing data live
// in an engine::State; algorithms are free functions over (System, State).
#pragma once

#include <sinew/engine/body.h>
#include <sinew/engine/constraint.h>
#include <sinew/engine/force_element.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/state.h>
#include <sinew/functions/function.h>
#include <sinew/kinematics/joint_model.h>
#include <sinew/math/transform.h>

#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace sinew::engine {

/// How a joint is imposed. kParameterized: the six equations inverse(X_GF) * X_GM = X_FM(q)
/// with the joint coordinates as extra unknowns (any JointModel). The others are direct
/// Cartesian forms that need no joint unknowns; their coordinates are read off the poses:
/// kPin (rotation q about the common z axis of F and M), kBall (body-fixed X-Y-Z angles, speeds
/// = w_FM in F), kUniversal (rotation about x, then about the new y), kWeld (no motion).
enum class JointForm { kParameterized, kPin, kBall, kUniversal, kWeld };

/// How a coordinate moves.
enum class CoordinateMotion { kFree, kLocked, kPrescribed };

/// A generalized coordinate of a joint.
struct Coordinate {
  std::string name;
  int joint = -1;              ///< index into System::joints()
  int index_in_joint = 0;      ///< position in the joint's q
  double default_value = 0.0;  ///< rad or m
  double default_speed = 0.0;  ///< rad/s or m/s (Ball: w_FM component in F)
  CoordinateMotion motion = CoordinateMotion::kFree;
  functions::FunctionPtr prescribed;  ///< q(t) for kPrescribed
  /// Weight of (q - default_value)^2 in the assembly of the default state (AssembleState);
  /// 0 lets the coordinate move freely to satisfy the constraints.
  double assembly_weight = 1.0;
};

/// A joint between frame F on body `parent` and frame M on body `child`:
/// X_GB = X_GP * X_PF * X_FM(q) * inverse(X_BM).
struct Joint {
  std::string name;
  int parent = 0;
  int child = 0;
  Transform X_PF;
  Transform X_BM;
  JointForm form = JointForm::kParameterized;
  /// X_FM(q) for kParameterized (required). Unused by the direct forms.
  std::shared_ptr<const kinematics::JointModel> model;
  std::vector<int> coordinates;  ///< indices into System::coordinates(), in joint order
};

/// Description of a coordinate passed to System::AddJoint.
struct CoordinateDesc {
  std::string name;
  double default_value = 0.0;
  double default_speed = 0.0;
  CoordinateMotion motion = CoordinateMotion::kFree;
  functions::FunctionPtr prescribed;
  double assembly_weight = 1.0;  ///< see Coordinate::assembly_weight (>= 0)
};

/// A Cartesian multibody system. Build it with the Add* functions, then Finalize(); after that
/// it is used as const by every algorithm (many States may share one System).
class System {
 public:
  /// A system holding only ground (body 0), with gravity `gravity` (m/s^2, in G).
  explicit System(const Vec3& gravity = Vec3(0, -9.80665, 0));

  /// Adds a body; returns its index. Mass must be >= 0 and the inertia symmetric.
  int AddBody(const Body& body);
  /// Adds a joint (its coordinates in joint order); returns its index. The joints must connect
  /// every body to ground (a joint may point towards ground: it is then used reversed; a joint
  /// between two bodies already connected closes a loop).
  int AddJoint(const std::string& name, int parent, const Transform& X_PF, int child,
               const Transform& X_BM, JointForm form,
               std::shared_ptr<const kinematics::JointModel> model,
               const std::vector<CoordinateDesc>& coordinates);
  /// Adds an extra constraint (loop closures, couplers, ...).
  void AddConstraint(std::shared_ptr<const Constraint> constraint);
  /// Adds a force element evaluated with every acceleration computation; returns its index.
  /// Its state variables and inputs get their places in State::z and State::inputs now, after
  /// those of the elements added before it (see StateVariableBegin, InputBegin).
  int AddForceElement(std::shared_ptr<const ForceElement> force);
  void SetGravity(const Vec3& gravity) { gravity_ = gravity; }

  /// Checks the system (tree, masses, coordinates) and lays out the unknowns. Throws
  /// sinew::Error for a system that cannot be simulated.
  void Finalize();
  bool finalized() const { return finalized_; }

  const Vec3& gravity() const { return gravity_; }
  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<Joint>& joints() const { return joints_; }
  const std::vector<Coordinate>& coordinates() const { return coordinates_; }
  /// Every constraint: first the joints' (in joint order), then the coordinate locks and
  /// prescribed motions, then the extra ones. Valid after Finalize().
  const std::vector<std::shared_ptr<const Constraint>>& constraints() const { return constraints_; }
  const std::vector<std::shared_ptr<const ForceElement>>& force_elements() const { return forces_; }
  /// First entry of force element k's state variables in State::z, and of its inputs in
  /// State::inputs.
  int StateVariableBegin(int k) const { return force_layout_[k].z_begin; }
  int InputBegin(int k) const { return force_layout_[k].input_begin; }
  /// Number of force element k's state variables and inputs.
  int NumStateVariables(int k) const { return force_layout_[k].num_z; }
  int NumInputs(int k) const { return force_layout_[k].num_inputs; }
  /// The context force element k reads in an evaluation of `state`.
  ForceContext MakeForceContext(int k, const State& state) const {
    return ForceContext{*this, state, force_layout_[k].z_begin, force_layout_[k].input_begin};
  }
  /// Names of every auxiliary state variable ("<element>/<variable>", State::z order) and of
  /// every input ("<element>/<input>", State::inputs order).
  const std::vector<std::string>& state_variable_names() const { return z_names_; }
  const std::vector<std::string>& input_names() const { return input_names_; }
  int num_state_variables() const { return static_cast<int>(z_names_.size()); }
  int num_inputs() const { return static_cast<int>(input_names_.size()); }
  int num_bodies() const { return static_cast<int>(bodies_.size()); }
  int num_coordinates() const { return static_cast<int>(coordinates_.size()); }

  /// True when coordinate `i` belongs to a parameterized joint (its q and u are integrated).
  bool IsIntegrated(int i) const { return u_column_[i] >= 0; }
  /// The velocity-unknown column of integrated coordinate `i` among the integrated speeds, or -1.
  int SpeedIndex(int i) const { return u_column_[i]; }
  /// Number of integrated speeds (coordinates of parameterized joints).
  int num_integrated() const { return num_integrated_; }
  /// Joint indices in tree order (every joint after the joint that places its inboard body).
  const std::vector<int>& tree_order() const { return tree_order_; }
  /// True when joint j places its parent body from its child (child nearer to ground).
  bool IsReversed(int j) const { return reversed_[j]; }
  /// True when joint j closes a loop of joints: it places no body (not in tree_order()), and
  /// its constraint is solved with the others; states are assembled by projection.
  bool IsLoop(int j) const { return loop_[j]; }
  /// Whether any joint closes a loop.
  bool HasLoops() const { return std::find(loop_.begin(), loop_.end(), true) != loop_.end(); }
  /// The values of free coordinates (index into coordinates(), value), sorted, where the
  /// accelerations or their rate of change jump: the breakpoints of parameterized joints' axis
  /// functions and of couplers' functions (a cubic spline's knots and ends). rk45 ends a failing
  /// step there. Valid after Finalize().
  const std::vector<std::pair<int, double>>& breakpoints() const { return breakpoints_; }
  /// Whether constraints were added with AddConstraint (couplers, welds, ...).
  bool HasExtraConstraints() const { return !extra_constraints_.empty(); }
  /// Whether constraint k holds by construction after the fixed-step schemes' position update
  /// (ApplyTreeDisplacement): a tree joint's constraint, or the lock of a coordinate (whose
  /// speed is zero). Loop joints, prescribed motions and extra constraints must be projected.
  bool HeldByTreePlacement(int k) const { return held_by_tree_placement_[k]; }
  /// Index in constraints() of the first constraint added with AddConstraint (the others
  /// follow it). Valid after Finalize().
  int FirstExtraConstraint() const {
    return static_cast<int>(constraints_.size() - extra_constraints_.size());
  }
  /// The joint that places body `b` from ground outward, or -1 (ground).
  int JointOfBody(int b) const { return joint_of_body_[b]; }

  /// Whether any force element carries data between steps (ForceElement::HasDiscreteData).
  bool HasDiscreteData() const { return !discrete_forces_.empty(); }
  /// What the integrators call at the end of every accepted step: each such element's data
  /// from `state` (ForceElement::UpdateDiscreteData) replaces its entry in state.discrete.
  /// `only_missing`: only elements without an entry get one (before the first step, so that
  /// contacts present at the start keep their history from there).
  void UpdateDiscreteData(State& state, bool only_missing = false) const;

  int FindBody(std::string_view name) const;
  int FindJoint(std::string_view name) const;
  int FindCoordinate(std::string_view name) const;
  /// Index of a state variable or input by its full name ("<element>/<variable>"), or -1.
  int FindStateVariable(std::string_view name) const;
  int FindInput(std::string_view name) const;

 private:
  void RequireNotFinalized() const;
  // breakpoints_ from the joints and the extra constraints (Finalize).
  void CollectBreakpoints();

  Vec3 gravity_;
  std::vector<Body> bodies_;
  std::vector<Joint> joints_;
  std::vector<Coordinate> coordinates_;
  std::vector<std::shared_ptr<const Constraint>> extra_constraints_;
  std::vector<std::shared_ptr<const Constraint>> constraints_;
  std::vector<std::shared_ptr<const ForceElement>> forces_;
  struct ForceLayout {
    int z_begin = 0;
    int num_z = 0;
    int input_begin = 0;
    int num_inputs = 0;
  };
  std::vector<ForceLayout> force_layout_;
  std::vector<int> discrete_forces_;  // the force elements with discrete data
  std::vector<std::string> z_names_;
  std::vector<std::string> input_names_;
  std::vector<int> u_column_;
  std::vector<int> tree_order_;
  std::vector<std::pair<int, double>> breakpoints_;
  std::vector<int> joint_of_body_;
  std::vector<bool> reversed_;
  std::vector<bool> loop_;
  std::vector<bool> held_by_tree_placement_;  // per constraint
  int num_integrated_ = 0;
  bool finalized_ = false;
};

}  // namespace sinew::engine
