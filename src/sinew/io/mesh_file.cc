#include <sinew/common/error.h>
#include <sinew/io/mesh_file.h>
#include <sinew/io/mesh_obj.h>
#include <sinew/io/mesh_stl.h>
#include <sinew/io/mesh_vtp.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace sinew::io {

namespace fs = std::filesystem;

std::vector<std::string> MeshSearchDirs(const std::string& model_file,
                                        const std::vector<std::string>& extra_dirs) {
  std::vector<std::string> dirs;
  fs::path folder = fs::path(model_file).parent_path();
  if (folder.empty()) folder = ".";
  dirs.push_back(folder.string());
  dirs.push_back((folder / "Geometry").string());
  dirs.insert(dirs.end(), extra_dirs.begin(), extra_dirs.end());
  if (const char* env = std::getenv(kGeometryPathVariable)) {
    std::string_view list = env;
    while (!list.empty()) {
      const size_t colon = list.find(':');
      std::string_view dir = list.substr(0, colon);
      if (!dir.empty()) dirs.emplace_back(dir);
      if (colon == std::string_view::npos) break;
      list.remove_prefix(colon + 1);
    }
  }
  return dirs;
}

std::optional<std::string> FindMeshFile(const std::string& mesh_file,
                                        const std::vector<std::string>& dirs) {
  std::error_code ec;
  const fs::path name(mesh_file);
  if (name.is_absolute()) {
    if (fs::is_regular_file(name, ec)) return name.string();
    return std::nullopt;
  }
  for (const std::string& dir : dirs) {
    const fs::path candidate = fs::path(dir) / name;
    if (fs::is_regular_file(candidate, ec)) return candidate.string();
  }
  return std::nullopt;
}

TriangleMesh ReadMesh(const std::string& file) {
  std::string ext = fs::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".vtp") return ReadVtp(file);
  if (ext == ".obj") return ReadObj(file);
  if (ext == ".stl") return ReadStl(file);
  throw Error(SourceLocation{file, 0}, "",
              "unsupported mesh format '" + ext + "' (expected .vtp, .obj or .stl)");
}

}  // namespace sinew::io
