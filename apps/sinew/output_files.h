// Output paths of the `sinew` commands, checked up front (before any work is done): folders
// made on demand, extensions, names the system accepts, writable folders.
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

/// Checks the output folder `dir` given with `option` and creates it (with its parents): not
/// empty, not a file, names the system accepts, writable. Throws sinew::Error naming it.
void PrepareOutputFolder(const std::string& dir, const std::string& option = "--out");

/// Checks the output file `file` given with `option` and creates its folder: not empty, not a
/// folder, names the system accepts, a writable folder. Throws sinew::Error naming it.
void PrepareOutputFile(const std::string& file, const std::string& option = "--out");

}  // namespace sinew::cli
