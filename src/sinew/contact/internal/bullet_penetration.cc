#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <sinew/contact/internal/bullet_penetration.h>

namespace sinew::contact {
namespace {

// Bullet's pair detector: GJK, and EPA when the cores overlap.
bool PairDetector(const btConvexShape* A, const btTransform& X_A, const btConvexShape* B,
                  const btTransform& X_B, BulletOverlap& out) {
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;
  btGjkPairDetector gjk(A, B, &simplex, &epa);
  btGjkPairDetector::ClosestPointInput input;
  input.m_transformA = X_A;
  input.m_transformB = X_B;
  btPointCollector output;
  gjk.getClosestPoints(input, output, nullptr);
  if (!output.m_hasResult || !(output.m_distance < 0.0)) return false;
  out.normal_on_B = output.m_normalOnBInWorld;
  out.point_on_B = output.m_pointInWorld;
  out.distance = output.m_distance;
  return true;
}

// How far A lies beyond B along the unit `n` (negative: they overlap along n): the least of
// n . a over A less the greatest of n . b over B (shapes without margin).
btScalar SeparationAlong(const btVector3& n, const btConvexShape* A, const btTransform& X_A,
                         const btConvexShape* B, const btTransform& X_B) {
  const btVector3 a = X_A(A->localGetSupportVertexWithoutMarginNonVirtual(-n * X_A.getBasis()));
  const btVector3 b = X_B(B->localGetSupportVertexWithoutMarginNonVirtual(n * X_B.getBasis()));
  return n.dot(a - b);
}

enum class Direct { kOverlap, kApart, kUndecided };

// GJK and EPA (btGjkEpaSolver2::Penetration) for shapes without margin, as Bullet's pair
// detector calls them once its GJK finds the cores overlapping: both transforms shifted by their
// midpoint, the first guess from A's origin to B's. kUndecided where Bullet would go on (GJK or
// EPA failing: it tries other guesses) or repair the result (a degenerate normal, or one pointing
// backwards: the shapes overlap less along it than against it).
Direct DirectEpa(const btConvexShape* A, const btTransform& X_A, const btConvexShape* B,
                 const btTransform& X_B, BulletOverlap& out) {
  const btVector3 offset = (X_A.getOrigin() + X_B.getOrigin()) * btScalar(0.5);
  btTransform local_A = X_A, local_B = X_B;
  local_A.getOrigin() -= offset;
  local_B.getOrigin() -= offset;
  const btVector3 guess = (local_B.getOrigin() - local_A.getOrigin()).safeNormalize();
  btGjkEpaSolver2::sResults result;
  if (!btGjkEpaSolver2::Penetration(A, local_A, B, local_B, guess, result)) {
    return result.status == btGjkEpaSolver2::sResults::Separated ? Direct::kApart
                                                                 : Direct::kUndecided;
  }
  const btVector3 a_to_b = result.witnesses[1] - result.witnesses[0];
  const btScalar length = a_to_b.length();
  if (!(length > SIMD_EPSILON)) return Direct::kUndecided;
  const btVector3 n = a_to_b / length;
  if (SeparationAlong(-n, A, local_A, B, local_B) > SeparationAlong(n, A, local_A, B, local_B))
    return Direct::kUndecided;
  out.normal_on_B = n;
  out.point_on_B = result.witnesses[1] + offset;
  out.distance = -length;
  return Direct::kOverlap;
}

}  // namespace

bool BulletPenetration(const btConvexShape* A, const btTransform& X_A, const btConvexShape* B,
                       const btTransform& X_B, BulletOverlap& out) {
  if (A->getMarginNonVirtual() == 0.0 && B->getMarginNonVirtual() == 0.0) {
    switch (DirectEpa(A, X_A, B, X_B, out)) {
      case Direct::kOverlap:
        return true;
      case Direct::kApart:
        return false;
      case Direct::kUndecided:
        break;
    }
  }
  return PairDetector(A, X_A, B, X_B, out);
}

}  // namespace sinew::contact
