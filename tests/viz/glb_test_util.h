// Test helper: splits a .glb into its JSON document and BIN chunk, checking the container
// layout of the glTF 2.0 specification (header, 4-byte aligned chunks, padding bytes).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sinew::viz::testing {

struct ParsedGlb {
  nlohmann::json doc;
  std::vector<uint8_t> bin;
};

inline uint32_t U32(const std::vector<uint8_t>& b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

/// Parses and checks the container; ADD_FAILURE on any violation.
inline ParsedGlb ParseGlb(const std::vector<uint8_t>& glb) {
  ParsedGlb out;
  if (glb.size() < 20) {
    ADD_FAILURE() << "GLB too short";
    return out;
  }
  EXPECT_EQ(U32(glb, 0), 0x46546C67u) << "magic 'glTF'";
  EXPECT_EQ(U32(glb, 4), 2u) << "version";
  EXPECT_EQ(U32(glb, 8), glb.size()) << "total length";
  const uint32_t json_length = U32(glb, 12);
  EXPECT_EQ(U32(glb, 16), 0x4E4F534Au) << "JSON chunk type";
  EXPECT_EQ(json_length % 4, 0u);
  std::string text(glb.begin() + 20, glb.begin() + 20 + json_length);
  out.doc = nlohmann::json::parse(text);  // trailing spaces are valid JSON whitespace
  size_t at = 20 + json_length;
  if (at < glb.size()) {
    const uint32_t bin_length = U32(glb, at);
    EXPECT_EQ(U32(glb, at + 4), 0x004E4942u) << "BIN chunk type";
    EXPECT_EQ(bin_length % 4, 0u);
    EXPECT_EQ(at + 8 + bin_length, glb.size());
    out.bin.assign(glb.begin() + at + 8, glb.begin() + at + 8 + bin_length);
  }
  return out;
}

/// Reads accessor `index` as floats (tightly packed FLOAT accessors only).
inline std::vector<float> ReadFloatAccessor(const ParsedGlb& glb, int index) {
  const auto& accessor = glb.doc["accessors"][index];
  const auto& view = glb.doc["bufferViews"][accessor["bufferView"].get<int>()];
  EXPECT_EQ(accessor["componentType"], 5126);
  const std::string type = accessor["type"];
  const int components = type == "SCALAR" ? 1 : type == "VEC3" ? 3 : type == "VEC4" ? 4 : 0;
  const size_t count = accessor["count"].get<size_t>() * components;
  const size_t offset = view.value("byteOffset", 0);
  EXPECT_EQ(offset % 4, 0u);
  EXPECT_LE(offset + count * 4, glb.bin.size());
  std::vector<float> values(count);
  std::memcpy(values.data(), glb.bin.data() + offset, count * 4);
  return values;
}

}  // namespace sinew::viz::testing
