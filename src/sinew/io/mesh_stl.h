// Reader for STL meshes, ASCII and binary.
#pragma once

#include <sinew/io/mesh_data.h>

#include <string>
#include <string_view>

namespace sinew::io {

/// Reads an .stl file, ASCII (`solid ... facet normal ... endsolid`) or binary (80-byte header,
/// triangle count, 50 bytes per triangle). Shared corners are merged so normals are smooth.
/// Throws sinew::Error with file (and line for ASCII) on malformed input.
TriangleMesh ReadStl(const std::string& file);

/// Same, from the file's bytes.
TriangleMesh ParseStl(std::string_view bytes, const std::string& file);

}  // namespace sinew::io
