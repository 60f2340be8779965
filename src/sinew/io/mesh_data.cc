#include <sinew/common/error.h>
#include <sinew/io/mesh_data.h>

#include <string>

namespace sinew::io {

void ComputeVertexNormals(TriangleMesh& mesh) {
  mesh.normals.assign(mesh.positions.size(), Vec3f::Zero());
  for (const auto& t : mesh.triangles) {
    const Vec3f& a = mesh.positions[t[0]];
    // The cross product's length is twice the area: larger faces weigh more.
    const Vec3f n = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    for (uint32_t i : t) mesh.normals[i] += n;
  }
  for (Vec3f& n : mesh.normals) {
    const float length = n.norm();
    n = length > 0 ? Vec3f(n / length) : Vec3f(0, 0, 1);
  }
}

void ValidateMesh(const TriangleMesh& mesh, const std::string& file) {
  const size_t n = mesh.positions.size();
  // A NaN or infinite vertex would reach the .glb (invalid glTF) and the scene bounds.
  for (size_t i = 0; i < n; ++i) {
    if (!mesh.positions[i].allFinite()) {
      throw Error(SourceLocation{file, 0}, "",
                  "vertex " + std::to_string(i) + " has a coordinate that is not a finite number");
    }
  }
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (uint32_t v : mesh.triangles[i]) {
      if (v >= n) {
        throw Error(SourceLocation{file, 0}, "",
                    "triangle " + std::to_string(i) + " refers to vertex " + std::to_string(v) +
                        " but the mesh has " + std::to_string(n) + " vertices");
      }
    }
  }
  if (!mesh.normals.empty() && mesh.normals.size() != n) {
    throw Error(SourceLocation{file, 0}, "",
                "the mesh has " + std::to_string(mesh.normals.size()) + " normals for " +
                    std::to_string(n) + " vertices");
  }
}

}  // namespace sinew::io
