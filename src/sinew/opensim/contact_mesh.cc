#include <sinew/common/error.h>
#include <sinew/io/mesh_file.h>
#include <sinew/opensim/internal/contact_mesh.h>

#include <string>

namespace sinew::opensim::internal {
namespace {

[[noreturn]] void FailAt(const model::ModelSpec& spec, const model::ContactGeometrySpec& g,
                         const std::string& message) {
  throw Error({spec.file, g.where.line}, "/contactgeometryset/" + g.name, message);
}

}  // namespace

std::shared_ptr<const contact::ShapeMesh> ReadContactMesh(
    const model::ModelSpec& spec, const model::ContactGeometrySpec& g,
    const std::vector<std::string>& geometry_dirs) {
  if (g.mesh_file.empty()) FailAt(spec, g, "ContactMesh has no <filename>");
  const std::vector<std::string> dirs = io::MeshSearchDirs(spec.file, geometry_dirs);
  const std::optional<std::string> file = io::FindMeshFile(g.mesh_file, dirs);
  if (!file) {
    std::string searched;
    for (const std::string& dir : dirs) searched += (searched.empty() ? "" : ", ") + dir;
    FailAt(spec, g,
           "mesh file '" + g.mesh_file + "' not found in " + searched +
               " (the model's folder, its Geometry/ folder, --geometry-dir and $" +
               io::kGeometryPathVariable + ")");
  }
  const io::TriangleMesh read = io::ReadMesh(*file);
  auto mesh = std::make_shared<contact::ShapeMesh>();
  for (const io::Vec3f& v : read.positions) mesh->vertices.push_back(v.cast<double>());
  for (const auto& t : read.triangles)
    mesh->triangles.push_back(
        {static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  if (mesh->triangles.empty()) FailAt(spec, g, "mesh file '" + *file + "' has no faces");
  return mesh;
}

}  // namespace sinew::opensim::internal
