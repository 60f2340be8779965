// RGB images and PNG encoding/decoding (zlib), for the renderer and the viewer tests.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sinew::viz {

/// An 8-bit RGB image, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgb;  ///< width * height * 3 bytes.

  Image() = default;
  Image(int w, int h, uint8_t r = 0, uint8_t g = 0, uint8_t b = 0);
  uint8_t* At(int x, int y) { return rgb.data() + 3 * (static_cast<size_t>(y) * width + x); }
  const uint8_t* At(int x, int y) const {
    return rgb.data() + 3 * (static_cast<size_t>(y) * width + x);
  }
};

/// PNG file bytes of `image` (colour type 2, 8 bits, filter 0 per row, zlib).
std::vector<uint8_t> EncodePng(const Image& image);

/// Decodes a non-interlaced 8-bit PNG (grey, grey+alpha, RGB or RGBA; alpha dropped).
/// Throws sinew::Error naming `name` on anything else or on corrupt data (a chunk whose CRC
/// does not match, a malformed header, a broken compressed stream).
Image DecodePng(const std::vector<uint8_t>& bytes, const std::string& name);

/// Reads a whole file; throws sinew::Error when it cannot be opened.
std::vector<uint8_t> ReadFileBytes(const std::string& path);

}  // namespace sinew::viz
