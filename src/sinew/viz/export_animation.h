// One call to export a model and its motion for viewing: the entry point for `sinew export`
// and `sinew simulate --export`.
#pragma once

#include <sinew/common/error.h>
#include <sinew/io/storage.h>
#include <sinew/model/model_spec.h>
#include <sinew/viz/body_motion.h>
#include <sinew/viz/collision_parts.h>
#include <sinew/viz/contact_arrows.h>
#include <sinew/viz/floor_plane.h>
#include <sinew/viz/visual_scene.h>

#include <optional>
#include <string>

namespace sinew::viz {

/// Options of ExportAnimation.
struct ExportOptions {
  VisualOptions visual;  ///< Mode (primitives/mesh/none) and extra mesh folders.
  std::string title;     ///< Page/scene title; the model's name when empty.
  /// When > 0, frames closer than 1/max_fps s to the previously kept one are dropped (the
  /// first and last frames are always kept), so long fine-step simulations stay small.
  double max_fps = 0;
  /// Draw the model's paths (muscles, springs, ligaments) when the motion has coordinates.
  bool paths = true;
  /// A table (the states the motion came from) whose activation columns shade the paths
  /// (ShadeByActivation); null or without such columns: every path muscle red.
  const io::Storage* activations = nullptr;
  /// Collision shapes drawn in the contact colour (opensim::CollisionPartsOf).
  std::vector<CollisionPart> collision_parts;
  /// The floor the viewer's grid lies on; unset: ViewFloor (the model's floor).
  std::optional<FloorPlane> floor;
  /// A contacts table (contacts.sto) whose forces are drawn as arrows (ContactArrowsFromTable),
  /// with the bodies of its column groups the caller knows; null: no arrows.
  const io::Storage* contacts = nullptr;
  GroupBodies contact_groups;
};

/// The two export formats, told by the file name's extension.
enum class ExportFormat { kGlb, kHtml };

/// The format of `path`: .glb is binary glTF, .html or .htm the HTML viewer (any case). Throws
/// sinew::Error naming `path` for any other extension, so a command can check before working.
ExportFormat ExportFormatOf(const std::string& path);

/// The frames of `motion` kept for a frame rate of at most `max_fps` (all when <= 0).
BodyMotion ThinMotion(const BodyMotion& motion, double max_fps);

/// Writes `spec` moving along `motion` (body poses X_GB per frame; one frame for a still pose)
/// to `path`: a binary glTF 2.0 file when it ends in .glb, a self-contained HTML viewer when it
/// ends in .html/.htm, with the model's paths as red lines (options.paths, motion.q needed;
/// paths that cannot be drawn are named in the scene's warnings), and the viewer's hints
/// (MakeViewHints on the floor, with the contact arrows of options.contacts; column groups
/// that name no body are in the scene's warnings). Returns the scene it drew: its
/// `warnings` and `missing_meshes` say what could not be drawn as asked. Throws sinew::Error for
/// another extension, a motion whose frames do not cover every body, or an unwritable file.
VisualScene ExportAnimation(const model::ModelSpec& spec, const BodyMotion& motion,
                            const std::string& path, const ExportOptions& options);

}  // namespace sinew::viz
