// The triangles of an OpenSim ContactMesh: its <filename> found as visual meshes are (the
// model's folder, its Geometry/ subfolder, $SINEW_GEOMETRY_PATH) and read. Shared by the contact
// forces (ElasticFoundationForce) and the collision shapes.
#pragma once

#include <sinew/contact/contact_shape.h>
#include <sinew/model/model_spec.h>

#include <memory>

namespace sinew::opensim::internal {

/// Throws sinew::Error at the geometry's line, naming it, when the mesh has no <filename>, its
/// file is not found, or it has no faces.
std::shared_ptr<const contact::ShapeMesh> ReadContactMesh(const model::ModelSpec& spec,
                                                          const model::ContactGeometrySpec& g);

}  // namespace sinew::opensim::internal
