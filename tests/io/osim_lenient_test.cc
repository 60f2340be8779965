// Inputs that real OpenSim files contain and a strict XML parser rejects: names with '::', a bare
// '&', a stray non-UTF-8 byte, nested comments. They load as OpenSim loads them, with the line
// numbers of everything after them unchanged. A truncated file is still an error.
#include <gtest/gtest.h>
#include <sinew/io/internal/xml_document.h>
#include <sinew/io/osim_reader.h>

#include <string>

namespace sinew {
namespace {

// One body on a slider; `mass_line` is line 7 of the text.
std::string Model(const std::string& before_body, const std::string& mass_text) {
  return "<OpenSimDocument Version=\"40000\">\n"  // 1
         "<Model name=\"m\">\n"                   // 2
         "<Ground name=\"ground\"/>\n"            // 3
         + before_body +                          // 4 (one line)
         "\n<BodySet><objects>\n"                 // 5
         "<Body name=\"b\">\n"                    // 6
         "<mass>" +
         mass_text +
         "</mass>\n"  // 7
         "</Body></objects></BodySet>\n"
         "<JointSet><objects><SliderJoint name=\"s\">\n"
         "<socket_parent_frame>/ground</socket_parent_frame>\n"
         "<socket_child_frame>/bodyset/b</socket_child_frame>\n"
         "<coordinates><Coordinate name=\"x\"/></coordinates>\n"
         "</SliderJoint></objects></JointSet>\n"
         "</Model></OpenSimDocument>\n";
}

TEST(OsimLenient, DoubleColonInElementNames) {
  const model::ModelSpec spec = io::ReadOsimString(
      Model("<ForceSet><objects><HuntCrossleyForce name=\"c\"><HuntCrossleyForce::"
            "ContactParametersSet><objects/></HuntCrossleyForce::ContactParametersSet>"
            "</HuntCrossleyForce></objects></ForceSet>",
            "2"),
      "colons.osim");
  ASSERT_EQ(spec.forces.size(), 1u);
  EXPECT_EQ(spec.forces[0].element.children[0].tag, "HuntCrossleyForce::ContactParametersSet");
  EXPECT_EQ(spec.bodies[1].mass, 2.0);
}

TEST(OsimLenient, BareAmpersand) {
  const model::ModelSpec spec =
      io::ReadOsimString(Model("<credits>Smith & Jones</credits>", "3"), "amp.osim");
  EXPECT_EQ(spec.bodies[1].mass, 3.0);
  EXPECT_EQ(spec.bodies[1].where.line, 6);
}

TEST(OsimLenient, NonUtf8Byte) {
  const model::ModelSpec spec =
      io::ReadOsimString(Model("<credits>M\xFCller \xE9t\xE9</credits>", "4"), "latin1.osim");
  EXPECT_EQ(spec.bodies[1].mass, 4.0);
}

TEST(OsimLenient, NestedCommentsKeepLinesAndValues) {
  // The nested comment spans lines 4-5 of the model line 4: the value on line 7 is unaffected,
  // and a nested comment inside a value leaves only the number.
  const std::string text =
      Model("<!-- outer <!-- inner --> still outer -->", "<!-- a <!-- b --> c --> 5.5");
  const model::ModelSpec spec = io::ReadOsimString(text, "nested.osim");
  EXPECT_EQ(spec.bodies[1].mass, 5.5);
  EXPECT_EQ(spec.bodies[1].where.line, 6);
}

TEST(OsimLenient, UnbalancedNestedCommentEndsAtFirstClose) {
  // Never balanced: the comment ends at its first "-->" (as TinyXML, OpenSim's parser, does).
  const model::ModelSpec spec =
      io::ReadOsimString(Model("<!-- a <!-- b -->", "6"), "unbalanced.osim");
  EXPECT_EQ(spec.bodies[1].mass, 6.0);
}

TEST(OsimLenient, LineNumbersSurviveMultiLineNestedComment) {
  const std::string text = Model("<!-- x\n<!-- y\n-->\n-->", "oops");
  try {
    io::ReadOsimString(text, "lines.osim");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 10);  // mass moved down by the 3 newlines of the comment
    EXPECT_EQ(e.component(), "/bodyset/b");
  }
}

TEST(OsimLenient, ManyUnbalancedNestsStayLinear) {
  // 100000 comments that each open a nest that never closes: each ends at its first "-->".
  // (A rescan to the end of the text per comment would take minutes here.)
  std::string comments;
  for (int i = 0; i < 100000; ++i) comments += "<!-- <!-- -->";
  const model::ModelSpec spec = io::ReadOsimString(Model(comments, "7"), "many.osim");
  EXPECT_EQ(spec.bodies[1].mass, 7.0);
}

TEST(OsimLenient, UnterminatedCommentIsAnError) {
  const std::string text = Model("<!-- never closed", "1");
  EXPECT_THROW(io::ReadOsimString(text, "open.osim"), Error);
}

TEST(OsimLenient, TruncatedAfterLenientPartsIsAnError) {
  const std::string text = Model("<credits>a & b</credits>", "1");
  for (size_t cut : {text.size() / 3, text.size() / 2, text.size() - 20}) {
    EXPECT_THROW(io::ReadOsimString(text.substr(0, cut), "cut.osim"), Error) << cut;
  }
}

TEST(OsimLenient, RealFilesWithColonsAndAmpersands) {
  const std::string dir = std::string(SINEW_TEST_DATA_DIR) + "/";
  const model::ModelSpec block =
      io::ReadOsim(dir + "opensim-org/opensim-models/Models/BouncingBlock/bouncing_block.osim");
  bool found = false;
  for (const model::ForceSpec& f : block.forces) {
    for (const model::Element& e : f.element.children)
      found = found || e.tag.find("::") != std::string::npos;
  }
  EXPECT_TRUE(found);
  const model::ModelSpec knee = io::ReadOsim(
      dir +
      "clnsmith/opensim-jam/models/lenhart2015/scale_generic_model/lenhart2015_unscaled.osim");
  EXPECT_NE(knee.FindBody("femur_r"), model::kNone);
}

}  // namespace
}  // namespace sinew
