// The corpus of real OpenSim files that the corpus sweeps read: the folder given to CMake as
// SINEW_CORPUS_DIR (tests/CMakeLists.txt). Without it those tests are skipped, loudly.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>

namespace sinew::testing {

/// The corpus folder, or an empty path when the build was configured without one.
inline std::filesystem::path CorpusDir() { return std::filesystem::path(SINEW_CORPUS_DIR); }

}  // namespace sinew::testing

/// First statement of a corpus sweep: skips the test (ctest lists it as skipped) when the build
/// was configured without a corpus.
#define SINEW_SKIP_WITHOUT_CORPUS()                                                   \
  if (::sinew::testing::CorpusDir().empty())                                          \
  GTEST_SKIP() << "no corpus configured (cmake -DSINEW_CORPUS_DIR=<folder>): corpus " \
                  "sweep not run"
