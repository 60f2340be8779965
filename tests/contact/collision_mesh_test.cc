// A ContactMesh collides as its triangles (btBvhTriangleMeshShape), concave or not, fixed to
// ground or on a moving body: a ball in an open V groove (tests/data/sinew/v_groove.obj, walls
// y = |x| / 2, whose convex hull is filled up to y = 0.25) touches each wall once, at the
// closed-form depth, in any pose of the groove, and comes to rest down in the groove under NSC
// (on the closed-form height) and SMC (lower by its Hertz dents), where the hull would hold it
// on top; on a cart that slides on a rail it does so with the cart, which moves as the
// conserved momentum says; the groove upside down as a falling roof rests on a ground ball on
// both walls. Against another mesh one of the two is its convex hull, exact for a
// closed convex mesh and otherwise a Report warning.
#include <gtest/gtest.h>
#include <sinew/contact/collision_detection.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
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

// The model text `text`, read as the file `file`, parsed with collision (unless `forces`, the
// forces the text has, is not empty) and the geometry folders `dirs`.
Scene ParseText(const std::string& text, ContactMethod method, const CollisionMaterial& material,
                const std::string& forces = "", const std::string& file = kModelFile,
                const std::vector<std::string>& dirs = {}) {
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

// The ball model with `geometry` and `forces` (see ParseText).
Scene Parse(const std::string& geometry, ContactMethod method = ContactMethod::kNsc,
            const CollisionMaterial& material = CollisionMaterial{}, const std::string& forces = "",
            const std::string& file = kModelFile, const std::vector<std::string>& dirs = {}) {
  const std::string text = testing::FreeBodyModel(
      kM, Vec3::Constant(0.4 * kM * kR * kR), Vec3(0, -kG, 0),
      "<ContactSphere name=\"ball\"><socket_frame>/bodyset/body</socket_frame><radius>" +
          std::to_string(kR) + "</radius></ContactSphere>" + geometry,
      forces);
  return ParseText(text, method, material, forces, file, dirs);
}

std::string Groove(const std::string& frame, const std::string& name = "groove") {
  return "<ContactMesh name=\"" + name + "\"><socket_frame>" + frame +
         "</socket_frame><filename>v_groove.obj</filename></ContactMesh>";
}

// The cart's mass (kg): ten balls.
constexpr double kCartMass = 10.0;
// Where the ball is dropped from by default on the cart (m): 2 cm off the groove's axis, 0.2 m
// up (inside the groove's hull), so that the default pose, where SMC leaves out the pairs that
// already overlap, has the ball clear of the groove.
constexpr double kDropX = 0.02, kDropY = 0.2;

// A cart "cart" (kCartMass) on a rail along x (a SliderJoint, coordinate "cart_x") carrying
// the groove, the free ball "ball" (kM, radius kR; coordinates rx ... tz, at (kDropX, kDropY,
// 0)), gravity -y, and `geometry` besides the groove and the ball's sphere. Bodies: ground 0,
// cart 1, ball 2.
std::string CartModel(const std::string& geometry = "") {
  std::ostringstream m;
  m.precision(17);
  const double inertia = 0.4 * kM * kR * kR;
  m << R"(<OpenSimDocument Version="40000"><Model name="groove_cart">
<gravity>0 )"
    << -kG << R"( 0</gravity><Ground name="ground"/><BodySet><objects>
<Body name="cart"><mass>)"
    << kCartMass << R"(</mass><inertia>1 1 1 0 0 0</inertia></Body>
<Body name="ball"><mass>)"
    << kM << "</mass><inertia>" << inertia << " " << inertia << " " << inertia
    << R"( 0 0 0</inertia></Body></objects></BodySet>
<JointSet><objects><SliderJoint name="rail"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/cart</socket_child_frame><coordinates><Coordinate name="cart_x"/>
</coordinates></SliderJoint><FreeJoint name="free"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/ball</socket_child_frame><coordinates>
<Coordinate name="rx"/><Coordinate name="ry"/><Coordinate name="rz"/>
<Coordinate name="tx"><default_value>)"
    << kDropX << R"(</default_value></Coordinate>
<Coordinate name="ty"><default_value>)"
    << kDropY << R"(</default_value></Coordinate>
<Coordinate name="tz"/></coordinates></FreeJoint></objects></JointSet>
<ContactGeometrySet><objects>
<ContactSphere name="sphere"><socket_frame>/bodyset/ball</socket_frame><radius>)"
    << kR << "</radius></ContactSphere>" << Groove("/bodyset/cart") << geometry
    << "</objects></ContactGeometrySet></Model></OpenSimDocument>";
  return m.str();
}

// The contacts of the model at the body poses `X_GB` (ground first).
std::vector<CollisionContact> ContactsAtPoses(const CollisionModel& model,
                                              const std::vector<Transform>& X_GB) {
  const CollisionDetector detector(model, std::nullopt);
  std::vector<CollisionContact> out;
  detector.FindContacts(X_GB, [&](const CollisionContact& c) { out.push_back(c); });
  return out;
}

// The contacts of the model with the ball's body (body 1) at `p_GB`.
std::vector<CollisionContact> ContactsAt(const CollisionModel& model, const Vec3& p_GB) {
  return ContactsAtPoses(model, {Transform(), Transform::Translation(p_GB)});
}

// `model` with the groove's convex hull (the same vertices as kConvexMesh) for its triangles.
CollisionModel WithGrooveHull(const CollisionModel& model) {
  CollisionModel hull = model;
  for (CollisionGeometry& g : hull.geometry) {
    if (g.name != "groove") continue;
    g.kind = CollisionShapeKind::kConvexMesh;
    g.vertices = std::shared_ptr<const std::vector<Vec3>>(g.mesh, &g.mesh->vertices);
  }
  return hull;
}

// The geometry named `name` of `scene`'s collision model (or nullptr).
const CollisionGeometry* FindGeometry(const Scene& scene, const std::string& name) {
  const auto it = std::find_if(scene.model.geometry.begin(), scene.model.geometry.end(),
                               [&](const CollisionGeometry& g) { return g.name == name; });
  return it == scene.model.geometry.end() ? nullptr : &*it;
}

// True when the Report has a warning about the geometry `name` saying `what`.
bool Warned(const Scene& scene, const std::string& name, const std::string& what) {
  return std::any_of(scene.warnings.begin(), scene.warnings.end(), [&](const Diagnostic& d) {
    return d.component == "/contactgeometryset/" + name &&
           d.message.find(what) != std::string::npos;
  });
}

// Runs `scene` to `t_end` under NSC (friction 0.5, no restitution, h = 1 ms, tight solver);
// returns the number of contacts of the last step.
size_t RunNsc(Scene& scene, double t_end) {
  return testing::RunCollisionNsc(*scene.system, scene.state, scene.model, 0.5, t_end);
}

// Runs `scene` (SMC) to `t_end` with rk45 at accuracy 1e-9 and steps up to `max_step` (s; 0: no
// bound).
void RunSmc(Scene& scene, double t_end, double max_step = 0.0) {
  engine::IntegratorSettings settings;
  settings.accuracy = 1e-9;
  settings.step = max_step;
  auto integrator = engine::MakeIntegrator("rk45", *scene.system, settings);
  integrator->StepTo(scene.state, t_end);
}

// The height (m) of the ball's centre above the groove's bottom at rest under SMC (Hertz with
// `material` on both shapes) when the two press together with the weight of `mass` (kg): each
// wall carries N = mass g / (2 cos(a)) (no friction: the ball is centred), dented by
// d = (N / (4/3 E* sqrt(r)))^(2/3) with E* = E / (2 (1 - nu^2)) and the ball's radius (the
// walls are flat): (r - d) / cos(a).
double SmcRestHeight(const CollisionMaterial& material, double mass = kM,
                     double* dent_out = nullptr) {
  const double modulus =
      material.young_modulus / (2.0 * (1.0 - material.poisson_ratio * material.poisson_ratio));
  const double load = mass * kG / (2.0 * kCos);
  const double dent = std::pow(load / (4.0 / 3.0 * modulus * std::sqrt(kR)), 2.0 / 3.0);
  if (dent_out) *dent_out = dent;
  return (kR - dent) / kCos;
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
  // Where the ball rests on the walls, the hull (a prism whose slanted faces are the walls)
  // buries it: the least way out is through a wall, 2 r (up it would be the hull's top minus
  // the ball's lowest point, 0.238 m).
  const std::vector<CollisionContact> buried =
      ContactsAt(WithGrooveHull(scene.model), Vec3(0, kRestHeight, 0));
  ASSERT_EQ(buried.size(), 1u);
  EXPECT_NEAR(buried[0].depth, std::min(2 * kR, kHullTop - (kRestHeight - kR)), 1e-6);  // EPA
}

TEST(CollisionMeshTest, BallDroppedIntoAGroundGrooveRestsOnBothWallsWithNsc) {
  // Dropped from 0.2 m (inside the groove's hull, which would bury it), inelastic, h = 1 ms: it
  // stops on both walls with its centre at r / cos(a), exactly (the envelope makes NSC stop a shape
  // where it meets another, docs/contact.md).
  Scene scene = Parse(Groove("/ground"));
  engine::SetCoordinateValue(*scene.system, scene.state, "ty", 0.2);
  const size_t contacts = RunNsc(scene, 0.5);
  const engine::BodyState& ball = scene.state.bodies[1];
  EXPECT_NEAR(ball.p_GB.y(), kRestHeight, 1e-9);
  EXPECT_NEAR(ball.p_GB.x(), 0.0, 1e-9);
  EXPECT_NEAR(ball.v_GB.norm(), 0.0, 1e-9);
  EXPECT_EQ(contacts, 2u);
  std::cout << "NSC ball in the V groove: rests at " << ball.p_GB.y() << " m (closed form "
            << kRestHeight << ", error " << ball.p_GB.y() - kRestHeight << "; speed "
            << ball.v_GB.norm() << " m/s), " << contacts << " contacts\n";
}

TEST(CollisionMeshTest, BallDroppedIntoAGroundGrooveSettlesOnItsHertzDentsWithSmc) {
  // SMC (Hertz with E = 1e7 Pa, nu = 0.3 on both shapes; restitution 0.4), rk45: the ball rests
  // on its two Hertz dents (SmcRestHeight).
  const CollisionMaterial material;
  Scene scene = Parse(Groove("/ground"), ContactMethod::kSmc, material);
  engine::SetCoordinateValue(*scene.system, scene.state, "ty", 0.2);
  RunSmc(scene, 3.0);
  double dent = 0.0;
  const double closed = SmcRestHeight(material, kM, &dent);
  const engine::BodyState& ball = scene.state.bodies[1];
  // The residual bounce decays with the Hertz damping; at 3 s it is below 1e-8 m.
  EXPECT_NEAR(ball.p_GB.y(), closed, 1e-8);
  EXPECT_NEAR(ball.p_GB.x(), 0.0, 1e-9);
  EXPECT_LT(ball.v_GB.norm(), 1e-6);
  std::cout << "SMC ball in the V groove: rests at " << ball.p_GB.y() << " m (closed form "
            << closed << ", dent " << dent << " m; error " << ball.p_GB.y() - closed << ")\n";
}

TEST(CollisionMeshTest, MeshOnAMovingBodyCollidesAsItsTrianglesInAnyPose) {
  // The groove on the cart, the cart turned 0.5 rad about (1, 2, 3) and moved: the ball 1 mm
  // into each wall (its centre (r - d) / cos(a) above the bottom, in the groove's frame C)
  // touches each wall once at that depth, along the wall's normal turned with the cart, as on
  // ground; the hull would bury it (depth about 2 r). No warning: the mesh is exact.
  const Scene scene = ParseText(CartModel(), ContactMethod::kNsc, {});
  const CollisionGeometry* groove = FindGeometry(scene, "groove");
  ASSERT_NE(groove, nullptr);
  EXPECT_EQ(groove->kind, CollisionShapeKind::kTriangleMesh);
  EXPECT_FALSE(groove->fixed_to_ground);
  EXPECT_FALSE(Warned(scene, "groove", "convex hull"));
  const Mat3 R_GC = Eigen::AngleAxisd(0.5, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Transform X_GC(R_GC, Vec3(0.3, -0.2, 0.7));
  constexpr double kDepth = 1e-3;
  for (const double z : {0.0, 0.2, -0.13}) {
    const Vec3 p_CO(0, (kR - kDepth) / kCos, z);
    const std::vector<Transform> X_GB = {Transform(), X_GC, Transform::Translation(X_GC * p_CO)};
    const std::vector<CollisionContact> c = ContactsAtPoses(scene.model, X_GB);
    ASSERT_EQ(c.size(), 2u) << "z = " << z;
    for (const CollisionContact& k : c) {
      // GJK between a point grown by r and a triangle: exact but for rounding.
      EXPECT_NEAR(k.depth, kDepth, 1e-12);
      const double side = (X_GC.Inverse() * k.p_G).x() > 0 ? 1.0 : -1.0;
      EXPECT_NEAR((k.n_G - R_GC * Vec3(-side * kSin, kCos, 0)).norm(), 0.0, 1e-12);
      EXPECT_EQ(k.body1, 1);  // the cart
      EXPECT_EQ(k.body2, 2);  // the ball
      EXPECT_NEAR(k.radius, kR, 0.0);
    }
    const std::vector<CollisionContact> buried = ContactsAtPoses(WithGrooveHull(scene.model), X_GB);
    ASSERT_EQ(buried.size(), 1u);
    EXPECT_GT(buried[0].depth, 2 * kR - 2e-3);
  }
}

TEST(CollisionMeshTest, BallDroppedIntoAGrooveOnACartRestsOnBothWallsWithNsc) {
  // The ball dropped 2 cm off the groove's axis into the groove on a 10 kg cart that slides
  // freely on a rail along x (inelastic, friction 0.5, h = 1 ms). It rolls down a wall pushing
  // the cart away, and both come to rest: the ball on both walls, r / cos(a) above the bottom
  // and over it; nothing pushes along x from outside, so the mass centre stays put, m 0.02 m,
  // and the cart ends at m 0.02 / (m + M).
  Scene scene = ParseText(CartModel(), ContactMethod::kNsc, {});
  ASSERT_EQ(scene.system->bodies()[1].name, "cart");
  ASSERT_EQ(scene.system->bodies()[2].name, "ball");
  const size_t contacts = RunNsc(scene, 1.0);
  const engine::BodyState& cart = scene.state.bodies[1];
  const engine::BodyState& ball = scene.state.bodies[2];
  const double cart_x = kM * kDropX / (kM + kCartMass);
  EXPECT_NEAR(ball.p_GB.y() - cart.p_GB.y(), kRestHeight, 1e-9);
  EXPECT_NEAR(ball.p_GB.x() - cart.p_GB.x(), 0.0, 1e-9);
  EXPECT_NEAR(cart.p_GB.x(), cart_x, 1e-9);
  EXPECT_NEAR(ball.v_GB.norm() + cart.v_GB.norm(), 0.0, 1e-9);
  EXPECT_EQ(contacts, 2u);
  std::cout << "NSC ball in the groove on a cart: rests " << ball.p_GB.y() - cart.p_GB.y()
            << " m above its bottom (error " << ball.p_GB.y() - cart.p_GB.y() - kRestHeight << "), "
            << ball.p_GB.x() - cart.p_GB.x() << " m off its axis; cart at " << cart.p_GB.x()
            << " m (closed form " << cart_x << ", error " << cart.p_GB.x() - cart_x << "); speeds "
            << ball.v_GB.norm() << ", " << cart.v_GB.norm() << " m/s\n";
}

TEST(CollisionMeshTest, BallDroppedIntoAGrooveOnACartSettlesOnItsHertzDentsWithSmc) {
  // As with NSC, under SMC (rk45): the ball rests on its Hertz dents (SmcRestHeight) over the
  // groove's bottom, and the cart at m 0.02 / (m + M) (momentum along x stays zero).
  const CollisionMaterial material;
  Scene scene = ParseText(CartModel(), ContactMethod::kSmc, material);
  RunSmc(scene, 3.0);
  const engine::BodyState& cart = scene.state.bodies[1];
  const engine::BodyState& ball = scene.state.bodies[2];
  const double closed = SmcRestHeight(material);
  const double cart_x = kM * kDropX / (kM + kCartMass);
  EXPECT_NEAR(ball.p_GB.y() - cart.p_GB.y(), closed, 1e-8);
  EXPECT_NEAR(ball.p_GB.x() - cart.p_GB.x(), 0.0, 1e-8);
  EXPECT_NEAR(cart.p_GB.x(), cart_x, 1e-8);
  EXPECT_LT(ball.v_GB.norm() + cart.v_GB.norm(), 1e-6);
  std::cout << "SMC ball in the groove on a cart: rests " << ball.p_GB.y() - cart.p_GB.y()
            << " m above its bottom (error " << ball.p_GB.y() - cart.p_GB.y() - closed << "), "
            << ball.p_GB.x() - cart.p_GB.x() << " m off its axis; cart at " << cart.p_GB.x()
            << " m (closed form " << cart_x << ", error " << cart.p_GB.x() - cart_x << "); speeds "
            << ball.v_GB.norm() << ", " << cart.v_GB.norm() << " m/s\n";
}

// A roof "roof" (kCartMass, the groove upside down: its ContactMesh turned +90 degrees about z,
// so that it opens towards -x) on a rail along x (coordinate "roof_x", from 0.3 m), gravity -x,
// above a ground ContactSphere "post" (radius kR) at the origin. Bodies: ground 0, roof 1.
std::string RoofModel() {
  std::ostringstream m;
  m.precision(17);
  m << R"(<OpenSimDocument Version="40000"><Model name="roof_on_post">
<gravity>)"
    << -kG << R"( 0 0</gravity><Ground name="ground"/><BodySet><objects>
<Body name="roof"><mass>)"
    << kCartMass << R"(</mass><inertia>1 1 1 0 0 0</inertia></Body>
</objects></BodySet><JointSet><objects><SliderJoint name="rail">
<socket_parent_frame>/ground</socket_parent_frame><socket_child_frame>/bodyset/roof</socket_child_frame>
<coordinates><Coordinate name="roof_x"><default_value>0.3</default_value></Coordinate></coordinates>
</SliderJoint></objects></JointSet><ContactGeometrySet><objects>
<ContactSphere name="post"><socket_frame>/ground</socket_frame><radius>)"
    << kR << R"(</radius>
</ContactSphere><ContactMesh name="groove"><socket_frame>/bodyset/roof</socket_frame>
<orientation>0 0 )"
    << std::numbers::pi / 2 << R"(</orientation><filename>v_groove.obj</filename>
</ContactMesh></objects></ContactGeometrySet></Model></OpenSimDocument>)";
  return m.str();
}

TEST(CollisionMeshTest, ConcaveRoofDroppedOnAPostRestsOnBothWalls) {
  // The 10 kg roof falls (along -x) onto the ground ball until both its inner walls rest on
  // it: its ridge r / cos(a) from the ball's centre under NSC, (r - d) / cos(a) under SMC with
  // the dents of the roof's weight (SmcRestHeight). Its hull would stop with its flat side on
  // the ball, the ridge r + 0.25 m from its centre.
  const CollisionMaterial material;
  for (const ContactMethod method : {ContactMethod::kNsc, ContactMethod::kSmc}) {
    Scene scene = ParseText(RoofModel(), method, material);
    ASSERT_EQ(scene.system->bodies()[1].name, "roof");
    const std::vector<Transform> X_GB_hull_rest = {
        Transform(), Transform::Translation(Vec3(kR + kHullTop, 0, 0))};
    double closed = kRestHeight;
    if (method == ContactMethod::kNsc) {
      EXPECT_EQ(RunNsc(scene, 1.0), 2u);
      // The hull at its own rest: touching (depth 0 to EPA's accuracy).
      const std::vector<CollisionContact> hull =
          ContactsAtPoses(WithGrooveHull(scene.model), X_GB_hull_rest);
      ASSERT_EQ(hull.size(), 1u);
      EXPECT_NEAR(hull[0].depth, 0.0, 1e-6);
    } else {
      // Free fall is a parabola, which rk45 integrates exactly, so its steps grow; unbounded,
      // the roof went through the post (a wall is a sheet: a step that carries the post's
      // centre past it pushes the post out the far side).
      RunSmc(scene, 3.0, 1e-3);
      closed = SmcRestHeight(material, kCartMass);
    }
    const engine::BodyState& roof = scene.state.bodies[1];
    EXPECT_NEAR(roof.p_GB.x(), closed, method == ContactMethod::kNsc ? 1e-9 : 1e-8);
    EXPECT_LT(roof.v_GB.norm(), method == ContactMethod::kNsc ? 1e-9 : 1e-6);
    std::cout << (method == ContactMethod::kNsc ? "NSC" : "SMC") << " roof on a post: ridge at "
              << roof.p_GB.x() << " m (closed form " << closed << ", error "
              << roof.p_GB.x() - closed << "; its hull's " << kR + kHullTop << "), speed "
              << roof.v_GB.norm() << " m/s\n";
  }
}

// A cube of half edge `h` centred at the origin, its 12 triangles counter-clockwise from
// outside; its corner (h, h, h) moved to (dent, dent, dent) (h: not moved).
ShapeMesh Cube(double h, double dent) {
  ShapeMesh cube;
  for (int i = 0; i < 8; ++i)
    cube.vertices.push_back(Vec3(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h));
  cube.vertices[7] = Vec3::Constant(dent);
  cube.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return cube;
}

TEST(CollisionMeshTest, MeshAgainstMeshIsAHullExactWhenClosedConvexElseReported) {
  // Closed convex: a cube; not: a cube with a corner pushed in, the open groove.
  EXPECT_TRUE(IsClosedConvex(Cube(0.1, 0.1)));
  EXPECT_FALSE(IsClosedConvex(Cube(0.1, 0.05)));
  const Scene scene = ParseText(CartModel(Groove("/ground", "floor")), ContactMethod::kNsc, {});
  const CollisionGeometry* floor = FindGeometry(scene, "floor");
  ASSERT_NE(floor, nullptr);
  EXPECT_TRUE(floor->fixed_to_ground);
  EXPECT_FALSE(IsClosedConvex(*floor->mesh));
  // Which one is the hull: the moving one, a closed convex one first, else the second.
  EXPECT_EQ(MeshPairHull({false, true}, {false, true}), -1);
  EXPECT_EQ(MeshPairHull({false, false}, {true, false}), 1);
  EXPECT_EQ(MeshPairHull({true, false}, {false, true}), 0);
  EXPECT_EQ(MeshPairHull({true, true}, {true, false}), 0);
  EXPECT_EQ(MeshPairHull({true, false}, {true, false}), 1);
  // The cart's groove against the ground's is its hull, and the Report says so; the pair is
  // tested (ball-groove, ball-floor, groove-floor).
  EXPECT_TRUE(Warned(scene, "groove", "convex hull"));
  EXPECT_TRUE(Warned(scene, "groove", "'floor'"));
  EXPECT_EQ(CollisionDetector(scene.model, std::nullopt).num_pairs(), 3);
  // A closed convex mesh (a cube of half edge h on the cart) in the ground's groove is exact:
  // its bottom edges sink e below the walls, which they enter by e cos(a) along the walls'
  // normals.
  CollisionModel model = scene.model;
  constexpr double kHalf = 0.1, kSink = 2e-3;
  for (CollisionGeometry& g : model.geometry) {
    if (g.name == "groove") g.mesh = std::make_shared<const ShapeMesh>(Cube(kHalf, kHalf));
  }
  const double y = kHalf / 2 + kHalf - kSink;  // the walls are h / 2 high at x = +-h
  const std::vector<CollisionContact> c = ContactsAtPoses(
      model,
      {Transform(), Transform::Translation(Vec3(0, y, 0)), Transform::Translation(Vec3(5, 5, 5))});
  ASSERT_GE(c.size(), 2u);
  bool left = false, right = false;
  for (const CollisionContact& k : c) {
    EXPECT_NEAR(k.depth, kSink * kCos, 1e-6);  // EPA's accuracy
    const double side = k.p_G.x() > 0 ? 1.0 : -1.0;
    (side > 0 ? right : left) = true;
    EXPECT_NEAR((k.n_G - Vec3(-side * kSin, kCos, 0)).norm(), 0.0, 1e-6);
    EXPECT_EQ(k.body1, 0);
    EXPECT_EQ(k.body2, 1);
  }
  EXPECT_TRUE(left && right);
  double worst = 0.0;
  for (const CollisionContact& k : c) worst = std::max(worst, std::abs(k.depth - kSink * kCos));
  std::cout << "cube in the V groove: " << c.size() << " contacts, depth error " << worst << " m\n";
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
