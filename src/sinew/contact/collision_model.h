// Collision shapes of a parsed model (the seed's EnableCollision): a cylinder along every
// segment from a body's frame to each joint frame on it, the seed's two collision families
// (alternating with depth in the joint tree), and the pairs of bodies that never collide: a
// body and its parent (every pair a joint joins). Every other pair may collide.
#pragma once

#include <sinew/contact/collision_material.h>
#include <sinew/contact/contact_shape.h>
#include <sinew/math/transform.h>
#include <sinew/math/types.h>
#include <sinew/model/model_spec.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sinew::contact {

/// How contact is to be treated in a system (the seed's two methods): kNsc non-smooth
/// (complementarity), kSmc smooth (penalty).
enum class ContactMethod {
  kNsc,
  kSmc,
  // The seed's spellings, so that programs written against its API compile unchanged.
  NSC = kNsc,
  SMC = kSmc,
};

/// A capsule-like cylinder fixed to a body, from `p_B_start` to `p_B_end` (in B, metres).
struct CollisionCylinder {
  int body = model::kGroundIndex;
  Vec3 p_B_start = Vec3::Zero();
  Vec3 p_B_end = Vec3::Zero();
  double radius = 0.0;  ///< m
  int material = 0;     ///< index into CollisionModel::materials
};

/// The kinds of collision geometry besides the seed's cylinders.
enum class CollisionShapeKind {
  kSphere,      ///< OpenSim's ContactSphere: centred at S's origin, `radius`.
  kBox,         ///< a box centred at S's origin, `half_extents` along S's axes.
  kHalfSpace,   ///< OpenSim's ContactHalfSpace convention: the solid x > 0 of S, outward normal -x.
  kCylinder,    ///< OpenSim's ContactCylinder: axis S's z, `radius`, from -half_length to +.
  kEllipsoid,   ///< OpenSim's ContactEllipsoid: semi-axes `radii` along S's x, y, z.
  kConvexMesh,  ///< the convex hull of `vertices` (in S): a concave mesh is filled in.
  /// OpenSim's ContactMesh, on ground or on a moving body: its triangles `mesh` (in S) exactly,
  /// concave or not (Bullet's btBvhTriangleMeshShape); each triangle is a two-sided sheet.
  /// Against another triangle mesh one of the two collides as its convex hull (MeshPairHull).
  kTriangleMesh,
};

/// The half length of an OpenSim ContactCylinder as a collision shape, in radii: Simbody's
/// cylinder is infinite along its z axis; OpenSim draws it 4 radii long, and so it collides.
inline constexpr double kContactCylinderHalfLength = 2.0;

/// A collision shape fixed to a body (OpenSim's contact geometry) or to ground (the
/// environment: a ground plane, a box, ...).
struct CollisionGeometry {
  std::string name;
  CollisionShapeKind kind = CollisionShapeKind::kSphere;
  int body = model::kGroundIndex;
  Transform X_BS;                    ///< the shape's frame S in its body
  double radius = 0.0;               ///< kSphere, kCylinder: m
  Vec3 half_extents = Vec3::Zero();  ///< kBox: m
  int material = 0;                  ///< index into CollisionModel::materials
  double half_length = 0.0;          ///< kCylinder: m
  Vec3 radii = Vec3::Zero();         ///< kEllipsoid: m
  std::shared_ptr<const std::vector<Vec3>> vertices = nullptr;  ///< kConvexMesh: in S, m
  std::shared_ptr<const ShapeMesh> mesh = nullptr;              ///< kTriangleMesh: in S, m
  /// kTriangleMesh: its body never moves relative to ground (welded to it). A shape on the
  /// ground body itself never moves whatever this says.
  bool fixed_to_ground = false;
};

/// True when the triangles of `mesh` close a convex solid: every edge is shared by exactly two
/// triangles and every vertex lies on one side of each triangle's plane (within 1e-9 of the
/// mesh's size). Then its convex hull is the mesh itself.
bool IsClosedConvex(const ShapeMesh& mesh);

/// One triangle mesh (kTriangleMesh) of a pair of meshes that may touch.
struct MeshPairSide {
  bool moves = false;          ///< neither on ground nor fixed_to_ground
  bool closed_convex = false;  ///< IsClosedConvex
};

/// Which mesh of a pair of triangle meshes collides as its convex hull against the other's
/// triangles (the detector never tests triangles against triangles): -1 when neither moves (no
/// contact); else a moving closed convex mesh (its hull is exact), `b` first; else the moving
/// mesh, `b` when both move (a concave mesh is then filled in: the parser's Report says so).
/// Returns 0 for `a`, 1 for `b`.
int MeshPairHull(const MeshPairSide& a, const MeshPairSide& b);

/// Shapes, families and excluded pairs of a model.
struct CollisionModel {
  std::vector<CollisionCylinder> shapes;    ///< the seed's cylinders
  std::vector<CollisionGeometry> geometry;  ///< contact geometry and environment shapes
  /// Materials the shapes refer to; entry 0 is the default material.
  std::vector<CollisionMaterial> materials = std::vector<CollisionMaterial>(1);
  /// The seed's family of each body (ground: 0). Kept for the seed's API and for inspection:
  /// filtering is per pair (`jointed`), see docs/contact.md.
  std::vector<int> family;
  /// Pairs of bodies a joint joins (parent, child), ground included: these never collide.
  std::vector<std::pair<int, int>> jointed;

  /// True when shapes of bodies `a` and `b` may touch: different bodies that no joint joins.
  /// Ground's shapes (the environment, contact geometry fixed to ground) touch every body, its
  /// children included: the exclusion is for segments that overlap at their joint.
  bool CanCollide(int a, int b) const;
};

/// The name AddGroundPlane gives the plane it adds.
inline constexpr const char* kGroundPlaneName = "ground_plane";

/// Adds the ground plane y = `height` (the solid below it) to `model`'s environment.
void AddGroundPlane(CollisionModel& model, double height, int material = 0);

/// Builds the collision model of `spec`: bodies at odd tree depth (`depth` per body, ground 0)
/// get `family_1`, at even depth `family_2` (as the seed); every joint's parent and child
/// are an excluded pair. The cylinder radius is 10% of the median segment
/// length of the model's joints (at least 1 mm). Segments shorter than 1 mm get no shape, and
/// two joints at one point of a body one shape.
CollisionModel BuildCollisionModel(const model::ModelSpec& spec, const std::vector<int>& depth,
                                   int family_1, int family_2);

}  // namespace sinew::contact
