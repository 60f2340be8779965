// Internal to the glTF writer: the viewer's hints in the scene's extras, and contact force
// arrows as animated nodes.
#pragma once

#include <sinew/viz/internal/glb_builder.h>
#include <sinew/viz/view_hints.h>

#include <vector>

namespace sinew::viz::internal {

/// The nodes of one arrow: `arrow` (at the start point, +y turned along the force, scale 0
/// when there is no force), its children `shaft` (a cylinder from y = 0 to its y scale) and
/// `head` (a cone from its y translation, its y scale long).
struct ArrowNodes {
  int arrow = 0, shaft = 0, head = 0;
};

/// The scene extras of `hints` (floor, grid, follow, contact_arrows; docs/contact.md).
json ViewHintsExtras(const ViewHints& hints, const std::vector<int>& arrow_nodes);

/// Adds a node "contact_forces" with one arrow per entry of `arrows` (green), posed at frame 0.
/// Returns its index; `nodes` gets each arrow's nodes.
int AddArrowNodes(json& doc, BinaryBuilder& bin, const ContactArrows& arrows,
                  std::vector<ArrowNodes>& nodes);

/// Appends the channels that pose every arrow at each frame (LINEAR, the time input
/// accessor `input`).
void AddArrowChannels(BinaryBuilder& bin, int input, const ContactArrows& arrows,
                      const std::vector<ArrowNodes>& nodes, json& samplers, json& channels);

}  // namespace sinew::viz::internal
