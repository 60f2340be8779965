// A small software renderer (z-buffer, per-pixel Lambert shading, 2x2 supersampling), so
// `sinew render` makes pictures without a display, a GPU or a browser.
#pragma once

#include <sinew/math/transform.h>
#include <sinew/viz/floor_plane.h>
#include <sinew/viz/image.h>
#include <sinew/viz/visual_scene.h>

#include <optional>
#include <string>
#include <vector>

namespace sinew::viz {

/// A perspective camera in ground coordinates.
struct Camera {
  Vec3 eye = Vec3(3, 1, 3);    ///< Eye position (m).
  Vec3 target = Vec3::Zero();  ///< Point looked at (m).
  Vec3 up = Vec3::UnitY();     ///< Approximate up direction.
  double fov_y = 0.6;          ///< Vertical field of view (rad).
};

/// Options of RenderScene.
struct RenderOptions {
  int width = 800;
  int height = 600;
  /// Direction from the model to the eye when the camera is framed automatically, in ground:
  /// OpenSim's x points forward, y up, z to the model's right.
  Vec3 view_direction = Vec3(1.0, 0.35, 0.8);
  Vec3 background = Vec3(0.96, 0.96, 0.96);  ///< RGB in [0, 1].
  /// A floor with the model's shadow on it from the key light: on `floor_plane` when given
  /// (ModelFloor, FloorUnder), else under the model's lowest point.
  bool floor = false;
  std::optional<FloorPlane> floor_plane;
  Vec3 line_color = Vec3(0.8, 0.1, 0.1);  ///< RGB of the lines (muscle paths).
  double line_width = 2.0;                ///< Line width (pixels).
  /// Parts in ground (X_BG is each one's pose in ground) drawn last, over the model and the
  /// lines (depth-tested only among themselves), casting no shadow, as the viewer draws the
  /// contact force arrows (ContactArrowParts). RenderFramed frames them with the model.
  std::vector<VisualPart> overlay;
};

/// Parses a view name: "front" (from +x), "back", "right" (from +z), "left", "top" or "iso".
/// Throws sinew::Error otherwise.
Vec3 ParseViewDirection(const std::string& view);

/// World-space bounds of the posed scene (min, max), ground's parts left out unless
/// `with_ground`, and the stand-ins of unbounded shapes (VisualPart::unbounded: half-space
/// slabs) unless nothing else is there; an empty scene gives a unit box.
std::pair<Vec3, Vec3> SceneBounds(const VisualScene& scene, const std::vector<Transform>& X_GB,
                                  bool with_ground = true);

/// A camera looking at the bounds' centre from `direction`, far enough that the bounding
/// sphere fits the view at the given aspect ratio (width / height).
Camera FrameCamera(const std::pair<Vec3, Vec3>& bounds, const Vec3& direction, double aspect);

/// The most memory RenderScene may take for its buffers: 1 GiB, about 9 million pixels (a
/// 3840 x 2160 image fits). The pixel limits alone (16384 x 16384) would allow 30 GB.
inline constexpr size_t kMaxRenderBytes = size_t{1} << 30;

/// The bytes RenderScene needs for a `width` x `height` image: the 2x2 supersampled depth and
/// colour buffers and the final image, held together while it resolves (about 115 bytes a
/// pixel). Encoding the PNG afterwards needs about 12 bytes a pixel, less than that.
size_t RenderBytes(int width, int height);

/// Throws sinew::Error unless a `width` x `height` image is 1..16384 pixels each way and
/// RenderBytes(width, height) <= kMaxRenderBytes; the message gives both figures.
void CheckRenderSize(int width, int height);

/// Renders the scene with bodies posed at X_GB (one transform per spec body), and over it the
/// polylines `lines` (points in ground, m; e.g. PathLines::vertices of one frame), depth-tested
/// against the bodies, line i in line_colors[i] when given, else in options.line_color. Throws
/// sinew::Error when CheckRenderSize refuses the size in `options`.
Image RenderScene(const VisualScene& scene, const std::vector<Transform>& X_GB,
                  const Camera& camera, const RenderOptions& options,
                  const std::vector<std::vector<Vec3>>& lines = {},
                  const std::vector<Vec3>& line_colors = {});

/// `bounds` grown to hold every point of `lines`.
std::pair<Vec3, Vec3> GrowBounds(std::pair<Vec3, Vec3> bounds,
                                 const std::vector<std::vector<Vec3>>& lines);

/// Renders the scene posed at X_GB, with the polylines `lines` as RenderScene draws them, and the
/// camera framed automatically: FrameCamera on the bounds of the posed bodies, the lines (the
/// lines' alone when no body has geometry) and options.overlay's parts, from
/// options.view_direction, at the aspect ratio of the image (what `sinew render` and Python's
/// Model.render draw). Throws as RenderScene.
Image RenderFramed(const VisualScene& scene, const std::vector<Transform>& X_GB,
                   const RenderOptions& options, const std::vector<std::vector<Vec3>>& lines = {},
                   const std::vector<Vec3>& line_colors = {});

}  // namespace sinew::viz
