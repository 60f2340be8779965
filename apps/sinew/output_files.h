// Output paths of the `sinew` commands: folders made on demand, extensions checked up front.
#pragma once

#include <string>

namespace sinew::cli {

/// Creates `dir` and its missing parents. Throws sinew::Error naming it when that fails.
void CreateFolder(const std::string& dir);

/// Creates the folder that will hold `file` (and its parents); nothing for a bare file name.
void CreateParentFolder(const std::string& file);

/// Throws sinew::Error (exit code 2) unless `file` ends in `extension` (e.g. ".png", compared
/// without regard to case); `what` names the format in the message ("PNG").
void RequireExtension(const std::string& file, const std::string& extension,
                      const std::string& what);

}  // namespace sinew::cli
