#include <sinew/common/atomic_file.h>
#include <sinew/common/error.h>
#include <sinew/viz/gltf_writer.h>
#include <sinew/viz/internal/glb_builder.h>
#include <sinew/viz/internal/gltf_contact_arrows.h>
#include <sinew/viz/internal/gltf_mesh.h>
#include <sinew/viz/internal/gltf_path_lines.h>

#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <string_view>

namespace sinew::viz {
namespace {

using internal::BinaryBuilder;
using internal::json;

json TranslationOf(const Transform& X) { return {X.p.x(), X.p.y(), X.p.z()}; }

// glTF quaternion order is x, y, z, w.
json RotationOf(const Mat3& R) {
  Quat q(R);
  q.normalize();
  return {q.x(), q.y(), q.z(), q.w()};
}

void AppendUint32(std::vector<uint8_t>& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

}  // namespace

std::vector<uint8_t> WriteGlb(const VisualScene& scene, const BodyMotion& motion,
                              const std::string& model_name, const PathLines* lines,
                              const ViewHints* hints) {
  json doc;
  doc["asset"] = {{"version", "2.0"}, {"generator", "Sinew"}};
  doc["scene"] = 0;
  doc["nodes"] = json::array();
  doc["meshes"] = json::array();
  doc["materials"] = json::array();
  BinaryBuilder bin(doc);

  // Geometry shared by parts (the same shared_ptr) is stored once.
  std::map<const io::TriangleMesh*, json> primitive_of;
  auto primitive = [&](const io::TriangleMesh& mesh) -> json {
    auto it = primitive_of.find(&mesh);
    if (it != primitive_of.end()) return it->second;
    return primitive_of[&mesh] = internal::MeshPrimitive(bin, mesh);
  };

  json root_children = json::array();
  std::vector<int> body_nodes;
  for (const VisualBody& body : scene.bodies) {
    json node = {{"name", body.name}, {"extras", {{"body_index", body.body}}}};
    if (!motion.X_GB.empty() && body.body < static_cast<int>(motion.X_GB[0].size())) {
      const Transform& X = motion.X_GB[0][body.body];
      node["translation"] = TranslationOf(X);
      node["rotation"] = RotationOf(X.R);
    }
    json children = json::array();
    for (const VisualPart& part : body.parts) {
      if (!part.mesh || part.mesh->empty()) continue;
      json material = {
          {"name", part.name},
          {"pbrMetallicRoughness",
           {{"baseColorFactor", {part.color.x(), part.color.y(), part.color.z(), part.opacity}},
            {"metallicFactor", 0.0},
            {"roughnessFactor", 0.7}}},
          {"doubleSided", true}};
      if (part.opacity < 1.0) material["alphaMode"] = "BLEND";
      doc["materials"].push_back(material);
      json p = primitive(*part.mesh);
      p["material"] = doc["materials"].size() - 1;
      doc["meshes"].push_back({{"name", part.name}, {"primitives", json::array({p})}});
      json child = {{"name", part.name},
                    {"mesh", doc["meshes"].size() - 1},
                    {"translation", TranslationOf(part.X_BG)},
                    {"rotation", RotationOf(part.X_BG.R)},
                    {"scale", {part.scale.x(), part.scale.y(), part.scale.z()}},
                    {"extras", {{"source", part.source}}}};
      if (part.unbounded) child["extras"]["unbounded"] = true;  // the viewer frames without it
      doc["nodes"].push_back(child);
      children.push_back(doc["nodes"].size() - 1);
    }
    if (!children.empty()) node["children"] = children;
    doc["nodes"].push_back(node);
    body_nodes.push_back(static_cast<int>(doc["nodes"].size() - 1));
    root_children.push_back(body_nodes.back());
  }
  std::vector<int> path_frame_nodes;
  if (lines && !lines->names.empty() && !lines->vertices.empty()) {
    root_children.push_back(internal::AddPathNodes(doc, bin, *lines, path_frame_nodes));
  }
  std::vector<internal::ArrowNodes> arrow_nodes;
  const bool arrows =
      hints && !hints->arrows.empty() && hints->arrows.start.size() == motion.times.size();
  if (arrows)
    root_children.push_back(internal::AddArrowNodes(doc, bin, hints->arrows, arrow_nodes));
  doc["nodes"].push_back({{"name", model_name}, {"children", root_children}});
  doc["scenes"] = json::array({{{"name", model_name}, {"nodes", {doc["nodes"].size() - 1}}}});
  if (hints) {
    std::vector<int> arrow_node_list;
    for (const internal::ArrowNodes& n : arrow_nodes) arrow_node_list.push_back(n.arrow);
    doc["scenes"][0]["extras"] = internal::ViewHintsExtras(*hints, arrow_node_list);
  }

  // The animation: one time input shared by every channel.
  const size_t n_frames = motion.times.size();
  if (n_frames >= 2 && motion.X_GB.size() == n_frames) {
    std::vector<float> times(n_frames);
    for (size_t k = 0; k < n_frames; ++k) {
      times[k] = static_cast<float>(motion.times[k] - motion.times[0]);
    }
    const int input = bin.AddFloats(times, "SCALAR", 1, 0, true);
    json samplers = json::array(), channels = json::array();
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
      const int b = scene.bodies[i].body;
      if (b >= static_cast<int>(motion.X_GB[0].size())) continue;
      std::vector<float> translation, rotation;
      Quat previous = Quat::Identity();
      for (size_t k = 0; k < n_frames; ++k) {
        const Transform& X = motion.X_GB[k][b];
        translation.insert(translation.end(),
                           {static_cast<float>(X.p.x()), static_cast<float>(X.p.y()),
                            static_cast<float>(X.p.z())});
        Quat q(X.R);
        q.normalize();
        // q and -q are the same rotation; keep neighbours in one hemisphere so that
        // interpolation takes the short way.
        if (k > 0 && q.dot(previous) < 0) q.coeffs() = -q.coeffs();
        previous = q;
        rotation.insert(rotation.end(), {static_cast<float>(q.x()), static_cast<float>(q.y()),
                                         static_cast<float>(q.z()), static_cast<float>(q.w())});
      }
      const int t_out = bin.AddFloats(translation, "VEC3", 3, 0, false);
      const int r_out = bin.AddFloats(rotation, "VEC4", 4, 0, false);
      samplers.push_back({{"input", input}, {"output", t_out}, {"interpolation", "LINEAR"}});
      channels.push_back({{"sampler", samplers.size() - 1},
                          {"target", {{"node", body_nodes[i]}, {"path", "translation"}}}});
      samplers.push_back({{"input", input}, {"output", r_out}, {"interpolation", "LINEAR"}});
      channels.push_back({{"sampler", samplers.size() - 1},
                          {"target", {{"node", body_nodes[i]}, {"path", "rotation"}}}});
    }
    internal::AddPathChannels(bin, times, path_frame_nodes, samplers, channels);
    if (arrows)
      internal::AddArrowChannels(bin, input, hints->arrows, arrow_nodes, samplers, channels);
    doc["animations"] = json::array({{{"name", "motion"},
                                      {"samplers", samplers},
                                      {"channels", channels},
                                      {"extras", {{"start_time", motion.times[0]}}}}});
  }
  if (doc["meshes"].empty()) {
    doc.erase("meshes");
    doc.erase("materials");
  }
  std::vector<uint8_t>& data = bin.bytes();
  while (data.size() % 4 != 0) data.push_back(0);
  if (!data.empty()) doc["buffers"] = json::array({{{"byteLength", data.size()}}});
  if (doc["accessors"].empty()) {
    doc.erase("accessors");
    doc.erase("bufferViews");
  }

  // GLB: header, JSON chunk padded with spaces, BIN chunk padded with zeros.
  std::string text = doc.dump();
  while (text.size() % 4 != 0) text.push_back(' ');
  const size_t total = 12 + 8 + text.size() + (data.empty() ? 0 : 8 + data.size());
  std::vector<uint8_t> out;
  out.reserve(total);
  AppendUint32(out, 0x46546C67);  // "glTF"
  AppendUint32(out, 2);
  AppendUint32(out, static_cast<uint32_t>(total));
  AppendUint32(out, static_cast<uint32_t>(text.size()));
  AppendUint32(out, 0x4E4F534A);  // "JSON"
  out.insert(out.end(), text.begin(), text.end());
  if (!data.empty()) {
    AppendUint32(out, static_cast<uint32_t>(data.size()));
    AppendUint32(out, 0x004E4942);  // "BIN\0"
    out.insert(out.end(), data.begin(), data.end());
  }
  return out;
}

void WriteFileBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  WriteFileAtomically(path,
                      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace sinew::viz
