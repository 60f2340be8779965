// The model description ("spec"): plain data read from an .osim file, nothing simulated.
// All frames are resolved to the body they are fixed to; all indices point into ModelSpec's
// vectors. Body index 0 is always ground. Units: SI (m, kg, s, rad, N).
#pragma once

#include <sinew/common/error.h>
#include <sinew/functions/function.h>
#include <sinew/math/transform.h>
#include <sinew/model/element.h>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sinew::model {

inline constexpr int kGroundIndex = 0;  ///< ModelSpec::bodies[0] is ground.
inline constexpr int kNone = -1;        ///< An index that refers to nothing.

/// Named numeric properties without a typed field (e.g. "radius", "half_lengths").
using NumberMap = std::map<std::string, std::vector<double>>;

/// Visual geometry attached to a frame (4.x attached_geometry, 3.x VisibleObject).
struct GeometrySpec {
  std::string name;
  std::string type;  ///< "Mesh", "Sphere", "Cylinder", "Brick", "Ellipsoid", "Cone", ...
  int body = kGroundIndex;
  std::string frame;      ///< Path of the frame it is attached to.
  Transform X_BG;         ///< Pose of the geometry in the body frame.
  std::string mesh_file;  ///< For meshes: the file name as written.
  Vec3 scale_factors = Vec3::Ones();
  Vec3 color = Vec3::Ones();  ///< RGB in [0, 1].
  double opacity = 1.0;
  bool visible = true;
  NumberMap dimensions;  ///< radius, half_lengths, half_height, radii, ...
};

/// A wrap object (WrapCylinder, WrapSphere, WrapEllipsoid, WrapTorus) fixed to a body.
struct WrapObjectSpec {
  std::string name;
  std::string type;
  int body = kGroundIndex;
  Transform X_BW;        ///< Pose in the body frame (xyz_body_rotation, translation).
  std::string quadrant;  ///< "all", "+x", "-y", ...
  bool active = true;
  NumberMap dimensions;  ///< radius, length, dimensions, inner_radius, outer_radius
  /// WrapDoubleCylinderObst only: the body its V cylinder is fixed to (wrapVcylHomeBodyName)
  /// and the V cylinder's frame V in that body (xyz_body_rotationVcyl, translationVcyl);
  /// kNone for every other type.
  int second_body = kNone;
  Transform X_BV;
  SourceLocation where;
};

/// A body: mass properties about its mass centre, in its own (generally non-centroidal) frame.
struct BodySpec {
  std::string name;
  std::string path;                 ///< "/bodyset/femur_r" ("/ground" for ground).
  double mass = 0.0;                ///< kg
  Vec3 mass_center = Vec3::Zero();  ///< p_BCm, in the body frame (m).
  Mat3 inertia = Mat3::Zero();      ///< About the mass centre, body axes (kg m^2).
  std::vector<GeometrySpec> geometry;
  std::vector<WrapObjectSpec> wrap_objects;
  SourceLocation where;
};

/// A frame fixed to a body: PhysicalOffsetFrames (nested allowed) and 3.x joint frames.
struct FrameSpec {
  std::string name;
  std::string path;         ///< Full path, e.g. "/jointset/knee_r/femur_r_offset".
  std::string parent;       ///< Path of the frame it is offset from.
  Transform X_PF;           ///< Offset from that parent frame.
  int body = kGroundIndex;  ///< The body it is fixed to after resolving all offsets.
  Transform X_BF;           ///< Its pose in that body's frame.
  SourceLocation where;
};

/// OpenSim joint classes Sinew knows; kUnknown for anything else (e.g. a plugin's joint).
enum class JointType {
  kPin,
  kSlider,
  kUniversal,
  kGimbal,
  kBall,
  kFree,
  kPlanar,
  kEllipsoid,
  kWeld,
  kScapulothoracic,
  kCustom,
  kConstantCurvature,
  kUnknown
};

/// One of a CustomJoint's six axes: s = function(coordinates), along or about `axis` (in F).
struct TransformAxisSpec {
  std::string name;                 ///< rotation1..3, translation1..3
  std::vector<int> coordinates;     ///< Indices into ModelSpec::coordinates.
  Vec3 axis = Vec3::UnitX();        ///< As written (normalized on use).
  functions::FunctionPtr function;  ///< Never null: defaults filled as OpenSim does.
};

/// A joint between a parent frame F (on body `parent_body`) and a child frame M (on
/// `child_body`): X_GB = X_GP * X_PF * X_FM(q) * inverse(X_BM).
struct JointSpec {
  std::string name;
  std::string path;  ///< "/jointset/knee_r"
  std::string type;  ///< OpenSim class name as written.
  JointType kind = JointType::kUnknown;
  int parent_body = kGroundIndex;
  int child_body = kGroundIndex;
  std::string parent_frame;      ///< Path of F.
  std::string child_frame;       ///< Path of M.
  Transform X_PF;                ///< F in the parent body frame.
  Transform X_BM;                ///< M in the child body frame.
  bool reverse = false;          ///< 3.x `reverse`: parent and child roles swapped in the file.
  std::vector<int> coordinates;  ///< Indices into ModelSpec::coordinates, in joint order.
  std::vector<TransformAxisSpec> spatial_transform;  ///< CustomJoint: 6 axes, else empty.
  NumberMap parameters;  ///< Other numeric properties (radii_x_y_z, ...).
  Element element;       ///< Everything the file said about the joint.
  SourceLocation where;
};

enum class MotionType { kRotational, kTranslational, kCoupled };

/// A generalized coordinate of a joint.
struct CoordinateSpec {
  std::string name;
  std::string path;   ///< "/jointset/knee_r/knee_angle_r"
  int joint = kNone;  ///< Index into ModelSpec::joints.
  MotionType motion_type = MotionType::kRotational;
  double default_value = 0.0;        ///< rad or m
  double default_speed_value = 0.0;  ///< rad/s or m/s (Ball/Free: angular velocity component)
  double range_min = -1e300, range_max = 1e300;
  bool clamped = false;
  /// is_free_to_satisfy_constraints: the assembly of the initial state does not try to keep
  /// this coordinate at its default value.
  bool free_to_satisfy_constraints = false;
  bool locked = false;
  bool prescribed = false;
  functions::FunctionPtr prescribed_function;  ///< q(t) when prescribed; may be null.
  SourceLocation where;
};

/// A point of a geometry path. Location is in the body frame (resolved through its frame).
struct PathPointSpec {
  std::string name;
  std::string type;  ///< PathPoint, ConditionalPathPoint, MovingPathPoint
  int body = kGroundIndex;
  std::string frame;
  Vec3 location = Vec3::Zero();  ///< p_BP in the body frame (fixed points).
  int coordinate = kNone;        ///< ConditionalPathPoint: active when range_min <= q <= range_max
  double range_min = 0, range_max = 0;
  std::array<functions::FunctionPtr, 3>
      location_functions;  ///< MovingPathPoint x, y, z (in frame F)
  std::array<int, 3> location_coordinates{kNone, kNone, kNone};
  Transform X_BF;  ///< The frame's pose in the body (for moving points).
};

/// A wrap object used by a path.
struct PathWrapSpec {
  std::string wrap_object;
  std::string method;  ///< "hybrid", "midpoint", "axial"
  std::array<int, 2> range{-1, -1};
};

/// A muscle's or spring's path.
struct GeometryPathSpec {
  std::vector<PathPointSpec> points;
  std::vector<PathWrapSpec> wraps;
};

/// A FunctionBasedPath (OpenSim 4.5+): the path's length as a function of coordinates, with no
/// points. The functions take the coordinates' values in `coordinates` order (the lengthening
/// speed function: those values, then the coordinates' speeds).
struct FunctionBasedPathSpec {
  std::string name;              ///< The path's name ("path").
  std::vector<int> coordinates;  ///< coordinate_paths, as indices into ModelSpec::coordinates.
  functions::FunctionPtr length_function;  ///< L(q) in m; never null.
  /// moment_arm_functions: r_i(q), one per coordinate; empty when the file gives none (then
  /// r_i = -dL/dq_i).
  std::vector<functions::FunctionPtr> moment_arm_functions;
  /// lengthening_speed_function(q, u); null when the file gives none (then -sum r_i qdot_i).
  functions::FunctionPtr lengthening_speed_function;
  SourceLocation where;
};

/// A frame a force is attached to through one of its sockets, resolved to its body.
struct ForceFrameSpec {
  std::string path;         ///< The frame's absolute path ("/forceset/bushing/ball_offset").
  int body = kGroundIndex;  ///< The body it is fixed to.
  Transform X_BF;           ///< Its pose in that body's frame.
};

/// A force or actuator (muscles included). Type-specific properties stay in `element`.
struct ForceSpec {
  std::string name;
  std::string path;
  std::string type;  ///< OpenSim class name
  bool applies_force = true;
  std::optional<GeometryPathSpec> geometry_path;
  /// Its FunctionBasedPath, when it has one instead of a GeometryPath.
  std::optional<FunctionBasedPathSpec> function_based_path;
  /// Frames named by the force's frame sockets, by socket name: "frame1" and "frame2" (4.x
  /// socket_frame1/2, or 3.x body_1/body_2 offset by location_body_i/orientation_body_i as
  /// OpenSim's upgrade does), "frame" (socket_frame).
  std::map<std::string, ForceFrameSpec, std::less<>> frames;
  /// Function-valued properties of the classes whose builders need them, by property name: one
  /// function for a Function property (FunctionBasedBushingForce's m_x_theta_x_function), the
  /// members in order for a FunctionSet (PrescribedForce's forceFunctions).
  std::map<std::string, std::vector<functions::FunctionPtr>, std::less<>> functions;
  Element element;
  SourceLocation where;
  /// Format version of the document the force was read from: the model's, or its ForceSet
  /// file's (10500 for a ForceSet file without an OpenSimDocument, as OpenSim assumes; its
  /// version-dependent upgrades, such as the actuators' flipped directions, follow it).
  int version = 0;
};

/// A frame a constraint attaches to, resolved to the body it is fixed to: WeldConstraint's
/// frame1/frame2 (4.x sockets, or 3.x body_1/body_2 with location_body_i and
/// orientation_body_i), PointConstraint's and ConstantDistanceConstraint's body_1/body_2,
/// PointOnLineConstraint's line_body/follower_body.
struct ConstraintFrame {
  int body = kNone;   ///< body index (kNone when the constraint type has no such frame)
  std::string frame;  ///< the frame's absolute path (a body's or an offset frame's)
  Transform X_BF;     ///< the frame's pose in its body
};

/// A constraint (CoordinateCouplerConstraint, WeldConstraint, PointConstraint, ...).
struct ConstraintSpec {
  std::string name;
  std::string path;
  std::string type;
  bool enabled = true;
  /// CoordinateCouplerConstraint: the coordinates of independent_coordinate_names and
  /// dependent_coordinate_name (indices into ModelSpec::coordinates; empty / kNone for other
  /// types) and coupled_coordinates_function (null when absent or for other types).
  std::vector<int> independent_coordinates;
  int dependent_coordinate = kNone;
  functions::FunctionPtr function;
  double scale_factor = 1.0;  ///< CoordinateCouplerConstraint: q_dep = scale_factor f(q_ind)
  std::array<ConstraintFrame, 2> frames;  ///< the two frames of a body-to-body constraint
  Element element;
  SourceLocation where;
};

/// A marker fixed to a body.
struct MarkerSpec {
  std::string name;
  int body = kGroundIndex;
  std::string frame;
  Vec3 location = Vec3::Zero();  ///< p_BM in the body frame.
  bool fixed = false;
  SourceLocation where;
};

/// Contact geometry (ContactHalfSpace, ContactSphere, ContactMesh, ...).
struct ContactGeometrySpec {
  std::string name;
  std::string type;
  int body = kGroundIndex;
  std::string frame;
  Transform X_BC;        ///< Pose in the body frame.
  NumberMap dimensions;  ///< radius, ...
  std::string mesh_file;
  Element element;
  SourceLocation where;
};

/// A controller (PrescribedController, ...). Settings stay in `element`.
struct ControllerSpec {
  std::string name;
  std::string type;
  std::vector<std::string> actuators;
  /// PrescribedController: one control function of time per entry of `actuators`.
  std::vector<functions::FunctionPtr> functions;
  Element element;
  SourceLocation where;
};

/// Everything an .osim file says about a model.
struct ModelSpec {
  std::string name;
  std::string file;  ///< The file it was read from.
  int version = 0;   ///< OpenSimDocument Version, e.g. 30000, 40000.
  Vec3 gravity = Vec3(0, -9.80665, 0);
  std::vector<BodySpec> bodies;  ///< [0] is ground.
  std::vector<FrameSpec> frames;
  std::vector<JointSpec> joints;
  std::vector<CoordinateSpec> coordinates;
  std::vector<ConstraintSpec> constraints;
  std::vector<ForceSpec> forces;
  std::vector<MarkerSpec> markers;
  std::vector<ContactGeometrySpec> contact_geometry;
  std::vector<ControllerSpec> controllers;
  std::vector<Element> other_components;  ///< Probes, components, ...: kept, not simulated.
  Diagnostics warnings;

  /// Index of the body named `name` ("ground" gives 0), or kNone.
  int FindBody(std::string_view body_name) const;
  /// Index of the joint named `name`, or kNone.
  int FindJoint(std::string_view joint_name) const;
  /// Index of the coordinate named `name`, or kNone.
  int FindCoordinate(std::string_view coordinate_name) const;
};

}  // namespace sinew::model
