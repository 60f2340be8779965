// OpenSim's ContactCylinder, ContactEllipsoid and ContactMesh as collision shapes (Bullet's
// btCylinderShape, an exact ellipsoid support for GJK, a mesh's triangles): their depths on a
// plane against closed forms, and under NSC a cylinder resting on its radius and rolling down
// an incline at 2/3 g sin(a), an ellipsoid resting on each semi-axis, a mesh cube on half its
// edge; bad sizes and a missing mesh are errors with file, line and component.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/contact/collision_contact_provider.h>
#include <sinew/contact/collision_detection.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "contact/contact_models.h"

namespace sinew::contact {
namespace {

constexpr double kG = 9.80665;
// Beside tests/data/sinew/cube.obj, so that the mesh is found as a visual mesh would be.
const std::string kModelFile = std::string(SINEW_TEST_DATA_DIR) + "/sinew/shapes.osim";
// Half the edge of cube.obj: the file's 0.1 as meshes are read, in single precision.
const double kHalfEdge = static_cast<double>(0.1f);

// A free body "body" with the contact geometry `geometry` (named "shape", on /bodyset/body)
// above the ground ContactHalfSpace "floor" (the solid y < 0).
std::string OneShapeModel(double mass, const Vec3& inertia, const Vec3& gravity,
                          const std::string& geometry) {
  return testing::FreeBodyModel(mass, inertia, gravity, geometry, "");
}

std::string Cylinder(double radius) {
  std::ostringstream g;
  g << "<ContactCylinder name=\"shape\"><socket_frame>/bodyset/body</socket_frame><radius>"
    << radius << "</radius></ContactCylinder>";
  return g.str();
}
std::string Ellipsoid(const Vec3& radii) {
  std::ostringstream g;
  g.precision(17);
  g << "<ContactEllipsoid name=\"shape\"><socket_frame>/bodyset/body</socket_frame><radii>"
    << radii.transpose() << "</radii></ContactEllipsoid>";
  return g.str();
}
std::string Mesh(const std::string& file) {
  return "<ContactMesh name=\"shape\"><socket_frame>/bodyset/body</socket_frame><filename>" + file +
         "</filename></ContactMesh>";
}

struct Scene {
  std::unique_ptr<engine::System> system;
  CollisionModel model;
  engine::State state;
};

Scene Parse(const std::string& text) {
  Scene scene;
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  const model::ModelSpec spec = io::ReadOsimString(text, kModelFile);
  scene.system = std::make_unique<engine::System>(spec.gravity);
  parser.ParseSpec(*scene.system, spec);
  scene.system->Finalize();
  scene.model = parser.GetCollisionModel();
  scene.state = engine::MakeDefaultState(*scene.system);
  return scene;
}

// The contacts of the model at the body pose X_GB of "body" (body 1).
std::vector<CollisionContact> ContactsAt(const CollisionModel& model, const Transform& X_GB) {
  const CollisionDetector detector(model, std::nullopt);
  std::vector<CollisionContact> out;
  detector.FindContacts({Transform(), X_GB}, [&](const CollisionContact& c) { out.push_back(c); });
  return out;
}

Mat3 Rotation(double angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}

// The scene with its floor (the ground half-space y < 0) replaced by a ground box whose top face
// is y = 0 (4 m by 4 m, 1 m thick), or with `mesh` by a flat ground mesh there (the same square
// as two triangles sharing the diagonal x = z).
void PutOnGround(Scene& scene, bool mesh = false) {
  CollisionGeometry& floor = scene.model.geometry[0];
  ASSERT_EQ(floor.kind, CollisionShapeKind::kHalfSpace);
  floor.X_BS = Transform();
  if (mesh) {
    auto square = std::make_shared<ShapeMesh>();
    square->vertices = {Vec3(-2, 0, -2), Vec3(2, 0, -2), Vec3(2, 0, 2), Vec3(-2, 0, 2)};
    square->triangles = {{0, 1, 2}, {0, 2, 3}};
    floor.kind = CollisionShapeKind::kTriangleMesh;
    floor.mesh = square;
  } else {
    floor.kind = CollisionShapeKind::kBox;
    floor.X_BS = Transform::Translation(Vec3(0, -0.5, 0));
    floor.half_extents = Vec3(2.0, 0.5, 2.0);
  }
}

TEST(CollisionShapesTest, DepthsOnAPlaneAreTheClosedForms) {
  // The lowest point of each shape 5 mm below the floor: depth 5 mm, exactly (support points).
  constexpr double kDepth = 5e-3, kR = 0.1;
  // Cylinder (axis z, 4 radii long) lying: its two cap rims touch; standing on a cap: its rim's
  // lowest point is the cap's centre plane, 2 r below the centre.
  const Scene cylinder = Parse(OneShapeModel(1, Vec3::Ones(), Vec3::Zero(), Cylinder(kR)));
  ASSERT_EQ(cylinder.model.geometry.size(), 2u);
  std::vector<CollisionContact> c =
      ContactsAt(cylinder.model, Transform::Translation(Vec3(0, kR - kDepth, 0)));
  ASSERT_EQ(c.size(), 2u);
  for (const CollisionContact& k : c) {
    EXPECT_NEAR(k.depth, kDepth, 1e-15);
    EXPECT_NEAR(std::abs(k.p_G.z()), 2 * kR, 1e-15);  // one at each end
  }
  // Standing, the cap touches all round its rim: four points a quarter turn apart, so that
  // their centre is the cap's (one point alone would tip it over).
  const Mat3 upright = Rotation(std::numbers::pi / 2, Vec3::UnitX());  // z onto -y
  c = ContactsAt(cylinder.model, Transform(upright, Vec3(0, 2 * kR - kDepth, 0)));
  ASSERT_EQ(c.size(), 4u);
  Vec3 centre = Vec3::Zero();
  for (const CollisionContact& k : c) {
    EXPECT_NEAR(k.depth, kDepth, 1e-15);
    EXPECT_NEAR(std::hypot(k.p_G.x(), k.p_G.z()), kR, 1e-15);
    centre += k.p_G / 4;
  }
  EXPECT_NEAR(centre.x(), 0.0, 1e-15);
  EXPECT_NEAR(centre.z(), 0.0, 1e-15);
  for (size_t i = 1; i < c.size(); ++i) {  // a quarter turn apart: at sqrt(2) r or 2 r
    const double apart = (c[i].p_G - c[0].p_G).norm();
    EXPECT_TRUE(std::abs(apart - std::sqrt(2.0) * kR) < 1e-15 || std::abs(apart - 2 * kR) < 1e-15)
        << apart;
  }
  // Ellipsoid (0.1, 0.2, 0.3): on each semi-axis, and turned 30 degrees about z, where its
  // lowest point is sqrt(a^2 sin^2 + b^2 cos^2) below its centre.
  const Vec3 radii(0.1, 0.2, 0.3);
  const Scene ellipsoid = Parse(OneShapeModel(1, Vec3::Ones(), Vec3::Zero(), Ellipsoid(radii)));
  const double angle = std::numbers::pi / 6;
  const struct {
    Mat3 R;
    double half_height;
  } poses[] = {{Mat3::Identity(), radii.y()},
               {Rotation(std::numbers::pi / 2, Vec3::UnitZ()), radii.x()},
               {Rotation(std::numbers::pi / 2, Vec3::UnitX()), radii.z()},
               {Rotation(angle, Vec3::UnitZ()),
                std::hypot(radii.x() * std::sin(angle), radii.y() * std::cos(angle))}};
  for (const auto& pose : poses) {
    c = ContactsAt(ellipsoid.model, Transform(pose.R, Vec3(0, pose.half_height - kDepth, 0)));
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, kDepth, 1e-12) << pose.half_height;
  }
  // The cube mesh (edge 0.2 m) on a face: its four lower corners.
  const Scene cube = Parse(OneShapeModel(1, Vec3::Ones(), Vec3::Zero(), Mesh("cube.obj")));
  c = ContactsAt(cube.model, Transform::Translation(Vec3(0, kHalfEdge - kDepth, 0)));
  ASSERT_EQ(c.size(), 4u);
  for (const CollisionContact& k : c) EXPECT_NEAR(k.depth, kDepth, 1e-15);
}

TEST(CollisionShapesTest, ShapesOnABoxFaceTouchAsOnAPlane) {
  // The same shapes 5 mm into the top face of a ground box: the points that would touch a plane
  // there and lie over the face, each at its depth through the face (GJK and EPA alone give one
  // point, to EPA's 1e-6 m, and a cylinder lying on one point rocks); over the face's edge only
  // the part over the face. With an envelope of 2 mm, 1 mm above: the gaps.
  constexpr double kDepth = 5e-3, kR = 0.1;
  Scene cylinder = Parse(OneShapeModel(1, Vec3::Ones(), Vec3::Zero(), Cylinder(kR)));
  PutOnGround(cylinder);
  const auto expect_rims = [&](const std::vector<CollisionContact>& c, double depth, double x) {
    ASSERT_EQ(c.size(), 2u);
    for (const CollisionContact& k : c) {
      EXPECT_NEAR(k.depth, depth, 1e-15);
      const Vec3 up = k.body1 == 0 ? k.n_G : Vec3(-k.n_G);
      EXPECT_EQ(up, Vec3::UnitY());
      EXPECT_NEAR(k.p_G.y(), -depth / 2, 1e-15);
      EXPECT_NEAR(k.p_G.x(), x, 1e-15);
      EXPECT_NEAR(std::abs(k.p_G.z()), 2 * kR, 1e-15);  // one at each end
      EXPECT_EQ(k.radius, kR);                          // the face is flat
    }
  };
  expect_rims(ContactsAt(cylinder.model, Transform::Translation(Vec3(0.3, kR - kDepth, 0))), kDepth,
              0.3);
  const CollisionDetector enveloped(cylinder.model, std::nullopt, {}, 2e-3);
  std::vector<CollisionContact> c;
  enveloped.FindContacts({Transform(), Transform::Translation(Vec3(0.3, kR + 1e-3, 0))},
                         [&](const CollisionContact& k) { c.push_back(k); });
  expect_rims(c, -1e-3, 0.3);
  // Turned about y so that one end lies past the face's edge x = 2 (the other over the face):
  // the rim over the face, and the line it lies on where it leaves the face, at the edge (on
  // the rim alone it would tip over the edge). Tilted down past the edge by 0.01 rad about z,
  // the part over the face is deepest at the edge: there, by the closed form, and the rim.
  const Mat3 along_x = Rotation(std::numbers::pi / 2, Vec3::UnitY());  // its axis z onto x
  c = ContactsAt(cylinder.model, Transform(along_x, Vec3(2.0, kR - kDepth, 0)));
  ASSERT_EQ(c.size(), 2u);
  for (const CollisionContact& k : c) {
    EXPECT_NEAR(k.depth, kDepth, 1e-15);
    EXPECT_NEAR(k.p_G.y(), -kDepth / 2, 1e-15);
    EXPECT_EQ(std::abs(k.n_G.y()), 1.0);
  }
  EXPECT_NEAR(std::min(c[0].p_G.x(), c[1].p_G.x()), 2.0 - 2 * kR, 1e-15);
  EXPECT_NEAR(std::max(c[0].p_G.x(), c[1].p_G.x()), 2.0, 1e-15);
  const double tilt = 0.01;
  const Transform tilted(Rotation(-tilt, Vec3::UnitZ()) * along_x, Vec3(2.0, kR - kDepth, 0));
  c = ContactsAt(cylinder.model, tilted);
  ASSERT_EQ(c.size(), 2u);
  // The lowest line of the tilted cylinder: y = (centre y) - r / cos(tilt) - (x - 2) tan(tilt).
  const auto line_depth = [&](double x) {
    return -(kR - kDepth - kR / std::cos(tilt) - (x - 2.0) * std::tan(tilt));
  };
  for (const CollisionContact& k : c) {
    EXPECT_NEAR(k.depth, line_depth(k.p_G.x()), 1e-12) << k.p_G.x();  // the normal is vertical
  }
  EXPECT_NEAR(std::max(c[0].p_G.x(), c[1].p_G.x()), 2.0, 1e-15);
  EXPECT_GT(std::max(c[0].depth, c[1].depth), kDepth);  // deeper at the edge than at the rim
  // On a flat ground mesh across the triangles' common diagonal: both rims, as on the plane.
  Scene on_mesh = Parse(OneShapeModel(1, Vec3::Ones(), Vec3::Zero(), Cylinder(kR)));
  PutOnGround(on_mesh, true);
  expect_rims(ContactsAt(on_mesh.model, Transform::Translation(Vec3(0.1, kR - kDepth, 0))), kDepth,
              0.1);
  // Ellipsoid (0.1, 0.2, 0.3) turned 30 degrees about z: one point, its exact depth.
  const Vec3 radii(0.1, 0.2, 0.3);
  Scene ellipsoid = Parse(OneShapeModel(1, Vec3::Ones(), Vec3::Zero(), Ellipsoid(radii)));
  PutOnGround(ellipsoid);
  const double angle = std::numbers::pi / 6;
  const double half_height = std::hypot(radii.x() * std::sin(angle), radii.y() * std::cos(angle));
  c = ContactsAt(ellipsoid.model,
                 Transform(Rotation(angle, Vec3::UnitZ()), Vec3(0, half_height - kDepth, 0)));
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].depth, kDepth, 1e-15);
}

TEST(CollisionShapesTest, ShapesMeetEachOtherThroughGjk) {
  // Two shapes against each other (GJK/EPA): an ellipsoid (0.1, 0.2, 0.3) fixed to ground
  // 5 mm into the top face of the cube mesh (y = 0.1) from above, its b axis vertical: one
  // contact, though its point lies on the diagonal the face's two triangles share, where EPA
  // puts each triangle's point about 1e-6 m apart.
  const std::string text = OneShapeModel(1, Vec3::Ones(), Vec3::Zero(), Mesh("cube.obj"));
  Scene scene = Parse(text);
  CollisionGeometry ellipsoid;
  ellipsoid.name = "e";
  ellipsoid.kind = CollisionShapeKind::kEllipsoid;
  ellipsoid.body = 0;  // fixed to ground, above the origin
  ellipsoid.radii = Vec3(0.1, 0.2, 0.3);
  ellipsoid.X_BS = Transform::Translation(Vec3(0, 0.1 + 0.2 - 5e-3, 0));
  scene.model.geometry = {scene.model.geometry[1], ellipsoid};  // the cube and the ellipsoid
  const std::vector<CollisionContact> c = ContactsAt(scene.model, Transform());
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].depth, 5e-3, 1e-6);  // EPA's accuracy
  EXPECT_NEAR(std::abs(c[0].n_G.y()), 1.0, 1e-6);
}

// Runs `scene` under NSC (friction `mu`, no restitution, h = 1 ms, tight solver) to `t_end`.
void RunNsc(Scene& scene, double mu, double t_end) {
  testing::RunCollisionNsc(*scene.system, scene.state, scene.model, mu, t_end);
}

// The solid cylinder of the tests below (m = 1 kg, r = 0.1 m, length 4 r: I about its axis
// m r^2 / 2) under `gravity` above the ground `ground`: "floor" (the half-space), "box" or "mesh"
// (PutOnGround).
constexpr double kCylinderM = 1.0, kCylinderR = 0.1;
const std::string kGrounds[] = {"floor", "box", "mesh"};
Scene SolidCylinderOn(const std::string& ground, const Vec3& gravity) {
  constexpr double m = kCylinderM, r = kCylinderR, length = 4 * r;
  const Vec3 inertia(m * (3 * r * r + length * length) / 12, m * (3 * r * r + length * length) / 12,
                     m * r * r / 2);
  Scene scene = Parse(OneShapeModel(m, inertia, gravity, Cylinder(r)));
  if (ground != "floor") PutOnGround(scene, ground == "mesh");
  return scene;
}

TEST(CollisionShapesTest, CylinderRestsOnItsRadiusAndRollsDownAnInclineAtTwoThirdsGSin) {
  // A solid cylinder (m = 1 kg, r = 0.1 m, length 4 r: I about its axis m r^2 / 2) lying on
  // the floor, axis along z. On the level it rests with its centre at r (the envelope is exact:
  // the stepper stops it where it meets the floor). On an incline of 20 degrees (gravity turned:
  // downhill is +x) with mu = 0.5 > tan(a) / 3 it rolls without slipping at
  // a = g sin(a) / (1 + I / (m r^2)) = 2/3 g sin(a), from rest: exactly per step (each step's
  // impulses are the continuous law's over the step), to the solver's tolerance.
  // The same on a ground box's top face and on a flat ground mesh (its two rims, as on the plane).
  constexpr double kR = kCylinderR;
  for (const std::string& ground : kGrounds) {
    SCOPED_TRACE("on the ground " + ground);
    Scene level = SolidCylinderOn(ground, Vec3(0, -kG, 0));
    engine::SetCoordinateValue(*level.system, level.state, "ty", kR + 0.01);
    RunNsc(level, 0.5, 0.5);
    EXPECT_NEAR(level.state.bodies[1].p_GB.y(), kR, 1e-9);
    EXPECT_NEAR(level.state.bodies[1].v_GB.norm(), 0.0, 1e-9);
    const double a = 20.0 * std::numbers::pi / 180.0;
    Scene incline = SolidCylinderOn(ground, kG * Vec3(std::sin(a), -std::cos(a), 0));
    engine::SetCoordinateValue(*incline.system, incline.state, "ty", kR);
    constexpr double kT = 0.5;
    RunNsc(incline, 0.5, kT);
    const engine::BodyState& body = incline.state.bodies[1];
    const double closed = 2.0 / 3.0 * kG * std::sin(a) * kT;
    EXPECT_NEAR(body.v_GB.x(), closed, 1e-9 * closed);
    EXPECT_NEAR(body.v_GB.x() + body.w_GB.z() * kR, 0.0, 1e-9);  // rolls: no slip
    EXPECT_NEAR(body.p_GB.y(), kR, 1e-9);
    std::cout << "cylinder: rests at " << level.state.bodies[1].p_GB.y() << " m (r = " << kR
              << "); rolls at " << body.v_GB.x() << " m/s after " << kT << " s (closed form "
              << closed << ", relative " << body.v_GB.x() / closed - 1 << "), slip "
              << body.v_GB.x() + body.w_GB.z() * kR << " m/s"
              << " (on the ground " << ground << ")"
              << "\n";
  }
}

TEST(CollisionShapesTest, CylinderDroppedTiltedOntoItsCapStandsUp) {
  // The cylinder above (r = 0.1 m, 4 r long) dropped 1 cm onto its cap, its axis 0.05 rad off
  // the vertical (its centre of mass well over the cap: tan(0.05) < r / 2 r), inelastic: it
  // lands on the cap's rim, turns back onto the cap and stands, its centre at 2 r, the axis
  // vertical. On the cap's one deepest rim point it toppled. On the floor, the box, the mesh.
  constexpr double kR = kCylinderR;
  for (const std::string& ground : kGrounds) {
    SCOPED_TRACE("on the ground " + ground);
    Scene scene = SolidCylinderOn(ground, Vec3(0, -kG, 0));
    engine::SetCoordinateValue(*scene.system, scene.state, "rx", std::numbers::pi / 2 + 0.05);
    engine::SetCoordinateValue(*scene.system, scene.state, "ty", 2 * kR + 0.01);
    RunNsc(scene, 0.5, 1.0);
    const engine::BodyState& body = scene.state.bodies[1];
    const Vec3 axis = body.quat_GB * Vec3::UnitZ();  // the geometry's axis
    const double off_vertical = std::acos(std::min(1.0, std::abs(axis.y())));
    EXPECT_NEAR(off_vertical, 0.0, 1e-6);
    EXPECT_NEAR(body.p_GB.y(), 2 * kR, 1e-9);
    EXPECT_NEAR(body.v_GB.norm() + body.w_GB.norm(), 0.0, 1e-9);
    std::cout << "cylinder on its cap (" << ground << "): axis " << off_vertical
              << " rad off the vertical, centre at " << body.p_GB.y() << " m (2 r = " << 2 * kR
              << ")\n";
  }
}

TEST(CollisionShapesTest, CylinderRestsLevelInTheGrooveOfTwoParallelCylinders) {
  // The solid cylinder dropped 1 cm into the groove of two fixed parallel cylinders of its size
  // (axes along z at x = +-0.15 m, y = 0.3 m), 5 cm off their middle along the axes: it rests on
  // the two lines of contact, level, its axis at y = 0.3 + sqrt((2 r)^2 - 0.15^2). On one point
  // of each line (Bullet's) it rocked.
  constexpr double kR = kCylinderR, kSpread = 0.15, kHeight = 0.3;
  Scene scene = SolidCylinderOn("floor", Vec3(0, -kG, 0));
  for (const double x : {-kSpread, kSpread}) {
    CollisionGeometry log;
    log.name = x < 0 ? "left" : "right";
    log.kind = CollisionShapeKind::kCylinder;
    log.body = 0;
    log.radius = kR;
    log.half_length = 2 * kR;
    log.X_BS = Transform::Translation(Vec3(x, kHeight, 0));
    scene.model.geometry.push_back(log);
  }
  const double rest = kHeight + std::sqrt(4 * kR * kR - kSpread * kSpread);
  engine::SetCoordinateValue(*scene.system, scene.state, "ty", rest + 0.01);
  engine::SetCoordinateValue(*scene.system, scene.state, "tz", 0.05);
  const size_t contacts =
      testing::RunCollisionNsc(*scene.system, scene.state, scene.model, 0.5, 1.0);
  const engine::BodyState& body = scene.state.bodies[1];
  const Vec3 axis = body.quat_GB * Vec3::UnitZ();
  EXPECT_EQ(contacts, 4u);                      // the ends of the two lines
  EXPECT_NEAR(std::abs(axis.z()), 1.0, 1e-12);  // level and along the groove
  EXPECT_NEAR(body.p_GB.x(), 0.0, 1e-9);
  EXPECT_NEAR(body.p_GB.y(), rest, 1e-9);
  EXPECT_NEAR(body.v_GB.norm() + body.w_GB.norm(), 0.0, 1e-9);
  std::cout << "cylinder in a groove: axis " << std::acos(std::min(1.0, std::abs(axis.z())))
            << " rad off the groove, centre " << body.p_GB.y() - rest << " m from the closed form, "
            << contacts << " contacts\n";
}

TEST(CollisionShapesTest, CubeMeshOverhangingABoxsEdgeRestsOnIt) {
  // The cube mesh (edge 0.2 m, as its hull) dropped 1 cm onto the ground box 6 cm past its edge
  // x = 2 (its centre of mass 4 cm inside): it rests level on its two corners over the face and
  // the edge's two points, its centre at half its edge, where it landed. On the corners alone
  // it tipped over; and resting (at distance zero, where GJK's direction can be any) it once
  // got Bullet's one point with a slanted normal and slid 1e-5 m.
  Scene cube =
      Parse(OneShapeModel(1, Vec3::Constant(1.0 / 6 * 0.04), Vec3(0, -kG, 0), Mesh("cube.obj")));
  PutOnGround(cube);
  engine::SetCoordinateValue(*cube.system, cube.state, "tx", 2.0 - 0.04);
  engine::SetCoordinateValue(*cube.system, cube.state, "ty", kHalfEdge + 0.01);
  const size_t contacts = testing::RunCollisionNsc(*cube.system, cube.state, cube.model, 0.5, 1.0);
  const engine::BodyState& body = cube.state.bodies[1];
  const Vec3 up = body.quat_GB * Vec3::UnitY();
  EXPECT_EQ(contacts, 4u);
  EXPECT_NEAR(up.y(), 1.0, 1e-12);
  EXPECT_NEAR(body.p_GB.y(), kHalfEdge, 1e-9);
  EXPECT_NEAR(body.p_GB.x(), 2.0 - 0.04, 1e-9);
  EXPECT_NEAR(body.v_GB.norm() + body.w_GB.norm(), 0.0, 1e-9);
  std::cout << "cube mesh over an edge: " << contacts << " contacts, tilted "
            << std::acos(std::min(1.0, up.y())) << " rad, centre " << body.p_GB.y() - kHalfEdge
            << " m from half its edge\n";
}

TEST(CollisionShapesTest, EllipsoidRestsOnEachSemiAxisAndCubeMeshOnHalfItsEdge) {
  // Dropped 1 cm with a principal axis vertical (an equilibrium: the lowest point below the
  // centre), inelastic: each comes to rest with its centre at that semi-axis above the floor.
  const Vec3 radii(0.1, 0.2, 0.3);
  const Vec3 inertia = 0.2 * Vec3(radii.y() * radii.y() + radii.z() * radii.z(),
                                  radii.x() * radii.x() + radii.z() * radii.z(),
                                  radii.x() * radii.x() + radii.y() * radii.y());
  const struct {
    const char* coordinate;  // the rotation putting the axis vertical
    double angle;
    double half_height;
  } poses[] = {{"rx", 0.0, radii.y()},
               {"rz", std::numbers::pi / 2, radii.x()},
               {"rx", std::numbers::pi / 2, radii.z()}};
  for (const auto& pose : poses) {
    Scene scene = Parse(OneShapeModel(1, inertia, Vec3(0, -kG, 0), Ellipsoid(radii)));
    engine::SetCoordinateValue(*scene.system, scene.state, pose.coordinate, pose.angle);
    engine::SetCoordinateValue(*scene.system, scene.state, "ty", pose.half_height + 0.01);
    RunNsc(scene, 0.5, 0.5);
    EXPECT_NEAR(scene.state.bodies[1].p_GB.y(), pose.half_height, 1e-9);
    EXPECT_NEAR(scene.state.bodies[1].v_GB.norm(), 0.0, 1e-9);
    std::cout << "ellipsoid: rests at " << scene.state.bodies[1].p_GB.y() << " m (semi-axis "
              << pose.half_height << ")\n";
  }
  Scene cube =
      Parse(OneShapeModel(1, Vec3::Constant(1.0 / 6 * 0.04), Vec3(0, -kG, 0), Mesh("cube.obj")));
  engine::SetCoordinateValue(*cube.system, cube.state, "ty", 0.11);
  RunNsc(cube, 0.5, 0.5);
  EXPECT_NEAR(cube.state.bodies[1].p_GB.y(), kHalfEdge, 1e-9);
  EXPECT_NEAR(cube.state.bodies[1].v_GB.norm(), 0.0, 1e-9);
  std::cout << "cube mesh: rests " << cube.state.bodies[1].p_GB.y() - kHalfEdge
            << " m from half its edge\n";
}

TEST(CollisionShapesTest, BadSizesAndMissingMeshesAreErrorsWithFileLineAndComponent) {
  for (const auto& [geometry, what] :
       {std::pair<std::string, std::string>{Cylinder(-0.1), "radius > 0"},
        {Ellipsoid(Vec3(0.1, 0.0, 0.3)), "three radii > 0"},
        {Mesh("no_such_mesh.obj"), "not found"}}) {
    try {
      Parse(OneShapeModel(1, Vec3::Ones(), Vec3::Zero(), geometry));
      FAIL() << "expected an error for " << geometry;
    } catch (const Error& error) {
      EXPECT_EQ(error.where().file, kModelFile);
      EXPECT_GT(error.where().line, 0);
      EXPECT_EQ(error.component(), "/contactgeometryset/shape");
      EXPECT_NE(std::string(error.what()).find(what), std::string::npos) << error.what();
    }
  }
  // Through the C++ API: a mesh without vertices.
  CollisionModel model;
  CollisionGeometry empty;
  empty.name = "empty";
  empty.kind = CollisionShapeKind::kConvexMesh;
  model.geometry.push_back(empty);
  EXPECT_THROW(CollisionDetector(model, std::nullopt), Error);
}

}  // namespace
}  // namespace sinew::contact
