#include <sinew/viz/internal/gltf_mesh.h>

namespace sinew::viz::internal {
namespace {

std::vector<float> Flatten(const std::vector<io::Vec3f>& v) {
  std::vector<float> out;
  out.reserve(3 * v.size());
  for (const io::Vec3f& p : v) out.insert(out.end(), {p.x(), p.y(), p.z()});
  return out;
}

}  // namespace

json MeshPrimitive(BinaryBuilder& bin, const io::TriangleMesh& mesh) {
  io::TriangleMesh copy;
  const io::TriangleMesh* m = &mesh;
  if (mesh.normals.size() != mesh.positions.size()) {
    copy = mesh;
    io::ComputeVertexNormals(copy);
    m = &copy;
  }
  std::vector<uint32_t> indices;
  indices.reserve(3 * m->triangles.size());
  for (const auto& t : m->triangles) indices.insert(indices.end(), t.begin(), t.end());
  return {{"attributes",
           {{"POSITION", bin.AddFloats(Flatten(m->positions), "VEC3", 3, kArrayBuffer, true)},
            {"NORMAL", bin.AddFloats(Flatten(m->normals), "VEC3", 3, kArrayBuffer, false)}}},
          {"indices", bin.AddIndices(indices)},
          {"mode", 4}};
}

}  // namespace sinew::viz::internal
