// A run that leaves parts of a model out says so ONCE on stderr, with counts by kind taken
// from the model file itself, and names the `sinew inspect` command that lists them; --strict
// makes it an error (exit code 2). Columns of an initial-states file that name no simulated
// coordinate are reported the same way.
#include <gtest/gtest.h>

#include <pugixml.hpp>
#include <string>

#include "apps/cli_test_util.h"
#include "apps/unsupported_wraps.h"
#include "engine/test_models.h"

namespace sinew {
namespace {

using testing::CliRun;
using testing::CountOccurrences;

const std::string kData = SINEW_TEST_DATA_DIR;
const std::string kArm26 = kData + "/opensim-org/opensim-models/Models/Arm26/arm26.osim";

// Counts in the file itself (an XML parser, not Sinew's reader): the ForceSet's elements whose
// class ends in "Muscle" but is not simulated (every muscle class but Thelen2003Muscle), the
// forces Sinew simulates (Thelen2003Muscle, PathActuator, Point, Torque and CoordinateActuator,
// SpringGeneralizedForce, PointToPointSpring, CoordinateLimitForce, the bushings, the
// expression-based forces, PrescribedForce) and its other forces, the
// ConstraintSet's CoordinateCouplerConstraints (simulated) and other elements, and every body's
// WrapObjectSet's.
struct FileCounts {
  int muscles = 0, simulated_forces = 0, other_forces = 0, couplers = 0, constraints = 0,
      wrap_objects = 0;
};

FileCounts CountInFile(const std::string& osim) {
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_file(osim.c_str()));
  FileCounts counts;
  for (const pugi::xpath_node& n : doc.select_nodes("//ForceSet/objects/*")) {
    const std::string tag = n.node().name();
    if (tag.ends_with("Muscle") && tag != "Thelen2003Muscle") {
      ++counts.muscles;
    } else if (tag == "Thelen2003Muscle" || tag == "PathActuator" || tag == "PointActuator" ||
               tag == "TorqueActuator" || tag == "CoordinateActuator" ||
               tag == "SpringGeneralizedForce" || tag == "PointToPointSpring" ||
               tag == "CoordinateLimitForce" || tag == "BushingForce" ||
               tag == "FunctionBasedBushingForce" || tag == "ExpressionBasedBushingForce" ||
               tag == "ExpressionBasedCoordinateForce" ||
               tag == "ExpressionBasedPointToPointForce" || tag == "PrescribedForce") {
      ++counts.simulated_forces;
    } else {
      ++counts.other_forces;
    }
  }
  for (const pugi::xpath_node& n : doc.select_nodes("//ConstraintSet/objects/*")) {
    if (std::string(n.node().name()) == "CoordinateCouplerConstraint") {
      ++counts.couplers;
    } else {
      ++counts.constraints;
    }
  }
  counts.wrap_objects =
      static_cast<int>(doc.select_nodes("//BodySet//WrapObjectSet/objects/*").size());
  return counts;
}

class NotSimulatedTest : public testing::CliTest {
 protected:
  // arm26 with two kinds of parts Sinew does not simulate: its 6 Thelen2003Muscles read as
  // Millard2012AccelerationMuscle and its 2 WrapEllipsoids as a plugin's MyPluginWrapObject.
  std::string Arm26WithUnsupportedParts() const {
    std::string text = testing::ReadText(
        testing::WriteWithUnsupportedWraps(kArm26, Path("with_unsupported_wraps.osim")));
    const std::string from = "Thelen2003Muscle", to = "Millard2012AccelerationMuscle";
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
      text.replace(at, from.size(), to);
      at += to.size();
    }
    const std::string copy = Path("unsupported.osim");
    std::ofstream(copy) << text;
    return copy;
  }
};

TEST_F(NotSimulatedTest, SimulateSaysOnceWhatIsLeftOutByKind) {
  const std::string model = Arm26WithUnsupportedParts();
  const FileCounts counts = CountInFile(model);
  ASSERT_EQ(counts.muscles, 6);
  const std::string expected =
      "sinew: warning: 6 muscles and 2 wrap objects are NOT simulated: results are those of the "
      "skeleton without them. List them with: sinew inspect " +
      model + "\n";
  const CliRun run = Run("simulate " + model + " --duration 0 --quiet --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(CountOccurrences(run.err, expected), 1) << run.err;
  EXPECT_EQ(CountOccurrences(run.err, "NOT simulated"), 1) << run.err;
  // The summary says the same without --quiet.
  const CliRun loud = Run("simulate " + model + " --duration 0 --out " + Path("out"));
  ASSERT_EQ(loud.exit_code, 0) << loud.err;
  EXPECT_EQ(CountOccurrences(loud.err, expected), 1) << loud.err;
}

TEST_F(NotSimulatedTest, StrictMakesItAnError) {
  // arm26's muscles and its cylinders and ellipsoids are simulated; a plugin's wrap object is not.
  const std::string model =
      testing::WriteWithUnsupportedWraps(kArm26, Path("with_unsupported_wraps.osim"));
  const CliRun run =
      Run("simulate " + model + " --duration 0 --strict --quiet --out " + Path("out"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("sinew: error: " + model + ": --strict: 2 wrap objects are NOT simulated"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("out/states.sto")));
  // A model with nothing left out passes --strict, silently.
  const CliRun clean = Run("simulate " + kData +
                           "/projectchrono/chrono/data/opensim/double_pendulum.osim "
                           "--duration 0.01 --strict --quiet --out " +
                           Path("clean"));
  EXPECT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_EQ(clean.err, "");
}

// arm26 from a states file as OpenSim 4 writes them: coordinate values and speeds, and the
// muscles' activation and fiber_length, which set the muscles' states; two more columns name
// a muscle the model does not have.
TEST_F(NotSimulatedTest, UnusableInitialStateColumnsAreReportedInOneLine) {
  const std::string states = Path("arm26_states.sto");
  {
    std::ofstream out(states);
    out << "states\nversion=1\ninDegrees=no\nendheader\ntime"
           "\t/jointset/r_shoulder/r_shoulder_elev/value\t/jointset/r_shoulder/r_shoulder_elev/"
           "speed"
           "\t/jointset/r_elbow/r_elbow_flex/value\t/jointset/r_elbow/r_elbow_flex/speed";
    for (const char* muscle :
         {"TRIlong", "TRIlat", "TRImed", "BIClong", "BICshort", "BRA", "ghost"}) {
      out << "\t/forceset/" << muscle << "/activation\t/forceset/" << muscle << "/fiber_length";
    }
    out << "\n0\t0.1\t0\t0.5\t0";
    for (int i = 0; i < 7; ++i) out << "\t0.05\t0.1";
    out << "\n";
  }
  const std::string base = "simulate " + kArm26 + " --duration 0 --quiet --initial-states " +
                           states + " --out " + Path("out");
  const CliRun run = Run(base);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(CountOccurrences(run.err, "are not used"), 1) << run.err;
  EXPECT_NE(run.err.find("sinew: warning: " + states +
                         ": 2 columns are not used (/forceset/ghost/activation, "
                         "/forceset/ghost/fiber_length): they name no coordinate value or speed "
                         "or state variable that is simulated\n"),
            std::string::npos)
      << run.err;
  // The coordinates and the muscles' states were used: the first row of states.sto is the file's.
  const auto columns = engine::testing::ReadStoColumns(Path("out/states.sto"));
  EXPECT_EQ(columns.at("/jointset/r_shoulder/r_shoulder_elev/value").front(), 0.1);
  EXPECT_EQ(columns.at("/jointset/r_elbow/r_elbow_flex/value").front(), 0.5);
  EXPECT_EQ(columns.at("/forceset/BRA/activation").front(), 0.05);
  EXPECT_EQ(columns.at("/forceset/BRA/fiber_length").front(), 0.1);
  // --strict refuses the file (on a model with nothing else left out).
  const std::string pendulum = kData + "/projectchrono/chrono/data/opensim/double_pendulum.osim";
  const std::string ghost = Path("ghost_states.sto");
  std::ofstream(ghost) << "states\nversion=1\ninDegrees=no\nendheader\ntime"
                          "\t/forceset/ghost/activation\n0\t0.5\n";
  const CliRun strict = Run("simulate " + pendulum +
                            " --duration 0 --quiet --strict "
                            "--initial-states " +
                            ghost + " --out " + Path("out2"));
  EXPECT_EQ(strict.exit_code, 2) << strict.err;
  EXPECT_NE(strict.err.find("sinew: error: " + ghost + ": --strict: 1 column is not used"),
            std::string::npos)
      << strict.err;
}

}  // namespace
}  // namespace sinew
