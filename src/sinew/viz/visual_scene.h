// What a model looks like: per body, a list of triangle-mesh parts posed in the body frame.
// Built once from the spec; exporters and the renderer then only need body poses X_GB.
#pragma once

#include <sinew/common/error.h>
#include <sinew/io/mesh_data.h>
#include <sinew/math/transform.h>
#include <sinew/model/model_spec.h>

#include <memory>
#include <string>
#include <vector>

namespace sinew::viz {

/// How bodies are drawn (the seed's three visualization modes).
enum class VisType {
  kNone,        ///< Nothing: bodies carry no geometry (the default).
  kPrimitives,  ///< A sphere at each body frame, cylinders to its joints, coloured by depth.
  kMesh,        ///< The model's attached geometry (mesh files and analytic shapes).
  // The seed's spellings, so that programs written against its API compile unchanged.
  NONE = kNone,
  PRIMITIVES = kPrimitives,
  MESH = kMesh,
};

/// Parses "none", "primitives" or "mesh"; throws sinew::Error otherwise.
VisType ParseVisType(const std::string& text);

/// The colour of contact geometry (OpenSim's ContactSphere, ContactHalfSpace, ContactMesh,
/// ContactEllipsoid), drawn with the bodies in the primitives and mesh modes: orange, a colour
/// no other part uses.
inline const Vec3 kContactColor = Vec3(1.0, 0.5, 0.05);

/// One drawable piece fixed to a body: vertex v of `mesh` is at X_BG * (scale .* v) in B.
struct VisualPart {
  std::string name;
  std::shared_ptr<const io::TriangleMesh> mesh;
  Transform X_BG;                    ///< Pose of the part in the body frame.
  Vec3 scale = Vec3::Ones();         ///< Per-axis scale applied before X_BG.
  Vec3 color = Vec3(0.9, 0.9, 0.9);  ///< RGB in [0, 1].
  double opacity = 1.0;
  std::string source;  ///< Mesh file read, or the shape's kind ("Sphere").
  /// A finite stand-in for an unbounded shape (a half-space's slab): drawn, but left out of the
  /// bounds a camera is framed on (SceneBounds).
  bool unbounded = false;
};

/// The parts of one body (index into ModelSpec::bodies).
struct VisualBody {
  std::string name;
  int body = model::kGroundIndex;
  std::vector<VisualPart> parts;
};

/// A geometry whose mesh file was found in none of the searched folders.
/// A mesh file that was read: the name the model gives and the file found for it.
struct ReadMeshFile {
  std::string file;  ///< As the model names it ("r_patella.vtp", "../shared/x.obj", "/abs/y.stl").
  std::string path;  ///< The file read, in the first search folder that has it (or as given).
};

struct MissingMesh {
  std::string file;    ///< The mesh file as the model names it (e.g. "r_patella.vtp").
  size_t warning = 0;  ///< Index of its entry in VisualScene::warnings.
};

/// Everything drawable in a model, one entry per spec body in the same order.
struct VisualScene {
  std::vector<VisualBody> bodies;
  Diagnostics warnings;  ///< Missing meshes, unsupported shapes, fallbacks.
  /// One entry per geometry whose mesh file was not found (each also in `warnings`), in
  /// model order; a file several geometries use appears once per geometry.
  std::vector<MissingMesh> missing_meshes;
  /// The folders searched for mesh files, in search order (kMesh mode only).
  std::vector<std::string> mesh_dirs;
  /// Every mesh file read, once each, in model order: where each one came from.
  std::vector<ReadMeshFile> read_meshes;
};

/// Options for BuildVisualScene.
struct VisualOptions {
  VisType mode = VisType::kMesh;
  std::vector<std::string> geometry_dirs;  ///< Searched after the model's folders.
};

/// Builds the scene of `spec` in `options.mode`. In kMesh mode a mesh file is searched in the
/// model's folder, its Geometry/ subfolder, `geometry_dirs`, then $SINEW_GEOMETRY_PATH, as
/// OpenSim searches: a relative name is joined to each folder as written (so "../x.vtp" may
/// leave it), an absolute name is used as given; `read_meshes` says which file was read. A body
/// whose mesh is missing or unreadable gets a warning naming the file and the folders searched,
/// and is drawn with primitives instead. Mesh files shared by several bodies are read once.
VisualScene BuildVisualScene(const model::ModelSpec& spec, const VisualOptions& options);

}  // namespace sinew::viz
