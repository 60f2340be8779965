// A model copy for tests of what is said about wrap objects Sinew does not wrap over.
#pragma once

#include <fstream>
#include <string>

#include "apps/cli_test_util.h"

namespace sinew::testing {

/// Writes to `copy` the model `model` with every WrapEllipsoid made a MyPluginWrapObject (a
/// plugin's wrap type, which Sinew does not wrap over), and returns `copy`.
inline std::string WriteWithUnsupportedWraps(const std::string& model, const std::string& copy) {
  std::string text = ReadText(model);
  const std::string from = "WrapEllipsoid", to = "MyPluginWrapObject";
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
    text.replace(at, from.size(), to);
    at += to.size();
  }
  std::ofstream(copy) << text;
  return copy;
}

}  // namespace sinew::testing
