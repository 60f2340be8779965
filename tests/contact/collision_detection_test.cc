// Collision detection of the seed's collision cylinders through Bullet (CollisionDetector):
// overlaps of cylinders with each other and with a ground plane against their closed forms, and
// on a real skeleton the family filter and the pairs left out because they overlap at rest.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/contact/collision_detection.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/opensim/parser.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "contact/contact_models.h"

namespace sinew::contact {
namespace {

std::vector<CollisionContact> Contacts(const CollisionDetector& detector,
                                       const std::vector<Transform>& X_GB) {
  std::vector<CollisionContact> out;
  detector.FindContacts(X_GB, [&](const CollisionContact& c) { out.push_back(c); });
  return out;
}

// Bodies 1 and 2 (ground is 0), one family: a 1 m cylinder of radius `r` along x through each
// body's origin.
CollisionModel TwoCylinders(double r) {
  CollisionModel model;
  model.family = {0, 1, 1};
  model.shapes = {{1, Vec3(-0.5, 0, 0), Vec3(0.5, 0, 0), r},
                  {2, Vec3(-0.5, 0, 0), Vec3(0.5, 0, 0), r}};
  return model;
}

TEST(CollisionDetectionTest, CylindersOverlapByTheirRadiiMinusTheirDistance) {
  const double r = 0.05;
  const CollisionDetector detector(TwoCylinders(r), std::nullopt);
  ASSERT_EQ(detector.num_pairs(), 1);
  // Parallel, side by side 0.08 m apart along y: they overlap by 2r - 0.08 = 0.02 m.
  std::vector<Transform> X_GB = {Transform(), Transform(),
                                 Transform::Translation(Vec3(0, 0.08, 0))};
  std::vector<CollisionContact> c = Contacts(detector, X_GB);
  // They touch along a line: at its two ends (one point, Bullet's, would let them rock), each
  // at the closed-form depth (exact: the radial distance from the other's surface).
  ASSERT_EQ(c.size(), 2u);
  for (const CollisionContact& k : c) {
    EXPECT_NEAR(k.depth, 2 * r - 0.08, 1e-15);
    // The normal points from body1 to body2, the point is midway through the overlap.
    const double sign = k.body2 == 2 ? 1.0 : -1.0;
    EXPECT_NEAR((sign * k.n_G - Vec3::UnitY()).norm(), 0.0, 1e-15);
    EXPECT_NEAR(k.p_G.y(), 0.04, 1e-15);
    EXPECT_NEAR(std::abs(k.p_G.x()), 0.5, 1e-15);
    EXPECT_NEAR(k.radius, r / 2, 1e-15);
  }
  EXPECT_NEAR(c[0].p_G.x() + c[1].p_G.x(), 0.0, 1e-15);  // one at each end
  // Body 2 moved 0.3 m along the axes: the line's ends are body 1's end x = 0.5 and body 2's
  // end x = -0.2.
  X_GB[2] = Transform::Translation(Vec3(0.3, 0.08, 0));
  c = Contacts(detector, X_GB);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(std::min(c[0].p_G.x(), c[1].p_G.x()), -0.2, 1e-15);
  EXPECT_NEAR(std::max(c[0].p_G.x(), c[1].p_G.x()), 0.5, 1e-15);
  for (const CollisionContact& k : c) EXPECT_NEAR(k.depth, 2 * r - 0.08, 1e-15);
  // Crossed at right angles (body 2 turned about y: its axis along z), axes 0.09 m apart along
  // y: one point (Bullet's EPA converges to about 1e-6), 0.01 m.
  X_GB[2] =
      Transform(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix(), Vec3(0, 0.09, 0));
  c = Contacts(detector, X_GB);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].depth, 2 * r - 0.09, 1e-6);
  // Given as rest poses, an overlapping pair is left out.
  const CollisionDetector rest(TwoCylinders(r), std::nullopt, X_GB);
  EXPECT_EQ(rest.num_pairs(), 0);
  EXPECT_EQ(rest.num_excluded_at_rest(), 1);
  // Apart: nothing.
  X_GB[2] = Transform::Translation(Vec3(0, 0.11, 0));
  EXPECT_TRUE(Contacts(detector, X_GB).empty());
}

// FindContacts keeps the shapes' poses in per-thread scratch: a visitor that queries a detector
// again on the same thread (here at other poses, between two pairs of the outer query) must
// leave the outer query's later pairs their own poses.
TEST(CollisionDetectionTest, AVisitorMayQueryADetectorAgain) {
  const double r = 0.05;
  const CollisionDetector outer(TwoCylinders(r), 0.0);  // with a floor at y = 0
  const CollisionDetector inner(TwoCylinders(r), 0.0);
  // Body 1 lies 0.01 m into the floor (both rims), body 2 0.08 m above it (they overlap by
  // 0.02 m along a line: its two ends): the cylinders' pair is tested first, then each with the
  // floor.
  const std::vector<Transform> X_outer = {Transform(), Transform::Translation(Vec3(0, 0.04, 0)),
                                          Transform::Translation(Vec3(0, 0.12, 0))};
  // Far apart and above the floor: no contact.
  const std::vector<Transform> X_inner = {Transform(), Transform::Translation(Vec3(0, 1, 0)),
                                          Transform::Translation(Vec3(0, 3, 0))};
  const std::vector<CollisionContact> alone = Contacts(outer, X_outer);
  ASSERT_EQ(alone.size(), 4u);
  ASSERT_TRUE(Contacts(inner, X_inner).empty());
  std::vector<CollisionContact> nested;
  bool inner_empty = true;
  outer.FindContacts(X_outer, [&](const CollisionContact& c) {
    nested.push_back(c);
    inner_empty = inner_empty && Contacts(inner, X_inner).empty();
  });
  EXPECT_TRUE(inner_empty);
  ASSERT_EQ(nested.size(), alone.size());
  for (size_t k = 0; k < alone.size(); ++k) {
    EXPECT_EQ(nested[k].depth, alone[k].depth);
    EXPECT_EQ(nested[k].p_G, alone[k].p_G);
  }
}

TEST(CollisionDetectionTest, CylinderSinksIntoTheGroundPlaneByItsLowestPoint) {
  // One upright cylinder (along y, 1 m, radius 0.05) whose bottom is 0.003 m below the plane
  // y = 0.2, and one lying along x whose side is 0.001 m below it.
  CollisionModel model;
  model.family = {0, 1, 2};
  model.jointed = {{0, 1}, {1, 2}};  // a parent and its child: only the plane
  model.shapes = {{1, Vec3(0, 0, 0), Vec3(0, 1, 0), 0.05},
                  {2, Vec3(-0.5, 0, 0), Vec3(0.5, 0, 0), 0.05}};
  const CollisionDetector detector(model, 0.2);
  ASSERT_EQ(detector.num_pairs(), 2);
  const std::vector<Transform> X_GB = {Transform(), Transform::Translation(Vec3(0, 0.197, 0)),
                                       Transform::Translation(Vec3(3, 0.2 + 0.05 - 0.001, 0))};
  std::vector<CollisionContact> c = Contacts(detector, X_GB);
  // The upright cylinder touches at four points of its bottom rim a quarter turn apart, the
  // lying one at both ends' rims.
  ASSERT_EQ(c.size(), 6u);
  int lying = 0;
  Vec3 upright_centre = Vec3::Zero();
  for (const CollisionContact& k : c) {
    EXPECT_EQ(k.body1, 0);
    EXPECT_EQ(k.n_G, Vec3::UnitY());
    EXPECT_NEAR(k.depth, k.body2 == 1 ? 0.003 : 0.001, 1e-12);
    EXPECT_NEAR(k.p_G.y(), 0.2 - k.depth / 2, 1e-12);
    if (k.body2 == 2) {
      ++lying;
      EXPECT_NEAR(std::abs(k.p_G.x() - 3), 0.5, 1e-12);
    } else {
      EXPECT_NEAR(std::hypot(k.p_G.x(), k.p_G.z()), 0.05, 1e-12);
      upright_centre += k.p_G / 4;
    }
  }
  EXPECT_EQ(lying, 2);
  EXPECT_NEAR(upright_centre.x(), 0.0, 1e-12);  // the four hold the cap about its centre
  EXPECT_NEAR(upright_centre.z(), 0.0, 1e-12);
}

TEST(CollisionDetectionTest, SphereRestsOnAnEnvironmentBoxAndItsFloorByTheirClosedForms) {
  // ball_on_floor.osim (a 0.1 m ContactSphere over its ContactHalfSpace floor) with a box
  // added to the environment through the parser: 1 m wide, its top face at y = 0.5.
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  parser.AddEnvironmentBox("step", Transform::Translation(Vec3(0, 0.25, 0)), Vec3(0.5, 0.25, 0.5));
  parser.Parse(std::string(SINEW_TEST_DATA_DIR) + "/sinew/ball_on_floor.osim");
  const CollisionModel& model = parser.GetCollisionModel();
  ASSERT_EQ(model.geometry.size(), 3u);  // floor, sphere, step
  const CollisionDetector detector(model, std::nullopt);
  // The ball's centre 0.08 m above the step's top: 0.02 m into it, normal +y (from ground's
  // box to the ball), the point midway through the overlap. On the box's face the ball
  // touches as on a plane there: its lowest point, at its depth through the face, exact to
  // rounding, with its own radius (the face is flat).
  std::vector<Transform> X_GB = {Transform(), Transform::Translation(Vec3(0.1, 0.58, 0))};
  std::vector<CollisionContact> c = Contacts(detector, X_GB);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].body1, 0);
  EXPECT_NEAR(c[0].depth, 0.02, 1e-15);
  EXPECT_EQ(c[0].n_G, Vec3::UnitY());
  EXPECT_NEAR(c[0].p_G.y(), 0.49, 1e-15);
  EXPECT_EQ(c[0].radius, 0.1);
  // Beside the step, 0.005 m into the floor: the floor's contact only, exact.
  X_GB[1] = Transform::Translation(Vec3(2, 0.095, 0));
  c = Contacts(detector, X_GB);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].depth, 0.005, 1e-15);
  EXPECT_NEAR(c[0].radius, 0.1, 1e-15);
  // A box needs positive half extents.
  EXPECT_THROW(parser.AddEnvironmentBox("flat", Transform(), Vec3(1, 0, 1)), Error);
}

TEST(CollisionDetectionTest, EnvelopeReportsTheExactGapOfEveryShape) {
  // The same scene with an envelope of 2 mm: each shape is reported while it is less than that
  // from what it meets, with the gap as a negative depth, and its overlap unchanged once it
  // overlaps. GJK works on the shapes grown by 1 mm each (the margin), whose overlap is the
  // true one plus the envelope.
  constexpr double kEnvelope = 2e-3;
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  parser.AddEnvironmentBox("step", Transform::Translation(Vec3(0, 0.25, 0)), Vec3(0.5, 0.25, 0.5));
  parser.Parse(std::string(SINEW_TEST_DATA_DIR) + "/sinew/ball_on_floor.osim");
  const CollisionDetector detector(parser.GetCollisionModel(), std::nullopt, {}, kEnvelope);
  // 1.5 mm above the step (the floor far below): one contact, depth -1.5 mm, midway in the gap.
  std::vector<Transform> X_GB = {Transform(), Transform::Translation(Vec3(0.1, 0.6015, 0))};
  std::vector<CollisionContact> c = Contacts(detector, X_GB);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].depth, -1.5e-3, 1e-9);
  EXPECT_NEAR(c[0].p_G.y(), 0.50075, 1e-9);
  EXPECT_NEAR((c[0].n_G - Vec3::UnitY()).norm(), 0.0, 1e-9);
  // 0.02 m into the step: as without the envelope.
  X_GB[1] = Transform::Translation(Vec3(0.1, 0.58, 0));
  c = Contacts(detector, X_GB);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].depth, 0.02, 1e-9);
  EXPECT_NEAR(c[0].p_G.y(), 0.49, 1e-9);
  // 2.5 mm above: beyond the envelope, nothing.
  X_GB[1] = Transform::Translation(Vec3(0.1, 0.6025, 0));
  EXPECT_TRUE(Contacts(detector, X_GB).empty());
  // Beside the step, 1 mm above the floor half-space: depth -1 mm exactly.
  X_GB[1] = Transform::Translation(Vec3(2, 0.101, 0));
  c = Contacts(detector, X_GB);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].depth, -1e-3, 1e-15);
  EXPECT_NEAR(c[0].p_G.y(), 0.0005, 1e-15);
  // Two parallel cylinders (r = 5 cm) 0.101 m apart: a gap of 1 mm at both ends of their line.
  const CollisionDetector pair(TwoCylinders(0.05), std::nullopt, {}, kEnvelope);
  X_GB = {Transform(), Transform(), Transform::Translation(Vec3(0, 0.101, 0))};
  c = Contacts(pair, X_GB);
  ASSERT_EQ(c.size(), 2u);
  for (const CollisionContact& k : c) EXPECT_NEAR(k.depth, -1e-3, 1e-15);
  EXPECT_THROW(CollisionDetector(TwoCylinders(0.05), std::nullopt, {}, -1e-3), Error);
}

// A box (half extents 0.1, 0.05, 0.1 m) on body 1 and a ground box whose top face is y = 0.
CollisionModel BoxOnAGroundBox() {
  CollisionModel model;
  model.family = {0, 1};
  CollisionGeometry ground;
  ground.name = "ground_box";
  ground.kind = CollisionShapeKind::kBox;
  ground.body = 0;
  ground.X_BS = Transform::Translation(Vec3(0, -0.25, 0));
  ground.half_extents = Vec3(1.0, 0.25, 1.0);
  CollisionGeometry box = ground;
  box.name = "box";
  box.body = 1;
  box.X_BS = Transform();
  box.half_extents = Vec3(0.1, 0.05, 0.1);
  model.geometry = {ground, box};
  return model;
}

// The corners (in G) of the box's face y = -0.05 at the pose X_GB, and the contacts' points
// matched to them: each contact within `tolerance` of a corner carried up (along +y) by half
// the contact's depth, every contact at a distinct corner.
void ExpectContactsAtCorners(const std::vector<CollisionContact>& contacts, const Transform& X_GB,
                             const std::vector<Vec3>& corners_B, double tolerance) {
  std::vector<bool> used(corners_B.size(), false);
  for (const CollisionContact& c : contacts) {
    bool matched = false;
    for (size_t k = 0; k < corners_B.size() && !matched; ++k) {
      const Vec3 midway = X_GB * corners_B[k] + 0.5 * c.depth * Vec3::UnitY();
      if (!used[k] && (c.p_G - midway).norm() < tolerance) used[k] = matched = true;
    }
    EXPECT_TRUE(matched) << "a contact at " << c.p_G.transpose() << " at no corner";
  }
}

// A pose of the box, the corners of its face y = -0.05 expected to touch, and their depth.
struct CornerCase {
  Transform X_GB;
  std::vector<Vec3> corners;
  double depth;
};

// The contacts at the case's pose: one per corner, each at the depth, its normal up (from
// body1 towards body2: from ground up, or from the box down) and at its corner, to `tolerance`.
std::vector<CollisionContact> ExpectCornerContacts(const CollisionDetector& detector,
                                                   const CornerCase& k, double tolerance) {
  const std::vector<CollisionContact> c = Contacts(detector, {Transform(), k.X_GB});
  EXPECT_EQ(c.size(), k.corners.size());
  for (const CollisionContact& contact : c) {
    EXPECT_NEAR(contact.depth, k.depth, tolerance);
    const Vec3 up = contact.body1 == 0 ? contact.n_G : Vec3(-contact.n_G);
    EXPECT_NEAR((up - Vec3::UnitY()).norm(), 0.0, tolerance);
  }
  ExpectContactsAtCorners(c, k.X_GB, k.corners, tolerance);
  return c;
}

TEST(CollisionDetectionTest, BoxOnABoxTouchesAtTheCornersOfItsFaceByTheirClosedForms) {
  // Bullet's box-box detector gives a face's points (GJK and EPA alone give one, and a box on
  // one point tips): four corners flat, two on a tilted box's lowest edge, each with its own
  // depth, exact to rounding, with or without an envelope (then gaps below it too).
  const std::vector<Vec3> bottom = {Vec3(0.1, -0.05, 0.1), Vec3(0.1, -0.05, -0.1),
                                    Vec3(-0.1, -0.05, 0.1), Vec3(-0.1, -0.05, -0.1)};
  const double theta = 0.1;  // the tilt about z: the edge x = -0.1 lowest
  const Mat3 R_tilt = Eigen::AngleAxisd(theta, Vec3::UnitZ()).toRotationMatrix();
  const double lowest = 0.1 * std::sin(theta) + 0.05 * std::cos(theta);  // below the centre
  const Mat3 R_turn = Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY()).toRotationMatrix();
  for (const double envelope : {0.0, 2e-3}) {
    SCOPED_TRACE("envelope " + std::to_string(envelope));
    const CollisionDetector detector(BoxOnAGroundBox(), std::nullopt, {}, envelope);
    ASSERT_EQ(detector.num_pairs(), 1);
    std::vector<CornerCase> cases = {
        {Transform::Translation(Vec3(0.3, 0.05 - 3e-3, -0.2)), bottom, 3e-3},  // flat
        {Transform(R_turn, Vec3(0, 0.05 - 1e-3, 0)), bottom, 1e-3},            // turned 45 deg
        {Transform(R_tilt, Vec3(0, lowest - 2e-3, 0)), {bottom[2], bottom[3]}, 2e-3}};  // edge
    if (envelope > 0.0) {
      cases.push_back({Transform::Translation(Vec3(0, 0.05 + 1.5e-3, 0)), bottom, -1.5e-3});
      cases.push_back(
          {Transform(R_tilt, Vec3(0, lowest + 5e-4, 0)), {bottom[2], bottom[3]}, -5e-4});
    }
    for (const CornerCase& k : cases) {
      for (const CollisionContact& contact : ExpectCornerContacts(detector, k, 1e-12))
        EXPECT_EQ(contact.radius, kFlatShapeRadius);  // as a box's corners on a plane
    }
    // Beyond the envelope (or just apart without one): nothing.
    EXPECT_TRUE(Contacts(detector,
                         {Transform(), Transform::Translation(Vec3(0, 0.05 + envelope + 5e-4, 0))})
                    .empty());
  }
  // The box as a closed triangle mesh (a ContactMesh cube on a moving body): it collides as its
  // hull (exact), so at the same corners, flat and tilted.
  CollisionModel cube = BoxOnAGroundBox();
  cube.geometry[1].kind = CollisionShapeKind::kTriangleMesh;
  cube.geometry[1].mesh = testing::MakeBoxMesh(Vec3(0.1, 0.05, 0.1));
  const CollisionDetector on_box(cube, std::nullopt);
  ExpectCornerContacts(on_box, {Transform::Translation(Vec3(0.3, 0.05 - 3e-3, -0.2)), bottom, 3e-3},
                       1e-12);
  ExpectCornerContacts(
      on_box, {Transform(R_tilt, Vec3(0, lowest - 2e-3, 0)), {bottom[2], bottom[3]}, 2e-3}, 1e-12);
  // Half over the ground box's edge x = 1 (its corners at x = 0.9 over the face, 1.1 past it):
  // the two corners over the face and, where its bottom face leaves the box's top, two points
  // on the edge, at z = -+0.1, all 3 mm deep (on the two corners alone it tipped over the
  // edge). Tilted by 0.01 rad about z, its corners past the edge lowest: the edge's points at
  // the depth of the bottom face there (linear over the face: exact).
  std::vector<CollisionContact> c =
      Contacts(on_box, {Transform(), Transform::Translation(Vec3(1.0, 0.05 - 3e-3, 0))});
  ASSERT_EQ(c.size(), 4u);
  int on_edge = 0;
  for (const CollisionContact& k : c) {
    EXPECT_NEAR(k.depth, 3e-3, 1e-15);
    EXPECT_NEAR(std::abs(k.p_G.z()), 0.1, 1e-15);
    if (std::abs(k.p_G.x() - 1.0) < 1e-15)
      ++on_edge;
    else
      EXPECT_NEAR(k.p_G.x(), 0.9, 1e-15);
  }
  EXPECT_EQ(on_edge, 2);
  const double tilt = -0.01;  // the corners x = +0.1 go down
  const Mat3 R_down = Eigen::AngleAxisd(tilt, Vec3::UnitZ()).toRotationMatrix();
  const Transform tilted(R_down, Vec3(1.0, 0.05 - 2e-3, 0));
  // The bottom face's depth at x (in G), from the plane through its corners.
  const Vec3 n_bottom = R_down * Vec3::UnitY();
  const Vec3 on_bottom = tilted * Vec3(0, -0.05, 0);
  const auto bottom_depth = [&](double x) {
    // y of the bottom plane at (x, z = 0): n . (p - on_bottom) = 0.
    return -(on_bottom.y() - n_bottom.x() * (x - on_bottom.x()) / n_bottom.y());
  };
  c = Contacts(on_box, {Transform(), tilted});
  ASSERT_EQ(c.size(), 4u);
  on_edge = 0;
  for (const CollisionContact& k : c) {
    const double x = k.p_G.x() - 0.5 * k.depth * k.n_G.x();  // the face's normal is vertical
    EXPECT_NEAR(k.depth, bottom_depth(x), 1e-15) << x;
    if (std::abs(x - 1.0) < 1e-15) ++on_edge;
  }
  EXPECT_EQ(on_edge, 2);
}

// A ground mesh of two triangles: `vertices` (4, in G), triangles (0, 1, 2) and (0, 2, 3).
CollisionGeometry GroundMesh(const std::vector<Vec3>& vertices) {
  auto mesh = std::make_shared<ShapeMesh>();
  mesh->vertices = vertices;
  mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
  CollisionGeometry g;
  g.name = "ground_mesh";
  g.kind = CollisionShapeKind::kTriangleMesh;
  g.body = 0;
  g.mesh = mesh;
  return g;
}

TEST(CollisionDetectionTest, BoxOnAFlatMeshTouchesAtItsCornersAndOnARidgeAtTheRidge) {
  // The box of BoxOnAGroundBox on a flat square mesh y = 0 (two triangles sharing the diagonal
  // x = z, which passes under the box): its corners over the triangles and through their plane
  // are the contacts, as on a half-space (GJK and EPA give one point per triangle region, and
  // a box on one or two points tips); exact depths and points. On a ridge (two slopes meeting
  // at x = 0) the ridge dents the box's bottom face and no corner is near a slope: Bullet's
  // point at the ridge stays.
  const std::vector<Vec3> bottom = {Vec3(0.1, -0.05, 0.1), Vec3(0.1, -0.05, -0.1),
                                    Vec3(-0.1, -0.05, 0.1), Vec3(-0.1, -0.05, -0.1)};
  const double theta = 0.1;
  const Mat3 R_tilt = Eigen::AngleAxisd(theta, Vec3::UnitZ()).toRotationMatrix();
  const double lowest = 0.1 * std::sin(theta) + 0.05 * std::cos(theta);
  const Mat3 R_turn = Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY()).toRotationMatrix();
  CollisionModel flat = BoxOnAGroundBox();
  flat.geometry[0] = GroundMesh({Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(1, 0, 1), Vec3(-1, 0, 1)});
  for (const double envelope : {0.0, 2e-3}) {
    SCOPED_TRACE("envelope " + std::to_string(envelope));
    const CollisionDetector detector(flat, std::nullopt, {}, envelope);
    std::vector<CornerCase> cases = {
        {Transform::Translation(Vec3(0.03, 0.05 - 3e-3, 0.02)), bottom, 3e-3},
        {Transform(R_turn, Vec3(0.01, 0.05 - 1e-3, 0)), bottom, 1e-3},
        {Transform(R_tilt, Vec3(0, lowest - 2e-3, 0)), {bottom[2], bottom[3]}, 2e-3}};
    if (envelope > 0.0)
      cases.push_back({Transform::Translation(Vec3(0.03, 0.05 + 1.5e-3, 0.02)), bottom, -1.5e-3});
    for (const CornerCase& k : cases) ExpectCornerContacts(detector, k, 1e-15);
  }
  // A hull of the box's eight corners (kConvexMesh) the same way.
  CollisionModel hull = flat;
  hull.geometry[1].kind = CollisionShapeKind::kConvexMesh;
  auto corners = std::make_shared<std::vector<Vec3>>();
  for (int i = 0; i < 8; ++i)
    corners->push_back(Vec3(i & 1 ? 0.1 : -0.1, i & 2 ? 0.05 : -0.05, i & 4 ? 0.1 : -0.1));
  hull.geometry[1].vertices = corners;
  ExpectCornerContacts(CollisionDetector(hull, std::nullopt),
                       {Transform::Translation(Vec3(0.03, 0.05 - 3e-3, 0.02)), bottom, 3e-3},
                       1e-15);
  // The box as a closed triangle mesh (a ContactMesh cube): against the floor mesh it collides
  // as its hull (MeshPairHull, closed and convex: exact), its corners the same way.
  CollisionModel cube = flat;
  cube.geometry[1].kind = CollisionShapeKind::kTriangleMesh;
  cube.geometry[1].mesh = testing::MakeBoxMesh(Vec3(0.1, 0.05, 0.1));
  ExpectCornerContacts(CollisionDetector(cube, std::nullopt),
                       {Transform::Translation(Vec3(0.03, 0.05 - 3e-3, 0.02)), bottom, 3e-3},
                       1e-15);
  ExpectCornerContacts(CollisionDetector(cube, std::nullopt),
                       {Transform(R_tilt, Vec3(0, lowest - 2e-3, 0)), {bottom[2], bottom[3]}, 2e-3},
                       1e-15);
  CollisionModel ridge = BoxOnAGroundBox();
  ridge.geometry[0] =
      GroundMesh({Vec3(-1, -0.5, -1), Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(-1, -0.5, 1)});
  auto slopes = std::make_shared<ShapeMesh>(*ridge.geometry[0].mesh);
  slopes->vertices.insert(slopes->vertices.end(), {Vec3(1, -0.5, -1), Vec3(1, -0.5, 1)});
  slopes->triangles.insert(slopes->triangles.end(), {{1, 4, 5}, {1, 5, 2}});
  ridge.geometry[0].mesh = slopes;
  const CollisionDetector on_ridge(ridge, std::nullopt);
  const std::vector<CollisionContact> c =
      Contacts(on_ridge, {Transform(), Transform::Translation(Vec3(0, 0.05 - 2e-3, 0))});
  ASSERT_FALSE(c.empty());
  for (const CollisionContact& contact : c) {
    EXPECT_NEAR(contact.depth, 2e-3, 1e-6);  // EPA's accuracy
    EXPECT_NEAR(std::abs(contact.p_G.x()), 0.0, 1e-6);
  }
}

TEST(CollisionDetectionTest, SkeletonAtRestTouchesNothingAndNeverItsParents) {
  // The seed's Rajagopal2015 with EnableCollision: no allowed pair of its cylinders overlaps
  // in the default pose (nothing needs leaving out), and none is a parent and its child.
  opensim::OpenSimParser parser;
  parser.EnableCollision(1, 2);
  parser.Parse(std::string(SINEW_TEST_DATA_DIR) +
               "/projectchrono/chrono/data/opensim/Rajagopal2015.osim");
  const CollisionModel& model = parser.GetCollisionModel();
  const model::ModelSpec& spec = parser.GetSpec();
  kinematics::KinematicTree tree(spec);
  std::vector<Transform> X_GB(spec.bodies.size());
  kinematics::CalcBodyPoses(tree, tree.default_q(), X_GB);
  const CollisionDetector all(model, std::nullopt);
  const CollisionDetector filtered(model, std::nullopt, X_GB);
  EXPECT_TRUE(Contacts(all, X_GB).empty());
  EXPECT_EQ(filtered.num_excluded_at_rest(), 0);
  EXPECT_EQ(filtered.num_pairs(), all.num_pairs());
  // Every allowed pair: not a parent and its child.
  int shapes_pairs = 0;
  for (size_t a = 0; a < model.shapes.size(); ++a) {
    for (size_t b = a + 1; b < model.shapes.size(); ++b) {
      const int p = model.shapes[a].body, q = model.shapes[b].body;
      if (!model.CanCollide(p, q)) continue;
      ++shapes_pairs;
      for (const model::JointSpec& j : spec.joints) {
        EXPECT_FALSE((p == j.parent_body && q == j.child_body) ||
                     (q == j.parent_body && p == j.child_body))
            << j.name;
      }
    }
  }
  EXPECT_EQ(shapes_pairs, all.num_pairs());
  std::cout << "Rajagopal2015: " << all.num_pairs()
            << " cylinder pairs allowed (not parent and child), "
            << "none overlapping at rest\n";
}

}  // namespace
}  // namespace sinew::contact
