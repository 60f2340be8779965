// What the commands write and where: outputs checked before any work (a bad --out is exit code
// 2 with a message naming it, for every command), files replaced whole, and a symbolic link in
// the output folder replaced, never followed to a file outside it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "apps/cli_test_util.h"

namespace sinew {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;

const std::string kModel = std::string(SINEW_TEST_DATA_DIR) +
                           "/opensim-org/opensim-core/Applications/Analyze/tests/resources/"
                           "SinglePin.osim";

class OutputsTest : public testing::CliTest {
 protected:
  // Expects exit code 2, nothing on stdout, and `message` on stderr.
  void ExpectRefused(const std::string& args, const std::string& message) const {
    const CliRun run = Run(args);
    EXPECT_EQ(run.exit_code, 2) << args << "\n" << run.err;
    EXPECT_EQ(run.out, "") << args;
    EXPECT_NE(run.err.find("sinew: error: " + message), std::string::npos) << args << "\n"
                                                                           << run.err;
  }
};

TEST_F(OutputsTest, ASymbolicLinkInTheOutputFolderIsReplacedNotFollowed) {
  const fs::path outside = dir() / "outside.txt";
  std::ofstream(outside) << "precious\n";
  fs::create_directories(dir() / "out");
  fs::create_symlink(outside, dir() / "out" / "states.sto");
  fs::create_symlink(outside, dir() / "out" / "bodies.sto");
  const CliRun run = Run("simulate " + kModel + " --duration 0.05 --quiet --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(testing::ReadText(outside), "precious\n");
  for (const char* name : {"states.sto", "bodies.sto"}) {
    const fs::path file = dir() / "out" / name;
    EXPECT_FALSE(fs::is_symlink(file)) << name;
    EXPECT_NE(testing::ReadText(file).find("endheader"), std::string::npos) << name;
  }
}

TEST_F(OutputsTest, NoTemporaryFileIsLeftBesideTheOutputs) {
  const CliRun run = Run("kinematics " + kModel + " --out " + Path("k"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  int entries = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir() / "k")) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
    ++entries;
  }
  EXPECT_EQ(entries, 1);  // bodies.sto (the model has no markers)
}

TEST_F(OutputsTest, AnExistingFileAsTheOutputFolderIsRefusedByEveryCommand) {
  std::ofstream(Path("file")) << "not a folder\n";
  const std::string message =
      Path("file") + ": --out must be a folder, and this is an existing file";
  ExpectRefused("simulate " + kModel + " --duration 100 --out " + Path("file"), message);
  ExpectRefused("kinematics " + kModel + " --out " + Path("file"), message);
  ExpectRefused("export " + kModel + " --out " + Path("file/x.glb"),
                Path("file") + ": cannot create folder");
  ExpectRefused("render " + kModel + " --out " + Path("file/x.png"),
                Path("file") + ": cannot create folder");
  EXPECT_EQ(testing::ReadText(Path("file")), "not a folder\n");
}

TEST_F(OutputsTest, AnEmptyOrTooLongOutputIsRefusedByEveryCommand) {
  ExpectRefused("simulate " + kModel + " --duration 1 --out ''",
                "--out is empty: give the name of the output");
  ExpectRefused("kinematics " + kModel + " --out ''", "--out is empty");
  ExpectRefused("render " + kModel + " --out ''", "the output is written as PNG only");
  ExpectRefused("export " + kModel + " --out ''", "cannot tell the export format from ''");
  const std::string long_name(300, 'a');
  const std::string too_long = "--out has a name of 300 characters ('aaaaaaaaaaaaaaaaaaaa...')";
  ExpectRefused("simulate " + kModel + " --duration 1 --out " + Path(long_name), too_long);
  ExpectRefused("kinematics " + kModel + " --out " + Path(long_name), too_long);
  ExpectRefused("export " + kModel + " --out " + Path(long_name + ".glb"),
                "--out has a name of 304 characters");
  ExpectRefused("render " + kModel + " --out " + Path(long_name + ".png"),
                "--out has a name of 304 characters");
}

TEST_F(OutputsTest, AFolderWhereAFileIsWantedIsRefused) {
  fs::create_directories(dir() / "scene.glb");
  ExpectRefused("export " + kModel + " --out " + Path("scene.glb"),
                Path("scene.glb") + ": --out must be a file name, and this is a folder");
  fs::create_directories(dir() / "picture.png");
  ExpectRefused("render " + kModel + " --out " + Path("picture.png"),
                Path("picture.png") + ": --out must be a file name, and this is a folder");
}

TEST_F(OutputsTest, SimulateChecksItsExportFileBeforeSimulating) {
  // A long run: the check must come first, or this would take minutes.
  ExpectRefused("simulate " + kModel + " --duration 1e5 --report-interval 10 --out " + Path("out") +
                    " --export " + Path("motion.gltf"),
                Path("motion.gltf") + ": cannot tell the export format from '.gltf'");
  EXPECT_FALSE(fs::exists(dir() / "out" / "states.sto"));
}

TEST_F(OutputsTest, AFolderThatCannotBeCreatedIsRefused) {
  ExpectRefused("simulate " + kModel + " --duration 1 --out /proc/sinew-out",
                "/proc/sinew-out: cannot create folder");
}

// Mesh names are resolved as OpenSim resolves them: a relative name (".." included) against the
// model's folder and then Geometry/ and the extra folders, an absolute name as given. --verbose
// says which file was read for each.
TEST_F(OutputsTest, VerboseExportSaysWhereEachMeshWasRead) {
  std::string model = testing::ReadText(kModel);
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  fs::create_directories(dir() / "models");
  fs::create_directories(dir() / "shared");
  std::ofstream(dir() / "shared" / "cube.obj") << triangle;
  std::ofstream(dir() / "cone.obj") << triangle;
  const std::string absolute = Path("cone.obj");
  model.replace(model.find("cuboid.vtp"), 10, "../shared/cube.obj");
  model.replace(model.find("ConePendulum.vtp"), 16, absolute);
  std::ofstream(dir() / "models" / "pin.osim") << model;
  const CliRun run = Run("export " + Path("models/pin.osim") + " --verbose --out " + Path("m.glb"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("sinew: note: mesh '../shared/cube.obj' read from " + Path("models") +
                         "/../shared/cube.obj\n"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("sinew: note: mesh '" + absolute + "' read from " + absolute + "\n"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(run.err.find("not found"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace sinew
