// ElementValues reads the properties of components the spec keeps as element trees (actuators,
// controllers). Every number is checked where it is read: NaN never passes, infinity only
// where a property is a bound.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/model/element_values.h>

#include <cmath>
#include <limits>
#include <string>

namespace sinew::model {
namespace {

Element Actuator(const std::string& tag, const std::string& text) {
  Element e{"CoordinateActuator", "act", "", 10, {}};
  e.children.push_back(Element{tag, "", text, 12, {}});
  return e;
}

// Expects reading `tag` to fail at the property's line (12), naming the file and component.
template <typename Read>
void ExpectRejected(const std::string& tag, const std::string& text, Read read) {
  const Element element = Actuator(tag, text);
  const ElementValues values(element, "m.osim", "/forceset/act");
  try {
    read(values);
    ADD_FAILURE() << "<" << tag << ">" << text << " was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "m.osim");
    EXPECT_EQ(e.where().line, 12);
    EXPECT_EQ(e.component(), "/forceset/act");
    EXPECT_NE(std::string(e.what()).find("<" + tag + ">"), std::string::npos) << e.what();
  }
}

TEST(ElementValuesTest, NumbersMustBeFinite) {
  for (const char* bad : {"nan", "NaN", "inf", "-Inf", "infinity"}) {
    ExpectRejected("optimal_force", bad,
                   [](const ElementValues& v) { v.Double("optimal_force", 1); });
  }
  ExpectRejected("axis", "0 nan 1",
                 [](const ElementValues& v) { v.Vector3("axis", Vec3::Zero()); });
  ExpectRejected("axis", "0 inf 1",
                 [](const ElementValues& v) { v.Vector3("axis", Vec3::Zero()); });
  ExpectRejected("optimal_force", "1e999",
                 [](const ElementValues& v) { v.Double("optimal_force", 1); });
}

TEST(ElementValuesTest, BoundsMayBeInfiniteButNotNaN) {
  const Element element = Actuator("max_control", "Inf");
  const ElementValues values(element, "m.osim", "/forceset/act");
  EXPECT_EQ(values.Bound("max_control", 1.0), std::numeric_limits<double>::infinity());
  EXPECT_EQ(values.Bound("min_control", -2.0), -2.0);  // absent: the fallback
  ExpectRejected("max_control", "NaN", [](const ElementValues& v) { v.Bound("max_control", 1); });
  ExpectRejected("max_control", "big", [](const ElementValues& v) { v.Bound("max_control", 1); });
}

}  // namespace
}  // namespace sinew::model
