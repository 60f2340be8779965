// The corpus of real OpenSim files that the corpus sweeps read: the folder given to CMake as
// SINEW_CORPUS_DIR (tests/CMakeLists.txt). Without it those tests are skipped, loudly.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <vector>

namespace sinew::testing {

/// The corpus folder, or an empty path when the build was configured without one.
inline std::filesystem::path CorpusDir() { return std::filesystem::path(SINEW_CORPUS_DIR); }

/// The corpus's .osim files smaller than `max_bytes`, sorted.
inline std::vector<std::filesystem::path> CorpusModelFiles(
    std::uintmax_t max_bytes = std::numeric_limits<std::uintmax_t>::max()) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(CorpusDir())) {
    if (entry.is_regular_file() && entry.path().extension() == ".osim" &&
        entry.file_size() < max_bytes) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sinew::testing

/// First statement of a corpus sweep: skips the test (ctest lists it as skipped) when the build
/// was configured without a corpus.
#define SINEW_SKIP_WITHOUT_CORPUS()                                                   \
  if (::sinew::testing::CorpusDir().empty())                                          \
  GTEST_SKIP() << "no corpus configured (cmake -DSINEW_CORPUS_DIR=<folder>): corpus " \
                  "sweep not run"
