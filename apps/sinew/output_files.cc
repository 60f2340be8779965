#include "apps/sinew/output_files.h"

#include <sinew/common/error.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace sinew::cli {

void CreateFolder(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(SourceLocation{dir, 0}, "", "cannot create folder: " + ec.message());
}

void CreateParentFolder(const std::string& file) {
  const std::filesystem::path parent = std::filesystem::path(file).parent_path();
  if (!parent.empty()) CreateFolder(parent.string());
}

void RequireExtension(const std::string& file, const std::string& extension,
                      const std::string& what) {
  std::string ext = std::filesystem::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != extension) {
    throw Error(SourceLocation{file, 0}, "",
                "the output is written as " + what + " only: its name must end in " + extension +
                    (ext.empty() ? " (it has no extension)" : ", not " + ext));
  }
}

}  // namespace sinew::cli
