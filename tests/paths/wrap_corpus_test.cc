// Every wrap object of the OpenSim corpus (SINEW_CORPUS_DIR) either builds a surface that wraps
// a segment through it to finite tangent points and length, or is refused by type with an error
// naming it. The counts per type equal a grep of the corpus for each element.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/osim_reader.h>
#include <sinew/paths/wrap_surface_factory.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "corpus.h"

namespace sinew::paths {
namespace {

namespace fs = std::filesystem;

TEST(WrapCorpusTest, EveryWrapObjectBuildsOrIsRefusedByType) {
  SINEW_SKIP_WITHOUT_CORPUS();
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(sinew::testing::CorpusDir())) {
    if (entry.is_regular_file() && entry.path().extension() == ".osim") files.push_back(entry);
  }
  std::sort(files.begin(), files.end());
  std::map<std::string, int> built, refused;
  for (const fs::path& file : files) {
    model::ModelSpec spec;
    try {
      spec = io::ReadOsim(file.string());
    } catch (const Error&) {
      continue;  // the reader's own sweep lists the one file it refuses (no wrap objects)
    }
    for (const model::BodySpec& body : spec.bodies) {
      for (const model::WrapObjectSpec& wrap : body.wrap_objects) {
        std::unique_ptr<WrapSurface> surface;
        try {
          surface = MakeWrapSurface(wrap);
        } catch (const Error& error) {
          EXPECT_NE(std::string(error.what()).find(wrap.name), std::string::npos);
          EXPECT_NE(std::string(error.what()).find("is not a wrap surface"), std::string::npos)
              << error.what();
          ++refused[wrap.type];
          continue;
        }
        ++built[wrap.type];
        // A segment through the centre along each axis of W, from far outside on both sides
        // (along z it is parallel to a cylinder's axis and stays straight).
        for (int axis = 0; axis < 3; ++axis) {
          const Vec3 p = Vec3::Unit(axis) * 10.0 + Vec3(1e-3, 2e-3, 3e-3);
          const WrapResult r = surface->Wrap(p, -p, WrapOptions{});
          EXPECT_TRUE(r.p_WT1.allFinite() && r.p_WT2.allFinite() && std::isfinite(r.arc_length))
              << file << " " << wrap.name;
        }
      }
    }
  }
  // grep -o '<WrapCylinder[ >]' etc. over the corpus's .osim files: 428 cylinders, less the 40
  // of opensim-creator_382_repro.osim, which the reader refuses.
  EXPECT_EQ(
      built,
      (std::map<std::string, int>{
          {"WrapCylinder", 388}, {"WrapEllipsoid", 122}, {"WrapSphere", 6}, {"WrapTorus", 4}}));
  EXPECT_TRUE(refused.empty());
}

}  // namespace
}  // namespace sinew::paths
