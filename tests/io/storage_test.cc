#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/storage.h>
#include <sinew/io/storage_functions.h>
#include <sinew/io/storage_labels.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "corpus.h"

namespace sinew {
namespace {

// Files from opensim-core's test resources (Analyze, or ID for the shoulder motion).
std::string PendulumFile(const std::string& name) {
  return std::string(SINEW_TEST_DATA_DIR) +
         "/opensim-org/opensim-core/Applications/Analyze/tests/resources/" + name;
}
std::string DataFile(const std::string& name) {
  if (name.starts_with("Thorascapular")) {
    return std::string(SINEW_TEST_DATA_DIR) +
           "/opensim-org/opensim-core/Applications/ID/tests/resources/" + name;
  }
  return PendulumFile(name);
}

TEST(StorageTest, ReadsOpenSim4PathLabelsInDegrees) {
  io::Storage s = io::ReadStorage(DataFile("double_pendum1sec.sto"));
  EXPECT_EQ(s.name, "Results");
  EXPECT_EQ(s.Metadata("version"), "1");
  EXPECT_TRUE(s.in_degrees);
  EXPECT_EQ(s.time_label, "time");
  ASSERT_EQ(s.NumColumns(), 4);
  EXPECT_EQ(s.NumRows(), 52);
  EXPECT_TRUE(s.notes.empty());
  EXPECT_EQ(s.labels[0], "/jointset/pin1/q1/value");
  EXPECT_EQ(s.labels[3], "/jointset/pin2/q2/speed");
  EXPECT_EQ(s.time[1], 0.01);
  EXPECT_EQ(s.Value(1, 1), 5.97581046);
  // Both pins are rotational: values and speeds convert. Row 0 starts at -45 and -60 degrees
  // (written with 8 decimals: -44.99999981, so within 2e-7 deg = 3.3e-9 rad).
  const std::vector<std::string> rotational = {"q1", "q2"};
  io::ConvertDegreesToRadians(s, rotational);
  EXPECT_FALSE(s.in_degrees);
  EXPECT_NEAR(s.Value(0, 0), -std::numbers::pi / 4, 4e-9);
  EXPECT_NEAR(s.Value(0, 2), -std::numbers::pi / 3, 4e-9);
  EXPECT_NEAR(s.Value(1, 1), 5.97581046 * std::numbers::pi / 180, 1e-15);
  EXPECT_EQ(s.time[1], 0.01);  // time never converts
}

TEST(StorageTest, DegreesFileMatchesItsRadiansTwin) {
  // OpenSim wrote the same SinglePin run in radians (.sto) and in degrees (.mot). The .mot has
  // no inDegrees line and no version (it carries an old SIMM header instead): OpenSim's Storage
  // reads such an old .mot as a SIMM motion, in degrees, and so does ReadStorage, with a note.
  // Values have 20 digits, so the converted degrees agree with the radians to rounding.
  io::Storage radians = io::ReadStorage(PendulumFile("SinglePin_states.sto"));
  io::Storage degrees = io::ReadStorage(DataFile("SinglePin_states_degrees.mot"));
  EXPECT_FALSE(radians.in_degrees);  // an old .sto without inDegrees: radians
  EXPECT_FALSE(radians.in_degrees_stated);
  EXPECT_TRUE(degrees.in_degrees);
  EXPECT_FALSE(degrees.in_degrees_stated);
  ASSERT_EQ(degrees.notes.size(), 1u);
  EXPECT_NE(degrees.notes[0].message.find("as OpenSim reads a SIMM motion"), std::string::npos);
  EXPECT_EQ(degrees.comments.front(), "# SIMM Motion File Header:");
  EXPECT_EQ(degrees.Metadata("nRows"), "");                     // nRows is structural, not metadata
  const std::vector<std::string> model_coordinates = {"r1_z"};  // r1_z is rotational
  io::ConvertDegreesToRadians(degrees, model_coordinates);
  ASSERT_EQ(radians.NumRows(), 302);
  ASSERT_EQ(degrees.NumRows(), radians.NumRows());
  ASSERT_EQ(degrees.labels, radians.labels);
  double worst = 0.0;
  for (int row = 0; row < radians.NumRows(); ++row) {
    EXPECT_EQ(degrees.time[row], radians.time[row]);
    for (int column = 0; column < 2; ++column) {
      worst = std::max(worst, std::abs(degrees.Value(row, column) - radians.Value(row, column)));
    }
  }
  EXPECT_LT(worst, 1e-14);
}

// Without an inDegrees line, OpenSim's Storage (Storage.cpp: _inDegrees false by default,
// set true after parseHeaders when `_fileVersion < 1 && isMotFile`; "Angles are in degrees."
// read when the version is 0) decides the unit from the version and the extension.
TEST(StorageTest, WithoutInDegreesTheUnitFollowsOpenSimsRule) {
  const std::string body = "endheader\ntime\tq\n0\t90\n";
  struct Case {
    std::string header, file;
    bool degrees, stated;
  };
  const Case cases[] = {
      {"m\n", "old.mot", true, false},              // SIMM motion: degrees
      {"m\nversion=0\n", "old.MOT", true, false},   // version 0 is old too
      {"m\nversion=1\n", "new.mot", false, false},  // version 1: OpenSim's default, radians
      {"m\n", "old.sto", false, false},             // not a .mot: radians
      {"m\nAngles are in radians.\n", "old.mot", false, true},
      {"m\nAngles are in degrees.\n", "old.sto", true, true},
      {"m\ninDegrees=no\n", "old.mot", false, true},  // a stated unit is followed
  };
  for (const Case& c : cases) {
    const io::Storage s = io::ParseStorage(c.header + body, c.file);
    EXPECT_EQ(s.in_degrees, c.degrees) << c.header << c.file;
    EXPECT_EQ(s.in_degrees_stated, c.stated) << c.header << c.file;
  }
}

TEST(StorageTest, ReadsLenientOldFiles) {
  // Tabs after every header line, an empty label between two tabs, no version or inDegrees.
  io::Storage s = io::ReadStorage(PendulumFile("SinglePin_InitialStates.sto"));
  EXPECT_EQ(s.name, "S26pre_CMC_states");
  ASSERT_EQ(s.labels, (std::vector<std::string>{"r1_z", "r1_z_u"}));
  ASSERT_EQ(s.NumRows(), 1);
  EXPECT_EQ(s.Value(0, 0), 1.0);
  EXPECT_TRUE(s.notes.empty());
  io::Storage shoulder = io::ReadStorage(DataFile("ThorascapularShoulderModel_static.mot"));
  EXPECT_EQ(shoulder.name, "Default_Position.mot");
  EXPECT_EQ(shoulder.NumColumns(), 17);
  EXPECT_EQ(shoulder.NumRows(), 6);
  EXPECT_EQ(shoulder.Value(5, 16), 0.17);
}

TEST(StorageTest, ToleratesWrongCountsButNotesThem) {
  io::Storage s = io::ParseStorage(
      "states\nnRows=3\nnColumns=4\nendheader\ntime a b\n0 1 2\n1 3 4\n", "counts.sto");
  EXPECT_EQ(s.NumRows(), 2);
  ASSERT_EQ(s.notes.size(), 2u);
  EXPECT_EQ(s.notes[0].where.line, 2);
  EXPECT_NE(s.notes[0].message.find("nRows=3"), std::string::npos);
  EXPECT_EQ(s.notes[1].where.line, 3);
  // Space-separated rows and labels, blank lines, CRLF endings, scientific notation, nan.
  io::Storage t = io::ParseStorage(
      "name\r\nversion=1\r\nendheader\r\n\r\ntime q\r\n0 4.93E-05\r\n\r\n1 nan\r\n", "crlf.mot");
  ASSERT_EQ(t.NumRows(), 2);
  EXPECT_EQ(t.Value(0, 0), 4.93e-05);
  EXPECT_TRUE(std::isnan(t.Value(1, 0)));
}

// Asserts that parsing `text` throws a sinew::Error at `line` mentioning `what`.
void ExpectParseError(const std::string& text, int line, const std::string& what) {
  try {
    io::ParseStorage(text, "bad.sto");
    FAIL() << "no error for: " << text;
  } catch (const Error& error) {
    EXPECT_EQ(error.where().file, "bad.sto");
    EXPECT_EQ(error.where().line, line) << error.what();
    EXPECT_NE(std::string(error.what()).find(what), std::string::npos) << error.what();
  }
}

TEST(StorageTest, BadFilesGiveErrorsWithLines) {
  ExpectParseError("name\nversion=1\ntime a\n0 1\n", 4, "endheader");
  ExpectParseError("name\nendheader\ntime\ta\tb\n0 1 2\n1 2\n", 5, "row has 2 values");
  ExpectParseError("name\nendheader\ntime a\n0 1\n0.5 x1\n", 5, "'x1'");
  ExpectParseError("name\ninDegrees=maybe\nendheader\ntime\n", 2, "inDegrees");
  ExpectParseError("name\nnRows=many\nendheader\ntime\n", 2, "nRows");
  ExpectParseError("name\nendheader\n\n", 3, "labels");
  ExpectParseError("markers\nDataType=Vec3\nendheader\ntime\tm1\n0\t1,2,3\n", 2, "Vec3");
  EXPECT_THROW(io::ReadStorage(DataFile("no_such_file.sto")), Error);
}

TEST(StorageTest, WriteReadRoundTripIsExact) {
  io::Storage s;
  s.name = "round trip";
  s.in_degrees = true;
  s.metadata = {{"DataType", "double"}, {"OpenSimVersion", "4.5"}};
  s.labels = {"/jointset/knee_r/knee_angle_r/value", "knee angle with spaces", "tx"};
  s.AppendRow(0.0, {0.1, -1.0 / 3.0, 1e-300});
  s.AppendRow(0.1, {std::numbers::pi, 6.02214076e23, -0.0});
  EXPECT_THROW(s.AppendRow(0.2, {1.0}), Error);
  const std::string text = io::FormatStorage(s);
  EXPECT_EQ(text.substr(0, text.find("endheader")),
            "round trip\nversion=1\nnRows=2\nnColumns=4\ninDegrees=yes\nDataType=double\n"
            "OpenSimVersion=4.5\n");
  io::Storage back = io::ParseStorage(text, "memory");
  EXPECT_EQ(back.name, s.name);
  EXPECT_TRUE(back.in_degrees);
  // The writer added version=1 in front of the other keys.
  ASSERT_EQ(back.metadata.size(), 3u);
  EXPECT_EQ(back.metadata[0], (std::pair<std::string, std::string>("version", "1")));
  EXPECT_EQ(back.metadata[1], s.metadata[0]);
  EXPECT_EQ(back.metadata[2], s.metadata[1]);
  EXPECT_EQ(back.labels, s.labels);
  EXPECT_EQ(back.time, s.time);
  EXPECT_EQ(back.values, s.values);  // bit-exact: shortest round-trip formatting
  EXPECT_TRUE(back.notes.empty());

  // Through a file, from a real one.
  io::Storage original = io::ReadStorage(DataFile("double_pendum1sec.sto"));
  const std::string path =
      (std::filesystem::temp_directory_path() / "sinew_storage_round_trip.sto").string();
  io::WriteStorage(original, path);
  io::Storage reread = io::ReadStorage(path);
  std::remove(path.c_str());
  EXPECT_EQ(reread.values, original.values);
  EXPECT_EQ(reread.labels, original.labels);
  EXPECT_EQ(reread.in_degrees, original.in_degrees);
}

// Every .sto/.mot in the OpenSim corpus (SINEW_CORPUS_DIR) reads; wrong declared counts are only
// noted.
TEST(StorageTest, ReadsEveryStorageFileInTheCorpus) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const std::filesystem::path root = testing::CorpusDir();
  int files = 0;
  std::vector<std::string> noted;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    const std::string extension = entry.path().extension().string();
    if (!entry.is_regular_file() || (extension != ".sto" && extension != ".mot")) continue;
    io::Storage s;
    EXPECT_NO_THROW(s = io::ReadStorage(entry.path().string())) << entry.path();
    ++files;
    // Count disagreements only (old .mot files also get a note that they are read in degrees).
    for (const Diagnostic& note : s.notes) {
      if (note.message.starts_with("nRows=") || note.message.starts_with("nColumns=")) {
        noted.push_back(entry.path().filename().string());
        break;
      }
    }
    EXPECT_EQ(s.values.size(), s.time.size() * s.labels.size()) << entry.path();
  }
  std::sort(noted.begin(), noted.end());
  for (const std::string& name : noted) std::cout << "header disagrees with data: " << name << "\n";
  // 72 storage files; 3 of them declare row or column counts their data disagree with (read
  // anyway, as OpenSim does, with a note). Any other file with a note fails this test.
  EXPECT_EQ(files, 72);
  EXPECT_EQ(noted, (std::vector<std::string>{"DoublePendulum3D_InitialStates.sto",
                                             "input_coordinate_values.sto",
                                             "std_SinglePin_JointReaction_ReactionLoads.sto"}));
}

TEST(StorageFunctionsTest, SplinesThroughAPendulumRunGiveItsSpeeds) {
  // SinglePin_states.sto holds q and u = dq/dt of a pendulum sampled every 0.01 s (20 digits).
  // The quintic spline through q interpolates q, and away from the ends its slope matches the
  // stored u to ~1e-8 (the quintic's interpolation error for this smooth motion; measured max
  // 2.7e-8). Near the ends the natural end conditions (3rd and 4th derivatives zero) cost more:
  // 8e-6 at t = 0, decaying by ~0.4 per sample. The file also repeats its final time
  // (2.99999999999998 and 3.0, 2e-14 apart), a near-duplicate knot that spoils the last few
  // samples' slopes. OpenSim's GCVSplineSet fit has both effects too.
  io::Storage s = io::ReadStorage(PendulumFile("SinglePin_states.sto"));
  std::vector<functions::FunctionPtr> splines = io::FitColumnSplines(s);
  ASSERT_EQ(splines.size(), 2u);
  double worst_value = 0.0, worst_speed = 0.0;
  for (int row = 0; row < s.NumRows(); ++row) {
    worst_value = std::max(worst_value, std::abs(splines[0]->Calc(s.time[row]) - s.Value(row, 0)));
    if (row >= 10 && row <= 290) {
      worst_speed = std::max(
          worst_speed, std::abs(splines[0]->CalcDerivative(s.time[row], 1) - s.Value(row, 1)));
    }
  }
  EXPECT_LT(worst_value, 1e-12);
  EXPECT_LT(worst_speed, 1e-7);
  EXPECT_LT(std::abs(splines[0]->CalcDerivative(0.0, 1) - s.Value(0, 1)), 2e-5);
  io::Storage one_row = io::ReadStorage(PendulumFile("SinglePin_InitialStates.sto"));
  EXPECT_THROW(io::FitColumnSplines(one_row), Error);
}

TEST(StorageLabelsTest, MapsOldAndPathStyleLabelsToCoordinates) {
  auto value = io::ParseColumnLabel("/jointset/knee_r/knee_angle_r/value");
  ASSERT_TRUE(value);
  EXPECT_EQ(value->coordinate, "knee_angle_r");
  EXPECT_EQ(value->kind, io::CoordinateColumnKind::kValue);
  EXPECT_EQ(value->path, "/jointset/knee_r/knee_angle_r");
  auto speed = io::ParseColumnLabel("/jointset/knee_r/knee_angle_r/speed");
  ASSERT_TRUE(speed);
  EXPECT_EQ(speed->kind, io::CoordinateColumnKind::kSpeed);
  EXPECT_FALSE(io::ParseColumnLabel("/forceset/soleus_r/activation"));
  EXPECT_FALSE(io::ParseColumnLabel("time"));
  auto old_value = io::ParseColumnLabel("knee_angle_r");
  ASSERT_TRUE(old_value);
  EXPECT_EQ(old_value->coordinate, "knee_angle_r");
  EXPECT_EQ(old_value->kind, io::CoordinateColumnKind::kValue);
  auto old_speed = io::ParseColumnLabel("r1_z_u");
  ASSERT_TRUE(old_speed);
  EXPECT_EQ(old_speed->coordinate, "r1_z");
  EXPECT_EQ(old_speed->kind, io::CoordinateColumnKind::kSpeed);
  // With the model's names: a coordinate whose own name ends in _u stays a value, unknown
  // labels do not resolve.
  const std::vector<std::string> names = {"tilt_u", "knee_angle_r"};
  EXPECT_EQ(io::ParseColumnLabel("tilt_u", names)->kind, io::CoordinateColumnKind::kValue);
  EXPECT_EQ(io::ParseColumnLabel("tilt_u_u", names)->coordinate, "tilt_u");
  EXPECT_FALSE(io::ParseColumnLabel("RF", names));
  EXPECT_FALSE(io::ParseColumnLabel("/jointset/hip/hip_flexion/value", names));
}

TEST(StorageLabelsTest, FindsCoordinateColumnsInEitherStyle) {
  io::Storage path_style = io::ReadStorage(DataFile("double_pendum1sec.sto"));
  EXPECT_EQ(io::FindCoordinateColumn(path_style, "q2"), 2);
  EXPECT_EQ(io::FindCoordinateColumn(path_style, "q2", io::CoordinateColumnKind::kSpeed), 3);
  EXPECT_EQ(io::FindCoordinateColumn(path_style, "q3"), -1);
  io::Storage old_style = io::ReadStorage(PendulumFile("SinglePin_states.sto"));
  EXPECT_EQ(io::FindCoordinateColumn(old_style, "r1_z"), 0);
  EXPECT_EQ(io::FindCoordinateColumn(old_style, "r1_z", io::CoordinateColumnKind::kSpeed), 1);
  EXPECT_EQ(io::FindCoordinateColumn(old_style, "r1"), -1);
}

TEST(StorageLabelsTest, ConvertsOnlyRotationalColumns) {
  io::Storage s = io::ParseStorage(
      "motion\ninDegrees=yes\nendheader\n"
      "time\tknee_angle_r\tknee_tx\t/jointset/knee_r/knee_angle_r/speed\tRF\n"
      "0\t90\t0.5\t180\t1\n",
      "m.mot");
  io::ConvertDegreesToRadians(s, [](std::string_view label) {
    auto column = io::ParseColumnLabel(label);
    return column && column->coordinate == "knee_angle_r";
  });
  EXPECT_FALSE(s.in_degrees);
  EXPECT_DOUBLE_EQ(s.Value(0, 0), std::numbers::pi / 2);
  EXPECT_EQ(s.Value(0, 1), 0.5);  // translation untouched
  EXPECT_DOUBLE_EQ(s.Value(0, 2), std::numbers::pi);
  EXPECT_EQ(s.Value(0, 3), 1.0);
  // Already in radians: nothing happens.
  io::ConvertDegreesToRadians(s, [](std::string_view) { return true; });
  EXPECT_DOUBLE_EQ(s.Value(0, 0), std::numbers::pi / 2);
  // And back.
  io::ConvertRadiansToDegrees(s, [](std::string_view label) { return label == "knee_angle_r"; });
  EXPECT_TRUE(s.in_degrees);
  EXPECT_DOUBLE_EQ(s.Value(0, 0), 90.0);
}

}  // namespace
}  // namespace sinew
