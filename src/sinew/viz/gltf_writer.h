// Binary glTF 2.0 (.glb) export of a visual scene, with body motion as an animation.
#pragma once

#include <sinew/viz/body_motion.h>
#include <sinew/viz/path_lines.h>
#include <sinew/viz/view_hints.h>
#include <sinew/viz/visual_scene.h>

#include <cstdint>
#include <string>
#include <vector>

namespace sinew::viz {

/// Builds a .glb: one node per body (named after it, posed at the first frame), one child
/// node per part carrying the part's X_BG and scale and a mesh with its material. When the
/// motion has two or more frames, one animation samples every body's translation and rotation
/// (quaternion xyzw) at the motion's times, shifted to start at 0 (the first time is kept in
/// the animation's extras as "start_time"). Units are metres, y up, as in OpenSim.
/// With `lines` (one frame per motion frame), a node "paths" holds one LINES mesh per frame
/// (all paths, in ground; the node's extras name the paths, the meshes' extras give their
/// vertex counts), and the
/// animation shows frame k's mesh (scale 1, STEP) from its time to the next frame's, hiding
/// it (scale 0) otherwise: the simplest animation of lines whose point count changes.
/// With `hints`, the scene's extras carry them for the HTML viewer ("floor", "grid",
/// "follow_body", "contact_arrows"), and each contact arrow (one frame per motion frame) is a
/// node "contact <force>.<group>" under a node "contact_forces", animated with the motion
/// (docs/contact.md, "Seeing it").
std::vector<uint8_t> WriteGlb(const VisualScene& scene, const BodyMotion& motion,
                              const std::string& model_name, const PathLines* lines = nullptr,
                              const ViewHints* hints = nullptr);

/// Writes bytes to a file, atomically (sinew::WriteFileAtomically); throws sinew::Error when the
/// file cannot be written.
void WriteFileBytes(const std::string& path, const std::vector<uint8_t>& bytes);

}  // namespace sinew::viz
