#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btTriangleCallback.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>
#include <LinearMath/btAabbUtil2.h>
#include <sinew/common/error.h>
#include <sinew/contact/collision_detection.h>
#include <sinew/contact/internal/bullet_ellipsoid.h>
#include <sinew/contact/internal/bullet_penetration.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace sinew::contact {
namespace {

btVector3 ToBt(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
Vec3 FromBt(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
btTransform ToBt(const Transform& X) {
  btMatrix3x3 R(X.R(0, 0), X.R(0, 1), X.R(0, 2), X.R(1, 0), X.R(1, 1), X.R(1, 2), X.R(2, 0),
                X.R(2, 1), X.R(2, 2));
  return btTransform(R, ToBt(X.p));
}

// A rotation taking the y axis onto the unit vector `u`.
Mat3 RotationYTo(const Vec3& u) {
  return Eigen::Quaterniond::FromTwoVectors(Vec3::UnitY(), u).toRotationMatrix();
}

enum class Kind { kCylinder, kSphere, kBox, kHalfSpace, kEllipsoid, kHull, kTriangleMesh };

// A triangle mesh for Bullet: the arrays its btTriangleIndexVertexArray points into, and the
// bounding-volume hierarchy over its triangles (btBvhTriangleMeshShape, built once).
struct BulletTriangleMesh {
  std::vector<int> indices;
  std::vector<btScalar> coordinates;
  std::unique_ptr<btTriangleIndexVertexArray> arrays;
  std::unique_ptr<btBvhTriangleMeshShape> shape;
};

struct Shape {
  int body = 0;
  Transform X_BS;  // for a cylinder, Bullet's: its axis along S's y
  Kind kind = Kind::kSphere;
  double radius = 0.0;  // of curvature; 0 for a half-space (infinite)
  // The distance from S's origin of the shape's farthest point (not inflated): the shape lies
  // in the ball of this radius about S's origin (unused for a half-space).
  double reach = 0.0;
  int material = 0;
  // Bullet's shape, inflated by half the envelope (its margin) for GJK; null for a half-space.
  std::unique_ptr<btConvexShape> bt;
  std::vector<Vec3> hull;                    // kHull, kTriangleMesh: its distinct points, in S
  std::unique_ptr<BulletTriangleMesh> mesh;  // kTriangleMesh (bt is its convex hull)
  MeshPairSide mesh_side;                    // kTriangleMesh: for MeshPairHull
  std::shared_ptr<const ShapeMesh> source;   // kTriangleMesh: the mesh it was built from
};

// Calls visit(p_S) for each point of the convex `shape` (in its frame S, not inflated) that can
// lie deepest in a half-space whose inward direction (into its solid) is the unit `d_S`; `visit`
// returns the point's depth in the half-space, and points that would lie no deeper than
// `shallowest` may be left out.
template <class Visit>
void ForEachCandidate(const Shape& shape, const Vec3& d_S, double shallowest, Visit&& visit) {
  switch (shape.kind) {
    case Kind::kSphere:  // its point farthest along d_S
      visit(Vec3(shape.radius * d_S.normalized()));
      break;
    case Kind::kCylinder: {
      // The deepest point of each cap's rim first (the core's support along d_S with its axial
      // part set to either end: both on one generator), then, per cap, the rim's points a
      // quarter, a half and three quarters of a turn from it. A cap flat on the surface touches
      // all round its rim, and on its one deepest point alone it would tip; the four, evenly
      // spread, hold it as a box's four corners hold the box (each takes its own depth, so
      // tilting it shifts the load continuously onto the deepest). Those lie shallower than the
      // deepest by r s, 2 r s and r s, s the sine of the angle between the axis and d_S: a
      // lying cylinder's are left out.
      std::array<Vec3, 2> deepest;
      std::array<double, 2> depth;
      for (int k = 0; k < 2; ++k) {
        deepest[k] = FromBt(shape.bt->localGetSupportingVertexWithoutMargin(
            btVector3(d_S.x(), k == 0 ? 1.0 : -1.0, d_S.z())));
        depth[k] = visit(deepest[k]);
      }
      const double rise = shape.radius * std::hypot(d_S.x(), d_S.z());
      for (int k = 0; k < 2; ++k) {
        if (!(depth[k] - rise > shallowest)) continue;
        const Vec3& p = deepest[k];
        visit(Vec3(-p.z(), p.y(), p.x()));
        visit(Vec3(-p.x(), p.y(), -p.z()));
        visit(Vec3(p.z(), p.y(), -p.x()));
      }
      break;
    }
    case Kind::kBox: {  // its corners
      const Vec3 h =
          FromBt(static_cast<const btBoxShape&>(*shape.bt).getHalfExtentsWithoutMargin());
      for (int i = 0; i < 8; ++i)
        visit(Vec3(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z()));
      break;
    }
    case Kind::kEllipsoid:  // its (exact) support point
      visit(FromBt(shape.bt->localGetSupportingVertexWithoutMargin(ToBt(d_S))));
      break;
    case Kind::kHull:  // its points (each one inside the half-space is a contact)
    case Kind::kTriangleMesh:
      for (const Vec3& p : shape.hull) visit(p);
      break;
    case Kind::kHalfSpace:
      break;
  }
}

// Bullet keeps a shape's margin outside its core (`extents` without it): the core grown by
// `inflation` all round, exactly the Minkowski sum GJK and EPA then work on.
template <class BtShape>
std::unique_ptr<btConvexShape> Inflated(const Vec3& extents, double inflation) {
  auto shape = std::make_unique<BtShape>(ToBt(extents + Vec3::Constant(inflation)));
  shape->setMargin(inflation);
  return shape;
}

Shape MakeCylinder(const CollisionCylinder& c, double inflation) {
  const Vec3 axis = c.p_B_end - c.p_B_start;
  const double length = axis.norm();
  Shape s;
  s.body = c.body;
  s.kind = Kind::kCylinder;
  s.X_BS = Transform(RotationYTo(axis / length), 0.5 * (c.p_B_start + c.p_B_end));
  s.radius = c.radius;
  s.material = c.material;
  s.reach = std::hypot(c.radius, 0.5 * length);
  s.bt = Inflated<btCylinderShape>(Vec3(c.radius, 0.5 * length, c.radius), inflation);
  return s;
}

// The distinct points of a mesh (files often repeat a vertex per face).
std::vector<Vec3> DistinctPoints(const std::vector<Vec3>& points) {
  std::vector<Vec3> sorted = points;
  const auto less = [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(sorted.begin(), sorted.end(), less);
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  return sorted;
}

// The largest distance of `points` from the origin.
double FarthestPoint(const std::vector<Vec3>& points) {
  double reach = 0.0;
  for (const Vec3& p : points) reach = std::max(reach, p.norm());
  return reach;
}

// Bullet's convex hull of `points`, grown by `inflation` (its margin).
std::unique_ptr<btConvexShape> ConvexHull(const std::vector<Vec3>& points, double inflation) {
  auto hull = std::make_unique<btConvexHullShape>();
  for (const Vec3& p : points) hull->addPoint(ToBt(p), false);
  hull->recalcLocalAabb();
  hull->setMargin(inflation);
  return hull;
}

Shape MakeGeometry(const CollisionGeometry& g, double inflation) {
  Shape s;
  s.body = g.body;
  s.X_BS = g.X_BS;
  s.material = g.material;
  switch (g.kind) {
    case CollisionShapeKind::kSphere:
      s.kind = Kind::kSphere;
      s.radius = g.radius;
      s.reach = g.radius;
      // The radius is a sphere's margin: a point grown by it.
      s.bt = std::make_unique<btSphereShape>(g.radius + inflation);
      break;
    case CollisionShapeKind::kBox:
      s.kind = Kind::kBox;
      s.radius = kFlatShapeRadius;
      s.reach = g.half_extents.norm();
      s.bt = Inflated<btBoxShape>(g.half_extents, inflation);
      break;
    case CollisionShapeKind::kHalfSpace:
      s.kind = Kind::kHalfSpace;
      break;
    case CollisionShapeKind::kCylinder:
      // OpenSim's axis is S's z, Bullet's its y: turn y onto z (+90 degrees about x).
      s.kind = Kind::kCylinder;
      s.radius = g.radius;
      s.X_BS = g.X_BS * Transform(RotationYTo(Vec3::UnitZ()), Vec3::Zero());
      s.reach = std::hypot(g.radius, g.half_length);
      s.bt = Inflated<btCylinderShape>(Vec3(g.radius, g.half_length, g.radius), inflation);
      break;
    case CollisionShapeKind::kEllipsoid: {
      s.kind = Kind::kEllipsoid;
      s.radius = g.radii.minCoeff();  // for SMC's Hertz law: the sharpest principal radius
      s.reach = g.radii.maxCoeff();
      s.bt = std::make_unique<BulletEllipsoid>(ToBt(g.radii));
      s.bt->setMargin(inflation);
      break;
    }
    case CollisionShapeKind::kConvexMesh: {
      s.kind = Kind::kHull;
      s.radius = kFlatShapeRadius;
      if (g.vertices) s.hull = DistinctPoints(*g.vertices);
      if (s.hull.empty()) throw Error("contact: the mesh '" + g.name + "' has no vertices");
      s.reach = FarthestPoint(s.hull);
      s.bt = ConvexHull(s.hull, inflation);
      break;
    }
    case CollisionShapeKind::kTriangleMesh: {
      s.kind = Kind::kTriangleMesh;
      s.radius = 0.0;  // flat faces: the other shape's curvature decides
      if (!g.mesh || g.mesh->triangles.empty())
        throw Error("contact: the mesh '" + g.name + "' has no triangles");
      s.hull = DistinctPoints(g.mesh->vertices);
      s.reach = FarthestPoint(s.hull);
      auto mesh = std::make_unique<BulletTriangleMesh>();
      const int num_vertices = static_cast<int>(g.mesh->vertices.size());
      for (const std::array<int, 3>& t : g.mesh->triangles) {
        for (const int v : t) {
          if (v < 0 || v >= num_vertices)
            throw Error("contact: the mesh '" + g.name + "' has a triangle with no vertex " +
                        std::to_string(v));
          mesh->indices.push_back(v);
        }
      }
      for (const Vec3& v : g.mesh->vertices) {
        for (int k = 0; k < 3; ++k) mesh->coordinates.push_back(v[k]);
      }
      mesh->arrays = std::make_unique<btTriangleIndexVertexArray>(
          static_cast<int>(g.mesh->triangles.size()), mesh->indices.data(), 3 * sizeof(int),
          num_vertices, mesh->coordinates.data(), 3 * sizeof(btScalar));
      mesh->shape = std::make_unique<btBvhTriangleMeshShape>(mesh->arrays.get(),
                                                             /*useQuantizedAabbCompression=*/true);
      s.mesh = std::move(mesh);
      // Its hull, for a pair with another mesh (MeshPairHull).
      s.bt = ConvexHull(s.hull, inflation);
      s.mesh_side.moves = g.body != model::kGroundIndex && !g.fixed_to_ground;
      s.source = g.mesh;  // IsClosedConvex is left to the detector: it matters for mesh pairs
      break;
    }
  }
  return s;
}

// The point of the triangle (a, b, c) closest to p (by the region of p: a vertex, an edge or
// the face).
Vec3 ClosestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// Two contact points closer than this (m) are one point of the mesh (Bullet's EPA is accurate
// to about 1e-7 m on these shapes).
constexpr double kMeshPointTolerance = 1e-6;

// Calls `visit` with the three vertices of each triangle Bullet reports.
template <class Visit>
struct TriangleVisitor : btTriangleCallback {
  explicit TriangleVisitor(Visit& v) : visit(v) {}
  void processTriangle(btVector3* triangle, int, int) override { visit(triangle); }
  Visit& visit;
};

// A contact of a convex shape with one triangle of a mesh, before the filter of
// CollideWithMesh: the contact, and where it touches the triangle (unmoved by the envelope).
struct TriangleContact {
  CollisionContact contact;
  Vec3 p_mesh_G;
  std::array<Vec3, 3> triangle_G;
  bool on_plane_points = false;  // as deep as the shape's plane points over it (then those)
};

// A shape's point through a mesh triangle's plane (CollideWithMesh): which of the points a
// half-space there would take (ForEachCandidate's order: a box's corner, a cylinder's rim) and
// its contact.
struct PlanePointContact {
  int point = 0;
  CollisionContact contact;
};

// The vector from the segment [p1, q1] to the segment [p2, q2] between their closest points
// (the clamped solution of the two-parameter least-squares problem).
Vec3 SegmentGap(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double c = d1.dot(r), b = d1.dot(d2), denom = a * e - b * b;
  double s = denom > 1e-12 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return p2 + t * d2 - (p1 + s * d1);
}

// The gap between two cylinders' axes (from a's to b's, between their closest points). A
// cylinder lies inside the capsule of its axis and radius: two cylinders whose axes are farther
// apart than their radii and the envelope cannot touch (a cheap test before GJK).
Vec3 CylinderAxesGap(const Shape& a, const Transform& X_GA, const Shape& b, const Transform& X_GB) {
  const auto& ca = static_cast<const btCylinderShape&>(*a.bt);
  const auto& cb = static_cast<const btCylinderShape&>(*b.bt);
  const Vec3 ha = X_GA.R.col(1) * ca.getHalfExtentsWithoutMargin().y();
  const Vec3 hb = X_GB.R.col(1) * cb.getHalfExtentsWithoutMargin().y();
  return SegmentGap(X_GA.p - ha, X_GA.p + ha, X_GB.p - hb, X_GB.p + hb);
}

// Whether the planes normal to `d` (in G, from A towards B) separate the convex shapes A and B,
// each grown by its margin: A's farthest point along d short of B's nearest (their support
// points with the margin; a box's is its corner, outside its rounded margin). A certificate:
// then they cannot touch, and GJK would find them apart (a cheap test before it, exact however
// near the pair is).
bool SeparatedAlong(const Vec3& d, const btConvexShape& A, const btTransform& X_GA,
                    const btConvexShape& B, const btTransform& X_GB) {
  const btVector3 n = ToBt(d);
  const btVector3 a = X_GA(A.localGetSupportingVertex(n * X_GA.getBasis()));
  const btVector3 b = X_GB(B.localGetSupportingVertex(-n * X_GB.getBasis()));
  return n.dot(a) < n.dot(b);
}

// What Bullet's box-box detector reports: up to four points on B, each with B's normal (towards
// A) and Bullet's distance (negative: an overlap).
struct BoxBoxPoints final : btDiscreteCollisionDetectorInterface::Result {
  std::array<BulletOverlap, 4> found;
  int count = 0;
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3& normal_on_B, const btVector3& point_on_B,
                       btScalar distance) override {
    if (count < static_cast<int>(found.size()))
      found[count++] = {normal_on_B, point_on_B, distance};
  }
};

// How far EPA's depth may lie from the exact one on curved shapes (m): Bullet's EPA stops at its
// vertex limit there (CollisionDetectionTest measures about 1e-6).
constexpr double kEpaAccuracy = 1e-5;

// Added to the bounding tests by reach (m), so that rounding in them never drops a contact.
constexpr double kReachSlack = 1e-9;

struct Pair {
  int i = 0;  // a half-space comes first
  int j = 0;
  double radius = 0.0;
  PairMaterial material;
};

}  // namespace

struct CollisionDetector::Impl {
  double envelope = 0.0;
  std::vector<Shape> shapes;
  std::vector<Pair> pairs;
  int excluded_at_rest = 0;

  // The shapes' poses X_GS (one per shape) at the body poses X_GB: computed once per query, as
  // a shape is in several pairs.
  void CalcShapePoses(const std::vector<Transform>& X_GB, std::vector<Transform>& X_GS) const {
    X_GS.resize(shapes.size());
    for (size_t k = 0; k < shapes.size(); ++k) X_GS[k] = X_GB[shapes[k].body] * shapes[k].X_BS;
  }
  // Each point of the convex shape p.j inside the half-space p.i. X_GS: the shapes' poses.
  template <class Visit>
  void CollideWithHalfSpace(const Pair& p, const std::vector<Transform>& X_GS, Visit&& visit) const;
  // Bullet's deepest contact of the convex shapes p.i and p.j, if they overlap.
  template <class Visit>
  void CollideConvex(const Pair& p, const std::vector<Transform>& X_GS, Visit&& visit) const;
  // The contacts of a convex shape over a box's face and clear of its sides (no GJK needed).
  template <class Visit>
  bool CollideOverBoxFace(const Pair& p, const Shape& box, const Transform& X_GX, const Shape& s,
                          const Transform& X_GS, double sign, Visit&& visit) const;
  // The contacts of a convex shape on a box's face, given Bullet's one (CollideConvex).
  template <class Visit>
  bool CollideOnBoxFace(const Shape& box, const Transform& X_GX, const Shape& s,
                        const Transform& X_GS, const CollisionContact& bullet, double sign,
                        Visit&& visit) const;
  // The contacts of two boxes (after CollideConvex's bounding tests): a face's points.
  template <class Visit>
  void CollideBoxes(const Pair& p, const btTransform& X_GA, const btTransform& X_GB,
                    Visit&& visit) const;
  // The contacts of the convex shape p.j with the triangles of the mesh p.i.
  template <class Visit>
  void CollideWithMesh(const Pair& p, const std::vector<Transform>& X_GS, Visit&& visit) const;
  template <class Visit>
  void Collide(const Pair& p, const std::vector<Transform>& X_GS, Visit&& visit) const {
    if (shapes[p.i].kind == Kind::kHalfSpace)
      CollideWithHalfSpace(p, X_GS, visit);
    else if (shapes[p.i].kind == Kind::kTriangleMesh)
      CollideWithMesh(p, X_GS, visit);
    else
      CollideConvex(p, X_GS, visit);
  }
};

CollisionDetector::CollisionDetector(const CollisionModel& model,
                                     std::optional<double> ground_height,
                                     const std::vector<Transform>& X_GB_rest, double envelope)
    : impl_(std::make_unique<Impl>()) {
  if (!(envelope >= 0.0) || !std::isfinite(envelope))
    throw Error("contact: the collision envelope must be a finite length >= 0");
  impl_->envelope = envelope;
  const double inflation = 0.5 * envelope;
  std::vector<Shape>& shapes = impl_->shapes;
  for (const CollisionCylinder& c : model.shapes) {
    if ((c.p_B_end - c.p_B_start).norm() > 0.0 && c.radius > 0.0)
      shapes.push_back(MakeCylinder(c, inflation));
  }
  for (const CollisionGeometry& g : model.geometry) shapes.push_back(MakeGeometry(g, inflation));
  if (ground_height) {
    CollisionModel environment;
    AddGroundPlane(environment, *ground_height);
    shapes.push_back(MakeGeometry(environment.geometry.front(), inflation));
  }
  // Whether a mesh is closed and convex (time linear in triangles times vertices) matters only
  // against another mesh (MeshPairHull) and, for a moving mesh, against a box (below).
  const auto is_mesh = [](const Shape& s) { return s.kind == Kind::kTriangleMesh; };
  const bool two_meshes = std::count_if(shapes.begin(), shapes.end(), is_mesh) >= 2;
  const bool a_box = std::any_of(shapes.begin(), shapes.end(),
                                 [](const Shape& s) { return s.kind == Kind::kBox; });
  for (Shape& s : shapes) {
    if (is_mesh(s) && (two_meshes || (a_box && s.mesh_side.moves)))
      s.mesh_side.closed_convex = IsClosedConvex(*s.source);
  }
  // A moving closed convex mesh is its own hull: against a box it collides as that convex
  // shape (CollideConvex), so that on the box's face it touches at its vertices over the face
  // as a box or a hull does; its triangles against the box would give one point per dented
  // triangle region, on which it rocks.
  const auto hull_on_box = [](const Shape& m, const Shape& other) {
    return m.kind == Kind::kTriangleMesh && m.mesh_side.moves && m.mesh_side.closed_convex &&
           other.kind == Kind::kBox;
  };
  std::vector<Transform> X_GS_rest;
  if (!X_GB_rest.empty()) impl_->CalcShapePoses(X_GB_rest, X_GS_rest);
  const int n = static_cast<int>(shapes.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const Shape& a = shapes[i];
      const Shape& b = shapes[j];
      if (a.kind == Kind::kHalfSpace && b.kind == Kind::kHalfSpace) continue;
      if (!model.CanCollide(a.body, b.body)) continue;
      // First a half-space (against whose solid the other's points are tested), else a
      // triangle mesh (against whose triangles the other, convex, is tested). Of two meshes,
      // MeshPairHull's collides as its hull against the other's triangles.
      const auto rank = [](Kind k) {
        return k == Kind::kHalfSpace ? 0 : k == Kind::kTriangleMesh ? 1 : 2;
      };
      bool swap = rank(b.kind) < rank(a.kind);
      if (a.kind == Kind::kTriangleMesh && b.kind == Kind::kTriangleMesh) {
        const int hull = MeshPairHull(a.mesh_side, b.mesh_side);
        if (hull < 0) continue;  // neither moves
        swap = hull == 0;
      }
      if (hull_on_box(a, b)) swap = true;  // the box first: CollideConvex
      if (hull_on_box(b, a)) swap = false;
      Pair p;
      p.i = swap ? j : i;
      p.j = swap ? i : j;
      p.radius = a.radius > 0.0 && b.radius > 0.0 ? a.radius * b.radius / (a.radius + b.radius)
                                                  : std::max(a.radius, b.radius);
      // Two flat shapes (a mesh's vertices on a half-space, a hull on a mesh): as a box's.
      if (p.radius == 0.0) p.radius = kFlatShapeRadius;
      const auto material_of = [&](int m) {
        return m >= 0 && m < static_cast<int>(model.materials.size()) ? model.materials[m]
                                                                      : CollisionMaterial{};
      };
      p.material = CombineMaterials(material_of(a.material), material_of(b.material));
      if (!X_GB_rest.empty() && a.body != model::kGroundIndex && b.body != model::kGroundIndex) {
        bool overlaps = false;
        impl_->Collide(p, X_GS_rest, [&](const CollisionContact&) { overlaps = true; });
        if (overlaps) {
          ++impl_->excluded_at_rest;
          continue;
        }
      }
      impl_->pairs.push_back(p);
    }
  }
}

CollisionDetector::~CollisionDetector() = default;

int CollisionDetector::num_pairs() const { return static_cast<int>(impl_->pairs.size()); }

int CollisionDetector::num_excluded_at_rest() const { return impl_->excluded_at_rest; }

std::vector<std::pair<int, int>> CollisionDetector::BodyPairs() const {
  std::vector<std::pair<int, int>> pairs;
  for (const Pair& p : impl_->pairs) {
    const int a = impl_->shapes[p.i].body, b = impl_->shapes[p.j].body;
    pairs.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

template <class Visit>
void CollisionDetector::Impl::CollideWithHalfSpace(const Pair& p,
                                                   const std::vector<Transform>& X_GS_all,
                                                   Visit&& visit) const {
  const Shape& h = shapes[p.i];
  const Shape& s = shapes[p.j];
  const Transform& X_GH = X_GS_all[p.i];
  const Transform& X_GS = X_GS_all[p.j];
  const Vec3 inward_G = X_GH.R.col(0);  // into the solid x > 0
  // No point of the shape lies deeper than its origin plus its reach: when that is no deeper
  // than -envelope, no candidate below would be reported.
  if (!((X_GS.p - X_GH.p).dot(inward_G) + s.reach + kReachSlack > -envelope)) return;
  CollisionContact c;
  c.body1 = h.body;
  c.body2 = s.body;
  c.n_G = -inward_G;
  c.radius = p.radius;
  c.material = p.material;
  ForEachCandidate(s, X_GS.R.transpose() * inward_G, -envelope, [&](const Vec3& p_S) {
    const Vec3 p_G = X_GS * p_S;
    c.depth = (p_G - X_GH.p).dot(inward_G);
    if (!(c.depth > -envelope)) return c.depth;
    c.p_G = p_G + 0.5 * c.depth * c.n_G;
    visit(c);
    return c.depth;
  });
}

namespace {
// GJK, and EPA for the penetration (BulletPenetration), between convex shapes A and B, each
// inflated by half the envelope (the overlap of the inflated shapes is the true one plus the
// envelope, and its midway point is the true one's). On overlap sets c's normal (Bullet's, from
// B towards A), depth and midway point, and `p_on_B_G` (if given) to Bullet's point, on
// inflated B.
bool Penetrate(const btConvexShape* A, const btTransform& X_GA, const btConvexShape* B,
               const btTransform& X_GB, double envelope, CollisionContact& c,
               Vec3* p_on_B_G = nullptr) {
  BulletOverlap output;
  if (!BulletPenetration(A, X_GA, B, X_GB, output)) return false;
  c.n_G = FromBt(output.normal_on_B).normalized();
  const double inflated_depth = -output.distance;
  // EPA may fail on deep or degenerate overlaps: no usable normal, no contact.
  if (!c.n_G.allFinite() || !std::isfinite(inflated_depth)) return false;
  c.depth = inflated_depth - envelope;
  c.p_G = FromBt(output.point_on_B) - 0.5 * inflated_depth * c.n_G;
  if (p_on_B_G) *p_on_B_G = FromBt(output.point_on_B);
  return true;
}
}  // namespace

namespace {
// Two cylinders lying along each other touch along a line, and on Bullet's one point of it they
// rock. Where their lateral surfaces meet, each cylinder's deepest generator towards the other
// (its deepest rim points, one per cap: a straight line of its surface) ends at its caps; an end
// within the other cylinder's length and radius (or the envelope) is a contact, at its radial
// depth there (exact: the distance from the other's lateral surface, along its radius, which is
// then the normal). For two parallel cylinders these are the ends of their line of contact; for
// crossing ones the ends lie outside each other and there are none. `bullet`: the pair's contact
// (normal from b's body towards a's, as CollideConvex sets it).
struct CylinderLinePoints {
  std::array<CollisionContact, 4> found;
  int count = 0;
  double deepest = -std::numeric_limits<double>::infinity();
};
CylinderLinePoints PointsAlongCylinders(const Shape& a, const Transform& X_GA, const Shape& b,
                                        const Transform& X_GB, const Vec3& axes_gap_G,
                                        const CollisionContact& bullet, double envelope) {
  CylinderLinePoints out;
  // Only where their lateral surfaces meet: the gap between their axes (from a's to b's,
  // CylinderAxesGap) square to both within 1e-3 rad (not where a cap meets: end to end, or an
  // end on a side). Its direction is the deepest lines' (exact for parallel axes; within 1e-3
  // rad of it the ends' depths are off by at most r 1e-6 / 2), not Bullet's normal (to EPA's
  // 1e-5).
  const double gap = axes_gap_G.norm();
  if (!(gap > 0.0)) return out;
  const Vec3 toward_b_G = axes_gap_G / gap;
  constexpr double kSquare = 1e-3;  // the cosine allowed
  if (!(std::abs(toward_b_G.dot(X_GA.R.col(1))) < kSquare) ||
      !(std::abs(toward_b_G.dot(X_GB.R.col(1))) < kSquare))
    return out;
  const auto half_length = [](const Shape& s) {
    return static_cast<const btCylinderShape&>(*s.bt).getHalfExtentsWithoutMargin().y();
  };
  // The ends of `from`'s deepest line towards `into` (along d_G) inside `into`; `toward_a` is
  // the unit normal's sign, so that it points from b's body towards a's. An end exactly at
  // the other's end is taken once: from a (`ends_included`), not from b.
  const auto add_ends = [&](const Shape& from, const Transform& X_GF, const Shape& into,
                            const Transform& X_GI, const Vec3& d_G, double toward_a,
                            bool ends_included) {
    const Vec3 axis_G = X_GI.R.col(1);
    const double h = half_length(into);
    int candidate = 0;
    ForEachCandidate(from, X_GF.R.transpose() * d_G, 0.0, [&](const Vec3& p_S) {
      constexpr double kOutside = -std::numeric_limits<double>::infinity();
      if (candidate++ >= 2) return kOutside;  // the line's ends only
      const Vec3 p_G = X_GF * p_S;
      const Vec3 r_G = p_G - X_GI.p;
      const double z = r_G.dot(axis_G);
      if (ends_included ? !(std::abs(z) <= h) : !(std::abs(z) < h)) return kOutside;
      const Vec3 radial_G = r_G - z * axis_G;
      const double rho = radial_G.norm();
      const double depth = into.radius - rho;
      if (!(depth > -envelope) || !(rho > 0.0)) return depth;
      out.deepest = std::max(out.deepest, depth);
      if (out.count == static_cast<int>(out.found.size())) return depth;
      CollisionContact& c = out.found[out.count++];
      c = bullet;
      const Vec3 outward_G = radial_G / rho;  // out of `into` at the point
      c.n_G = toward_a * outward_G;
      c.depth = depth;
      c.p_G = p_G + 0.5 * depth * outward_G;
      return depth;
    });
  };
  add_ends(a, X_GA, b, X_GB, toward_b_G, 1.0, true);
  add_ends(b, X_GB, a, X_GA, -toward_b_G, -1.0, false);
  return out;
}

}  // namespace

template <class Visit>
void CollisionDetector::Impl::CollideConvex(const Pair& p, const std::vector<Transform>& X_GS,
                                            Visit&& visit) const {
  const Shape& a = shapes[p.i];
  const Shape& b = shapes[p.j];
  const Transform& X_GSa = X_GS[p.i];
  const Transform& X_GSb = X_GS[p.j];
  // Each shape, grown by half the envelope, lies in the ball of its reach plus that about its
  // origin: two disjoint balls, no contact (the cheapest test first, most pairs are far apart).
  const double reach = a.reach + b.reach + envelope + kReachSlack;
  if ((X_GSa.p - X_GSb.p).squaredNorm() > reach * reach) return;
  // A candidate separating axis: between the origins, or between two cylinders' axes.
  Vec3 axis = X_GSb.p - X_GSa.p;
  if (a.kind == Kind::kCylinder && b.kind == Kind::kCylinder) {
    axis = CylinderAxesGap(a, X_GSa, b, X_GSb);
    const double touch = a.radius + b.radius + envelope;
    if (axis.squaredNorm() > touch * touch) return;
  }
  const btTransform X_GA = ToBt(X_GSa);
  const btTransform X_GBs = ToBt(X_GSb);
  // Broad phase: the shapes' bounding boxes.
  btVector3 min_a, max_a, min_b, max_b;
  a.bt->getAabb(X_GA, min_a, max_a);
  b.bt->getAabb(X_GBs, min_b, max_b);
  if (!TestAabbAgainstAabb2(min_a, max_a, min_b, max_b)) return;
  if (axis.squaredNorm() > 0.0 && SeparatedAlong(axis, *a.bt, X_GA, *b.bt, X_GBs)) return;
  if (a.kind == Kind::kBox && b.kind == Kind::kBox) return CollideBoxes(p, X_GA, X_GBs, visit);
  if (a.kind == Kind::kBox && CollideOverBoxFace(p, a, X_GSa, b, X_GSb, -1.0, visit)) return;
  if (b.kind == Kind::kBox && CollideOverBoxFace(p, b, X_GSb, a, X_GSa, 1.0, visit)) return;
  // Narrow phase: GJK, and EPA for the penetration.
  CollisionContact c;
  if (!Penetrate(a.bt.get(), X_GA, b.bt.get(), X_GBs, envelope, c)) return;
  c.body1 = b.body;
  c.body2 = a.body;
  c.radius = p.radius;
  c.material = p.material;
  // (two boxes went to CollideBoxes above)
  if (a.kind == Kind::kBox && CollideOnBoxFace(a, X_GSa, b, X_GSb, c, -1.0, visit)) return;
  if (b.kind == Kind::kBox && CollideOnBoxFace(b, X_GSb, a, X_GSa, c, 1.0, visit)) return;
  if (a.kind == Kind::kCylinder && b.kind == Kind::kCylinder) {
    const CylinderLinePoints line = PointsAlongCylinders(a, X_GSa, b, X_GSb, axis, c, envelope);
    for (int k = 0; k < line.count; ++k) visit(line.found[k]);
    if (line.count > 0 && line.deepest >= c.depth - kEpaAccuracy) return;  // they hold the deepest
  }
  visit(c);
}

namespace {
// The points of shape s (pose X_GS) that a half-space on a face of `box` (pose X_GX, half extents
// h) would take (ForEachCandidate), through the face's plane (or within the envelope of it) and
// over the face, and for a cylinder across the face's edge its deepest line at the edge: each at
// its depth through the plane along the face's normal (exact), with the shape's radius (the
// face is flat: as on a half-space). The face: `axis` of the box's frame,
// `side` +1 or -1. `base` gives the bodies and material; `sign` +1 when body1 is the box.
struct BoxFacePoints {
  std::array<CollisionContact, 10> found;  // a box's 8 corners; a cylinder's 8 rim points, 2 ends
  int count = 0;
  double deepest = -std::numeric_limits<double>::infinity();
  bool nearer_a_side = false;  // a point through the plane lies nearer a side face (left out)
};
// A hull lying across an edge of a box's face (pose X_GX, half extents h; the face: `axis`,
// `side`): its vertices through the face's plane (`through_X`, in the box's frame, within the
// envelope) span a polygon on the plane (their convex hull there), which the face's rectangle
// clips; the points the clipping makes, on the face's edges and at its corners, are contacts
// too (`add`: the point in G and its depth), at depths interpolated along the polygon's edges.
// Exact when those vertices lie on one face of the hull (a sole, a cube's face: the depth is
// linear over it); otherwise the chords' depths, at most the hull's there.
template <class Add>
void AddWhereTheFaceClips(const std::vector<Vec3>& through_X, const Vec3& h, int axis, double side,
                          double envelope, const Transform& X_GX, Add&& add) {
  const int j1 = (axis + 1) % 3, j2 = (axis + 2) % 3;
  struct Corner {
    double u, v, depth;
    bool made;  // by the clipping (the others were taken as vertices over the face)
  };
  thread_local std::vector<Corner> points, polygon, clipped;
  points.clear();
  for (const Vec3& p : through_X) points.push_back({p[j1], p[j2], h[axis] - side * p[axis], false});
  // The convex hull on the plane (Andrew's monotone chain), counter-clockwise in (u, v).
  std::sort(points.begin(), points.end(), [](const Corner& a, const Corner& b) {
    return a.u < b.u || (a.u == b.u && a.v < b.v);
  });
  const auto cross = [](const Corner& o, const Corner& a, const Corner& b) {
    return (a.u - o.u) * (b.v - o.v) - (a.v - o.v) * (b.u - o.u);
  };
  polygon.clear();
  for (int pass = 0; pass < 2; ++pass) {
    const size_t start = polygon.size();
    for (size_t k = 0; k < points.size(); ++k) {
      const Corner& p = pass == 0 ? points[k] : points[points.size() - 1 - k];
      while (polygon.size() >= start + 2 &&
             cross(polygon[polygon.size() - 2], polygon.back(), p) <= 0.0)
        polygon.pop_back();
      polygon.push_back(p);
    }
    polygon.pop_back();  // each chain's last point starts the other
  }
  if (polygon.size() < 2) return;
  // Clipped by the four sides of the rectangle in turn (Sutherland-Hodgman); a segment (two
  // points) is a polygon of two edges, so it stays a segment.
  const auto clip = [&](int coordinate, double sign, double limit) {
    const auto value = [&](const Corner& c) { return sign * (coordinate == 0 ? c.u : c.v); };
    clipped.clear();
    for (size_t k = 0; k < polygon.size(); ++k) {
      const Corner& a = polygon[k];
      const Corner& b = polygon[(k + 1) % polygon.size()];
      const bool a_in = value(a) <= limit, b_in = value(b) <= limit;
      if (a_in) clipped.push_back(a);
      if (a_in != b_in) {
        const double t = (limit - value(a)) / (value(b) - value(a));
        clipped.push_back({a.u + t * (b.u - a.u), a.v + t * (b.v - a.v),
                           a.depth + t * (b.depth - a.depth), true});
      }
    }
    std::swap(polygon, clipped);
  };
  clip(0, 1.0, h[j1]);
  clip(0, -1.0, h[j1]);
  clip(1, 1.0, h[j2]);
  clip(1, -1.0, h[j2]);
  for (size_t k = 0; k < polygon.size(); ++k) {
    const Corner& c = polygon[k];
    if (!c.made || !(c.depth > -envelope)) continue;
    bool repeated = false;  // a segment's clipped ends come twice (from both its edges)
    for (size_t i = 0; i < k && !repeated; ++i)
      repeated = polygon[i].made && polygon[i].u == c.u && polygon[i].v == c.v;
    if (repeated) continue;
    Vec3 p_X;
    p_X[j1] = c.u;
    p_X[j2] = c.v;
    p_X[axis] = side * (h[axis] - c.depth);
    add(X_GX * p_X, c.depth);
  }
}

BoxFacePoints PointsThroughBoxFace(const Vec3& h, const Transform& X_GX, int axis, double side,
                                   const Shape& s, const Transform& X_GS,
                                   const CollisionContact& base, double sign, double envelope) {
  BoxFacePoints out;
  const Vec3 face_G = side * X_GX.R.col(axis);  // the face's outward normal
  const auto depth_of = [&](const Vec3& p_X) { return h[axis] - side * p_X[axis]; };
  const auto add = [&](const Vec3& p_G, double depth) {
    out.deepest = std::max(out.deepest, depth);
    if (out.count == static_cast<int>(out.found.size())) return;
    CollisionContact& c = out.found[out.count++];
    c = base;
    c.n_G = sign * face_G;
    c.depth = depth;
    c.p_G = p_G + 0.5 * depth * face_G;
    c.radius = s.radius > 0.0 ? s.radius : kFlatShapeRadius;
  };
  std::array<Vec3, 2> generator_X;  // a cylinder's first two candidates: its deepest generator
  int candidate = 0;
  const bool hull = s.kind == Kind::kHull || s.kind == Kind::kTriangleMesh;
  thread_local std::vector<Vec3> through_X;  // a hull's vertices through the plane
  through_X.clear();
  bool hull_past_a_side = false;
  ForEachCandidate(s, X_GS.R.transpose() * -face_G, -envelope, [&](const Vec3& p_S) {
    const Vec3 p_G = X_GS * p_S;
    const Vec3 p_X = X_GX.R.transpose() * (p_G - X_GX.p);
    if (candidate < 2) generator_X[candidate] = p_X;
    ++candidate;
    const double depth = depth_of(p_X);
    if (!(depth > -envelope)) return depth;
    if (hull) through_X.push_back(p_X);
    for (int j = 0; j < 3; ++j) {
      if (j == axis) continue;
      const double to_side = h[j] - std::abs(p_X[j]);  // from the box's side face j, inside
      if (to_side < 0.0) {
        hull_past_a_side = hull;
        return depth;
      }
      if (depth > 0.0 && to_side < depth) {
        out.nearer_a_side = true;
        return depth;
      }
    }
    add(p_G, depth);
    return depth;
  });
  if (hull_past_a_side && !out.nearer_a_side) {
    AddWhereTheFaceClips(through_X, h, axis, side, envelope, X_GX, add);
  }
  if (s.kind != Kind::kCylinder) return out;
  // A cylinder lying across an edge of the face: its deepest generator (a straight line on its
  // surface, the deepest point of every cross-section) also touches where it leaves the face,
  // at its depth there (linear along the line: exact). Clipped to the face's rectangle.
  const Vec3 d_X = generator_X[1] - generator_X[0];
  double t0 = 0.0, t1 = 1.0;
  for (int j = 0; j < 3; ++j) {
    if (j == axis) continue;
    if (d_X[j] == 0.0) {
      if (std::abs(generator_X[0][j]) > h[j]) return out;
      continue;
    }
    const double ta = (-h[j] - generator_X[0][j]) / d_X[j];
    const double tb = (h[j] - generator_X[0][j]) / d_X[j];
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  }
  if (!(t0 <= t1)) return out;
  for (const double t : {t0, t1}) {
    if (t == 0.0 || t == 1.0 || (t == t1 && t1 == t0)) continue;  // a rim: taken above
    const Vec3 p_X = generator_X[0] + t * d_X;
    const double depth = depth_of(p_X);
    if (depth > -envelope) add(X_GX * p_X, depth);
  }
  return out;
}

Vec3 BoxHalfExtents(const Shape& box) {
  return FromBt(static_cast<const btBoxShape&>(*box.bt).getHalfExtentsWithoutMargin());
}
}  // namespace

// A convex shape s (pose X_GS) over a face of `box` (pose X_GX) and clear of the box's sides and
// far face (the ball of its reach about its centre): it can overlap the box only through that
// face, and then by exactly its deepest point's depth through it (any other way out is longer
// while no point through the face is nearer a side than the face), so its points through the
// face are the contacts, without GJK; none within the envelope: no contact. False (nothing
// visited) when the shape is not so placed.
template <class Visit>
bool CollisionDetector::Impl::CollideOverBoxFace(const Pair& p, const Shape& box,
                                                 const Transform& X_GX, const Shape& s,
                                                 const Transform& X_GS, double sign,
                                                 Visit&& visit) const {
  const Vec3 h = BoxHalfExtents(box);
  const Vec3 c_X = X_GX.R.transpose() * (X_GS.p - X_GX.p);  // the shape's centre
  int axis = 0;
  (c_X.cwiseAbs() - h).maxCoeff(&axis);
  const double side = c_X[axis] > 0.0 ? 1.0 : -1.0;
  if (side * c_X[axis] < h[axis] || side * c_X[axis] - s.reach <= -h[axis]) return false;
  for (int j = 0; j < 3; ++j) {
    if (j != axis && std::abs(c_X[j]) + s.reach > h[j]) return false;
  }
  CollisionContact base;
  base.body1 = shapes[p.j].body;
  base.body2 = shapes[p.i].body;
  base.material = p.material;
  const BoxFacePoints points =
      PointsThroughBoxFace(h, X_GX, axis, side, s, X_GS, base, sign, envelope);
  if (points.nearer_a_side) return false;
  for (int k = 0; k < points.count; ++k) visit(points.found[k]);
  return true;
}

// A convex shape s (pose X_GS) on a face of `box` (pose X_GX), given Bullet's contact of the
// pair (one point): the shape's points through the face (PointsThroughBoxFace; those nearer a
// side face left out) are the contacts when the deepest of them is as deep as Bullet's contact
// to EPA's accuracy. Lifting the shape off the face by that depth separates it from the box, so
// the face's normal is then a direction of least penetration: the contact is on the face, not
// at an edge or a corner of the box. The face tried first is the one Bullet's normal leaves the
// box through; then the one facing the shape's centre, since a shape touching a face at
// distance zero (resting on it under NSC) gets from GJK a direction that can be any. `sign`: +1
// when Bullet's normal points out of the box, -1 into it. False (nothing visited) otherwise.
template <class Visit>
bool CollisionDetector::Impl::CollideOnBoxFace(const Shape& box, const Transform& X_GX,
                                               const Shape& s, const Transform& X_GS,
                                               const CollisionContact& bullet, double sign,
                                               Visit&& visit) const {
  const Vec3 h = BoxHalfExtents(box);
  const auto on_face = [&](int axis, double side) {
    const BoxFacePoints points =
        PointsThroughBoxFace(h, X_GX, axis, side, s, X_GS, bullet, sign, envelope);
    if (points.count == 0 || !(std::abs(points.deepest - bullet.depth) <= kEpaAccuracy))
      return false;
    for (int k = 0; k < points.count; ++k) visit(points.found[k]);
    return true;
  };
  const Vec3 n_X = X_GX.R.transpose() * (sign * bullet.n_G);  // out of the box, in its frame
  int axis = 0;
  n_X.cwiseAbs().maxCoeff(&axis);
  const double side = n_X[axis] > 0.0 ? 1.0 : -1.0;
  if (on_face(axis, side)) return true;
  const Vec3 c_X = X_GX.R.transpose() * (X_GS.p - X_GX.p);  // the shape's centre
  int centre_axis = 0;
  (c_X.cwiseAbs() - h).maxCoeff(&centre_axis);
  const double centre_side = c_X[centre_axis] > 0.0 ? 1.0 : -1.0;
  if (centre_axis == axis && centre_side == side) return false;
  return on_face(centre_axis, centre_side);
}

// Bullet's box-box detector (ODE's, btBoxBoxDetector) on the boxes themselves: the points of
// the incident face within the reference face (up to four; one for an edge against an edge),
// each with its depth along the detector's normal. Within the envelope but apart, B is first
// carried towards A by the envelope along the normal GJK finds; a translation t changes every
// point's depth along a unit m by t . m, so subtracting that gives each point's true depth
// (exact), and the points go back with B.
template <class Visit>
void CollisionDetector::Impl::CollideBoxes(const Pair& p, const btTransform& X_GA,
                                           const btTransform& X_GB, Visit&& visit) const {
  const Shape& a = shapes[p.i];
  const Shape& b = shapes[p.j];
  CollisionContact c;
  c.body1 = b.body;
  c.body2 = a.body;
  c.radius = kFlatShapeRadius;  // corners and edges on a flat face, as a box's on a half-space
  c.material = p.material;
  Vec3 shift = Vec3::Zero();
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_transformA = X_GA;
  input.m_transformB = X_GB;
  if (envelope > 0.0) {
    if (!Penetrate(a.bt.get(), X_GA, b.bt.get(), X_GB, envelope, c)) return;
    shift = envelope * c.n_G;
    input.m_transformB.getOrigin() += ToBt(shift);
  }
  // The boxes themselves, without the margin (the detector measures sharp boxes).
  btBoxShape box_a(ToBt(BoxHalfExtents(a))), box_b(ToBt(BoxHalfExtents(b)));
  box_a.setMargin(0.0);
  box_b.setMargin(0.0);
  BoxBoxPoints points;
  btBoxBoxDetector detector(&box_a, &box_b);
  detector.getClosestPoints(input, points, nullptr);
  // Carried together, the boxes touch unless GJK's gap was the whole envelope (to rounding):
  // then GJK's own contact.
  if (points.count == 0 && envelope > 0.0) return visit(c);
  for (int k = 0; k < points.count; ++k) {
    c.n_G = FromBt(points.found[k].normal_on_B);
    c.depth = -points.found[k].distance - shift.dot(c.n_G);
    if (!(c.depth > -envelope)) continue;
    c.p_G = FromBt(points.found[k].point_on_B) - shift - 0.5 * c.depth * c.n_G;
    visit(c);
  }
}

// The points of shape s (pose X_GS) that a half-space on the plane of the triangle of `t`
// (Bullet's contact with it) would take (ForEachCandidate: a box's or a hull's vertices, a
// cylinder's two rims) that lie over the triangle and through its plane, or within the envelope
// of it, into `out`: each at its depth through the plane along the plane's normal, exact, as
// against a half-space but over the triangle only. True when the deepest of them is as deep as
// Bullet's contact (to EPA's accuracy): the triangle's overlap is then theirs, and Bullet's
// point is not a contact of its own; false when a feature of the mesh (an edge, a ridge) dents
// a face of the shape more, and Bullet's point stays.
namespace {
bool AddPlanePointsOverTriangle(const Shape& s, const Transform& X_GS, const TriangleContact& t,
                                double envelope, std::vector<PlanePointContact>& out) {
  const std::array<Vec3, 3>& v = t.triangle_G;
  Vec3 n = (v[1] - v[0]).cross(v[2] - v[0]);
  if (!(n.norm() > 0.0)) return false;  // a degenerate triangle: Bullet's point alone
  n.normalize();
  // Towards the side of the shape's centre (a two-sided sheet: the shape is pushed back out on
  // its own side). Not Bullet's normal: a box lying on a triangle touches it at distance zero,
  // where GJK's direction is any (seen at 30-60 degrees off the plane's normal).
  const double centre = (X_GS.p - v[0]).dot(n);
  if (centre < 0.0 || (centre == 0.0 && n.dot(t.contact.n_G) < 0.0)) n = -n;
  double deepest = -std::numeric_limits<double>::infinity();
  int point = 0;
  ForEachCandidate(s, X_GS.R.transpose() * -n, -envelope, [&](const Vec3& p_S) {
    const int index = point++;
    const Vec3 p_G = X_GS * p_S;
    const double depth = (v[0] - p_G).dot(n);
    if (!(depth > -envelope)) return depth;
    const Vec3 on_plane = p_G + depth * n;
    if ((ClosestPointOnTriangle(on_plane, v[0], v[1], v[2]) - on_plane).norm() > 1e-12)
      return depth;
    deepest = std::max(deepest, depth);
    PlanePointContact c{index, t.contact};
    c.contact.n_G = n;
    c.contact.depth = depth;
    c.contact.p_G = p_G + 0.5 * depth * n;
    out.push_back(c);
    return depth;
  });
  return deepest >= t.contact.depth - kEpaAccuracy;
}
}  // namespace

template <class Visit>
void CollisionDetector::Impl::CollideWithMesh(const Pair& p, const std::vector<Transform>& X_GS_all,
                                              Visit&& visit) const {
  const Shape& m = shapes[p.i];
  const Shape& s = shapes[p.j];
  const Transform& X_GM = X_GS_all[p.i];
  const Transform& X_GS = X_GS_all[p.j];
  // Broad phase: the triangles whose bounding boxes meet the convex shape's, both in M (the
  // mesh's hierarchy of boxes, btBvhTriangleMeshShape::processAllTriangles).
  // The shape's box is grown by the triangles' margin (half the envelope).
  const double inflation = 0.5 * envelope;
  btVector3 min_M, max_M;
  s.bt->getAabb(ToBt(X_GM.Inverse() * X_GS), min_M, max_M);
  min_M -= btVector3(inflation, inflation, inflation);
  max_M += btVector3(inflation, inflation, inflation);
  thread_local std::vector<TriangleContact> found;
  found.clear();
  // A box, a hull (a mesh colliding as its hull included) or a cylinder on a triangle: its
  // points that a half-space on the triangle's plane would take, over the triangle and through
  // the plane, each a contact (a box standing on a flat mesh has its four corners, a lying
  // cylinder its two rims).
  thread_local std::vector<PlanePointContact> plane_points;
  plane_points.clear();
  const bool by_plane_points = s.kind == Kind::kBox || s.kind == Kind::kHull ||
                               s.kind == Kind::kTriangleMesh || s.kind == Kind::kCylinder;
  const btTransform bt_X_GM = ToBt(X_GM);
  const btTransform bt_X_GS = ToBt(X_GS);
  // Narrow phase per triangle: GJK and EPA between the convex shape (A) and the triangle (B),
  // each grown by half the envelope, as CollideConvex.
  const auto on_triangle = [&](const btVector3* v) {
    btTriangleShape triangle(v[0], v[1], v[2]);
    triangle.setMargin(inflation);
    TriangleContact t;
    CollisionContact& c = t.contact;  // its normal from the triangle to the shape
    Vec3 p_inflated_G;
    if (!Penetrate(s.bt.get(), bt_X_GS, &triangle, bt_X_GM, envelope, c, &p_inflated_G)) return;
    c.body1 = m.body;
    c.body2 = s.body;
    c.radius = p.radius;
    c.material = p.material;
    t.p_mesh_G = p_inflated_G - inflation * c.n_G;
    for (int k = 0; k < 3; ++k) t.triangle_G[k] = X_GM * FromBt(v[k]);
    if (by_plane_points)
      t.on_plane_points = AddPlanePointsOverTriangle(s, X_GS, t, envelope, plane_points);
    found.push_back(t);
  };
  TriangleVisitor<decltype(on_triangle)> callback(on_triangle);
  m.mesh->shape->processAllTriangles(&callback, min_M, max_M);
  // A shape overlapping a surface of triangles overlaps the neighbours of the one it dents
  // too, each at its point nearest the shape: keep only the contacts that are local extremes
  // of the overlap over the surface. A contact is dropped when a triangle that holds its point
  // (a shared edge or vertex) overlaps more (the neighbour of the dented triangle), or when an
  // earlier contact is the same one (a contact on an edge or vertex, found by each triangle
  // there: as deep, and each point on the other's triangle, or the same point; EPA places a
  // curved shape's point to about 1e-6 m, so the two may lie either side of the edge). So a
  // sphere on a flat mesh touches once, in a V groove once per side.
  const auto on = [](const Vec3& q, const std::array<Vec3, 3>& v) {
    return (ClosestPointOnTriangle(q, v[0], v[1], v[2]) - q).norm() <= kMeshPointTolerance;
  };
  for (size_t k = 0; k < found.size(); ++k) {
    const TriangleContact& t = found[k];
    bool keep = true;
    for (size_t i = 0; i < found.size() && keep; ++i) {
      if (i == k) continue;
      const TriangleContact& o = found[i];
      const bool holds = on(t.p_mesh_G, o.triangle_G);
      if (holds && o.contact.depth > t.contact.depth + kMeshPointTolerance) keep = false;
      const bool same = (o.p_mesh_G - t.p_mesh_G).norm() <= kMeshPointTolerance ||
                        (holds && on(o.p_mesh_G, t.triangle_G));
      if (i < k && same && std::abs(o.contact.depth - t.contact.depth) <= kMeshPointTolerance)
        keep = false;
    }
    if (keep && !t.on_plane_points) visit(t.contact);
  }
  // Each point once where coplanar triangles share it (over their common edge).
  for (size_t k = 0; k < plane_points.size(); ++k) {
    const PlanePointContact& v = plane_points[k];
    bool repeated = false;
    for (size_t i = 0; i < k && !repeated; ++i) {
      const PlanePointContact& o = plane_points[i];
      repeated = o.point == v.point && o.contact.n_G.dot(v.contact.n_G) > 1.0 - 1e-12 &&
                 std::abs(o.contact.depth - v.contact.depth) <= kMeshPointTolerance;
    }
    if (!repeated) visit(v.contact);
  }
}

void CollisionDetector::FindContacts(
    const std::vector<Transform>& X_GB,
    const std::function<void(const CollisionContact&)>& visit) const {
  // Per-thread scratch (the detector is shared by threads): no allocation once grown. A visitor
  // that queries a detector again on this thread gets its own vector (no clobbering).
  thread_local std::vector<Transform> scratch;
  thread_local bool scratch_in_use = false;
  std::vector<Transform> nested;
  const bool use_scratch = !scratch_in_use;
  std::vector<Transform>& X_GS = use_scratch ? scratch : nested;
  scratch_in_use = true;
  struct Release {
    bool& in_use;
    bool release;
    ~Release() {
      if (release) in_use = false;
    }
  } release{scratch_in_use, use_scratch};
  impl_->CalcShapePoses(X_GB, X_GS);
  for (const Pair& p : impl_->pairs) impl_->Collide(p, X_GS, visit);
}

}  // namespace sinew::contact
