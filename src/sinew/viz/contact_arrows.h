// Contact forces as arrows for the viewer: per frame, each body's net contact force read from a
// contacts table (`sinew simulate`'s contacts.sto) and the point its arrow starts at.
#pragma once

#include <sinew/common/error.h>
#include <sinew/io/storage.h>
#include <sinew/model/model_spec.h>
#include <sinew/viz/body_motion.h>
#include <sinew/viz/floor_plane.h>
#include <sinew/viz/visual_scene.h>

#include <map>
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

}  // namespace sinew::viz
