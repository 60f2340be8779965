// Reader for VTK XML PolyData files (.vtp), the format of OpenSim's bone meshes.
#pragma once

#include <sinew/io/mesh_data.h>

#include <string>

namespace sinew::io {

/// Reads the polygons and triangle strips of a .vtp file as triangles (polygons are fanned),
/// with the point normals when the file has them. Data arrays may be `ascii` or inline
/// `binary` (base64), raw or compressed with `vtkZLibDataCompressor`, with UInt32 or UInt64
/// headers, little- or big-endian. Throws sinew::Error with file and line for anything else.
TriangleMesh ReadVtp(const std::string& file);

/// Same, from the text of a .vtp document; `file` names it in messages.
TriangleMesh ParseVtp(std::string text, const std::string& file);

}  // namespace sinew::io
