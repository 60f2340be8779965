// Reader for Wavefront .obj meshes (the geometry part: v, vn, f).
#pragma once

#include <sinew/io/mesh_data.h>

#include <string>

namespace sinew::io {

/// Reads vertices and faces of an .obj file; polygons are fanned into triangles, negative
/// (relative) indices are honoured, `v/vt/vn` corners keep their normals. Materials, texture
/// coordinates, groups and lines are ignored. Throws sinew::Error with file and line.
TriangleMesh ReadObj(const std::string& file);

/// Same, from the file's text.
TriangleMesh ParseObj(std::string_view text, const std::string& file);

}  // namespace sinew::io
