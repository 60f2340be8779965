// Malformed input gives a sinew::Error naming the file, the line and the component; never a
// crash, a hang or a silent misread.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>

#include <array>
#include <string>

namespace sinew {
namespace {

// A small 4.x model: ground -> (pin) -> upper -> (pin) -> lower. `joints` replaces the JointSet
// body and `extra_bodies` is appended to the BodySet.
std::string Model40(const std::string& joints, const std::string& extra_bodies = "",
                    const std::string& upper_mass = "1.5") {
  return R"(<?xml version="1.0" encoding="UTF-8" ?>
<OpenSimDocument Version="40000">
  <Model name="m">
    <Ground name="ground"/>
    <BodySet name="bodyset">
      <objects>
        <Body name="upper">
          <mass>)" +
         upper_mass + R"(</mass>
          <mass_center>0 -0.5 0</mass_center>
          <inertia>0.1 0.1 0.1 0 0 0</inertia>
        </Body>
        <Body name="lower">
          <mass>1</mass>
          <mass_center>0 -0.5 0</mass_center>
          <inertia>0.1 0.1 0.1 0 0 0</inertia>
        </Body>)" +
         extra_bodies + R"(
      </objects>
    </BodySet>
    <JointSet name="jointset">
      <objects>)" +
         joints + R"(
      </objects>
    </JointSet>
  </Model>
</OpenSimDocument>
)";
}

std::string Pin(const std::string& name, const std::string& parent, const std::string& child,
                const std::string& coordinate) {
  return R"(
        <PinJoint name=")" +
         name + R"(">
          <socket_parent_frame>)" +
         parent + R"(</socket_parent_frame>
          <socket_child_frame>)" +
         child + R"(</socket_child_frame>
          <coordinates><Coordinate name=")" +
         coordinate + R"("/></coordinates>
        </PinJoint>)";
}

const std::string kGoodJoints = Pin("j1", "/ground", "/bodyset/upper", "q1") +
                                Pin("j2", "/bodyset/upper", "/bodyset/lower", "q2");

// Reads `text` expecting an Error; checks file and line, returns it for further checks.
Error ExpectError(const std::string& text, int line, const std::string& component,
                  const std::string& fragment) {
  try {
    io::ReadOsimString(text, "bad.osim");
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "bad.osim") << e.what();
    if (line > 0) {
      EXPECT_EQ(e.where().line, line) << e.what();
    }
    EXPECT_EQ(e.component(), component) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    return e;
  }
  ADD_FAILURE() << "no error for input expected to fail with '" << fragment << "'";
  return Error("none");
}

int LineOf(const std::string& text, const std::string& needle) {
  const size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  int line = 1;
  for (size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return line;
}

TEST(OsimErrors, GoodModelLoads) {
  const model::ModelSpec spec = io::ReadOsimString(Model40(kGoodJoints), "good.osim");
  ASSERT_EQ(spec.bodies.size(), 3u);
  ASSERT_EQ(spec.joints.size(), 2u);
  EXPECT_EQ(spec.joints[1].parent_body, 1);
  EXPECT_EQ(spec.joints[1].child_body, 2);
}

TEST(OsimErrors, TruncatedFile) {
  const std::string text = Model40(kGoodJoints);
  const std::string truncated = text.substr(0, text.find("<JointSet"));
  const Error e = ExpectError(truncated, 0, "", "not a well-formed XML document");
  EXPECT_GT(e.where().line, 1);
}

TEST(OsimErrors, NotXml) {
  ExpectError("this is not a model", 1, "", "not a well-formed XML document");
  ExpectError("", 1, "", "");
  ExpectError("<html><body/></html>", 1, "", "not an OpenSim model");
}

TEST(OsimErrors, UnknownParentBody3x) {
  const std::string text = R"(<OpenSimDocument Version="30000"><Model name="m"><BodySet><objects>
<Body name="ground"/>
<Body name="arm"><mass>1</mass><Joint><PinJoint name="shoulder">
<parent_body>torso</parent_body>
<CoordinateSet><objects><Coordinate name="q"/></objects></CoordinateSet>
</PinJoint></Joint></Body>
</objects></BodySet></Model></OpenSimDocument>)";
  ExpectError(text, 4, "/jointset/shoulder", "parent_body 'torso' does not exist");
}

TEST(OsimErrors, DanglingSocketPath) {
  const std::string joints = Pin("j1", "/ground", "/bodyset/upper", "q1") +
                             Pin("knee_r", "/bodyset/femur", "/bodyset/lower", "q2");
  const std::string text = Model40(joints);
  ExpectError(text, LineOf(text, "/bodyset/femur"), "/jointset/knee_r",
              "<socket_parent_frame> '/bodyset/femur' does not exist");
  // Relative paths resolve from the joint: '../upper' is /jointset/upper, which does not exist.
  const std::string relative = Model40(Pin("j1", "/ground", "/bodyset/upper", "q1") +
                                       Pin("j2", "../upper", "/bodyset/lower", "q2"));
  ExpectError(relative, LineOf(relative, "../upper"), "/jointset/j2", "'/jointset/upper'");
}

TEST(OsimErrors, DuplicateBodyNames) {
  const std::string text = Model40(kGoodJoints, R"(
        <Body name="upper"><mass>1</mass></Body>)");
  ExpectError(text, LineOf(text, "<Body name=\"upper\"><mass>"), "/bodyset/upper",
              "duplicate body name 'upper'");
}

TEST(OsimErrors, AmbiguousCoordinateReferenceWarnsAndTakesTheFirst) {
  // Two coordinates named q: a path point conditioned on "q" gets the first, with a warning (as
  // OpenSim 3's name lookup does; chrono's newton_cradle.osim needs it).
  std::string text = Model40(Pin("j1", "/ground", "/bodyset/upper", "q") +
                             Pin("j2", "/bodyset/upper", "/bodyset/lower", "q"));
  const std::string forces = R"(<ForceSet><objects><PathSpring name="s"><GeometryPath>
<PathPointSet><objects>
<ConditionalPathPoint name="p"><socket_parent_frame>/ground</socket_parent_frame>
<socket_coordinate>q</socket_coordinate><range>0 1</range></ConditionalPathPoint>
</objects></PathPointSet></GeometryPath></PathSpring></objects></ForceSet>)";
  text.insert(text.find("  </Model>"), forces);
  const model::ModelSpec spec = io::ReadOsimString(text, "ambiguous.osim");
  EXPECT_EQ(spec.forces[0].geometry_path->points[0].coordinate, 0);
  bool warned = false;
  for (const Diagnostic& d : spec.warnings) {
    warned = warned || (d.component == "/forceset/s/geometrypath/p" &&
                        d.where.line == LineOf(text, "<socket_coordinate>") &&
                        d.message.find("'q' is ambiguous") != std::string::npos);
  }
  EXPECT_TRUE(warned);
  // A name that matches nothing is an error.
  const size_t at = text.find("<socket_coordinate>q<");
  text.replace(at, 21, "<socket_coordinate>z<");
  ExpectError(text, LineOf(text, "<socket_coordinate>"), "/forceset/s/geometrypath/p",
              "<socket_coordinate> 'z' does not exist");
}

TEST(OsimErrors, CycleOfJoints) {
  // upper and lower hang from each other and never from ground.
  const std::string text = Model40(Pin("a", "/bodyset/lower", "/bodyset/upper", "q1") +
                                   Pin("b", "/bodyset/upper", "/bodyset/lower", "q2"));
  // The error points at the first joint of the cycle, where it is in the file.
  ExpectError(text, LineOf(text, "<PinJoint name=\"a\">"), "/jointset/a",
              "joints form a cycle that never reaches ground");
}

TEST(OsimErrors, OffsetFramesInACycle) {
  const std::string joints = R"(
        <WeldJoint name="w">
          <socket_parent_frame>f1</socket_parent_frame>
          <socket_child_frame>/bodyset/upper</socket_child_frame>
          <frames>
            <PhysicalOffsetFrame name="f1"><socket_parent>f2</socket_parent></PhysicalOffsetFrame>
            <PhysicalOffsetFrame name="f2"><socket_parent>f1</socket_parent></PhysicalOffsetFrame>
          </frames>
        </WeldJoint>)";
  const std::string text = Model40(joints);
  ExpectError(text, LineOf(text, "<PhysicalOffsetFrame name=\"f1\">"), "/jointset/w/f1", "cycle");
}

TEST(OsimErrors, NonNumericValue) {
  const std::string text = Model40(kGoodJoints, "", "heavy");
  ExpectError(text, LineOf(text, "heavy"), "/bodyset/upper", "expects numbers, found 'heavy'");
}

TEST(OsimErrors, VectorOfWrongLength) {
  std::string text = Model40(kGoodJoints);
  const std::string from = "<mass_center>0 -0.5 0</mass_center>";
  text.replace(text.find(from), from.size(), "<mass_center>0 -0.5</mass_center>");
  ExpectError(text, LineOf(text, "<mass_center>0 -0.5<"), "/bodyset/upper",
              "<mass_center> expects 3 numbers, found 2");
}

TEST(OsimErrors, BodyLeftUnconnected) {
  const std::string text = Model40(kGoodJoints, R"(
        <Body name="loose"><mass>1</mass></Body>)");
  ExpectError(text, LineOf(text, "loose"), "/bodyset/loose",
              "body 'loose' is not connected to ground");
}

TEST(OsimErrors, JointWithWrongCoordinateCount) {
  const std::string joints = Pin("j1", "/ground", "/bodyset/upper", "q1") + R"(
        <PinJoint name="j2">
          <socket_parent_frame>/bodyset/upper</socket_parent_frame>
          <socket_child_frame>/bodyset/lower</socket_child_frame>
          <coordinates><Coordinate name="a"/><Coordinate name="b"/></coordinates>
        </PinJoint>)";
  const std::string text = Model40(joints);
  ExpectError(text, LineOf(text, "<PinJoint name=\"j2\">"), "/jointset/j2",
              "PinJoint needs 1 coordinate, found 2");
}

TEST(OsimErrors, CustomJointAxisNamesUnknownCoordinate) {
  const std::string joints = Pin("j1", "/ground", "/bodyset/upper", "q1") + R"(
        <CustomJoint name="c">
          <socket_parent_frame>/bodyset/upper</socket_parent_frame>
          <socket_child_frame>/bodyset/lower</socket_child_frame>
          <coordinates><Coordinate name="a"/></coordinates>
          <SpatialTransform>
            <TransformAxis name="rotation1"><coordinates>zz</coordinates><axis>0 0 1</axis></TransformAxis>
          </SpatialTransform>
        </CustomJoint>)";
  const std::string text = Model40(joints);
  ExpectError(text, LineOf(text, "<coordinates>zz"), "/jointset/c/rotation1",
              "coordinate 'zz' is not one of the joint's coordinates");
}

TEST(OsimErrors, BadVersionAndMissingModel) {
  ExpectError(R"(<OpenSimDocument Version="4x"><Model/></OpenSimDocument>)", 1, "",
              "Version '4x' is not a number");
  ExpectError(R"(<OpenSimDocument Version="40000"></OpenSimDocument>)", 1, "", "holds no <Model>");
}

TEST(OsimErrors, DeeplyNestedInputFailsWithoutExhaustingTheStack) {
  std::string text = "<OpenSimDocument Version=\"40000\"><Model name=\"m\">";
  for (int i = 0; i < 100000; ++i) text += "<a>";
  for (int i = 0; i < 100000; ++i) text += "</a>";
  text += "</Model></OpenSimDocument>";
  ExpectError(text, 1, "", "nested deeper than");
}

TEST(OsimErrors, LongChainOfOffsetFramesFailsWithoutExhaustingTheStack) {
  std::string frames;
  for (int i = 1; i <= 5000; ++i) {
    frames += "<PhysicalOffsetFrame name=\"f" + std::to_string(i) + "\"><socket_parent>" +
              (i == 1 ? std::string("/ground") : "/f" + std::to_string(i - 1)) +
              "</socket_parent></PhysicalOffsetFrame>\n";
  }
  std::string text = Model40(Pin("j1", "/f5000", "/bodyset/upper", "q1") +
                             Pin("j2", "/bodyset/upper", "/bodyset/lower", "q2"));
  text.insert(text.find("    <BodySet"), "<components>" + frames + "</components>\n");
  ExpectError(text, LineOf(text, "name=\"f4500\""), "/f4500", "chained deeper than 500");
  // A chain of 100 is fine: the joint's parent frame is on ground.
  std::string short_text = text;
  short_text.replace(short_text.find("/f5000"), 6, "/f100");
  const size_t from = short_text.find("<PhysicalOffsetFrame name=\"f101\"");
  short_text.erase(from, short_text.find("</components>") - from);
  const model::ModelSpec spec = io::ReadOsimString(short_text, "chain.osim");
  EXPECT_EQ(spec.joints[0].parent_body, model::kGroundIndex);
  EXPECT_EQ(spec.frames.size(), 100u);
}

// A long chain (10000 bodies, joints, coordinates, markers) reads without exhausting the stack
// and with every element in place. (Its reading time against n is measured by
// benchmarks/read_osim_chain.cc, not here.)
TEST(OsimErrors, LongChainReadsWithEveryElementInPlace) {
  const int n = 10000;
  std::string bodies, joints, markers;
  for (int i = 0; i < n; ++i) {
    const std::string b = "b" + std::to_string(i);
    bodies += "<Body name=\"" + b + "\"><mass>1</mass></Body>\n";
    joints +=
        Pin("j" + std::to_string(i), i == 0 ? "/ground" : "/bodyset/b" + std::to_string(i - 1),
            "/bodyset/" + b, "q" + std::to_string(i));
    markers += "<Marker name=\"m" + std::to_string(i) + "\"><socket_parent_frame>/bodyset/" + b +
               "</socket_parent_frame></Marker>\n";
  }
  std::string text = Model40(Pin("j_upper", "/ground", "/bodyset/upper", "qu") +
                                 Pin("j_lower", "/bodyset/upper", "/bodyset/lower", "ql") + joints,
                             bodies);
  text.insert(text.find("  </Model>"), "<MarkerSet><objects>" + markers + "</objects></MarkerSet>");
  const model::ModelSpec spec = io::ReadOsimString(text, "long.osim");
  ASSERT_EQ(spec.bodies.size(), static_cast<size_t>(n + 3));
  ASSERT_EQ(spec.joints.size(), static_cast<size_t>(n + 2));
  ASSERT_EQ(spec.markers.size(), static_cast<size_t>(n));
  // Bodies b0..b(n-1) follow upper and lower; joint j_i hangs b_i from b_(i-1) (b0 from ground)
  // with coordinate q_i, and marker m_i sits on b_i.
  int misplaced = 0;
  for (int i = 0; i < n; ++i) {
    const model::JointSpec& joint = spec.joints[i + 2];
    misplaced += joint.name != "j" + std::to_string(i) || joint.child_body != i + 3 ||
                 joint.parent_body != (i == 0 ? 0 : i + 2) ||
                 spec.coordinates[joint.coordinates.at(0)].name != "q" + std::to_string(i) ||
                 spec.markers[i].body != i + 3;
  }
  EXPECT_EQ(misplaced, 0);
}

TEST(OsimErrors, PathWrapRangeMustBeWholeNumbers) {
  std::string text = Model40(kGoodJoints);
  const std::string forces = R"(<ForceSet><objects><PathSpring name="s"><GeometryPath>
<PathPointSet><objects>
<PathPoint name="p1"><socket_parent_frame>/ground</socket_parent_frame></PathPoint>
<PathPoint name="p2"><socket_parent_frame>/bodyset/lower</socket_parent_frame></PathPoint>
</objects></PathPointSet>
<PathWrapSet><objects><PathWrap name="w"><wrap_object>cyl</wrap_object>
<range>1 1e300</range></PathWrap></objects></PathWrapSet>
</GeometryPath></PathSpring></objects></ForceSet>)";
  text.insert(text.find("  </Model>"), forces);
  const std::string wrap = R"(<WrapObjectSet><objects><WrapCylinder name="cyl"><radius>0.1</radius>
</WrapCylinder></objects></WrapObjectSet>)";
  text.insert(text.find("        </Body>"), wrap);
  ExpectError(text, LineOf(text, "<range>1 1e300"), "/forceset/s/geometrypath/w",
              "<range> expects two whole numbers");
  text.replace(text.find("1 1e300"), 7, "1 2");
  const model::ModelSpec spec = io::ReadOsimString(text, "wrap.osim");
  EXPECT_EQ(spec.forces[0].geometry_path->wraps[0].range, (std::array<int, 2>{1, 2}));
  EXPECT_EQ(spec.bodies[1].wrap_objects[0].name, "cyl");
}

TEST(OsimErrors, WrapDirectionMustBeRightOrLeftHanded) {
  std::string text = Model40(kGoodJoints);
  const std::string wrap = R"(<WrapObjectSet><objects><WrapCylinderObst name="obst">
<radius>0.1</radius>
<wrapDirection>clockwise</wrapDirection></WrapCylinderObst></objects></WrapObjectSet>)";
  text.insert(text.find("        </Body>"), wrap);
  ExpectError(text, LineOf(text, "<wrapDirection>"), "/bodyset/upper/wrapobjectset/obst",
              "wrapDirection 'clockwise' is not righthand or lefthand");
  // OpenSim's spellings: kept as wrap_direction +1 or -1.
  text.replace(text.find("clockwise"), 9, "Lefthanded");
  const model::ModelSpec spec = io::ReadOsimString(text, "wrap.osim");
  EXPECT_EQ(spec.bodies[1].wrap_objects[0].dimensions.at("wrap_direction"),
            std::vector<double>{-1.0});
  text.replace(text.find("Lefthanded"), 10, "right");
  EXPECT_EQ(io::ReadOsimString(text, "wrap.osim")
                .bodies[1]
                .wrap_objects[0]
                .dimensions.at("wrap_direction"),
            std::vector<double>{1.0});
}

TEST(OsimErrors, MissingFileOrDirectory) {
  EXPECT_THROW(io::ReadOsim("/nonexistent/model.osim"), Error);
  EXPECT_THROW(io::ReadOsim(testing::TempDir()), Error);
}

}  // namespace
}  // namespace sinew
