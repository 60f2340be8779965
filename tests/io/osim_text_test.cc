// The text of a model file: values split by a comment or processing instruction, names holding
// control characters (they would break .sto columns), and UTF-16 files with a byte order mark.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>

#include <string>

namespace sinew {
namespace {

// A 4.x model with one body on a pin joint; `mass` and the names are spliced in as given.
std::string Model(const std::string& mass = "1.5", const std::string& body = "upper",
                  const std::string& coordinate = "q1", const std::string& marker = "m1") {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n"
         "<OpenSimDocument Version=\"40000\">\n"
         "  <Model name=\"m\">\n"
         "    <Ground name=\"ground\"/>\n"
         "    <BodySet name=\"bodyset\"><objects>\n"
         "        <Body name=\"" +
         body +
         "\">\n"
         "          <mass>" +
         mass +
         "</mass>\n"
         "          <inertia>0.1 0.1 0.1 0 0 0</inertia>\n"
         "        </Body>\n"
         "    </objects></BodySet>\n"
         "    <JointSet name=\"jointset\"><objects>\n"
         "        <PinJoint name=\"j1\">\n"
         "          <socket_parent_frame>/ground</socket_parent_frame>\n"
         "          <socket_child_frame>/bodyset/" +
         body +
         "</socket_child_frame>\n"
         "          <coordinates><Coordinate name=\"" +
         coordinate +
         "\"/></coordinates>\n"
         "        </PinJoint>\n"
         "    </objects></JointSet>\n"
         "    <MarkerSet name=\"markerset\"><objects>\n"
         "        <Marker name=\"" +
         marker +
         "\">\n"
         "          <socket_parent_frame>/bodyset/" +
         body +
         "</socket_parent_frame>\n"
         "        </Marker>\n"
         "    </objects></MarkerSet>\n"
         "  </Model>\n"
         "</OpenSimDocument>\n";
}

// Expects reading `text` to fail at `line` with `fragment` in the message.
void ExpectError(const std::string& text, int line, const std::string& fragment) {
  try {
    io::ReadOsimString(text, "text.osim");
    ADD_FAILURE() << "no error; expected '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "text.osim") << e.what();
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(OsimText, TheModelReadsAsWritten) {
  const model::ModelSpec spec = io::ReadOsimString(Model(), "text.osim");
  ASSERT_EQ(spec.bodies.size(), 2u);
  EXPECT_EQ(spec.bodies[1].mass, 1.5);
  EXPECT_EQ(spec.markers.size(), 1u);
}

TEST(OsimText, ANumberSplitByACommentOrProcessingInstructionIsAnError) {
  const std::string split = "the text of <mass> is split by a comment, processing instruction";
  ExpectError(Model("1<!-- c -->0"), 7, split);
  ExpectError(Model("1<?pi x?>0"), 7, split);
  ExpectError(Model("1<![CDATA[0]]>"), 7, split);
  // A comment before or after the whole value is harmless.
  EXPECT_EQ(io::ReadOsimString(Model("<!-- c -->10<!-- d -->"), "text.osim").bodies[1].mass, 10);
}

TEST(OsimText, NamesWithControlCharactersAreErrorsWithTheirLine) {
  const std::string message = "holds a tab, newline or other control character";
  ExpectError(Model("1", "up&#9;per"), 6, "the name 'up\\tper' " + message);
  ExpectError(Model("1", "upper", "q&#10;1"), 15, "the name 'q\\n1' " + message);
  ExpectError(Model("1", "upper", "q1", "m&#13;1"), 19, "the name 'm\\r1' " + message);
  // A literal tab in an attribute is a space to XML (and then a legal name).
  EXPECT_EQ(io::ReadOsimString(Model("1", "upper", "q1", "m\t1"), "text.osim").markers[0].name,
            "m 1");
}

// `text` (ASCII) as UTF-16 with a byte order mark.
std::string Utf16(const std::string& text, bool big_endian) {
  std::string out = big_endian ? "\xFE\xFF" : "\xFF\xFE";
  for (const char c : text) {
    out += big_endian ? std::string{'\0', c} : std::string{c, '\0'};
  }
  return out;
}

TEST(OsimText, Utf16FilesWithAByteOrderMarkAreRead) {
  for (const bool big_endian : {false, true}) {
    const model::ModelSpec spec = io::ReadOsimString(Utf16(Model(), big_endian), "text.osim");
    ASSERT_EQ(spec.bodies.size(), 2u) << big_endian;
    EXPECT_EQ(spec.bodies[1].name, "upper");
    EXPECT_EQ(spec.bodies[1].mass, 1.5);
  }
  // Lines are counted as in the original: the error is on line 7 either way.
  ExpectError(Utf16(Model("heavy"), false), 7, "expects numbers, found 'heavy'");
  ExpectError(Utf16(Model(), true) + "x", 0, "odd number of bytes");
}

}  // namespace
}  // namespace sinew
