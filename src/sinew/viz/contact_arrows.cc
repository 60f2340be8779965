#include <sinew/viz/contact_arrows.h>
#include <sinew/viz/motion_poses.h>
#include <sinew/viz/primitive_shapes.h>
#include <sinew/viz/rasterizer.h>

#include <algorithm>
#include <cmath>

namespace sinew::viz {
namespace {

const char* const kAxes[3] = {"X", "Y", "Z"};

// The columns of one group: force X, Y, Z then torque X, Y, Z.
struct Group {
  std::string name;
  int body = model::kGroundIndex;
  int columns[6] = {};
};

std::string LastPathPart(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t start = name.find_first_not_of(" \t\n");
  const size_t end = name.find_last_not_of(" \t\n");
  return start == std::string::npos ? "" : name.substr(start, end - start + 1);
}

int GeometryBody(const model::ModelSpec& spec, const std::string& name) {
  for (const model::ContactGeometrySpec& g : spec.contact_geometry) {
    if (g.name == name) return g.body;
  }
  return model::kNone;
}

// The body a group label of force `force` names (model::kNone when none).
int BodyOfGroup(const model::ModelSpec& spec, const std::string& force, const std::string& group) {
  for (size_t b = 0; b < spec.bodies.size(); ++b) {
    if (spec.bodies[b].name == group) return static_cast<int>(b);
  }
  for (const model::FrameSpec& f : spec.frames) {
    if (f.name == group) return f.body;
  }
  for (const model::ContactGeometrySpec& g : spec.contact_geometry) {
    if (LastPathPart(g.frame) == group) return g.body;
  }
  // SmoothSphereHalfSpaceForce labels its groups after its two sockets.
  const char* socket = group == "Sphere"      ? "socket_sphere"
                       : group == "HalfSpace" ? "socket_half_space"
                                              : nullptr;
  for (const model::ForceSpec& f : spec.forces) {
    if (!socket || f.name != force) continue;
    if (const model::Element* e = f.element.Child(socket))
      return GeometryBody(spec, LastPathPart(e->text));
  }
  return model::kNone;
}

std::vector<Group> FindGroups(const model::ModelSpec& spec, const io::Storage& table,
                              const GroupBodies& known, Diagnostics* notes) {
  std::map<std::string, int> column;
  for (size_t c = 0; c < table.labels.size(); ++c) column[table.labels[c]] = static_cast<int>(c);
  std::vector<Group> groups;
  const std::string suffix = ".force.X";
  for (const std::string& label : table.labels) {
    if (!label.ends_with(suffix)) continue;
    Group g;
    g.name = label.substr(0, label.size() - suffix.size());
    bool complete = true;
    for (int i = 0; i < 6; ++i) {
      const auto it = column.find(g.name + (i < 3 ? ".force." : ".torque.") + kAxes[i % 3]);
      complete = complete && it != column.end();
      if (complete) g.columns[i] = it->second;
    }
    const size_t dot = g.name.rfind('.');
    if (!complete || dot == std::string::npos) continue;
    const auto it = known.find(g.name);
    g.body = it != known.end() ? it->second
                               : BodyOfGroup(spec, g.name.substr(0, dot), g.name.substr(dot + 1));
    if (g.body < 0 || g.body >= static_cast<int>(spec.bodies.size())) g.body = model::kNone;
    if (g.body == model::kNone) {
      if (notes) {
        Diagnostic d;
        d.component = "contacts: " + g.name;
        d.message = "names no body of the model; its force is not drawn";
        notes->push_back(std::move(d));
      }
      continue;
    }
    if (g.body != model::kGroundIndex) groups.push_back(g);
  }
  return groups;
}

// Row values at time t, linear between the rows around it; false outside the table's range.
bool RowAt(const io::Storage& table, double t, std::vector<double>& row) {
  if (table.time.empty() || t < table.time.front() || t > table.time.back()) return false;
  const auto it = std::lower_bound(table.time.begin(), table.time.end(), t);
  const int hi = static_cast<int>(it - table.time.begin());
  const int lo = std::max(0, hi - 1);
  const double span = table.time[hi] - table.time[lo];
  const double s = span > 0 ? (t - table.time[lo]) / span : 1.0;
  row.resize(table.labels.size());
  for (int c = 0; c < table.NumColumns(); ++c) {
    row[c] = table.Value(lo, c) + s * (table.Value(hi, c) - table.Value(lo, c));
  }
  return true;
}

// The farthest point of each body's drawn parts from its origin (m).
std::vector<double> BodyReach(const VisualScene& scene, size_t num_bodies) {
  std::vector<double> reach(num_bodies, 0.0);
  for (const VisualBody& body : scene.bodies) {
    if (body.body < 0 || body.body >= static_cast<int>(num_bodies)) continue;
    for (const VisualPart& part : body.parts) {
      if (!part.mesh) continue;
      for (const io::Vec3f& v : part.mesh->positions) {
        const Vec3 p = part.X_BG * part.scale.cwiseProduct(v.cast<double>());
        reach[body.body] = std::max(reach[body.body], p.norm());
      }
    }
  }
  return reach;
}

// Where the arrow of force F with moment M about the body origin o starts (see the header).
Vec3 ArrowStart(const Vec3& F, const Vec3& M, const Vec3& o, double reach,
                const FloorPlane& floor) {
  const double F2 = F.squaredNorm();
  if (F2 == 0) return o;
  const Vec3 nearest = o + F.cross(M) / F2;  // on the line of action {p : (p - o) x F = M}
  const double along = F.dot(floor.normal);
  if (along == 0) return nearest;
  const Vec3 crossing = nearest - F * (floor.HeightOf(nearest) / along);
  return (crossing - o).norm() <= 1.1 * reach ? crossing : nearest;
}

}  // namespace

ContactArrows ContactArrowsFromTable(const model::ModelSpec& spec, const io::Storage& contacts,
                                     const BodyMotion& motion, const VisualScene& scene,
                                     const FloorPlane& floor, const GroupBodies& known,
                                     Diagnostics* notes) {
  ContactArrows arrows;
  const std::vector<Group> groups = FindGroups(spec, contacts, known, notes);
  for (const Group& g : groups) {
    arrows.names.push_back(g.name);
    arrows.bodies.push_back(g.body);
  }
  const std::vector<double> reach = BodyReach(scene, spec.bodies.size());
  std::vector<double> row;
  double largest = 0;
  for (size_t k = 0; k < motion.times.size(); ++k) {
    arrows.start.emplace_back(groups.size(), Vec3::Zero());
    arrows.force.emplace_back(groups.size(), Vec3::Zero());
    const bool inside = RowAt(contacts, motion.times[k], row);
    for (size_t i = 0; i < groups.size(); ++i) {
      const Group& g = groups[i];
      const Vec3 o = motion.X_GB[k][g.body].p;
      arrows.start[k][i] = o;
      if (!inside) continue;
      const Vec3 F(row[g.columns[0]], row[g.columns[1]], row[g.columns[2]]);
      const Vec3 M(row[g.columns[3]], row[g.columns[4]], row[g.columns[5]]);
      if (!F.allFinite() || !M.allFinite()) continue;
      arrows.force[k][i] = F;
      arrows.start[k][i] = ArrowStart(F, M, o, reach[g.body], floor);
      largest = std::max(largest, F.norm());
    }
  }
  double mass = 0;
  for (const model::BodySpec& b : spec.bodies) mass += b.mass;
  arrows.body_weight = mass * spec.gravity.norm();
  if (!motion.X_GB.empty()) {
    const auto [lo, hi] = SceneBounds(scene, motion.X_GB[0], false);
    const double extent = (hi - lo).maxCoeff();
    const double unit = arrows.body_weight > 0 ? arrows.body_weight : largest;
    if (unit > 0) {
      arrows.unit_length = 0.5 * extent;
      arrows.metres_per_newton = arrows.unit_length / unit;
    }
  }
  return arrows;
}

ArrowShape ArrowShapeAt(const ContactArrows& arrows, size_t frame, size_t i) {
  ArrowShape shape;
  shape.start = arrows.start[frame][i];
  const Vec3& F = arrows.force[frame][i];
  const double length = F.norm() * arrows.metres_per_newton;
  if (!(length > 0)) return shape;
  const double unit = arrows.unit_length;
  const double head = 0.2 * unit, head_radius = 0.07 * unit;
  shape.length = length;
  shape.head_length = std::min(length, head);
  shape.shaft_length = length - shape.head_length;
  shape.shaft_radius = 0.025 * unit;
  const double thin = shape.head_length / head;  // a short arrow's head shrinks with it
  shape.head_radius = head_radius * thin;
  shape.rotation = Quat::FromTwoVectors(Vec3::UnitY(), F);
  shape.rotation.normalize();
  return shape;
}

std::shared_ptr<const io::TriangleMesh> ArrowShaftMesh() {
  static const std::shared_ptr<const io::TriangleMesh> shaft = [] {
    auto mesh = std::make_shared<io::TriangleMesh>(*UnitCylinder());
    for (io::Vec3f& p : mesh->positions) p.y() = 0.5f * (p.y() + 1.0f);  // moved up and halved
    return mesh;
  }();
  return shaft;
}

std::vector<VisualPart> ContactArrowParts(const ContactArrows& arrows, size_t frame) {
  std::vector<VisualPart> parts;
  for (size_t i = 0; i < arrows.names.size(); ++i) {
    const ArrowShape shape = ArrowShapeAt(arrows, frame, i);
    if (!(shape.length > 0)) continue;
    const Mat3 R = shape.rotation.toRotationMatrix();
    VisualPart shaft;
    shaft.name = "contact " + arrows.names[i];
    shaft.mesh = ArrowShaftMesh();
    shaft.X_BG = Transform(R, shape.start);
    shaft.scale = Vec3(shape.shaft_radius, shape.shaft_length, shape.shaft_radius);
    shaft.color = kContactArrowColor;
    shaft.source = "contact arrow";
    VisualPart head = shaft;
    head.mesh = UnitCone();
    head.X_BG.p = shape.start + R * Vec3(0, shape.shaft_length, 0);
    head.scale = Vec3(shape.head_radius, shape.head_length, shape.head_radius);
    if (shape.shaft_length > 0) parts.push_back(std::move(shaft));
    parts.push_back(std::move(head));
  }
  return parts;
}

std::vector<VisualPart> ContactArrowPartsAt(const model::ModelSpec& spec,
                                            const io::Storage& contacts, const io::Storage& table,
                                            const BodyMotion& shown, const VisualScene& scene,
                                            const FloorPlane& floor, Diagnostics* notes) {
  if (shown.times.empty() || shown.X_GB.empty()) return {};
  BodyMotion two;
  const double first = table.time.empty() ? shown.times[0] : table.time.front();
  two.times = {first, shown.times[0]};
  two.X_GB = {PosesAtTime(spec, table, first), shown.X_GB[0]};
  return ContactArrowParts(ContactArrowsFromTable(spec, contacts, two, scene, floor, {}, notes), 1);
}

}  // namespace sinew::viz
