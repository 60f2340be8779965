#include <sinew/contact/collision_detection.h>

#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <LinearMath/btAabbUtil2.h>

#include <cmath>
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

struct Shape {
  int body = 0;
  Transform X_BS;  // the shape's frame in its body (a cylinder's axis is S's y)
  double radius = 0.0;  // of curvature across the axis; 0 for the plane (infinite)
  std::unique_ptr<btConvexShape> bt;
};

}  // namespace

struct CollisionDetector::Impl {
  std::vector<Shape> shapes;
  std::vector<std::pair<int, int>> pairs;
  std::optional<double> ground_height;
  int excluded_at_rest = 0;

  // The contact of shape i with the ground plane (the solid y < ground_height), if they
  // overlap: the shape's deepest point is Bullet's support vertex along -y, as Bullet's
  // convex-plane algorithm finds it.
  std::optional<CollisionContact> CollideWithGround(int i, const std::vector<Transform>& X_GB) const;

  // Bullet's deepest contact of shapes i and j at the body poses X_GB, if they overlap.
  std::optional<CollisionContact> Collide(int i, int j, const std::vector<Transform>& X_GB) const;
};

CollisionDetector::CollisionDetector(const CollisionModel& model,
                                     std::optional<double> ground_height,
                                     const std::vector<Transform>& X_GB_rest)
    : impl_(std::make_unique<Impl>()) {
  for (const CollisionCylinder& c : model.shapes) {
    const Vec3 axis = c.p_B_end - c.p_B_start;
    const double length = axis.norm();
    if (!(length > 0.0) || !(c.radius > 0.0)) continue;
    Shape s;
    s.body = c.body;
    s.X_BS = Transform(RotationYTo(axis / length), 0.5 * (c.p_B_start + c.p_B_end));
    s.radius = c.radius;
    s.bt = std::make_unique<btCylinderShape>(btVector3(c.radius, 0.5 * length, c.radius));
    s.bt->setMargin(0.0);
    impl_->shapes.push_back(std::move(s));
  }
  const int cylinders = static_cast<int>(impl_->shapes.size());
  for (int i = 0; i < cylinders; ++i) {
    for (int j = i + 1; j < cylinders; ++j) {
      if (!model.CanCollide(impl_->shapes[i].body, impl_->shapes[j].body)) continue;
      if (!X_GB_rest.empty() && impl_->Collide(i, j, X_GB_rest)) {
        ++impl_->excluded_at_rest;
        continue;
      }
      impl_->pairs.emplace_back(i, j);
    }
  }
  impl_->ground_height = ground_height;
}

CollisionDetector::~CollisionDetector() = default;

int CollisionDetector::num_pairs() const {
  return static_cast<int>(impl_->pairs.size()) +
         (impl_->ground_height ? static_cast<int>(impl_->shapes.size()) : 0);
}

std::optional<CollisionContact> CollisionDetector::Impl::CollideWithGround(
    int i, const std::vector<Transform>& X_GB) const {
  const Shape& a = shapes[i];
  const Transform X_GS = X_GB[a.body] * a.X_BS;
  const Vec3 down_S = X_GS.R.transpose() * Vec3(0, -1, 0);
  const Vec3 p_G = X_GS * FromBt(a.bt->localGetSupportingVertexWithoutMargin(ToBt(down_S)));
  CollisionContact c;
  c.depth = *ground_height - p_G.y();
  if (!(c.depth > 0.0)) return std::nullopt;
  c.body1 = 0;
  c.body2 = a.body;
  c.n_G = Vec3::UnitY();
  c.p_G = p_G + 0.5 * c.depth * c.n_G;
  c.radius = a.radius;
  return c;
}

std::optional<CollisionContact> CollisionDetector::Impl::Collide(
    int i, int j, const std::vector<Transform>& X_GB) const {
  const Shape& a = shapes[i];
  const Shape& b = shapes[j];
  const btTransform X_GA = ToBt(X_GB[a.body] * a.X_BS);
  const btTransform X_GBs = ToBt(X_GB[b.body] * b.X_BS);
  // Broad phase: the shapes' bounding boxes.
  btVector3 min_a, max_a, min_b, max_b;
  a.bt->getAabb(X_GA, min_a, max_a);
  b.bt->getAabb(X_GBs, min_b, max_b);
  if (!TestAabbAgainstAabb2(min_a, max_a, min_b, max_b)) return std::nullopt;
  // Narrow phase: GJK, and EPA for the penetration.
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;
  btGjkPairDetector gjk(a.bt.get(), b.bt.get(), &simplex, &epa);
  btGjkPairDetector::ClosestPointInput input;
  input.m_transformA = X_GA;
  input.m_transformB = X_GBs;
  btPointCollector output;
  gjk.getClosestPoints(input, output, nullptr);
  if (!output.m_hasResult || !(output.m_distance < 0.0)) return std::nullopt;
  // Bullet's normal points from B towards A, its point lies on B.
  CollisionContact c;
  c.body1 = b.body;
  c.body2 = a.body;
  c.n_G = FromBt(output.m_normalOnBInWorld).normalized();
  c.depth = -output.m_distance;
  // EPA may fail on deep or degenerate overlaps: no usable normal, no contact.
  if (!c.n_G.allFinite() || !std::isfinite(c.depth)) return std::nullopt;
  c.p_G = FromBt(output.m_pointInWorld) - 0.5 * c.depth * c.n_G;
  c.radius = a.radius > 0.0 && b.radius > 0.0 ? a.radius * b.radius / (a.radius + b.radius)
                                              : std::max(a.radius, b.radius);
  return c;
}

void CollisionDetector::FindContacts(
    const std::vector<Transform>& X_GB,
    const std::function<void(const CollisionContact&)>& visit) const {
  for (const auto& [i, j] : impl_->pairs) {
    if (const std::optional<CollisionContact> c = impl_->Collide(i, j, X_GB)) visit(*c);
  }
  if (!impl_->ground_height) return;
  for (int i = 0; i < static_cast<int>(impl_->shapes.size()); ++i) {
    if (const std::optional<CollisionContact> c = impl_->CollideWithGround(i, X_GB)) visit(*c);
  }
}

int CollisionDetector::num_excluded_at_rest() const { return impl_->excluded_at_rest; }

}  // namespace sinew::contact
