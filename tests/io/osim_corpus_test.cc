// Every .osim file of the shared corpus (../shared/opensim-data) loads, except the files listed
// below as genuinely broken, which must fail with a precise error (file, line, component).
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "io/osim_reader.h"

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
  const fs::path root = SINEW_SHARED_DATA_DIR;
  if (!fs::exists(root)) GTEST_SKIP() << "no shared corpus at " << root;
  int loaded = 0, failed = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".osim") continue;
    const std::string name = entry.path().filename().string();
    const auto broken = kBroken.find(name);
    try {
      const ModelSpec spec = ReadOsim(entry.path().string());
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
  EXPECT_GT(loaded, 100);  // the corpus holds 136 models
}

}  // namespace
}  // namespace sinew
