// A ContactMesh fixed to ground collides as its triangles (btBvhTriangleMeshShape), concave or
// not: a ball in an open V groove (tests/data/sinew/v_groove.obj, walls y = |x| / 2, whose
// convex hull is filled up to y = 0.25) touches each wall once, at the closed-form depth, and
// comes to rest down in the groove under NSC (on the closed-form height) and SMC (lower by its
// Hertz dents), where the hull would hold it on top. A mesh on a moving body still collides as
// its hull, and the Report says so.
#include <gtest/gtest.h>
#include <sinew/contact/collision_contact_provider.h>
#include <sinew/contact/collision_detection.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_models.h"

namespace sinew::contact {
namespace {

constexpr double kG = 9.80665;
constexpr double kR = 0.1;  // the ball's radius, m
constexpr double kM = 1.0;  // its mass, kg
// Beside tests/data/sinew/v_groove.obj, so that the mesh is found as a visual mesh would be.
const std::string kModelFile = std::string(SINEW_TEST_DATA_DIR) + "/sinew/v_groove_ball.osim";
// The groove's walls rise at slope 1/2: angle a with tan(a) = 1/2.
const double kSin = 1.0 / std::sqrt(5.0), kCos = 2.0 / std::sqrt(5.0);
// Where the ball rests touching both walls: its centre r / cos(a) above the groove's bottom.
const double kRestHeight = kR / kCos;
// The top of the groove's convex hull.
constexpr double kHullTop = 0.25;

struct Scene {
  std::unique_ptr<engine::System> system;
  CollisionModel model;
  engine::State state;
  Diagnostics warnings;
};

// The ball model with `geometry` and `forces`, read as the file `file`, parsed with collision
// (unless a force is given) and the geometry folders `dirs`.
Scene Parse(const std::string& geometry, ContactMethod method = ContactMethod::kNsc,
            const CollisionMaterial& material = CollisionMaterial{}, const std::string& forces = "",
            const std::string& file = kModelFile, const std::vector<std::string>& dirs = {}) {
  const std::string text = testing::FreeBodyModel(
      kM, Vec3::Constant(0.4 * kM * kR * kR), Vec3(0, -kG, 0),
      "<ContactSphere name=\"ball\"><socket_frame>/bodyset/body</socket_frame><radius>" +
          std::to_string(kR) + "</radius></ContactSphere>" + geometry,
      forces);
  Scene scene;
  opensim::OpenSimParser parser;
  if (forces.empty()) parser.EnableCollision();
  parser.SetContactMethod(method);
  parser.SetContactMaterial(material);
  for (const std::string& dir : dirs) parser.AddGeometryDir(dir);
  const model::ModelSpec spec = io::ReadOsimString(text, file);
  scene.system = std::make_unique<engine::System>(spec.gravity);
  parser.ParseSpec(*scene.system, spec);
  scene.system->Finalize();
  scene.model = parser.GetCollisionModel();
  scene.state = engine::MakeDefaultState(*scene.system);
  scene.warnings = parser.GetReport().warnings();
  return scene;
}

std::string Groove(const std::string& frame) {
  return "<ContactMesh name=\"groove\"><socket_frame>" + frame +
         "</socket_frame><filename>v_groove.obj</filename></ContactMesh>";
}

// The contacts of the model with the ball's body (body 1) at `p_GB`.
std::vector<CollisionContact> ContactsAt(const CollisionModel& model, const Vec3& p_GB) {
  const CollisionDetector detector(model, std::nullopt);
  std::vector<CollisionContact> out;
  detector.FindContacts({Transform(), Transform::Translation(p_GB)},
                        [&](const CollisionContact& c) { out.push_back(c); });
  return out;
}

TEST(CollisionMeshTest, BallInAGroundGrooveTouchesEachWallOnceAtTheClosedFormDepth) {
  const Scene scene = Parse(Groove("/ground"));
  const auto groove = std::find_if(scene.model.geometry.begin(), scene.model.geometry.end(),
                                   [](const CollisionGeometry& g) { return g.name == "groove"; });
  ASSERT_NE(groove, scene.model.geometry.end());
  EXPECT_EQ(groove->kind, CollisionShapeKind::kTriangleMesh);
  // Centred over the groove, lowered so that it overlaps each wall by 1 mm: the centre is
  // (r - d) / cos(a) above the bottom. At z = 0 each wall's contact lies on the edge two of its
  // triangles share (found by both, counted once); at z = 0.2 inside one triangle. The
  // neighbouring triangles the ball also overlaps give no contact of their own.
  constexpr double kDepth = 1e-3;
  for (const double z : {0.0, 0.2, -0.13}) {
    const std::vector<CollisionContact> c =
        ContactsAt(scene.model, Vec3(0, (kR - kDepth) / kCos, z));
    ASSERT_EQ(c.size(), 2u) << "z = " << z;
    for (const CollisionContact& k : c) {
      EXPECT_NEAR(k.depth, kDepth, 1e-12);
      const double side = k.p_G.x() > 0 ? 1.0 : -1.0;  // the wall x > 0 pushes towards -x
      EXPECT_NEAR((k.n_G - Vec3(-side * kSin, kCos, 0)).norm(), 0.0, 1e-12);
      // Midway through the overlap: r - d/2 from the centre along -n.
      const Vec3 centre(0, (kR - kDepth) / kCos, z);
      EXPECT_NEAR((k.p_G - (centre - (kR - kDepth / 2) * k.n_G)).norm(), 0.0, 1e-12);
      EXPECT_EQ(k.body1, 0);
      EXPECT_EQ(k.body2, 1);
      EXPECT_NEAR(k.radius, kR, 0.0);  // flat triangles: the ball's curvature
    }
  }
  // On one wall only (centre over x = 0.3, 1 mm into it along its normal): one contact.
  const Vec3 on_wall = Vec3(0.3, 0.15, 0.1) + (kR - kDepth) * Vec3(-kSin, kCos, 0);
  const std::vector<CollisionContact> one = ContactsAt(scene.model, on_wall);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(one[0].depth, kDepth, 1e-12);
  // Where the ball rests on the walls, the hull (the same vertices as kConvexMesh, a prism
  // whose slanted faces are the walls) buries it: the least way out is through a wall, 2 r (up
  // it would be the hull's top minus the ball's lowest point, 0.238 m).
  CollisionModel hull = scene.model;
  for (CollisionGeometry& g : hull.geometry) {
    if (g.name != "groove") continue;
    g.kind = CollisionShapeKind::kConvexMesh;
    g.vertices = std::shared_ptr<const std::vector<Vec3>>(g.mesh, &g.mesh->vertices);
  }
  const std::vector<CollisionContact> buried = ContactsAt(hull, Vec3(0, kRestHeight, 0));
  ASSERT_EQ(buried.size(), 1u);
  EXPECT_NEAR(buried[0].depth, std::min(2 * kR, kHullTop - (kRestHeight - kR)), 1e-6);  // EPA
}

TEST(CollisionMeshTest, BallDroppedIntoAGroundGrooveRestsOnBothWallsWithNsc) {
  // Dropped from 0.2 m (inside the groove's hull, which would bury it), inelastic, h = 1 ms: it
  // stops on both walls with its centre at r / cos(a), exactly (the envelope makes NSC stop a shape
  // where it meets another, docs/contact.md).
  Scene scene = Parse(Groove("/ground"));
  engine::SetCoordinateValue(*scene.system, scene.state, "ty", 0.2);
  std::vector<Transform> X_GB;
  GatherBodyPoses(scene.state, X_GB);
  auto provider = std::make_shared<CollisionContactProvider>(
      scene.model, std::nullopt, NscMaterial{.friction = 0.5, .restitution = 0.0}, X_GB);
  engine::IntegratorSettings settings;
  settings.step = 1e-3;
  engine::NscSettings nsc;
  nsc.solver.max_iterations = 1000;
  nsc.solver.tolerance = 1e-12;
  engine::NscIntegrator integrator(*scene.system, provider, settings, nsc);
  integrator.StepTo(scene.state, 0.5);
  const engine::BodyState& ball = scene.state.bodies[1];
  EXPECT_NEAR(ball.p_GB.y(), kRestHeight, 1e-9);
  EXPECT_NEAR(ball.p_GB.x(), 0.0, 1e-9);
  EXPECT_NEAR(ball.v_GB.norm(), 0.0, 1e-9);
  EXPECT_EQ(integrator.last_contacts().size(), 2u);
  std::cout << "NSC ball in the V groove: rests at " << ball.p_GB.y() << " m (closed form "
            << kRestHeight << ", error " << ball.p_GB.y() - kRestHeight << "; speed "
            << ball.v_GB.norm() << " m/s), " << integrator.last_contacts().size() << " contacts\n";
}

TEST(CollisionMeshTest, BallDroppedIntoAGroundGrooveSettlesOnItsHertzDentsWithSmc) {
  // SMC (Hertz with E = 1e7 Pa, nu = 0.3 on both shapes; restitution 0.4), rk45: at rest each
  // wall carries N = m g / (2 cos(a)) (no friction: the ball is centred), dented by
  // d = (N / (4/3 E* sqrt(r)))^(2/3) with E* = E / (2 (1 - nu^2)) and the ball's radius (the
  // walls are flat): its centre rests (r - d) / cos(a) above the bottom.
  const CollisionMaterial material;
  Scene scene = Parse(Groove("/ground"), ContactMethod::kSmc, material);
  engine::SetCoordinateValue(*scene.system, scene.state, "ty", 0.2);
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-9;
  auto integrator = engine::MakeIntegrator("rk45", *scene.system, settings);
  integrator->StepTo(scene.state, 3.0);
  const double modulus =
      material.young_modulus / (2.0 * (1.0 - material.poisson_ratio * material.poisson_ratio));
  const double load = kM * kG / (2.0 * kCos);
  const double dent = std::pow(load / (4.0 / 3.0 * modulus * std::sqrt(kR)), 2.0 / 3.0);
  const double closed = (kR - dent) / kCos;
  const engine::BodyState& ball = scene.state.bodies[1];
  // The residual bounce decays with the Hertz damping; at 3 s it is below 1e-8 m.
  EXPECT_NEAR(ball.p_GB.y(), closed, 1e-8);
  EXPECT_NEAR(ball.p_GB.x(), 0.0, 1e-9);
  EXPECT_LT(ball.v_GB.norm(), 1e-6);
  std::cout << "SMC ball in the V groove: rests at " << ball.p_GB.y() << " m (closed form "
            << closed << ", dent " << dent << " m; error " << ball.p_GB.y() - closed << ")\n";
}

TEST(CollisionMeshTest, MeshOnAMovingBodyCollidesAsItsHullAndTheReportSaysSo) {
  const Scene scene = Parse(Groove("/bodyset/body"));
  const auto groove = std::find_if(scene.model.geometry.begin(), scene.model.geometry.end(),
                                   [](const CollisionGeometry& g) { return g.name == "groove"; });
  ASSERT_NE(groove, scene.model.geometry.end());
  EXPECT_EQ(groove->kind, CollisionShapeKind::kConvexMesh);
  const bool warned =
      std::any_of(scene.warnings.begin(), scene.warnings.end(), [](const Diagnostic& d) {
        return d.component == "/contactgeometryset/groove" &&
               d.message.find("convex hull") != std::string::npos;
      });
  EXPECT_TRUE(warned);
}

TEST(CollisionMeshTest, ContactMeshFilesAreSearchedInTheGeometryDirsAndMissingOnesNamed) {
  // The model read as if from a folder without the mesh: only the parser's geometry folder
  // (the CLI's --geometry-dir) has it, for the collision shape and for an
  // ElasticFoundationForce alike; without that folder the error names the file, the component
  // and every folder searched.
  const std::string elsewhere = std::string(SINEW_TEST_DATA_DIR) + "/no_such_folder/model.osim";
  const std::string meshes = std::string(SINEW_TEST_DATA_DIR) + "/sinew";
  const std::string foundation =
      "<ElasticFoundationForce name=\"foundation\"><ElasticFoundationForce::"
      "ContactParametersSet><objects><ElasticFoundationForce::ContactParameters><geometry>"
      "groove ball</geometry><stiffness>1e6</stiffness><dissipation>0</dissipation>"
      "</ElasticFoundationForce::ContactParameters></objects></ElasticFoundationForce::"
      "ContactParametersSet></ElasticFoundationForce>";
  for (const std::string& forces : {std::string(), foundation}) {
    const Scene found =
        Parse(Groove("/ground"), ContactMethod::kNsc, {}, forces, elsewhere, {meshes});
    if (forces.empty()) {
      EXPECT_TRUE(std::any_of(found.model.geometry.begin(), found.model.geometry.end(),
                              [](const CollisionGeometry& g) { return g.name == "groove"; }));
    } else {
      EXPECT_EQ(found.system->force_elements().size(), 1u);
    }
    try {
      Parse(Groove("/ground"), ContactMethod::kNsc, {}, forces, elsewhere, {"/no/such/dir"});
      FAIL() << "expected the mesh not to be found";
    } catch (const Error& error) {
      const std::string message = error.what();
      EXPECT_EQ(error.where().file, elsewhere);
      EXPECT_GT(error.where().line, 0);
      EXPECT_EQ(error.component(), "/contactgeometryset/groove");
      for (const std::string& part : {std::string("'v_groove.obj' not found"),
                                      std::string(SINEW_TEST_DATA_DIR) + "/no_such_folder/Geometry",
                                      std::string("/no/such/dir"), std::string("--geometry-dir")})
        EXPECT_NE(message.find(part), std::string::npos) << message << "\nlacks " << part;
    }
  }
}

}  // namespace
}  // namespace sinew::contact
