// What the reader makes of OpenSim's conventions, checked against values computed by hand:
// offset frames (nested, relative paths), 3.x offsets and `reverse`, CustomJoint defaults,
// coordinate order and motion types, markers, StationDefinedFrame, geometry, gravity.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/math/rotation.h>

#include <cmath>
#include <numbers>
#include <string>

namespace sinew {
namespace {

constexpr double kTol = 1e-14;
constexpr double kPi = std::numbers::pi;

std::string Doc(int version, const std::string& model_body) {
  return "<OpenSimDocument Version=\"" + std::to_string(version) + "\">\n<Model name=\"m\">\n" +
         model_body + "\n</Model>\n</OpenSimDocument>\n";
}

// Two nested offset frames on `upper`, addressed by relative paths from the joint:
// f1 = (translation 1 0 0, orientation 0 0 pi/2) on upper; f2 = (translation 0 1 0) on f1.
// By hand: p_B(f2) = Rz(pi/2) * (0 1 0) + (1 0 0) = (-1 0 0) + (1 0 0) = (0 0 0);
// R_B(f2) = Rz(pi/2).
const std::string kNested = Doc(40000, R"(
<Ground name="ground"/>
<BodySet name="bodyset"><objects>
  <Body name="upper"><mass>2</mass><mass_center>0 -0.5 0</mass_center>
    <inertia>1 2 3 0.1 0.2 0.3</inertia>
    <attached_geometry><Sphere name="ball"><socket_frame>..</socket_frame><radius>0.1</radius>
      <Appearance><opacity>0.5</opacity><color>1 0 0</color></Appearance></Sphere>
    </attached_geometry>
    <components>
      <PhysicalOffsetFrame name="f1"><socket_parent>..</socket_parent>
        <translation>1 0 0</translation><orientation>0 0 1.5707963267948966</orientation>
      </PhysicalOffsetFrame>
    </components>
  </Body>
  <Body name="lower"><mass>1</mass></Body>
</objects></BodySet>
<JointSet name="jointset"><objects>
  <WeldJoint name="w">
    <socket_parent_frame>/ground</socket_parent_frame>
    <socket_child_frame>../../bodyset/upper</socket_child_frame>
  </WeldJoint>
  <PinJoint name="pin">
    <socket_parent_frame>f2</socket_parent_frame>
    <socket_child_frame>/bodyset/lower</socket_child_frame>
    <coordinates><Coordinate name="q"><default_value>0.25</default_value>
      <default_speed_value>-1</default_speed_value><range>-1 2</range><locked>true</locked>
    </Coordinate></coordinates>
    <frames>
      <PhysicalOffsetFrame name="f2"><socket_parent>/bodyset/upper/f1</socket_parent>
        <translation>0 1 0</translation>
      </PhysicalOffsetFrame>
    </frames>
  </PinJoint>
</objects></JointSet>
<MarkerSet><objects>
  <Marker name="m1"><socket_parent_frame>/jointset/pin/f2</socket_parent_frame>
    <location>1 0 0</location></Marker>
</objects></MarkerSet>)");

TEST(OsimSemantics, NestedOffsetFramesAndRelativePaths) {
  const model::ModelSpec spec = io::ReadOsimString(kNested, "nested.osim");
  EXPECT_EQ(spec.version, 40000);
  EXPECT_TRUE(spec.gravity.isApprox(Vec3(0, -9.80665, 0)));  // OpenSim's default
  const model::JointSpec& pin = spec.joints[spec.FindJoint("pin")];
  EXPECT_EQ(pin.parent_body, spec.FindBody("upper"));
  EXPECT_EQ(pin.child_body, spec.FindBody("lower"));
  EXPECT_EQ(pin.parent_frame, "/jointset/pin/f2");
  EXPECT_EQ(pin.child_frame, "/bodyset/lower");
  EXPECT_NEAR((pin.X_PF.p - Vec3(0, 0, 0)).norm(), 0, kTol);
  const Mat3 Rz = RotationAboutAxis(Vec3::UnitZ(), kPi / 2);
  EXPECT_NEAR((pin.X_PF.R - Rz).norm(), 0, kTol);
  EXPECT_TRUE(pin.X_BM.isApprox(Transform::Identity()));
  // Both offset frames are listed with their parents and poses in the body.
  ASSERT_EQ(spec.frames.size(), 2u);
  for (const model::FrameSpec& f : spec.frames) {
    EXPECT_EQ(f.body, spec.FindBody("upper"));
    if (f.name == "f1") {
      EXPECT_EQ(f.path, "/bodyset/upper/f1");
      EXPECT_EQ(f.parent, "/bodyset/upper");
      EXPECT_NEAR((f.X_BF.p - Vec3(1, 0, 0)).norm(), 0, kTol);
    } else {
      EXPECT_EQ(f.path, "/jointset/pin/f2");
      EXPECT_EQ(f.parent, "/bodyset/upper/f1");
      EXPECT_NEAR((f.X_PF.p - Vec3(0, 1, 0)).norm(), 0, kTol);
    }
  }
  // Marker at (1 0 0) in f2: p_B = Rz(pi/2) * (1 0 0) + 0 = (0 1 0).
  ASSERT_EQ(spec.markers.size(), 1u);
  EXPECT_EQ(spec.markers[0].body, spec.FindBody("upper"));
  EXPECT_NEAR((spec.markers[0].location - Vec3(0, 1, 0)).norm(), 0, kTol);
  // Body mass properties: inertia [Ixx Iyy Izz Ixy Ixz Iyz] into a symmetric matrix.
  const model::BodySpec& upper = spec.bodies[spec.FindBody("upper")];
  EXPECT_EQ(upper.mass, 2.0);
  EXPECT_EQ(upper.inertia(0, 1), 0.1);
  EXPECT_EQ(upper.inertia(2, 0), 0.2);
  EXPECT_EQ(upper.inertia(1, 2), 0.3);
  EXPECT_EQ(upper.inertia(2, 2), 3.0);
  ASSERT_EQ(upper.geometry.size(), 1u);
  EXPECT_EQ(upper.geometry[0].type, "Sphere");
  EXPECT_EQ(upper.geometry[0].opacity, 0.5);
  EXPECT_EQ(upper.geometry[0].dimensions.at("radius")[0], 0.1);
  // Coordinate properties.
  const model::CoordinateSpec& q = spec.coordinates[spec.FindCoordinate("q")];
  EXPECT_EQ(q.path, "/jointset/pin/q");
  EXPECT_EQ(q.default_value, 0.25);
  EXPECT_EQ(q.default_speed_value, -1.0);
  EXPECT_EQ(q.range_min, -1.0);
  EXPECT_EQ(q.range_max, 2.0);
  EXPECT_TRUE(q.locked);
  EXPECT_EQ(q.motion_type, model::MotionType::kRotational);
}

// A 3.x file: offsets become frames named <body>_offset under the joint.
TEST(OsimSemantics, ThreeXOffsetsBecomeFrames) {
  const std::string text = Doc(30000, R"(<gravity>0 -9.81 0</gravity>
<BodySet><objects>
<Body name="ground"><Joint/></Body>
<Body name="rod"><mass>1</mass><inertia_xx>0.5</inertia_xx><inertia_xy>0.1</inertia_xy>
<Joint><SliderJoint name="slide"><parent_body>ground</parent_body>
<location_in_parent>1 2 3</location_in_parent><orientation_in_parent>0 0 0</orientation_in_parent>
<location>0 0.5 0</location><orientation>0.1 0.2 0.3</orientation>
<CoordinateSet><objects><Coordinate name="x"/></objects></CoordinateSet>
</SliderJoint></Joint></Body>
</objects></BodySet>)");
  const model::ModelSpec spec = io::ReadOsimString(text, "old.osim");
  EXPECT_TRUE(spec.gravity.isApprox(Vec3(0, -9.81, 0)));
  const model::JointSpec& j = spec.joints[0];
  EXPECT_EQ(j.parent_frame, "/jointset/slide/ground_offset");
  EXPECT_EQ(j.child_frame, "/jointset/slide/rod_offset");
  EXPECT_NEAR((j.X_PF.p - Vec3(1, 2, 3)).norm(), 0, kTol);
  EXPECT_NEAR((j.X_BM.p - Vec3(0, 0.5, 0)).norm(), 0, kTol);
  EXPECT_NEAR((j.X_BM.R - RotationFromBodyFixedXYZ(Vec3(0.1, 0.2, 0.3))).norm(), 0, kTol);
  EXPECT_EQ(spec.coordinates[0].motion_type, model::MotionType::kTranslational);
  EXPECT_EQ(spec.bodies[1].inertia(0, 0), 0.5);
  EXPECT_EQ(spec.bodies[1].inertia(1, 0), 0.1);
  EXPECT_EQ(spec.frames.size(), 2u);
}

// 3.x reverse=true: OpenSim's 30514 upgrade swaps the parent and child frames.
TEST(OsimSemantics, ReverseSwapsParentAndChild) {
  const model::ModelSpec spec = io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) +
                                             "/opensim-org/opensim-core/OpenSim/Simulation/"
                                             "SimbodyEngine/Test/double_pendulum_testReverse.osim");
  const model::JointSpec& pin1 = spec.joints[spec.FindJoint("pin1")];
  const model::JointSpec& pin2 = spec.joints[spec.FindJoint("pin2")];
  EXPECT_FALSE(pin1.reverse);
  EXPECT_TRUE(pin2.reverse);
  EXPECT_EQ(spec.bodies[pin2.parent_body].name, "rod2");
  EXPECT_EQ(spec.bodies[pin2.child_body].name, "rod1");
  EXPECT_EQ(pin2.parent_frame, "/jointset/pin2/rod2_offset");
  EXPECT_NEAR((pin2.X_PF.p - Vec3(0, 0.5, 0)).norm(), 0, kTol);  // `location` on rod2
  EXPECT_NEAR(pin2.X_BM.p.norm(), 0, kTol);                      // `location_in_parent`
}

// CustomJoint: missing functions take OpenSim's defaults, coordinates are ordered by first
// appearance across the axes, motion types follow the LinearFunction slope +-1 rule.
TEST(OsimSemantics, CustomJointDefaultsOrderAndMotionTypes) {
  const std::string text = Doc(40000, R"(<Ground name="ground"/>
<BodySet><objects><Body name="b"><mass>1</mass></Body></objects></BodySet>
<JointSet><objects><CustomJoint name="c">
<socket_parent_frame>/ground</socket_parent_frame><socket_child_frame>/bodyset/b</socket_child_frame>
<coordinates><Coordinate name="a"/><Coordinate name="t"/><Coordinate name="k"/><Coordinate name="s"/></coordinates>
<SpatialTransform>
 <TransformAxis name="rotation1"><coordinates>k</coordinates><axis>0 0 1</axis></TransformAxis>
 <TransformAxis name="rotation2"><coordinates>a</coordinates><axis>1 0 0</axis>
   <LinearFunction name="function"><coefficients>-1 0</coefficients></LinearFunction></TransformAxis>
 <TransformAxis name="rotation3"><coordinates></coordinates><axis>0 1 0</axis></TransformAxis>
 <TransformAxis name="translation1"><coordinates>k</coordinates><axis>1 0 0</axis>
   <SimmSpline name="function"><x>0 1 2</x><y>0 0.1 0.4</y></SimmSpline></TransformAxis>
 <TransformAxis name="translation2"><coordinates>t</coordinates><axis>0 1 0</axis></TransformAxis>
 <TransformAxis name="translation3"><coordinates>s</coordinates><axis>0 0 1</axis>
   <function><LinearFunction><coefficients>2 0</coefficients></LinearFunction></function></TransformAxis>
</SpatialTransform></CustomJoint></objects></JointSet>)");
  const model::ModelSpec spec = io::ReadOsimString(text, "custom.osim");
  const model::JointSpec& j = spec.joints[0];
  ASSERT_EQ(j.spatial_transform.size(), 6u);
  auto name = [&](int i) { return spec.coordinates[j.coordinates[i]].name; };
  ASSERT_EQ(j.coordinates.size(), 4u);
  EXPECT_EQ(name(0), "k");
  EXPECT_EQ(name(1), "a");
  EXPECT_EQ(name(2), "t");
  EXPECT_EQ(name(3), "s");
  // rotation1: one coordinate, no function -> identity LinearFunction.
  EXPECT_EQ(j.spatial_transform[0].function->TypeName(), "LinearFunction");
  EXPECT_EQ(j.spatial_transform[0].function->Calc(0.7), 0.7);
  // rotation3: no coordinate -> Constant 0.
  EXPECT_EQ(j.spatial_transform[2].function->TypeName(), "Constant");
  EXPECT_EQ(j.spatial_transform[2].function->Calc(3.0), 0.0);
  EXPECT_EQ(j.spatial_transform[3].function->TypeName(), "SimmSpline");
  EXPECT_EQ(j.spatial_transform[5].function->Calc(1.5), 3.0);  // wrapped 3.x form
  auto motion = [&](const char* n) { return spec.coordinates[spec.FindCoordinate(n)].motion_type; };
  EXPECT_EQ(motion("k"), model::MotionType::kRotational);     // rotation1, slope 1 (and a spline)
  EXPECT_EQ(motion("a"), model::MotionType::kRotational);     // slope -1
  EXPECT_EQ(motion("t"), model::MotionType::kTranslational);  // translation2, slope 1
  EXPECT_EQ(motion("s"), model::MotionType::kCoupled);        // slope 2
}

// StationDefinedFrame (4.5+): a = (0 0 0), b = (0 0 2), c = (1 0 0), origin (0 0 1), on body b,
// ab_axis z, ab_x_ac_axis x. By hand: z = (b - a)/|b - a| = (0 0 1); x = (b-a)x(c-a) normalized
// = (0 2 0)/2 = (0 1 0); y = z x x = (-1 0 0).
TEST(OsimSemantics, StationDefinedFrame) {
  const std::string text = Doc(40600, R"(<Ground name="ground"/>
<components>
 <Station name="a"><socket_parent_frame>/bodyset/b</socket_parent_frame><location>0 0 0</location></Station>
 <Station name="b"><socket_parent_frame>/bodyset/b</socket_parent_frame><location>0 0 2</location></Station>
 <Station name="c"><socket_parent_frame>/bodyset/b</socket_parent_frame><location>1 0 0</location></Station>
 <Station name="o"><socket_parent_frame>/bodyset/b</socket_parent_frame><location>0 0 1</location></Station>
 <StationDefinedFrame name="sdf"><socket_point_a>/a</socket_point_a><socket_point_b>/b</socket_point_b>
   <socket_point_c>/c</socket_point_c><socket_origin_point>/o</socket_origin_point>
   <ab_axis>z</ab_axis><ab_x_ac_axis>x</ab_x_ac_axis></StationDefinedFrame>
</components>
<BodySet><objects><Body name="b"><mass>1</mass></Body></objects></BodySet>
<JointSet><objects><FreeJoint name="free">
<socket_parent_frame>/ground</socket_parent_frame><socket_child_frame>/sdf</socket_child_frame>
</FreeJoint></objects></JointSet>)");
  const model::ModelSpec spec = io::ReadOsimString(text, "sdf.osim");
  const model::JointSpec& j = spec.joints[0];
  EXPECT_EQ(j.child_body, spec.FindBody("b"));
  Mat3 R;
  R.col(0) = Vec3(0, 1, 0);
  R.col(1) = Vec3(-1, 0, 0);
  R.col(2) = Vec3(0, 0, 1);
  EXPECT_NEAR((j.X_BM.R - R).norm(), 0, kTol);
  EXPECT_NEAR((j.X_BM.p - Vec3(0, 0, 1)).norm(), 0, kTol);
  // FreeJoint without coordinates: OpenSim makes six, rotations then translations.
  ASSERT_EQ(j.coordinates.size(), 6u);
  EXPECT_EQ(spec.coordinates[j.coordinates[2]].motion_type, model::MotionType::kRotational);
  EXPECT_EQ(spec.coordinates[j.coordinates[3]].motion_type, model::MotionType::kTranslational);
}

// Real files: arm26 (4.x) markers, wrap objects, path points; Rajagopal2016 joint frames.
TEST(OsimSemantics, Arm26PathsWrapsAndMarkers) {
  const model::ModelSpec spec = io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) +
                                             "/opensim-org/opensim-models/Models/Arm26/arm26.osim");
  const model::ForceSpec& tri = spec.forces[0];
  EXPECT_EQ(tri.type, "Thelen2003Muscle");
  ASSERT_TRUE(tri.geometry_path.has_value());
  EXPECT_GE(tri.geometry_path->points.size(), 2u);
  EXPECT_FALSE(tri.geometry_path->wraps.empty());
  ASSERT_NE(tri.element.Child("max_isometric_force"), nullptr);
  EXPECT_EQ(tri.element.Child("max_isometric_force")->text, "798.51999999999998");
  int wraps = 0;
  for (const model::BodySpec& b : spec.bodies) wraps += static_cast<int>(b.wrap_objects.size());
  EXPECT_GT(wraps, 0);
  EXPECT_EQ(spec.markers[0].name, "r_acromion");
}

TEST(OsimSemantics, MovingAndConditionalPathPoints) {
  const model::ModelSpec spec = io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) +
                                             "/opensim-org/opensim-core/OpenSim/Simulation/Test/"
                                             "testSimulationUtilities_leg6dof9musc_20303.osim");
  int moving = 0, conditional = 0;
  for (const model::ForceSpec& f : spec.forces) {
    if (!f.geometry_path) continue;
    for (const model::PathPointSpec& p : f.geometry_path->points) {
      if (p.type == "MovingPathPoint") {
        ++moving;
        for (int i = 0; i < 3; ++i) EXPECT_NE(p.location_functions[i], nullptr);
      }
      if (p.type == "ConditionalPathPoint") {
        ++conditional;
        EXPECT_NE(p.coordinate, model::kNone);
        EXPECT_LT(p.range_min, p.range_max);
      }
    }
  }
  EXPECT_GT(moving, 0);
  EXPECT_GT(conditional, 0);
  EXPECT_EQ(spec.constraints[0].type, "CoordinateCouplerConstraint");
}

// 3.x contact geometry (body_name, location, orientation) and a 1.9 wrap object on ground, with
// the values copied from the files.
TEST(OsimSemantics, ContactGeometryAndWrapObjects) {
  const std::string dir = std::string(SINEW_TEST_DATA_DIR) + "/opensim-org/opensim-core/";
  const model::ModelSpec ball =
      io::ReadOsim(dir + "OpenSim/Simulation/Test/BouncingBall_HuntCrossley.osim");
  ASSERT_EQ(ball.contact_geometry.size(), 2u);
  const model::ContactGeometrySpec& floor = ball.contact_geometry[0];
  EXPECT_EQ(floor.type, "ContactHalfSpace");
  EXPECT_EQ(floor.body, model::kGroundIndex);
  // orientation 0 0 -1.57079633: body-fixed XYZ angles, here one rotation about z.
  EXPECT_NEAR((floor.X_BC.R - RotationAboutAxis(Vec3::UnitZ(), -1.57079633)).norm(), 0, kTol);
  const model::ContactGeometrySpec& sphere = ball.contact_geometry[1];
  EXPECT_EQ(sphere.body, ball.FindBody("ball"));
  EXPECT_EQ(sphere.dimensions.at("radius")[0], 0.5);

  const model::ModelSpec arm = io::ReadOsim(dir + "OpenSim/Simulation/Test/arm26.osim");
  const auto& wraps = arm.bodies[model::kGroundIndex].wrap_objects;
  ASSERT_EQ(wraps.size(), 1u);
  EXPECT_EQ(wraps[0].name, "TRIlongglen");
  EXPECT_EQ(wraps[0].type, "WrapCylinder");
  EXPECT_EQ(wraps[0].quadrant, "x");
  EXPECT_NEAR((wraps[0].X_BW.p - Vec3(-0.043905, -0.0039, 0.1478)).norm(), 0, kTol);
  EXPECT_NEAR(
      (wraps[0].X_BW.R - RotationFromBodyFixedXYZ(Vec3(1.37531945, -0.29461158, 2.43595604)))
          .norm(),
      0, kTol);
  EXPECT_EQ(wraps[0].dimensions.at("radius")[0], 0.003);
  EXPECT_EQ(wraps[0].dimensions.at("length")[0], 0.03);
  // 1.9 VisibleObject geometry_files on ground: six meshes.
  EXPECT_EQ(arm.bodies[model::kGroundIndex].geometry.size(), 6u);
  EXPECT_EQ(arm.bodies[model::kGroundIndex].geometry[0].mesh_file, "ground_ribs.vtp");
}

// 3.05 DisplayGeometry: transform (rotations then translation) and scale factors.
TEST(OsimSemantics, DisplayGeometry) {
  const model::ModelSpec spec = io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) +
                                             "/opensim-org/opensim-core/OpenSim/Simulation/Test/"
                                             "double_pendulum.osim");
  const model::BodySpec& rod1 = spec.bodies[spec.FindBody("rod1")];
  ASSERT_EQ(rod1.geometry.size(), 2u);
  EXPECT_EQ(rod1.geometry[0].mesh_file, "cylinder.vtp");
  EXPECT_NEAR((rod1.geometry[0].X_BG.p - Vec3(0, 0.25, 0)).norm(), 0, kTol);
  EXPECT_NEAR((rod1.geometry[0].scale_factors - Vec3(0.02, 0.5, 0.02)).norm(), 0, kTol);
  EXPECT_EQ(rod1.geometry[1].mesh_file, "sphere.vtp");
  // 3.05 connectors: pin2 connects rod1 to rod2 with location_in_child 0 0.5 0.
  const model::JointSpec& pin2 = spec.joints[spec.FindJoint("pin2")];
  EXPECT_EQ(spec.bodies[pin2.parent_body].name, "rod1");
  EXPECT_EQ(spec.bodies[pin2.child_body].name, "rod2");
  EXPECT_NEAR((pin2.X_BM.p - Vec3(0, 0.5, 0)).norm(), 0, kTol);
}

// Controllers keep their actuator list and settings.
TEST(OsimSemantics, Controllers) {
  const std::string text = Doc(40000, R"(<Ground name="ground"/>
<BodySet><objects><Body name="b"><mass>1</mass></Body></objects></BodySet>
<JointSet><objects><SliderJoint name="s"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/b</socket_child_frame><coordinates><Coordinate name="x"/></coordinates>
</SliderJoint></objects></JointSet>
<ForceSet><objects><CoordinateActuator name="act"><coordinate>x</coordinate></CoordinateActuator>
</objects></ForceSet>
<ControllerSet><objects><PrescribedController name="ctl">
<socket_actuators>/forceset/act</socket_actuators>
<FunctionSet name="ControlFunctions"><objects><Constant name="f"><value>2</value></Constant>
</objects></FunctionSet></PrescribedController></objects></ControllerSet>)");
  const model::ModelSpec spec = io::ReadOsimString(text, "ctl.osim");
  ASSERT_EQ(spec.controllers.size(), 1u);
  EXPECT_EQ(spec.controllers[0].type, "PrescribedController");
  ASSERT_EQ(spec.controllers[0].actuators.size(), 1u);
  EXPECT_EQ(spec.controllers[0].actuators[0], "/forceset/act");
  EXPECT_NE(spec.controllers[0].element.Child("FunctionSet"), nullptr);
  // A CoordinateActuator naming a coordinate that does not exist is an error.
  std::string bad = text;
  bad.replace(bad.find("<coordinate>x<"), 14, "<coordinate>y<");
  EXPECT_THROW(io::ReadOsimString(bad, "ctl.osim"), Error);
}

// Joint-specific numbers are kept as parameters (chrono's 3.0 ScapulothoracicJoint model).
TEST(OsimSemantics, ScapulothoracicParameters) {
  const model::ModelSpec spec = io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) +
                                             "/projectchrono/chrono/data/opensim/"
                                             "ScapulothorachicJoint_Shoulder.osim");
  const model::JointSpec& j = spec.joints[spec.FindJoint("scapulothoracic")];
  EXPECT_EQ(j.kind, model::JointType::kScapulothoracic);
  EXPECT_EQ(j.parameters.at("thoracic_ellipsoid_radii_x_y_z"),
            (std::vector<double>{0.07, 0.15, 0.07}));
  EXPECT_EQ(j.parameters.at("scapula_winging_axis_origin"), (std::vector<double>{0, 0}));
  EXPECT_EQ(j.parameters.at("scapula_winging_axis_direction"), (std::vector<double>{0}));
  EXPECT_EQ(j.parameters.count("location_in_parent"), 0u);  // offsets are frames, not parameters
  EXPECT_NEAR((j.X_PF.p - Vec3(-0.02, -0.0173, 0.07)).norm(), 0, kTol);
  EXPECT_EQ(j.coordinates.size(), 4u);
}

// A prescribed coordinate keeps its function of time; without <prescribed> it is not prescribed
// (the property's default), even with a function.
TEST(OsimSemantics, PrescribedCoordinates) {
  const std::string joint = R"(<Ground name="ground"/>
<BodySet><objects><Body name="b"><mass>1</mass></Body></objects></BodySet>
<JointSet><objects><SliderJoint name="s"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/b</socket_child_frame><coordinates><Coordinate name="x">
<prescribed_function><LinearFunction><coefficients>0.5 0.1</coefficients></LinearFunction>
</prescribed_function>PRESCRIBED</Coordinate></coordinates></SliderJoint></objects></JointSet>)";
  auto read = [&](const std::string& prescribed) {
    std::string body = joint;
    body.replace(body.find("PRESCRIBED"), 10, prescribed);
    return io::ReadOsimString(Doc(40000, body), "prescribed.osim");
  };
  const model::ModelSpec on = read("<prescribed>true</prescribed>");
  EXPECT_TRUE(on.coordinates[0].prescribed);
  ASSERT_NE(on.coordinates[0].prescribed_function, nullptr);
  EXPECT_DOUBLE_EQ(on.coordinates[0].prescribed_function->Calc(2.0), 1.1);
  EXPECT_FALSE(read("<prescribed>false</prescribed>").coordinates[0].prescribed);
  EXPECT_FALSE(read("").coordinates[0].prescribed);
  EXPECT_NE(read("").coordinates[0].prescribed_function, nullptr);
}

// chrono's newton_cradle names five joints `sph1` (and their coordinates q1..q3 each): it loads,
// with warnings, and paths stay unique.
TEST(OsimSemantics, DuplicateJointNamesLoadWithWarnings) {
  const model::ModelSpec spec = io::ReadOsim(
      std::string(SINEW_TEST_DATA_DIR) + "/projectchrono/chrono/data/opensim/newton_cradle.osim");
  ASSERT_EQ(spec.joints.size(), 5u);
  EXPECT_EQ(spec.joints[0].path, "/jointset/sph1");
  EXPECT_EQ(spec.joints[4].path, "/jointset/sph1_5");
  EXPECT_EQ(spec.coordinates[14].path, "/jointset/sph1_5/q3");
  int duplicate_joints = 0, duplicate_coordinates = 0;
  for (const Diagnostic& d : spec.warnings) {
    duplicate_joints += d.message.find("duplicate joint name 'sph1'") != std::string::npos;
    duplicate_coordinates +=
        d.message.find("3 coordinate names are used more than once") != std::string::npos;
  }
  EXPECT_EQ(duplicate_joints, 4);
  EXPECT_EQ(duplicate_coordinates, 1);
}

TEST(OsimSemantics, ZeroMassModelIsNoted) {
  const std::string text = Doc(40000, R"(<Ground name="ground"/>
<BodySet><objects><Body name="b"><mass>0</mass></Body></objects></BodySet>
<JointSet><objects><WeldJoint name="w"><socket_parent_frame>/ground</socket_parent_frame>
<socket_child_frame>/bodyset/b</socket_child_frame></WeldJoint></objects></JointSet>)");
  const model::ModelSpec spec = io::ReadOsimString(text, "massless.osim");
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_NE(spec.warnings[0].message.find("every body has zero mass"), std::string::npos);
}

}  // namespace
}  // namespace sinew
