// Collision detection between a collision model's shapes (contact::CollisionModel: the seed's
// cylinders, OpenSim's ContactSphere, ContactHalfSpace, ContactCylinder, ContactEllipsoid and
// ContactMesh (its triangles, on ground or on a moving body), environment boxes and planes)
// through Bullet's collision library. Broad phase, cheapest first, each test conservative (it
// drops only pairs that cannot touch): a ball about each shape, the gap between two cylinders'
// axes, Bullet's bounding boxes, and one candidate separating axis (the shapes' support points
// along it). Narrow phase: GJK/EPA between convex shapes (Bullet's box-box detector between two
// boxes: a face's points) and between a convex shape and each triangle of a mesh near it (found
// through the mesh's btBvhTriangleMeshShape, in the mesh's current pose), and the shapes'
// support vertices against half-spaces (what Bullet's convex-plane algorithm does; several
// points per pair for boxes, cylinders, hulls and meshes).
// Of two meshes, one collides as its convex hull against the other's triangles (MeshPairHull:
// exact when it is closed and convex).
// Stateless per query (no contact caching), so one detector can be shared by threads and by the
// stages of a Runge-Kutta step.
#pragma once

#include <sinew/contact/collision_material.h>
#include <sinew/contact/collision_model.h>
#include <sinew/math/transform.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace sinew::contact {

/// The effective radius of curvature given to flat shapes (box faces, edges and corners), as
/// Chrono's default effective curvature radius: m.
inline constexpr double kFlatShapeRadius = 0.1;

/// One contact between two shapes: they overlap by `depth` (m; negative: a gap within the
/// detector's envelope) along `n_G` (unit, in G, from shape 1's body towards shape 2's body),
/// centred at `p_G` (midway through the overlap or gap); `radius` is the effective radius
/// of curvature of the pair (radii combined as r1 r2 / (r1 + r2); a half-space's and a box
/// face's are infinite, a box's edges and corners kFlatShapeRadius); `material` the pair's
/// combined material.
struct CollisionContact {
  int body1 = 0;
  int body2 = 0;
  Vec3 p_G = Vec3::Zero();
  Vec3 n_G = Vec3::UnitY();
  double depth = 0.0;
  double radius = 0.0;
  PairMaterial material;
};

/// Finds the contacts of a collision model's shapes with each other (pairs of bodies the model
/// allows, CollisionModel::CanCollide; never two shapes of one body, never two half-spaces)
/// and with a ground plane y = `ground_height` (the solid below it), when given. Bodies are the
/// model's body indices.
class CollisionDetector {
 public:
  /// Pairs of shapes on two moving bodies that already overlap at the rest poses `X_GB_rest`
  /// (one per body, ground first; the model's default pose), typically cylinders at the joints
  /// where segments meet, are left out: they could only push the joints apart. Empty
  /// `X_GB_rest`: every allowed pair is kept.
  /// `envelope` (m, >= 0): contacts are reported while the shapes are less than this apart,
  /// with a negative depth (the gap) until they overlap. Exact for every pair: GJK and EPA work
  /// on each convex shape grown by half the envelope (Bullet's margin), whose overlap is the
  /// true one plus the envelope; against a half-space the shape's own points are measured.
  /// Throws sinew::Error for a negative envelope, a mesh without vertices or triangles, or a
  /// triangle naming a vertex the mesh does not have.
  CollisionDetector(const CollisionModel& model, std::optional<double> ground_height,
                    const std::vector<Transform>& X_GB_rest = {}, double envelope = 0.0);
  ~CollisionDetector();
  CollisionDetector(const CollisionDetector&) = delete;
  CollisionDetector& operator=(const CollisionDetector&) = delete;

  /// Calls `visit` for every contact at the body poses `X_GB` (one per body, ground first):
  /// one point per pair of convex shapes (Bullet's deepest point), except two boxes: the points
  /// of a face in contact, up to four (Bullet's box-box detector), and a shape on a box's face
  /// (Bullet's point on the face): its points there, as against a half-space on that face but
  /// over the face only; against a half-space, a
  /// sphere's or an ellipsoid's deepest point, each of a cylinder's two cap rims' deepest
  /// points and each box corner, hull or mesh vertex that lies inside it; against a triangle
  /// mesh (kTriangleMesh, fixed or moving), one point per local extreme of the overlap over its
  /// surface (a sphere in a V groove touches each side once; a contact found by several
  /// triangles at a shared edge or vertex counts once), and a box's or a hull's vertices or a
  /// cylinder's rims over each triangle it touches, through the triangle's plane. Two flat shapes
  /// (mesh or hull vertices on a half-space, a hull on a mesh, two boxes) get the radius
  /// kFlatShapeRadius.
  void FindContacts(const std::vector<Transform>& X_GB,
                    const std::function<void(const CollisionContact&)>& visit) const;
  /// The number of shape pairs tested.
  int num_pairs() const;
  /// The number of shape pairs left out because they overlap at the rest poses.
  int num_excluded_at_rest() const;
  /// The body pairs (body1 < body2) of the tested shape pairs, sorted, each once.
  std::vector<std::pair<int, int>> BodyPairs() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sinew::contact
