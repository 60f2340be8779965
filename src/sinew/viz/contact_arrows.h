// Contact forces as arrows for the viewer and `sinew render`: per frame, each body's net contact
// force read from a contacts table (`sinew simulate`'s contacts.sto), the point its arrow starts
// at, and the arrow's shape.
#pragma once

#include <sinew/common/error.h>
#include <sinew/io/storage.h>
#include <sinew/model/model_spec.h>
#include <sinew/viz/body_motion.h>
#include <sinew/viz/floor_plane.h>
#include <sinew/viz/visual_scene.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sinew::viz {

/// One arrow per column group "<force>.<group>" of the table whose body is not ground, per
/// frame of the motion.
struct ContactArrows {
  std::vector<std::string> names;        ///< "<force>.<group>", one per arrow
  std::vector<int> bodies;               ///< the spec body each arrow pushes
  std::vector<std::vector<Vec3>> start;  ///< [frame][arrow]: where it starts, in ground (m)
  std::vector<std::vector<Vec3>> force;  ///< [frame][arrow]: the force, in ground (N)
  double body_weight = 0;                ///< the model's mass times |gravity| (N)
  double metres_per_newton = 0;          ///< drawn length per newton of force
  /// Drawn length of the reference force (body_weight, or the largest force when the model
  /// weighs nothing); the arrows' thickness is in proportion to it.
  double unit_length = 0;

  bool empty() const { return names.empty(); }
};

/// Column groups ("<force>.<group>") whose body the caller knows (from the system's contact
/// forces); the others are found by name in the spec.
using GroupBodies = std::map<std::string, int>;

/// The arrows of the table `contacts` (columns "<force>.<group>.force.X|Y|Z" and
/// ".torque.X|Y|Z": the net force on the group's body and its torque about the body's origin, in
/// ground) along `motion`, the table interpolated linearly at the motion's times (no force
/// outside its time range). A group's body is `known`'s, else the body, frame or contact
/// geometry's frame of that name, or a SmoothSphereHalfSpaceForce's "Sphere"/"HalfSpace" socket;
/// groups on ground (the floor's reaction) are left out, and groups that name nothing are noted
/// in `notes`.
///
/// The table gives a force and a moment, so only the force's line of action is known: the
/// arrow starts where that line crosses `floor` (the centre of pressure, as a force plate
/// reports it) when that point lies on the body (within 1.1 times the farthest point of its
/// drawn parts in `scene` from its origin), else at the point of the line nearest the body's
/// origin. Scale: the model's weight is drawn half as long as the model's largest extent in
/// the first frame (the largest force, when the model weighs nothing).
ContactArrows ContactArrowsFromTable(const model::ModelSpec& spec, const io::Storage& contacts,
                                     const BodyMotion& motion, const VisualScene& scene,
                                     const FloorPlane& floor, const GroupBodies& known,
                                     Diagnostics* notes);

/// The arrows' green (RGB in [0, 1]), in the viewer and in `sinew render`.
inline const Vec3 kContactArrowColor = Vec3(0.15, 0.75, 0.25);

/// How one arrow is drawn at one frame: from `start` along the force (+y turned by
/// `rotation`), `length` = |F| metres_per_newton long: a shaft (a cylinder of radius
/// shaft_radius, shaft_length long) then a head (a cone of base radius head_radius,
/// head_length long). The head is 0.2 unit_length long and 0.07 unit_length wide, the shaft
/// 0.025 unit_length wide; an arrow shorter than its head is all head, narrowed in proportion.
/// Without force, length is 0 and nothing is drawn.
struct ArrowShape {
  Vec3 start = Vec3::Zero();
  Quat rotation = Quat::Identity();
  double length = 0;
  double shaft_length = 0, shaft_radius = 0;
  double head_length = 0, head_radius = 0;
};

/// The shape of arrow `i` of `arrows` at `frame`.
ArrowShape ArrowShapeAt(const ContactArrows& arrows, size_t frame, size_t i);

/// A cylinder of radius 1 along y from y = 0 to y = 1: the arrows' shaft, scaled.
std::shared_ptr<const io::TriangleMesh> ArrowShaftMesh();

/// The arrows of `frame` as parts in ground (each part's X_BG is its pose in ground): per
/// arrow with a force, its shaft (ArrowShaftMesh) and its head (UnitCone), in
/// kContactArrowColor.
std::vector<VisualPart> ContactArrowParts(const ContactArrows& arrows, size_t frame);

/// The arrows `sinew render` draws at one time of a motion: ContactArrowsFromTable on the two
/// frames {the first row of `table`, `shown`} (no known groups: every group found by name), so
/// that the scale is the viewer's (from the motion's first frame), as parts at `shown`
/// (ContactArrowParts). `shown` is one frame of `table` (MotionAtTime). For a model that weighs
/// nothing the reference force is the larger of the two frames', not the whole motion's.
std::vector<VisualPart> ContactArrowPartsAt(const model::ModelSpec& spec,
                                            const io::Storage& contacts, const io::Storage& table,
                                            const BodyMotion& shown, const VisualScene& scene,
                                            const FloorPlane& floor, Diagnostics* notes);

}  // namespace sinew::viz
