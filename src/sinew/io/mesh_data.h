// A triangle mesh as read from a geometry file (.vtp, .obj, .stl): vertex positions in the
// file's own frame and units (OpenSim meshes are in metres), optional per-vertex normals.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sinew::io {

/// Single-precision 3-vector: the precision mesh files and glTF store.
using Vec3f = Eigen::Vector3f;

/// An indexed triangle mesh. Triangles are counter-clockwise seen from outside.
struct TriangleMesh {
  std::vector<Vec3f> positions;                    ///< Vertex positions (file units, m).
  std::vector<Vec3f> normals;                      ///< Unit normals per vertex, or empty.
  std::vector<std::array<uint32_t, 3>> triangles;  ///< Vertex indices.

  bool empty() const { return triangles.empty(); }
};

/// Fills `mesh.normals` with area-weighted averages of the adjacent face normals.
void ComputeVertexNormals(TriangleMesh& mesh);

/// Checks that every vertex is finite, every index is in range and normals (if any) match
/// positions; throws sinew::Error naming `file` otherwise. Every mesh reader ends with it.
void ValidateMesh(const TriangleMesh& mesh, const std::string& file);

}  // namespace sinew::io
