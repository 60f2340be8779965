#include <sinew/io/mesh_file.h>
#include <sinew/kinematics/body_depths.h>
#include <sinew/viz/primitive_shapes.h>
#include <sinew/viz/visual_scene.h>

#include <algorithm>
#include <map>
#include <set>

namespace sinew::viz {
namespace {

// First value of a named dimension, or `fallback`.
double Dimension(const model::GeometrySpec& g, const std::string& key, int i, double fallback) {
  auto it = g.dimensions.find(key);
  if (it == g.dimensions.end() || static_cast<int>(it->second.size()) <= i) return fallback;
  return it->second[i];
}

// A rotation taking +y to the unit vector `dir`.
Mat3 RotationYTo(const Vec3& dir) {
  return Eigen::Quaterniond::FromTwoVectors(Vec3::UnitY(), dir).toRotationMatrix();
}

// Size of the PRIMITIVES skeleton: spheres scale with the model's typical segment length.
double SkeletonRadius(const model::ModelSpec& spec) {
  std::vector<double> lengths;
  for (const model::JointSpec& j : spec.joints) {
    if (j.X_PF.p.norm() > 1e-6) lengths.push_back(j.X_PF.p.norm());
    if (j.X_BM.p.norm() > 1e-6) lengths.push_back(j.X_BM.p.norm());
  }
  if (lengths.empty()) return 0.02;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return std::clamp(0.12 * lengths[lengths.size() / 2], 0.003, 0.5);
}

// Green at the root, red at the deepest leaf.
Vec3 DepthColor(int depth, int max_depth) {
  const double s = max_depth > 0 ? static_cast<double>(depth) / max_depth : 0.0;
  return Vec3(0.15 + 0.75 * s, 0.8 - 0.65 * s, 0.15);
}

// The skeleton of body b: a sphere at its frame and a cylinder to each joint frame on it.
void AddPrimitives(const model::ModelSpec& spec, int b, double radius, const Vec3& color,
                   VisualBody& out) {
  VisualPart sphere;
  sphere.name = spec.bodies[b].name + "_frame";
  sphere.mesh = UnitSphere();
  sphere.scale = Vec3::Constant(radius);
  sphere.color = color;
  sphere.source = "primitive";
  out.parts.push_back(sphere);
  auto add_link = [&](const Vec3& p_BJ, const std::string& joint) {
    const double length = p_BJ.norm();
    if (length < 1e-9) return;
    VisualPart cylinder;
    cylinder.name = spec.bodies[b].name + "_to_" + joint;
    cylinder.mesh = UnitCylinder();
    cylinder.X_BG = Transform(RotationYTo(p_BJ / length), 0.5 * p_BJ);
    cylinder.scale = Vec3(0.4 * radius, 0.5 * length, 0.4 * radius);
    cylinder.color = color;
    cylinder.source = "primitive";
    out.parts.push_back(cylinder);
  };
  for (const model::JointSpec& j : spec.joints) {
    if (j.child_body == b) add_link(j.X_BM.p, j.name);
    if (j.parent_body == b) add_link(j.X_PF.p, j.name);
  }
}

class SceneBuilder {
 public:
  SceneBuilder(const model::ModelSpec& spec, const VisualOptions& options)
      : spec_(spec),
        options_(options),
        dirs_(io::MeshSearchDirs(spec.file, options.geometry_dirs)) {}

  VisualScene Build() {
    VisualScene scene;
    if (options_.mode == VisType::kMesh) scene.mesh_dirs = dirs_;
    // Unreached bodies (depth -1) are coloured as the root.
    std::vector<int> depth = kinematics::CalcBodyDepths(spec_);
    for (int& d : depth) d = std::max(d, 0);
    const int max_depth = *std::max_element(depth.begin(), depth.end());
    const double radius = SkeletonRadius(spec_);
    for (int b = 0; b < static_cast<int>(spec_.bodies.size()); ++b) {
      VisualBody body;
      body.name = spec_.bodies[b].name;
      body.body = b;
      bool fallback = options_.mode == VisType::kPrimitives;
      if (options_.mode == VisType::kMesh) {
        for (const model::GeometrySpec& g : spec_.bodies[b].geometry) {
          if (!g.visible) continue;
          if (!AddGeometry(b, g, body, scene)) fallback = true;
        }
      }
      if (fallback) AddPrimitives(spec_, b, radius, DepthColor(depth[b], max_depth), body);
      if (options_.mode != VisType::kNone) {
        for (const model::ContactGeometrySpec& c : spec_.contact_geometry) {
          if (c.body == b) AddContactGeometry(c, radius, body, scene);
        }
      }
      scene.bodies.push_back(std::move(body));
    }
    scene.read_meshes = read_;
    return scene;
  }

 private:
  // Adds one attached geometry; false when the body should fall back to primitives.
  bool AddGeometry(int b, const model::GeometrySpec& g, VisualBody& body, VisualScene& scene) {
    const std::string component = spec_.bodies[b].path + "/" + g.name;
    auto warn = [&](const std::string& message) {
      scene.warnings.push_back({SourceLocation{spec_.file, 0}, component, message});
    };
    VisualPart part;
    part.name = g.name;
    part.X_BG = g.X_BG;
    part.scale = g.scale_factors;
    part.color = g.color;
    part.opacity = g.opacity;
    part.source = g.type;
    Vec3 size = Vec3::Ones();
    if (g.type == "Mesh") {
      // OpenSim writes "Unassigned" (or nothing) for a mesh without a file: nothing to draw.
      if (g.mesh_file.empty() || g.mesh_file == "Unassigned") return true;
      part.mesh = LoadMesh(g.mesh_file, warn);
      if (!part.mesh) {
        if (not_found_.count(g.mesh_file) > 0) {
          scene.missing_meshes.push_back({g.mesh_file, scene.warnings.size() - 1});
        }
        return false;
      }
      part.source = g.mesh_file;
    } else if (g.type == "Sphere") {
      part.mesh = UnitSphere();
      size = Vec3::Constant(Dimension(g, "radius", 0, 1));
    } else if (g.type == "Ellipsoid") {
      part.mesh = UnitSphere();
      size = Vec3(Dimension(g, "radii", 0, 1), Dimension(g, "radii", 1, 1),
                  Dimension(g, "radii", 2, 1));
    } else if (g.type == "Cylinder") {
      part.mesh = UnitCylinder();
      const double r = Dimension(g, "radius", 0, 1);
      size = Vec3(r, Dimension(g, "half_height", 0, 1), r);
    } else if (g.type == "Brick") {
      part.mesh = UnitBox();
      size = Vec3(Dimension(g, "half_lengths", 0, 1), Dimension(g, "half_lengths", 1, 1),
                  Dimension(g, "half_lengths", 2, 1));
    } else if (g.type == "Cone") {
      part.mesh = UnitCone();
      const double r = Dimension(g, "base_radius", 0, 1);
      size = Vec3(r, Dimension(g, "height", 0, 1), r);
    } else if (g.type == "Torus") {
      const double ring = Dimension(g, "ring_radius", 0, 1);
      part.mesh = MakeTorus(Dimension(g, "tube_radius", 0, 0.1 * ring) / ring);
      size = Vec3::Constant(ring);
    } else if (g.type == "Line" || g.type == "Arrow") {
      AddSegment(g, part, body);
      return true;
    } else {
      // FrameGeometry and other decorations without a body shape.
      warn("geometry type '" + g.type + "' is not drawn");
      return true;
    }
    part.scale = part.scale.cwiseProduct(size);
    body.parts.push_back(std::move(part));
    return true;
  }

  // One ContactGeometry in kContactColor: a sphere, an ellipsoid, a mesh, or a half-space as a
  // thin square slab just inside its solid (x > 0 in its frame), 40 skeleton radii wide.
  void AddContactGeometry(const model::ContactGeometrySpec& c, double skeleton_radius,
                          VisualBody& body, VisualScene& scene) {
    auto warn = [&](const std::string& message) {
      scene.warnings.push_back(
          {SourceLocation{spec_.file, c.where.line}, "/contactgeometryset/" + c.name, message});
    };
    auto number = [&](const char* key, int i, double fallback) {
      const auto it = c.dimensions.find(key);
      return it != c.dimensions.end() && static_cast<int>(it->second.size()) > i ? it->second[i]
                                                                                 : fallback;
    };
    VisualPart part;
    part.name = c.name;
    part.X_BG = c.X_BC;
    part.color = kContactColor;
    part.source = c.type;
    if (c.type == "ContactSphere") {
      part.mesh = UnitSphere();
      part.scale = Vec3::Constant(number("radius", 0, skeleton_radius));
    } else if (c.type == "ContactEllipsoid") {
      part.mesh = UnitSphere();
      part.scale = Vec3(number("radii", 0, 1), number("radii", 1, 1), number("radii", 2, 1));
    } else if (c.type == "ContactHalfSpace") {
      const double half_width = std::max(1.0, 40.0 * skeleton_radius);
      const double half_thickness = 0.005 * half_width;
      part.mesh = UnitBox();
      part.X_BG = c.X_BC * Transform::Translation(Vec3(half_thickness, 0, 0));
      part.scale = Vec3(half_thickness, half_width, half_width);
      part.unbounded = true;
    } else if (c.type == "ContactMesh") {
      part.mesh = LoadMesh(c.mesh_file, warn);
      if (!part.mesh) {
        if (not_found_.count(c.mesh_file) > 0)
          scene.missing_meshes.push_back({c.mesh_file, scene.warnings.size() - 1});
        return;
      }
      part.source = c.mesh_file;
    } else {
      warn("contact geometry type '" + c.type + "' is not drawn");
      return;
    }
    body.parts.push_back(std::move(part));
  }

  // A Line (start_point to end_point) or an Arrow (from start_point along direction for
  // length, with a cone head), as thin cylinders in the geometry's frame.
  static void AddSegment(const model::GeometrySpec& g, const VisualPart& base, VisualBody& body) {
    const Vec3 start(Dimension(g, "start_point", 0, 0), Dimension(g, "start_point", 1, 0),
                     Dimension(g, "start_point", 2, 0));
    Vec3 end(Dimension(g, "end_point", 0, 0), Dimension(g, "end_point", 1, 1),
             Dimension(g, "end_point", 2, 0));
    const bool arrow = g.type == "Arrow";
    if (arrow) {
      const Vec3 dir(Dimension(g, "direction", 0, 0), Dimension(g, "direction", 1, 1),
                     Dimension(g, "direction", 2, 0));
      end = start + Dimension(g, "length", 0, 1) * dir.normalized();
    }
    const double length = (end - start).norm();
    if (!(length > 1e-12)) return;
    const Vec3 axis = (end - start) / length;
    const double head = arrow ? 0.15 * length : 0.0;
    VisualPart shaft = base;
    shaft.mesh = UnitCylinder();
    const Vec3 shaft_end = end - head * axis;
    shaft.X_BG = g.X_BG * Transform(RotationYTo(axis), 0.5 * (start + shaft_end));
    const double r = 0.015 * length;
    shaft.scale = base.scale.cwiseProduct(Vec3(r, 0.5 * (length - head), r));
    body.parts.push_back(shaft);
    if (arrow) {
      VisualPart cone = base;
      cone.name = base.name + "_head";
      cone.mesh = UnitCone();
      cone.X_BG = g.X_BG * Transform(RotationYTo(axis), shaft_end);
      cone.scale = base.scale.cwiseProduct(Vec3(3 * r, head, 3 * r));
      body.parts.push_back(cone);
    }
  }

  template <typename Warn>
  std::shared_ptr<const io::TriangleMesh> LoadMesh(const std::string& file, Warn&& warn) {
    auto cached = cache_.find(file);
    if (cached != cache_.end()) {
      if (!cached->second) warn("mesh '" + file + "' unavailable (see above); drawn as primitives");
      return cached->second;
    }
    std::shared_ptr<const io::TriangleMesh> mesh;
    if (std::optional<std::string> path = io::FindMeshFile(file, dirs_)) {
      try {
        mesh = std::make_shared<io::TriangleMesh>(io::ReadMesh(*path));
        read_.push_back({file, *path});
      } catch (const Error& e) {
        warn(std::string("cannot read mesh: ") + e.what() + "; drawn as primitives");
      }
    } else {
      std::string searched;
      for (const std::string& d : dirs_) searched += (searched.empty() ? "" : ", ") + d;
      warn("mesh file '" + file + "' not found in: " + searched + "; drawn as primitives");
      not_found_.insert(file);
    }
    cache_[file] = mesh;
    return mesh;
  }

  const model::ModelSpec& spec_;
  const VisualOptions& options_;
  std::vector<std::string> dirs_;
  std::map<std::string, std::shared_ptr<const io::TriangleMesh>> cache_;
  std::set<std::string> not_found_;  // files of cache_ found in no folder
  std::vector<ReadMeshFile> read_;   // files of cache_ read, in model order
};

}  // namespace

VisType ParseVisType(const std::string& text) {
  if (text == "none") return VisType::kNone;
  if (text == "primitives") return VisType::kPrimitives;
  if (text == "mesh") return VisType::kMesh;
  throw Error("unknown visualization mode '" + text + "' (expected none, primitives or mesh)");
}

VisualScene BuildVisualScene(const model::ModelSpec& spec, const VisualOptions& options) {
  return SceneBuilder(spec, options).Build();
}

}  // namespace sinew::viz
