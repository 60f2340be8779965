#include <sinew/viz/internal/gltf_path_lines.h>

#include <algorithm>

namespace sinew::viz::internal {
namespace {

// As unsigned shorts when they fit.
int AddIndices(BinaryBuilder& bin, const std::vector<uint32_t>& indices) {
  if (std::any_of(indices.begin(), indices.end(), [](uint32_t i) { return i > 0xFFFF; })) {
    return bin.AddIndices(indices);
  }
  return bin.AddIndices(std::vector<uint16_t>(indices.begin(), indices.end()));
}

}  // namespace

int AddPathNodes(json& doc, BinaryBuilder& bin, const PathLines& lines,
                 std::vector<int>& frame_nodes) {
  // Shaded by activation: the colours are per vertex (COLOR_0), the material white.
  const bool shaded = !lines.activation.empty();
  const Vec3 base = shaded ? Vec3::Ones() : lines.color;
  doc["materials"].push_back({{"name", "paths"},
                              {"pbrMetallicRoughness",
                               {{"baseColorFactor", {base.x(), base.y(), base.z(), 1.0}},
                                {"metallicFactor", 0.0},
                                {"roughnessFactor", 1.0}}}});
  const size_t material = doc["materials"].size() - 1;
  json children = json::array();
  frame_nodes.clear();
  std::vector<float> positions, colors;
  std::vector<uint32_t> indices;
  for (size_t k = 0; k < lines.vertices.size(); ++k) {
    positions.clear();
    colors.clear();
    indices.clear();
    std::vector<uint32_t> counts;
    counts.reserve(lines.vertices[k].size());
    for (size_t i = 0; i < lines.vertices[k].size(); ++i) {
      const std::vector<Vec3>& line = lines.vertices[k][i];
      const uint32_t first = static_cast<uint32_t>(positions.size() / 3);
      const Vec3 color = shaded ? PathColor(lines, lines.activation[k][i]) : lines.color;
      for (size_t j = 0; j < line.size(); ++j) {
        const Vec3& p = line[j];
        positions.insert(positions.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()),
                                           static_cast<float>(p.z())});
        if (shaded) {
          colors.insert(colors.end(), {static_cast<float>(color.x()), static_cast<float>(color.y()),
                                       static_cast<float>(color.z())});
        }
        // LINES: one index pair per segment of the polyline.
        if (j > 0)
          indices.insert(indices.end(),
                         {first + static_cast<uint32_t>(j) - 1, first + static_cast<uint32_t>(j)});
      }
      counts.push_back(static_cast<uint32_t>(line.size()));
    }
    json node = {{"name", "paths@" + std::to_string(k)}};
    if (k > 0) node["scale"] = {0.0, 0.0, 0.0};
    if (!indices.empty()) {
      json primitive = {
          {"attributes", {{"POSITION", bin.AddFloats(positions, "VEC3", 3, kArrayBuffer, true)}}},
          {"indices", AddIndices(bin, indices)},
          {"material", material},
          {"mode", 1}};
      if (shaded) {
        primitive["attributes"]["COLOR_0"] = bin.AddFloats(colors, "VEC3", 3, kArrayBuffer, false);
      }
      doc["meshes"].push_back({{"name", node["name"]},
                               {"primitives", json::array({primitive})},
                               {"extras", {{"vertex_counts", counts}}}});
      node["mesh"] = doc["meshes"].size() - 1;
    }
    doc["nodes"].push_back(node);
    frame_nodes.push_back(static_cast<int>(doc["nodes"].size() - 1));
    children.push_back(frame_nodes.back());
  }
  doc["nodes"].push_back(
      {{"name", "paths"}, {"children", children}, {"extras", {{"paths", lines.names}}}});
  return static_cast<int>(doc["nodes"].size() - 1);
}

void AddPathChannels(BinaryBuilder& bin, const std::vector<float>& times,
                     const std::vector<int>& frame_nodes, json& samplers, json& channels) {
  const size_t n = std::min(times.size(), frame_nodes.size());
  if (n < 2) return;
  for (size_t k = 0; k < n; ++k) {
    // Keys: hidden from the start (unless k is the first frame), shown at times[k], hidden
    // again at times[k + 1] (unless k is the last).
    std::vector<float> input, output;
    if (k > 0) input.push_back(times[0]), output.insert(output.end(), {0, 0, 0});
    input.push_back(times[k]);
    output.insert(output.end(), {1, 1, 1});
    if (k + 1 < n) input.push_back(times[k + 1]), output.insert(output.end(), {0, 0, 0});
    samplers.push_back({{"input", bin.AddFloats(input, "SCALAR", 1, 0, true)},
                        {"output", bin.AddFloats(output, "VEC3", 3, 0, false)},
                        {"interpolation", "STEP"}});
    channels.push_back({{"sampler", samplers.size() - 1},
                        {"target", {{"node", frame_nodes[k]}, {"path", "scale"}}}});
  }
}

}  // namespace sinew::viz::internal
