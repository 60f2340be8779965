// Every model of the OpenSim corpus (SINEW_CORPUS_DIR) with geometry paths: the paths compile,
// and at the default pose every length, lengthening speed (zero speeds) and moment arm about
// every free coordinate is finite. The count of such models is exact, so a model that newly
// fails (or newly has paths) fails the test until the expectation is changed on purpose.
#include <gtest/gtest.h>
#include <sinew/paths/path_analysis.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "corpus.h"
#include "paths/path_derivative_check.h"
#include "paths/path_test_util.h"

namespace sinew::paths {
namespace {

namespace fs = std::filesystem;

TEST(CorpusPathsTest, EveryModelsPathsComputeAtTheDefaultPose) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const std::vector<fs::path> files = sinew::testing::CorpusModelFiles();
  int with_paths = 0, paths_total = 0, wraps_total = 0, unconnected_total = 0;
  for (const fs::path& file : files) {
    std::unique_ptr<testing::PathModel> m;
    try {
      m = std::make_unique<testing::PathModel>(file.string());
    } catch (const Error& e) {
      // The reader's one refusal (see docs/testing.md), or a joint the tree cannot model.
      std::cout << "not read: " << e.what() << "\n";
      continue;
    }
    if (m->paths.paths().empty()) continue;
    ++with_paths;
    std::vector<int> free;
    for (size_t c = 0; c < m->spec.coordinates.size(); ++c) {
      if (!m->spec.coordinates[c].locked && !m->couplers.Drives(static_cast<int>(c))) {
        free.push_back(static_cast<int>(c));
      }
    }
    std::vector<double> q = m->tree.default_q();
    m->couplers.Apply(q);
    PathAnalysis analysis(m->spec, m->tree, m->couplers, m->paths, free);
    try {
      analysis.Calc(q, std::vector<double>(q.size(), 0.0));
    } catch (const Error& e) {
      ADD_FAILURE() << file << ": " << e.what();
      continue;
    }
    for (size_t p = 0; p < m->paths.paths().size(); ++p) {
      const std::string& name = m->paths.paths()[p].name();
      EXPECT_TRUE(std::isfinite(analysis.lengths()[p]) && analysis.lengths()[p] > 0.0)
          << file << " " << name;
      EXPECT_EQ(analysis.lengthening_speeds()[p], 0.0) << file << " " << name;
      for (size_t k = 0; k < free.size(); ++k) {
        EXPECT_TRUE(std::isfinite(analysis.moment_arm(k, p))) << file << " " << name;
      }
      for (const PathWrap& wrap : m->paths.paths()[p].wraps()) {
        ++wraps_total;
        unconnected_total += wrap.surface ? 0 : 1;
      }
    }
    paths_total += static_cast<int>(m->paths.paths().size());
  }
  std::cout << with_paths << " models, " << paths_total << " paths, " << wraps_total
            << " path wraps (" << unconnected_total << " over unsupported types, not applied)\n";
  EXPECT_EQ(with_paths, 78);
  // Every wrap object type the corpus's paths use (cylinders, ellipsoids, spheres, tori) wraps.
  EXPECT_EQ(unconnected_total, 0);
}

// The check on every corpus model with paths: at the default pose and one random pose,
// every path's moment arm about every coordinate (coupled coordinates moving along) and its
// lengthening speed equal the derivatives of its length, by central differences, to the
// differences' own error bound (testing::CheckMomentArmsAndSpeeds: tangent points carried by
// their wrap bodies, as OpenSim's analytic values are; unwrapped paths also against the length
// recomputed afresh); and the generalized force of a tension is -tension dL/du.
TEST(CorpusPathsTest, EveryModelsMomentArmsAreDerivativesOfLength) {
  SINEW_SKIP_WITHOUT_CORPUS();
  int checked = 0;
  for (const fs::path& file : sinew::testing::CorpusModelFiles()) {
    std::unique_ptr<testing::PathModel> m;
    try {
      m = std::make_unique<testing::PathModel>(file.string());
    } catch (const Error&) {
      continue;  // counted and reported by EveryModelsPathsComputeAtTheDefaultPose
    }
    if (m->paths.paths().empty()) continue;
    SCOPED_TRACE(file.string());
    const std::vector<std::vector<double>> poses = testing::MakePoses(*m, 1);
    testing::CheckMomentArmsAndSpeeds(*m, file.filename().string(), poses, false);
    testing::CheckGeneralizedForces(*m, poses);
    ++checked;
  }
  EXPECT_EQ(checked, 78);
}

}  // namespace
}  // namespace sinew::paths
