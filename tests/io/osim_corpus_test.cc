// Every .osim file of the corpus (SINEW_CORPUS_DIR, see tests/corpus.h) loads, except the files
// listed below as genuinely broken, which must fail with a precise error (file, line, component).
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "corpus.h"

namespace sinew {
namespace {

namespace fs = std::filesystem;

// File name -> the part of the error message that must appear, and why the file is broken.
const std::map<std::string, std::string> kBroken = {
    // A repro of an OpenSim Creator crash: joint hip_r has /ground as its *child*, so femur_r
    // and everything below it (knee, patella, ankle, foot) hangs from nothing.
    {"opensim-creator_382_repro.osim", "body 'femur_r' is not connected to ground"},
};

TEST(OsimCorpus, EveryFileLoadsOrFailsPrecisely) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const std::filesystem::path root = testing::CorpusDir();
  int loaded = 0, failed = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".osim") continue;
    const std::string name = entry.path().filename().string();
    const auto broken = kBroken.find(name);
    try {
      const model::ModelSpec spec = io::ReadOsim(entry.path().string());
      EXPECT_TRUE(broken == kBroken.end()) << name << " loaded but is listed as broken";
      EXPECT_GE(spec.bodies.size(), 1u) << name;
      ++loaded;
    } catch (const Error& e) {
      ++failed;
      if (broken == kBroken.end()) {
        ADD_FAILURE() << "unexpected failure: " << e.what();
        continue;
      }
      EXPECT_NE(std::string(e.what()).find(broken->second), std::string::npos) << e.what();
      EXPECT_EQ(e.where().file, entry.path().string());
      EXPECT_GT(e.where().line, 0);
      EXPECT_FALSE(e.component().empty());
    }
  }
  EXPECT_EQ(failed, static_cast<int>(kBroken.size()));
  EXPECT_EQ(loaded, 135);  // the corpus holds 136 models; one is broken
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// Files written by OpenSim 2.x/3.x state each coordinate's motion_type. Removing those elements
// and deriving the type with the CustomJoint rule (LinearFunction slope +-1 on a rotation or
// translation axis, else coupled) or from the joint type must give back what the file says,
// with one known difference: OpenSim 3 wrote its default, `rotational`, for coordinates that
// drive a rotation axis only through a spline or another non-identity function (wrist_mass
// flexion, Neck3dof pitch, patella
// angles: 12 coordinates in 9 files); the 4.x rule calls those coupled. The reader keeps the
// file's value when there is one, so this matters only for files without motion_type.
TEST(OsimCorpus, DerivedMotionTypesMatchTheOnesOpenSimWrote) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const std::filesystem::path root = testing::CorpusDir();
  int compared = 0, spline_rotations = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".osim") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.find("<motion_type>") == std::string::npos) continue;
    if (kBroken.count(entry.path().filename().string())) continue;
    const model::ModelSpec written = io::ReadOsimString(text, entry.path().string());
    // Blank out every <motion_type>...</motion_type> (same length: lines do not move).
    for (size_t at = text.find("<motion_type>"); at != std::string::npos;
         at = text.find("<motion_type>", at)) {
      const size_t end = text.find("</motion_type>", at) + std::string("</motion_type>").size();
      for (size_t i = at; i < end; ++i) {
        if (text[i] != '\n') text[i] = ' ';
      }
    }
    const model::ModelSpec derived = io::ReadOsimString(text, entry.path().string());
    ASSERT_EQ(written.coordinates.size(), derived.coordinates.size());
    for (size_t i = 0; i < written.coordinates.size(); ++i) {
      if (derived.coordinates[i].motion_type == model::MotionType::kCoupled &&
          written.coordinates[i].motion_type == model::MotionType::kRotational) {
        ++spline_rotations;
        continue;
      }
      EXPECT_EQ(static_cast<int>(written.coordinates[i].motion_type),
                static_cast<int>(derived.coordinates[i].motion_type))
          << entry.path().filename() << " " << written.coordinates[i].path << " written "
          << static_cast<int>(written.coordinates[i].motion_type) << " derived "
          << static_cast<int>(derived.coordinates[i].motion_type);
      ++compared;
    }
  }
  EXPECT_EQ(compared, 683);  // coordinates with a written motion_type, the 12 above excluded
  EXPECT_EQ(spline_rotations, 12);
}

}  // namespace
}  // namespace sinew
