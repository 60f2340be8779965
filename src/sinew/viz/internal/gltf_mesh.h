// Internal to the glTF writer: a triangle mesh as a glTF primitive.
#pragma once

#include <sinew/io/mesh_data.h>
#include <sinew/viz/internal/glb_builder.h>

namespace sinew::viz::internal {

/// Adds `mesh`'s positions, normals (computed when it has none) and triangles to `bin` and
/// returns the primitive (mode TRIANGLES, no material) that uses them.
json MeshPrimitive(BinaryBuilder& bin, const io::TriangleMesh& mesh);

}  // namespace sinew::viz::internal
