#include <sinew/common/error.h>
#include <sinew/viz/image.h>
#include <zlib.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

namespace sinew::viz {
namespace {

constexpr uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

void PutU32(std::vector<uint8_t>& out, uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<uint8_t>(v >> s));
}

uint32_t GetU32(const uint8_t* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | p[3];
}

void PutChunk(std::vector<uint8_t>& out, const char* type, const std::vector<uint8_t>& data) {
  PutU32(out, static_cast<uint32_t>(data.size()));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  PutU32(out, static_cast<uint32_t>(crc32(0, out.data() + start, out.size() - start)));
}

int Paeth(int a, int b, int c) {
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

}  // namespace

Image::Image(int w, int h, uint8_t r, uint8_t g, uint8_t b) : width(w), height(h) {
  rgb.resize(static_cast<size_t>(w) * h * 3);
  for (size_t i = 0; i < rgb.size(); i += 3) {
    rgb[i] = r;
    rgb[i + 1] = g;
    rgb[i + 2] = b;
  }
}

std::vector<uint8_t> EncodePng(const Image& image) {
  std::vector<uint8_t> out(kSignature, kSignature + 8);
  std::vector<uint8_t> header;
  PutU32(header, image.width);
  PutU32(header, image.height);
  header.insert(header.end(), {8, 2, 0, 0, 0});  // depth 8, RGB, deflate, filter 0, no interlace
  PutChunk(out, "IHDR", header);
  // Each row: filter type 0 (none), then the pixels.
  std::vector<uint8_t> raw;
  const size_t row = static_cast<size_t>(image.width) * 3;
  raw.reserve((row + 1) * image.height);
  for (int y = 0; y < image.height; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), image.rgb.begin() + y * row, image.rgb.begin() + (y + 1) * row);
  }
  uLongf size = compressBound(raw.size());
  std::vector<uint8_t> packed(size);
  if (compress2(packed.data(), &size, raw.data(), raw.size(), 6) != Z_OK) {
    throw Error("PNG encoding failed (zlib)");
  }
  packed.resize(size);
  PutChunk(out, "IDAT", packed);
  PutChunk(out, "IEND", {});
  return out;
}

Image DecodePng(const std::vector<uint8_t>& bytes, const std::string& name) {
  auto fail = [&](const std::string& message) -> Image {
    throw Error(SourceLocation{name, 0}, "", "PNG: " + message);
  };
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0) {
    return fail("not a PNG file");
  }
  int width = 0, height = 0, color = 0;
  std::vector<uint8_t> packed;
  for (size_t at = 8; at + 12 <= bytes.size();) {
    const uint32_t length = GetU32(&bytes[at]);
    if (at + 12 + static_cast<size_t>(length) > bytes.size()) return fail("truncated chunk");
    const std::string type(bytes.begin() + at + 4, bytes.begin() + at + 8);
    const uint8_t* data = &bytes[at + 8];
    if (crc32(0, &bytes[at + 4], length + 4) != GetU32(data + length)) {
      return fail("chunk " + type + " fails its CRC check");
    }
    if (type == "IHDR") {
      if (length != 13) return fail("IHDR chunk of " + std::to_string(length) + " bytes, not 13");
      width = static_cast<int>(GetU32(data));
      height = static_cast<int>(GetU32(data + 4));
      color = data[9];
      if (data[8] != 8 || data[12] != 0) return fail("only 8-bit non-interlaced images");
    } else if (type == "IDAT") {
      packed.insert(packed.end(), data, data + length);
    } else if (type == "IEND") {
      break;
    }
    at += 12 + length;
  }
  const int channels = color == 0 ? 1 : color == 4 ? 2 : color == 2 ? 3 : color == 6 ? 4 : 0;
  if (channels == 0) return fail("unsupported colour type");
  if (width <= 0 || height <= 0 || width > 32768 || height > 32768) {
    return fail("image size out of range");
  }
  const size_t stride = static_cast<size_t>(width) * channels;
  std::vector<uint8_t> raw((stride + 1) * height);
  uLongf raw_size = raw.size();
  if (uncompress(raw.data(), &raw_size, packed.data(), packed.size()) != Z_OK ||
      raw_size != raw.size()) {
    return fail("corrupt image data");
  }
  // Undo the per-row filters (None, Sub, Up, Average, Paeth) in place.
  std::vector<uint8_t> pixels(stride * height);
  for (int y = 0; y < height; ++y) {
    const uint8_t filter = raw[y * (stride + 1)];
    const uint8_t* in = &raw[y * (stride + 1) + 1];
    uint8_t* cur = &pixels[y * stride];
    const uint8_t* prev = y > 0 ? &pixels[(y - 1) * stride] : nullptr;
    for (size_t i = 0; i < stride; ++i) {
      const int a = i >= static_cast<size_t>(channels) ? cur[i - channels] : 0;
      const int b = prev ? prev[i] : 0;
      const int c = prev && i >= static_cast<size_t>(channels) ? prev[i - channels] : 0;
      int predictor = 0;
      switch (filter) {
        case 0:
          predictor = 0;
          break;
        case 1:
          predictor = a;
          break;
        case 2:
          predictor = b;
          break;
        case 3:
          predictor = (a + b) / 2;
          break;
        case 4:
          predictor = Paeth(a, b, c);
          break;
        default:
          return fail("bad row filter");
      }
      cur[i] = static_cast<uint8_t>(in[i] + predictor);
    }
  }
  Image image(width, height);
  for (size_t p = 0; p < static_cast<size_t>(width) * height; ++p) {
    const uint8_t* px = &pixels[p * channels];
    for (int k = 0; k < 3; ++k) image.rgb[3 * p + k] = channels >= 3 ? px[k] : px[0];
  }
  return image;
}

std::vector<uint8_t> ReadFileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(SourceLocation{path, 0}, "", "cannot open file");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace sinew::viz
