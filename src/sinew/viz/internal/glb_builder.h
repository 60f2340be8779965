// Internal to the glTF writer: the BIN chunk of a .glb and the buffer views and accessors that
// point into it, shared by the files that write parts of the document.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <type_traits>
#include <vector>

namespace sinew::viz::internal {

using nlohmann::json;

// glTF constants.
constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

// Accumulates the BIN chunk and the buffer views / accessors that point into it.
class BinaryBuilder {
 public:
  explicit BinaryBuilder(json& doc) : doc_(doc) {
    doc_["bufferViews"] = json::array();
    doc_["accessors"] = json::array();
  }

  // Appends floats as a buffer view + accessor; returns the accessor index.
  int AddFloats(const std::vector<float>& values, const char* type, int components, int target,
                bool with_min_max) {
    const int view = AddView(values.data(), values.size() * sizeof(float), target);
    json accessor = {{"bufferView", view},
                     {"componentType", kFloat},
                     {"count", values.size() / components},
                     {"type", type}};
    if (with_min_max) {
      std::vector<float> lo(components, 0), hi(components, 0);
      for (size_t i = 0; i < values.size(); ++i) {
        const size_t c = i % components;
        if (i < static_cast<size_t>(components) || values[i] < lo[c]) lo[c] = values[i];
        if (i < static_cast<size_t>(components) || values[i] > hi[c]) hi[c] = values[i];
      }
      accessor["min"] = lo;
      accessor["max"] = hi;
    }
    doc_["accessors"].push_back(accessor);
    return static_cast<int>(doc_["accessors"].size() - 1);
  }

  // Vertex indices as unsigned ints, or as unsigned shorts (half the bytes; fewer than 65536
  // vertices).
  template <typename Index>
  int AddIndices(const std::vector<Index>& indices) {
    static_assert(std::is_same_v<Index, uint32_t> || std::is_same_v<Index, uint16_t>);
    const int view = AddView(indices.data(), indices.size() * sizeof(Index), kElementArrayBuffer);
    doc_["accessors"].push_back(
        {{"bufferView", view},
         {"componentType", std::is_same_v<Index, uint32_t> ? kUnsignedInt : kUnsignedShort},
         {"count", indices.size()},
         {"type", "SCALAR"}});
    return static_cast<int>(doc_["accessors"].size() - 1);
  }

  std::vector<uint8_t>& bytes() { return bin_; }

 private:
  int AddView(const void* data, size_t size, int target) {
    while (bin_.size() % 4 != 0) bin_.push_back(0);  // accessors need 4-byte alignment
    json view = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", size}};
    if (target != 0) view["target"] = target;
    const uint8_t* p = static_cast<const uint8_t*>(data);
    bin_.insert(bin_.end(), p, p + size);
    doc_["bufferViews"].push_back(view);
    return static_cast<int>(doc_["bufferViews"].size() - 1);
  }

  json& doc_;
  std::vector<uint8_t> bin_;
};

}  // namespace sinew::viz::internal
