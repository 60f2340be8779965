// Triangle meshes of unit analytic shapes, used for OpenSim's analytic geometry (Sphere,
// Cylinder, Brick, Ellipsoid, Cone, Torus) and for the PRIMITIVES skeleton. Each shape is
// scaled into place by the part's scale factors, so one tessellation serves every instance.
#pragma once

#include <sinew/io/mesh_data.h>

#include <memory>

namespace sinew::viz {

/// Sphere of radius 1 at the origin.
std::shared_ptr<const io::TriangleMesh> UnitSphere();
/// Cylinder of radius 1 along y from y = -1 to y = 1, with caps (OpenSim's cylinder axis is y).
std::shared_ptr<const io::TriangleMesh> UnitCylinder();
/// Box with half-lengths 1 (x, y, z in [-1, 1]).
std::shared_ptr<const io::TriangleMesh> UnitBox();
/// Cone with base radius 1 in the plane y = 0 and apex at y = 1, with a base cap.
std::shared_ptr<const io::TriangleMesh> UnitCone();
/// Torus in the x-z plane around y: ring radius 1, tube radius `tube_ratio`.
std::shared_ptr<const io::TriangleMesh> MakeTorus(double tube_ratio);

}  // namespace sinew::viz
