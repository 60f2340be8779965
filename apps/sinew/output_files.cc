#include "apps/sinew/output_files.h"

#include <sinew/common/error.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace sinew::cli {
namespace {

namespace fs = std::filesystem;

// A path the system can take: each name at most NAME_MAX bytes, the whole at most PATH_MAX.
void CheckNameLengths(const std::string& path, const std::string& option) {
  if (path.empty()) throw Error(option + " is empty: give the name of the output");
  const long name_max = pathconf("/", _PC_NAME_MAX);
  const long path_max = pathconf("/", _PC_PATH_MAX);
  if (path_max > 0 && static_cast<long>(path.size()) >= path_max) {
    throw Error(option + " is " + std::to_string(path.size()) +
                " characters long; the system takes at most " + std::to_string(path_max - 1));
  }
  for (const fs::path& part : fs::path(path)) {
    if (name_max > 0 && static_cast<long>(part.string().size()) > name_max) {
      throw Error(option + " has a name of " + std::to_string(part.string().size()) +
                  " characters ('" + part.string().substr(0, 20) +
                  "...'); the system takes at most " + std::to_string(name_max));
    }
  }
}

void RequireWritableFolder(const std::string& dir, const std::string& option) {
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    throw Error(SourceLocation{dir, 0}, "",
                option + ": cannot write in this folder: " + std::strerror(errno));
  }
}

}  // namespace

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

void PrepareOutputFolder(const std::string& dir, const std::string& option) {
  CheckNameLengths(dir, option);
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    throw Error(SourceLocation{dir, 0}, "",
                option + " must be a folder, and this is an existing file");
  }
  CreateFolder(dir);
  RequireWritableFolder(dir, option);
}

void PrepareOutputFile(const std::string& file, const std::string& option) {
  CheckNameLengths(file, option);
  std::error_code ec;
  if (fs::is_directory(file, ec) || file.back() == '/') {
    throw Error(SourceLocation{file, 0}, "", option + " must be a file name, and this is a folder");
  }
  CreateParentFolder(file);
  const fs::path parent = fs::path(file).parent_path();
  RequireWritableFolder(parent.empty() ? "." : parent.string(), option);
}

}  // namespace sinew::cli
