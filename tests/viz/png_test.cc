// The PNG codec against an independent reading of the format (PNG specification, ISO/IEC
// 15948): chunks parsed by hand, every CRC checked with a CRC-32 written here, the image data
// inflated with zlib directly and the row filters undone here. And the library's decoder on
// images this test encodes with every row filter.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/viz/image.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace sinew::viz {
namespace {

// CRC-32 of the PNG specification (ISO 3309 / ITU-T V.42): reflected polynomial 0xEDB88320,
// register preset to all ones and inverted at the end; bit by bit, no table.
uint32_t Crc32(const uint8_t* data, size_t size) {
  uint32_t crc = 0xFFFFFFFFu;
  for (size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

uint32_t BigEndian32(const uint8_t* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | p[3];
}

void PutBigEndian32(std::vector<uint8_t>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(v >> shift));
}

struct Chunk {
  std::string type;
  std::vector<uint8_t> data;
  bool crc_ok = false;
};

// Splits PNG bytes into chunks after checking the 8-byte signature; each chunk's stored CRC is
// compared with Crc32(type + data). Fails the test on a malformed layout.
std::vector<Chunk> ParseChunks(const std::vector<uint8_t>& png) {
  static const uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  std::vector<Chunk> chunks;
  EXPECT_GE(png.size(), 8u);
  if (png.size() < 8 || !std::equal(kSignature, kSignature + 8, png.begin())) {
    ADD_FAILURE() << "no PNG signature";
    return chunks;
  }
  size_t at = 8;
  while (at < png.size()) {
    if (png.size() - at < 12) {
      ADD_FAILURE() << "truncated chunk at byte " << at;
      return chunks;
    }
    const uint32_t length = BigEndian32(&png[at]);
    if (png.size() - at - 12 < length) {
      ADD_FAILURE() << "chunk length " << length << " past the end at byte " << at;
      return chunks;
    }
    Chunk chunk;
    chunk.type.assign(png.begin() + at + 4, png.begin() + at + 8);
    chunk.data.assign(png.begin() + at + 8, png.begin() + at + 8 + length);
    chunk.crc_ok = Crc32(&png[at + 4], length + 4) == BigEndian32(&png[at + 8 + length]);
    chunks.push_back(std::move(chunk));
    at += 12 + length;
  }
  return chunks;
}

int PaethPredictor(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

// The predictor of filter `type` for byte i of a row (bpp bytes per pixel), given the
// unfiltered current row so far and the unfiltered previous row (zeros for the first row).
int Predictor(int type, const std::vector<uint8_t>& row, const std::vector<uint8_t>& above,
              size_t i, size_t bpp) {
  const int a = i >= bpp ? row[i - bpp] : 0;
  const int b = above[i];
  const int c = i >= bpp ? above[i - bpp] : 0;
  switch (type) {
    case 1:
      return a;
    case 2:
      return b;
    case 3:
      return (a + b) / 2;
    case 4:
      return PaethPredictor(a, b, c);
    default:
      return 0;
  }
}

// RGB image of the PNG bytes, decoded here: IHDR checked (8-bit RGB, no interlace), IDAT
// inflated with zlib, row filters 0-4 undone.
Image DecodeIndependently(const std::vector<uint8_t>& png) {
  const std::vector<Chunk> chunks = ParseChunks(png);
  EXPECT_FALSE(chunks.empty());
  if (chunks.empty()) return {};
  // IHDR first (13 bytes), IEND last and empty; every CRC right.
  EXPECT_EQ(chunks.front().type, "IHDR");
  EXPECT_EQ(chunks.back().type, "IEND");
  EXPECT_TRUE(chunks.back().data.empty());
  for (const Chunk& chunk : chunks) EXPECT_TRUE(chunk.crc_ok) << chunk.type;
  const std::vector<uint8_t>& header = chunks.front().data;
  EXPECT_EQ(header.size(), 13u);
  if (header.size() != 13) return {};
  const int width = static_cast<int>(BigEndian32(&header[0]));
  const int height = static_cast<int>(BigEndian32(&header[4]));
  EXPECT_EQ(header[8], 8);   // bit depth
  EXPECT_EQ(header[9], 2);   // colour type: truecolour (RGB)
  EXPECT_EQ(header[10], 0);  // compression: deflate
  EXPECT_EQ(header[11], 0);  // filter method: adaptive, five types
  EXPECT_EQ(header[12], 0);  // no interlace
  std::vector<uint8_t> packed;
  for (const Chunk& chunk : chunks) {
    if (chunk.type == "IDAT") packed.insert(packed.end(), chunk.data.begin(), chunk.data.end());
  }
  const size_t stride = static_cast<size_t>(width) * 3;
  std::vector<uint8_t> raw(height * (stride + 1) + 1);  // one spare byte: detects extra data
  uLongf raw_size = raw.size();
  EXPECT_EQ(uncompress(raw.data(), &raw_size, packed.data(), packed.size()), Z_OK);
  EXPECT_EQ(raw_size, height * (stride + 1));
  Image image(width, height);
  std::vector<uint8_t> above(stride, 0), row(stride);
  for (int y = 0; y < height; ++y) {
    const uint8_t* line = &raw[y * (stride + 1)];
    EXPECT_LE(line[0], 4) << "row " << y;
    for (size_t i = 0; i < stride; ++i) {
      row[i] = static_cast<uint8_t>(line[1 + i] + Predictor(line[0], row, above, i, 3));
    }
    std::copy(row.begin(), row.end(), image.rgb.begin() + y * stride);
    above = row;
  }
  return image;
}

// A test image whose rows differ and whose neighbouring bytes are unrelated.
Image Pattern(int width, int height) {
  Image image(width, height);
  for (size_t i = 0; i < image.rgb.size(); ++i) {
    image.rgb[i] = static_cast<uint8_t>((i * 37 + (i / 7) * 11 + i * i) & 0xff);
  }
  return image;
}

TEST(PngTest, OwnCrc32GivesTheStandardCheckValue) {
  // The CRC-32 check value of the ASCII digits "123456789" is 0xCBF43926.
  const std::string digits = "123456789";
  EXPECT_EQ(Crc32(reinterpret_cast<const uint8_t*>(digits.data()), digits.size()), 0xCBF43926u);
}

TEST(PngTest, EncodedFileDecodesIndependently) {
  const std::array<std::pair<int, int>, 4> sizes = {{{1, 1}, {7, 5}, {64, 3}, {13, 40}}};
  for (const auto& [width, height] : sizes) {
    const Image image = Pattern(width, height);
    const std::vector<uint8_t> png = EncodePng(image);
    const Image decoded = DecodeIndependently(png);
    EXPECT_EQ(decoded.width, width);
    EXPECT_EQ(decoded.height, height);
    EXPECT_EQ(decoded.rgb, image.rgb) << width << " x " << height;
  }
}

// PNG bytes of `image` written by this test: row y uses filter y % 5 (None, Sub, Up, Average,
// Paeth), so decoding them exercises every filter.
std::vector<uint8_t> EncodeWithEveryFilter(const Image& image) {
  const size_t stride = static_cast<size_t>(image.width) * 3;
  std::vector<uint8_t> raw;
  std::vector<uint8_t> above(stride, 0), row(stride);
  for (int y = 0; y < image.height; ++y) {
    const int type = y % 5;
    raw.push_back(static_cast<uint8_t>(type));
    std::copy(image.rgb.begin() + y * stride, image.rgb.begin() + (y + 1) * stride, row.begin());
    for (size_t i = 0; i < stride; ++i) {
      raw.push_back(static_cast<uint8_t>(row[i] - Predictor(type, row, above, i, 3)));
    }
    above = row;
  }
  uLongf size = compressBound(raw.size());
  std::vector<uint8_t> packed(size);
  EXPECT_EQ(compress(packed.data(), &size, raw.data(), raw.size()), Z_OK);
  packed.resize(size);
  std::vector<uint8_t> png = {137, 80, 78, 71, 13, 10, 26, 10};
  auto put_chunk = [&png](const std::string& type, const std::vector<uint8_t>& data) {
    PutBigEndian32(png, static_cast<uint32_t>(data.size()));
    const size_t start = png.size();
    png.insert(png.end(), type.begin(), type.end());
    png.insert(png.end(), data.begin(), data.end());
    PutBigEndian32(png, Crc32(&png[start], png.size() - start));
  };
  std::vector<uint8_t> header;
  PutBigEndian32(header, image.width);
  PutBigEndian32(header, image.height);
  header.insert(header.end(), {8, 2, 0, 0, 0});
  put_chunk("IHDR", header);
  // Two IDAT chunks: the decoder must concatenate them.
  const size_t half = packed.size() / 2;
  put_chunk("IDAT", std::vector<uint8_t>(packed.begin(), packed.begin() + half));
  put_chunk("IDAT", std::vector<uint8_t>(packed.begin() + half, packed.end()));
  put_chunk("IEND", {});
  return png;
}

TEST(PngTest, DecoderUndoesEveryRowFilter) {
  const Image image = Pattern(9, 11);
  const std::vector<uint8_t> png = EncodeWithEveryFilter(image);
  ASSERT_EQ(DecodeIndependently(png).rgb, image.rgb);  // the test's own encoder is right
  const Image decoded = DecodePng(png, "filters.png");
  EXPECT_EQ(decoded.width, 9);
  EXPECT_EQ(decoded.height, 11);
  EXPECT_EQ(decoded.rgb, image.rgb);
}

TEST(PngTest, EncodeDecodeRoundTripAndCorruptData) {
  Image image(7, 5);
  for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<uint8_t>(i * 37);
  std::vector<uint8_t> png = EncodePng(image);
  Image back = DecodePng(png, "mem.png");
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.rgb, image.rgb);
  // Corrupt the compressed data (the IDAT chunk starts at byte 33, its payload at 41) but give
  // the chunk a matching CRC: the inflate step must catch it.
  const uint32_t idat_length = BigEndian32(&png[33]);
  png[45] ^= 0xff;
  const uint32_t crc = Crc32(&png[37], idat_length + 4);
  for (int k = 0; k < 4; ++k) png[41 + idat_length + k] = static_cast<uint8_t>(crc >> (24 - 8 * k));
  try {
    DecodePng(png, "bad.png");
    ADD_FAILURE() << "corrupt image data was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("corrupt image data"), std::string::npos) << e.what();
  }
  EXPECT_THROW(DecodePng({1, 2, 3}, "bad.png"), Error);
}

TEST(PngTest, DecoderRejectsABadCrcAndAShortHeader) {
  const Image image = Pattern(4, 4);
  std::vector<uint8_t> png = EncodePng(image);
  // The last byte is IEND's CRC.
  png.back() ^= 0x01;
  try {
    DecodePng(png, "crc.png");
    ADD_FAILURE() << "a wrong CRC was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "crc.png");
    EXPECT_NE(std::string(e.what()).find("CRC"), std::string::npos) << e.what();
  }
  // An IHDR of 4 bytes (then the file ends): an error, not a read past the chunk.
  std::vector<uint8_t> short_header = {137, 80, 78, 71, 13, 10, 26, 10, 0, 0, 0, 4};
  const std::vector<uint8_t> body = {'I', 'H', 'D', 'R', 0, 0, 0, 4};
  short_header.insert(short_header.end(), body.begin(), body.end());
  PutBigEndian32(short_header, Crc32(body.data(), body.size()));
  EXPECT_THROW(DecodePng(short_header, "short.png"), Error);
}

}  // namespace
}  // namespace sinew::viz
