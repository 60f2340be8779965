// What the HTML viewer needs besides the scene and its animation: the floor its grid lies on,
// the grid's extent, the body the camera follows, the contact force arrows. WriteGlb keeps them
// in the glTF scene's extras (docs/contact.md, "Seeing it").
#pragma once

#include <sinew/model/model_spec.h>
#include <sinew/viz/body_motion.h>
#include <sinew/viz/contact_arrows.h>
#include <sinew/viz/floor_plane.h>
#include <sinew/viz/visual_scene.h>

#include <utility>

namespace sinew::viz {

struct ViewHints {
  FloorPlane floor;
  Vec3 grid_center = Vec3::Zero();  ///< Centre of the grid's square, on the floor (m).
  double grid_size = 2;             ///< Side of the grid's square (m).
  /// The spec body the camera follows when the page opens (model::kNone: none).
  int follow_body = model::kNone;
  ContactArrows arrows;  ///< Drawn when not empty.
};

/// The box of the model in the first frame of `motion`: its bodies' drawn parts (ground's left
/// out) and their origins.
std::pair<Vec3, Vec3> FirstPoseBounds(const VisualScene& scene, const BodyMotion& motion);

/// The floor a viewer or picture of `spec` in the first pose of `motion` shows:
/// FloorUnder(ModelFloor(spec), FirstPoseBounds(scene, motion)).
FloorPlane ViewFloor(const model::ModelSpec& spec, const VisualScene& scene,
                     const BodyMotion& motion);

/// The hints for `motion` of `spec` drawn as `scene`, on `floor`: the grid is a square of the
/// floor holding every body origin of every frame and the first pose, with half the model's
/// size to spare on each side (at least 2 m, and twice the model's size); the camera follows
/// the first body (spec order) whose origin moves farther from where it starts than the model's
/// size in the first frame (a falling, rolling or walking model), none otherwise.
ViewHints MakeViewHints(const model::ModelSpec& spec, const VisualScene& scene,
                        const BodyMotion& motion, const FloorPlane& floor);

}  // namespace sinew::viz
