// Finding and reading mesh files the way OpenSim does.
#pragma once

#include <sinew/io/mesh_data.h>

#include <optional>
#include <string>
#include <vector>

namespace sinew::io {

/// Name of the environment variable with extra mesh folders (separated by ':').
inline constexpr const char* kGeometryPathVariable = "SINEW_GEOMETRY_PATH";

/// The folders searched for a model's mesh files, in order: the model's folder, its
/// `Geometry/` subfolder, then `extra_dirs`, then the folders in $SINEW_GEOMETRY_PATH.
std::vector<std::string> MeshSearchDirs(const std::string& model_file,
                                        const std::vector<std::string>& extra_dirs);

/// The first existing `dir/mesh_file` over `dirs` (or `mesh_file` itself when absolute), or
/// nullopt.
std::optional<std::string> FindMeshFile(const std::string& mesh_file,
                                        const std::vector<std::string>& dirs);

/// Reads a .vtp, .obj or .stl file (chosen by extension, case-insensitive). Throws
/// sinew::Error for an unknown extension or a malformed file.
TriangleMesh ReadMesh(const std::string& file);

}  // namespace sinew::io
