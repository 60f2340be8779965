// Internal to the glTF writer: muscle paths as line meshes, one per frame, shown one at a time.
#pragma once

#include <sinew/viz/internal/glb_builder.h>
#include <sinew/viz/path_lines.h>

#include <vector>

namespace sinew::viz::internal {

/// Adds a node "paths" with one child node per frame of `lines`, each with a LINES mesh of
/// every path's polyline at that frame, one after the other (one red material). The "paths"
/// node's extras name the paths ("paths": [...]); each mesh's extras give their vertex counts
/// in that order ("vertex_counts": [...]). Child k has scale 1 at frame 0 only, else 0.
/// Returns the "paths" node's index; `frame_nodes` gets the children's indices.
int AddPathNodes(json& doc, BinaryBuilder& bin, const PathLines& lines,
                 std::vector<int>& frame_nodes);

/// Appends, per frame node k, a STEP scale channel that shows it (scale 1) from times[k] to
/// times[k + 1] and hides it (scale 0) the rest of the time; times start at 0 and increase.
void AddPathChannels(BinaryBuilder& bin, const std::vector<float>& times,
                     const std::vector<int>& frame_nodes, json& samplers, json& channels);

}  // namespace sinew::viz::internal
