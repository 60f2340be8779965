// The triangles of an OpenSim ContactMesh: its <filename> found as visual meshes are (the
// model's folder, its Geometry/ subfolder, the parser's geometry folders (`--geometry-dir`),
// $SINEW_GEOMETRY_PATH) and read. Shared by the contact forces (ElasticFoundationForce) and the
// collision shapes.
#pragma once

#include <sinew/contact/contact_shape.h>
#include <sinew/model/model_spec.h>

#include <memory>
#include <string>
#include <vector>

namespace sinew::opensim::internal {

/// `geometry_dirs` are searched after the model's folder and its Geometry/ subfolder (as
/// io::MeshSearchDirs). Throws sinew::Error at the geometry's line, naming it, when the mesh has
/// no <filename>, its file is not found (the message lists the folders searched), or it has no
/// faces.
std::shared_ptr<const contact::ShapeMesh> ReadContactMesh(
    const model::ModelSpec& spec, const model::ContactGeometrySpec& g,
    const std::vector<std::string>& geometry_dirs);

}  // namespace sinew::opensim::internal
