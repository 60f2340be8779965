#include <sinew/viz/internal/gltf_contact_arrows.h>
#include <sinew/viz/internal/gltf_mesh.h>
#include <sinew/viz/primitive_shapes.h>

namespace sinew::viz::internal {
namespace {

json ToJson(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

// One arrow's node values at one frame.
struct ArrowPose {
  Vec3 start = Vec3::Zero();
  Quat rotation = Quat::Identity();
  double scale = 0;  // 1 shown, 0 hidden (no force)
  Vec3 shaft_scale = Vec3::Zero();
  Vec3 head_translation = Vec3::Zero();
  Vec3 head_scale = Vec3::Zero();
};

ArrowPose PoseOf(const ContactArrows& arrows, size_t frame, size_t i) {
  const ArrowShape shape = ArrowShapeAt(arrows, frame, i);
  ArrowPose pose;
  pose.start = shape.start;
  if (!(shape.length > 0)) return pose;
  pose.rotation = shape.rotation;
  pose.scale = 1;
  pose.shaft_scale = Vec3(shape.shaft_radius, shape.shaft_length, shape.shaft_radius);
  pose.head_translation = Vec3(0, shape.shaft_length, 0);
  pose.head_scale = Vec3(shape.head_radius, shape.head_length, shape.head_radius);
  return pose;
}

json QuatJson(const Quat& q) { return {q.x(), q.y(), q.z(), q.w()}; }

void AppendVec(std::vector<float>& out, const Vec3& v) {
  out.insert(out.end(),
             {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())});
}

}  // namespace

json ViewHintsExtras(const ViewHints& hints, const std::vector<int>& arrow_nodes) {
  json extras = {{"floor",
                  {{"point", ToJson(hints.floor.point)},
                   {"normal", ToJson(hints.floor.normal)},
                   {"source", hints.floor.source}}},
                 {"grid", {{"center", ToJson(hints.grid_center)}, {"size", hints.grid_size}}},
                 {"follow_body", hints.follow_body}};
  const ContactArrows& a = hints.arrows;
  if (a.empty()) return extras;
  json list = json::array();
  for (size_t i = 0; i < a.names.size(); ++i) {
    list.push_back({{"name", a.names[i]}, {"body", a.bodies[i]}, {"node", arrow_nodes[i]}});
  }
  extras["contact_arrows"] = {{"metres_per_newton", a.metres_per_newton},
                              {"body_weight", a.body_weight},
                              {"unit_length", a.unit_length},
                              {"arrows", list}};
  return extras;
}

int AddArrowNodes(json& doc, BinaryBuilder& bin, const ContactArrows& arrows,
                  std::vector<ArrowNodes>& nodes) {
  doc["materials"].push_back(
      {{"name", "contact forces"},
       {"pbrMetallicRoughness",
        {{"baseColorFactor",
          {kContactArrowColor.x(), kContactArrowColor.y(), kContactArrowColor.z(), 1.0}},
         {"metallicFactor", 0.0},
         {"roughnessFactor", 0.6}}}});
  const size_t material = doc["materials"].size() - 1;
  auto add_mesh = [&](const char* name, const io::TriangleMesh& mesh) {
    json primitive = MeshPrimitive(bin, mesh);
    primitive["material"] = material;
    doc["meshes"].push_back({{"name", name}, {"primitives", json::array({primitive})}});
    return doc["meshes"].size() - 1;
  };
  const size_t shaft_mesh = add_mesh("arrow shaft", *ArrowShaftMesh());
  const size_t head_mesh = add_mesh("arrow head", *UnitCone());
  auto add_node = [&](json node) {
    doc["nodes"].push_back(std::move(node));
    return static_cast<int>(doc["nodes"].size() - 1);
  };
  json children = json::array();
  nodes.clear();
  for (size_t i = 0; i < arrows.names.size(); ++i) {
    const ArrowPose pose = PoseOf(arrows, 0, i);
    ArrowNodes n;
    n.shaft =
        add_node({{"name", "shaft"}, {"mesh", shaft_mesh}, {"scale", ToJson(pose.shaft_scale)}});
    n.head = add_node({{"name", "head"},
                       {"mesh", head_mesh},
                       {"translation", ToJson(pose.head_translation)},
                       {"scale", ToJson(pose.head_scale)}});
    n.arrow = add_node({{"name", "contact " + arrows.names[i]},
                        {"children", {n.shaft, n.head}},
                        {"translation", ToJson(pose.start)},
                        {"rotation", QuatJson(pose.rotation)},
                        {"scale", ToJson(Vec3::Constant(pose.scale))},
                        {"extras", {{"contact", arrows.names[i]}, {"body", arrows.bodies[i]}}}});
    nodes.push_back(n);
    children.push_back(n.arrow);
  }
  return add_node({{"name", "contact_forces"}, {"children", children}});
}

void AddArrowChannels(BinaryBuilder& bin, int input, const ContactArrows& arrows,
                      const std::vector<ArrowNodes>& nodes, json& samplers, json& channels) {
  const size_t n_frames = arrows.start.size();
  for (size_t i = 0; i < nodes.size(); ++i) {
    std::vector<float> start, rotation, scale, shaft_scale, head_translation, head_scale;
    Quat previous = Quat::Identity();
    for (size_t k = 0; k < n_frames; ++k) {
      const ArrowPose pose = PoseOf(arrows, k, i);
      AppendVec(start, pose.start);
      Quat q = pose.rotation;
      if (k > 0 && q.dot(previous) < 0) q.coeffs() = -q.coeffs();  // the short way round
      previous = q;
      rotation.insert(rotation.end(), {static_cast<float>(q.x()), static_cast<float>(q.y()),
                                       static_cast<float>(q.z()), static_cast<float>(q.w())});
      AppendVec(scale, Vec3::Constant(pose.scale));
      AppendVec(shaft_scale, pose.shaft_scale);
      AppendVec(head_translation, pose.head_translation);
      AppendVec(head_scale, pose.head_scale);
    }
    auto channel = [&](int node, const char* path, const std::vector<float>& values) {
      const bool quaternion = values.size() == 4 * n_frames;
      const int output =
          bin.AddFloats(values, quaternion ? "VEC4" : "VEC3", quaternion ? 4 : 3, 0, false);
      samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
      channels.push_back(
          {{"sampler", samplers.size() - 1}, {"target", {{"node", node}, {"path", path}}}});
    };
    channel(nodes[i].arrow, "translation", start);
    channel(nodes[i].arrow, "rotation", rotation);
    channel(nodes[i].arrow, "scale", scale);
    channel(nodes[i].shaft, "scale", shaft_scale);
    channel(nodes[i].head, "translation", head_translation);
    channel(nodes[i].head, "scale", head_scale);
  }
}

}  // namespace sinew::viz::internal
