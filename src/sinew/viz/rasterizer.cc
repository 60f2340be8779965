#include <sinew/common/error.h>
#include <sinew/viz/rasterizer.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew::viz {
namespace {

constexpr int kSupersample = 2;  // samples per pixel along each axis

// World pose of every vertex and normal of a part.
struct PosedPart {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
};

PosedPart Pose(const VisualPart& part, const Transform& X_GB) {
  PosedPart out;
  const Transform X_GG = X_GB * part.X_BG;  // part frame in ground
  // Normals transform with the inverse transpose of R * diag(scale).
  // (A zero scale flattens the part; its normals then follow the unflattened axes.)
  const Vec3 inv_scale = part.scale.unaryExpr([](double s) { return s == 0 ? 1.0 : 1.0 / s; });
  const io::TriangleMesh& m = *part.mesh;
  out.positions.reserve(m.positions.size());
  out.normals.reserve(m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    out.positions.push_back(X_GG * part.scale.cwiseProduct(m.positions[i].cast<double>()));
    const Vec3 n = i < m.normals.size() ? Vec3(m.normals[i].cast<double>()) : Vec3::UnitY();
    const Vec3 normal = X_GG.R * inv_scale.cwiseProduct(n);
    out.normals.push_back(normal.allFinite() && normal.norm() > 0 ? Vec3(normal.normalized())
                                                                  : Vec3::UnitY());
  }
  return out;
}

}  // namespace

Vec3 ParseViewDirection(const std::string& view) {
  if (view == "front") return Vec3(1, 0.15, 0);
  if (view == "back") return Vec3(-1, 0.15, 0);
  if (view == "right") return Vec3(0, 0.15, 1);
  if (view == "left") return Vec3(0, 0.15, -1);
  if (view == "top") return Vec3(0.01, 1, 0);
  if (view == "iso") return Vec3(1.0, 0.35, 0.8);
  throw Error("unknown view '" + view + "' (front, back, right, left, top or iso)");
}

std::pair<Vec3, Vec3> SceneBounds(const VisualScene& scene, const std::vector<Transform>& X_GB,
                                  bool with_ground) {
  // The unbounded shapes' stand-ins only when nothing else is there.
  for (const bool with_unbounded : {false, true}) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const VisualBody& body : scene.bodies) {
      if (body.body >= static_cast<int>(X_GB.size())) continue;
      if (!with_ground && body.body == model::kGroundIndex) continue;
      for (const VisualPart& part : body.parts) {
        if (!part.mesh || (part.unbounded && !with_unbounded)) continue;
        for (const Vec3& p : Pose(part, X_GB[body.body]).positions) {
          lo = lo.cwiseMin(p);
          hi = hi.cwiseMax(p);
        }
      }
    }
    if (lo.x() <= hi.x()) return {lo, hi};
  }
  return {Vec3::Constant(-1), Vec3::Constant(1)};
}

Camera FrameCamera(const std::pair<Vec3, Vec3>& bounds, const Vec3& direction, double aspect) {
  Camera camera;
  camera.target = 0.5 * (bounds.first + bounds.second);
  const double radius = std::max(0.5 * (bounds.second - bounds.first).norm(), 1e-3);
  const double fov = std::min(camera.fov_y, 2 * std::atan(aspect * std::tan(camera.fov_y / 2)));
  camera.eye = camera.target + direction.normalized() * (1.05 * radius / std::sin(fov / 2));
  return camera;
}

namespace {

// The supersampled frame being drawn: camera basis, depth and colour per sample.
class Canvas {
 public:
  Canvas(const Camera& camera, int w, int h, const Vec3& background)
      : w_(w), h_(h), eye_(camera.eye) {
    cz_ = (camera.eye - camera.target).normalized();  // the camera looks down -cz
    cx_ = camera.up.cross(cz_);
    if (cx_.norm() < 1e-9) cx_ = Vec3::UnitX().cross(cz_);
    cx_.normalize();
    cy_ = cz_.cross(cx_);
    focal_ = 0.5 * h / std::tan(0.5 * camera.fov_y);  // pixels
    near_ = 1e-3 * (camera.eye - camera.target).norm();
    depth_.assign(static_cast<size_t>(w) * h, std::numeric_limits<float>::infinity());
    color_.assign(static_cast<size_t>(w) * h, background);
  }

  const Vec3& view_axis() const { return cz_; }

  // Draws one triangle (ground coordinates). With `lit`, colour is Lambert-shaded from the
  // interpolated normals (both faces lit); otherwise it is `color` as is. `bias` (m) moves
  // the triangle towards the viewer in the depth test (shadows on the floor).
  void DrawTriangle(const Vec3 (&p)[3], const Vec3 (&n)[3], const Vec3& color, double opacity,
                    bool lit, const Vec3& key, double bias = 0) {
    Vec3 v[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3 d = p[k] - eye_;
      v[k] = Vec3(d.dot(cx_), d.dot(cy_), -d.dot(cz_) - bias);  // z: distance in front
    }
    // Behind (or too near) the camera; written so that NaN is skipped too.
    if (!(v[0].z() >= near_ && v[1].z() >= near_ && v[2].z() >= near_)) return;
    double sx[3], sy[3];
    for (int k = 0; k < 3; ++k) {
      sx[k] = 0.5 * w_ + focal_ * v[k].x() / v[k].z();
      sy[k] = 0.5 * h_ - focal_ * v[k].y() / v[k].z();
    }
    const double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
    if (!(std::abs(area) >= 1e-12) || !std::isfinite(area)) return;  // also NaN input
    // Pixel bounds, clamped in floating point before conversion (no overflow).
    auto pixel = [](double x, int limit) {
      return static_cast<int>(std::clamp(x, 0.0, static_cast<double>(limit)));
    };
    const int x0 = pixel(std::floor(std::min({sx[0], sx[1], sx[2]})), w_ - 1);
    const int x1 = pixel(std::ceil(std::max({sx[0], sx[1], sx[2]})), w_ - 1);
    const int y0 = pixel(std::floor(std::min({sy[0], sy[1], sy[2]})), h_ - 1);
    const int y1 = pixel(std::ceil(std::max({sy[0], sy[1], sy[2]})), h_ - 1);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        // Barycentric weights from edge functions (either winding: double-sided).
        const double l0 = ((sx[1] - px) * (sy[2] - py) - (sx[2] - px) * (sy[1] - py)) / area;
        const double l1 = ((sx[2] - px) * (sy[0] - py) - (sx[0] - px) * (sy[2] - py)) / area;
        const double l2 = 1 - l0 - l1;
        if (l0 < 0 || l1 < 0 || l2 < 0) continue;
        // Perspective-correct interpolation: weights over depth.
        const double w0 = l0 / v[0].z(), w1 = l1 / v[1].z(), w2 = l2 / v[2].z();
        const double z = 1 / (w0 + w1 + w2);
        const size_t at = static_cast<size_t>(y) * w_ + x;
        if (z >= depth_[at]) continue;
        depth_[at] = static_cast<float>(z);
        Vec3 shaded = color;
        if (lit) {
          Vec3 normal = (w0 * n[0] + w1 * n[1] + w2 * n[2]).normalized();
          const Vec3 point = z * (w0 * p[0] + w1 * p[1] + w2 * p[2]);
          if (normal.dot(eye_ - point) < 0) normal = -normal;  // light both faces
          const double diffuse =
              0.25 + 0.55 * std::max(0.0, normal.dot(key)) + 0.3 * std::max(0.0, normal.dot(cz_));
          shaded = (color * diffuse).cwiseMin(Vec3::Ones());
        }
        color_[at] = opacity * shaded + (1 - opacity) * color_[at];
      }
    }
  }

  // Draws the segment a-b (ground coordinates) `width` samples wide, depth-tested, pulled
  // slightly towards the viewer so that a line lying on a surface shows. A segment reaching
  // behind the camera is skipped.
  void DrawSegment(const Vec3& a, const Vec3& b, const Vec3& color, double width) {
    const Vec3 da = a - eye_, db = b - eye_;
    const double za = -da.dot(cz_), zb = -db.dot(cz_);
    if (!(za >= near_ && zb >= near_)) return;
    const double ax = 0.5 * w_ + focal_ * da.dot(cx_) / za,
                 ay = 0.5 * h_ - focal_ * da.dot(cy_) / za;
    const double bx = 0.5 * w_ + focal_ * db.dot(cx_) / zb,
                 by = 0.5 * h_ - focal_ * db.dot(cy_) / zb;
    const double span = std::max(std::abs(bx - ax), std::abs(by - ay));
    if (!std::isfinite(span) || span > 4.0 * (w_ + h_)) return;
    const int steps = static_cast<int>(std::ceil(span)) + 1;
    const int half = std::max(0, static_cast<int>(std::lround(0.5 * width)) - 1);
    for (int s = 0; s <= steps; ++s) {
      const double t = static_cast<double>(s) / steps;
      // Depth is perspective-correct: 1/z is linear on screen.
      const float z = static_cast<float>(0.995 / ((1 - t) / za + t / zb));
      const int cx = static_cast<int>(std::floor(ax + t * (bx - ax)));
      const int cy = static_cast<int>(std::floor(ay + t * (by - ay)));
      for (int y = cy - half; y <= cy + half + 1; ++y) {
        for (int x = cx - half; x <= cx + half + 1; ++x) {
          if (x < 0 || y < 0 || x >= w_ || y >= h_) continue;
          const size_t at = static_cast<size_t>(y) * w_ + x;
          if (z >= depth_[at]) continue;
          depth_[at] = z;
          color_[at] = color;
        }
      }
    }
  }

  // Forgets every depth drawn so far: what is drawn next lies over it.
  void ClearDepth() {
    std::fill(depth_.begin(), depth_.end(), std::numeric_limits<float>::infinity());
  }

  // Averages each block of supersample x supersample samples into one pixel.
  Image Resolve(int width, int height, int supersample) const {
    Image image(width, height);
    const double norm = 1.0 / (supersample * supersample);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        Vec3 sum = Vec3::Zero();
        for (int j = 0; j < supersample; ++j) {
          for (int i = 0; i < supersample; ++i) {
            sum += color_[static_cast<size_t>(y * supersample + j) * w_ + x * supersample + i];
          }
        }
        uint8_t* px = image.At(x, y);
        for (int k = 0; k < 3; ++k) {
          px[k] = static_cast<uint8_t>(std::lround(std::clamp(sum[k] * norm, 0.0, 1.0) * 255));
        }
      }
    }
    return image;
  }

 private:
  int w_, h_;
  Vec3 eye_, cx_, cy_, cz_;
  double focal_ = 1, near_ = 1e-3;
  std::vector<float> depth_;
  std::vector<Vec3> color_;
};

}  // namespace

size_t RenderBytes(int width, int height) {
  const size_t pixels = static_cast<size_t>(std::max(width, 0)) * std::max(height, 0);
  const size_t per_sample = sizeof(float) + sizeof(Vec3);  // depth and colour
  return pixels * (kSupersample * kSupersample * per_sample + 3);
}

void CheckRenderSize(int width, int height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    throw Error("render: image size must be between 1 and 16384 pixels");
  }
  const size_t bytes = RenderBytes(width, height);
  if (bytes > kMaxRenderBytes) {
    constexpr size_t kMiB = size_t{1} << 20;
    throw Error("render: a " + std::to_string(width) + " x " + std::to_string(height) +
                " image needs " + std::to_string(bytes / kMiB) +
                " MiB of frame buffers (2x2 supersampled), more than the cap of " +
                std::to_string(kMaxRenderBytes / kMiB) + " MiB; ask for fewer pixels (about " +
                std::to_string(kMaxRenderBytes / RenderBytes(1, 1) / 1000000) +
                " million at most)");
  }
}

std::pair<Vec3, Vec3> GrowBounds(std::pair<Vec3, Vec3> bounds,
                                 const std::vector<std::vector<Vec3>>& lines) {
  for (const std::vector<Vec3>& line : lines) {
    for (const Vec3& p : line) {
      bounds.first = bounds.first.cwiseMin(p);
      bounds.second = bounds.second.cwiseMax(p);
    }
  }
  return bounds;
}

Image RenderScene(const VisualScene& scene, const std::vector<Transform>& X_GB,
                  const Camera& camera, const RenderOptions& options,
                  const std::vector<std::vector<Vec3>>& lines,
                  const std::vector<Vec3>& line_colors) {
  CheckRenderSize(options.width, options.height);
  Canvas canvas(camera, options.width * kSupersample, options.height * kSupersample,
                options.background);
  // The key light, from above-front-right in ground (OpenSim: x forward, y up, z right); a
  // fill light comes from the camera.
  const Vec3 key = Vec3(0.5, 1.0, 0.6).normalized();
  std::vector<PosedPart> posed_parts;
  std::vector<const VisualPart*> parts;
  for (const VisualBody& body : scene.bodies) {
    if (body.body >= static_cast<int>(X_GB.size())) continue;
    for (const VisualPart& part : body.parts) {
      if (!part.mesh || part.mesh->empty()) continue;
      posed_parts.push_back(Pose(part, X_GB[body.body]));
      parts.push_back(&part);
    }
  }
  if (options.floor && !parts.empty()) {
    // A square of the floor plane around the model, and the model's shadow on it, cast along
    // the key light.
    const auto [lo, hi] = SceneBounds(scene, X_GB);
    const FloorPlane plane = options.floor_plane.value_or(HorizontalFloor(lo.y(), "lowest point"));
    const Vec3& up = plane.normal;
    const double reach = 1.0 * (hi - lo).maxCoeff();
    const Vec3 middle = 0.5 * (lo + hi);
    const Vec3 c = middle - up * plane.HeightOf(middle);
    const Vec3 u = up.unitOrthogonal() * reach, w = up.cross(u);
    const Vec3 floor_color = options.background * 0.9;
    const Vec3 corners[4] = {c + u - w, c - u - w, c - u + w, c + u + w};
    const Vec3 normals[3] = {up, up, up};
    canvas.DrawTriangle({corners[0], corners[1], corners[2]}, normals, floor_color, 1, false, key);
    canvas.DrawTriangle({corners[0], corners[2], corners[3]}, normals, floor_color, 1, false, key);
    const double bias = 1e-3 * reach;
    const double key_up = key.dot(up);
    for (size_t i = 0; key_up > 0.05 && i < parts.size(); ++i) {
      const PosedPart& posed = posed_parts[i];
      for (const auto& t : parts[i]->mesh->triangles) {
        Vec3 q[3];
        for (int k = 0; k < 3; ++k) {
          const Vec3& p = posed.positions[t[k]];
          q[k] = p - key * (plane.HeightOf(p) / key_up);  // along the light onto the plane
        }
        canvas.DrawTriangle(q, normals, floor_color * 0.7, 1, false, key, bias);
      }
    }
  }
  for (size_t i = 0; i < parts.size(); ++i) {
    const PosedPart& posed = posed_parts[i];
    for (const auto& t : parts[i]->mesh->triangles) {
      const Vec3 p[3] = {posed.positions[t[0]], posed.positions[t[1]], posed.positions[t[2]]};
      const Vec3 n[3] = {posed.normals[t[0]], posed.normals[t[1]], posed.normals[t[2]]};
      canvas.DrawTriangle(p, n, parts[i]->color, parts[i]->opacity, true, key);
    }
  }
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::vector<Vec3>& line = lines[i];
    const Vec3& color = i < line_colors.size() ? line_colors[i] : options.line_color;
    for (size_t j = 1; j < line.size(); ++j) {
      canvas.DrawSegment(line[j - 1], line[j], color, options.line_width * kSupersample);
    }
  }
  if (!options.overlay.empty()) canvas.ClearDepth();
  for (const VisualPart& part : options.overlay) {
    if (!part.mesh || part.mesh->empty()) continue;
    const PosedPart posed = Pose(part, Transform::Identity());
    for (const auto& t : part.mesh->triangles) {
      const Vec3 p[3] = {posed.positions[t[0]], posed.positions[t[1]], posed.positions[t[2]]};
      const Vec3 n[3] = {posed.normals[t[0]], posed.normals[t[1]], posed.normals[t[2]]};
      canvas.DrawTriangle(p, n, part.color, part.opacity, true, key);
    }
  }
  return canvas.Resolve(options.width, options.height, kSupersample);
}

Image RenderFramed(const VisualScene& scene, const std::vector<Transform>& X_GB,
                   const RenderOptions& options, const std::vector<std::vector<Vec3>>& lines,
                   const std::vector<Vec3>& line_colors) {
  CheckRenderSize(options.width, options.height);
  const bool has_parts = std::any_of(scene.bodies.begin(), scene.bodies.end(),
                                     [](const VisualBody& b) { return !b.parts.empty(); });
  const bool has_lines = std::any_of(lines.begin(), lines.end(),
                                     [](const std::vector<Vec3>& l) { return !l.empty(); });
  const Vec3 inf = Vec3::Constant(std::numeric_limits<double>::infinity());
  std::pair<Vec3, Vec3> bounds = GrowBounds(
      has_parts || !has_lines ? SceneBounds(scene, X_GB) : std::pair<Vec3, Vec3>{inf, -inf}, lines);
  // The overlay (contact arrows) in the picture too: a long arrow would leave it.
  for (const VisualPart& part : options.overlay) {
    if (!part.mesh) continue;
    for (const Vec3& p : Pose(part, Transform::Identity()).positions) {
      bounds.first = bounds.first.cwiseMin(p);
      bounds.second = bounds.second.cwiseMax(p);
    }
  }
  const Camera camera = FrameCamera(bounds, options.view_direction,
                                    static_cast<double>(options.width) / options.height);
  return RenderScene(scene, X_GB, camera, options, lines, line_colors);
}

}  // namespace sinew::viz
