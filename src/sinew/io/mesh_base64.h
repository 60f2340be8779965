// Base64 (RFC 4648) encoding and decoding, used by .vtp binary arrays and the HTML viewer.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sinew::io {

/// Encodes bytes as base64 with '=' padding.
std::string EncodeBase64(const uint8_t* data, size_t size);

/// Decodes base64 text; whitespace is skipped. Returns nullopt on a character outside the
/// alphabet or a truncated group.
std::optional<std::vector<uint8_t>> DecodeBase64(std::string_view text);

}  // namespace sinew::io
