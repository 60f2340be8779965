// Regression tests for issue #9: counts in a .vtp file are checked against the data actually
// present without overflow, and zlib inflation never goes beyond what the header promises.
// Before the fix, a NumberOfPoints whose triple wraps (or does not fit a signed 64-bit count)
// passed the size check and the reader ran past the end of the points array; the same held for
// NumberOfPolys and the offsets array. Each case must now be a sinew::Error naming the file and
// line, with no out-of-bounds read (the ASan CI build checks that part).
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/mesh_base64.h>
#include <sinew/io/mesh_vtp.h>
#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

namespace sinew {
namespace {

// Parses `xml` and returns the error message (empty when none was thrown).
std::string ErrorOf(const std::string& xml) {
  try {
    io::ParseVtp(xml, "limits.vtp");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// A one-triangle piece with the given counts and array bodies (ascii by default); the Points
// array is on line 4.
std::string Piece(const std::string& n_points, const std::string& n_polys,
                  const std::string& points_array, const std::string& offsets = "3",
                  const std::string& vtk_attributes = "") {
  return "<VTKFile type=\"PolyData\"" + vtk_attributes + ">\n<PolyData>\n<Piece NumberOfPoints=\"" +
         n_points + "\" NumberOfPolys=\"" + n_polys + "\">\n" + "<Points>" + points_array +
         "</Points>\n<Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 "
         "2</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">" +
         offsets + "</DataArray></Polys>\n</Piece></PolyData></VTKFile>";
}

std::string AsciiPoints(const std::string& numbers) {
  return "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">" + numbers +
         "</DataArray>";
}

const std::string kTriangle = "0 0 0 1 0 0 0 1 0";

TEST(VtpLimitsTest, TheValidTriangleLoads) {
  // The baseline every case below breaks in one place.
  const io::TriangleMesh mesh = io::ParseVtp(Piece("3", "1", AsciiPoints(kTriangle)), "t.vtp");
  EXPECT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

TEST(VtpLimitsTest, PointCountWhoseTripleWrapsIsRejected) {
  // 3 * 6148914691236517206 = 2^64 + 2: the old size check compared 2 with the 2 values given.
  const std::string message = ErrorOf(Piece("6148914691236517206", "1", AsciiPoints("0 0")));
  EXPECT_NE(message.find("limits.vtp:4:"), std::string::npos) << message;
  EXPECT_NE(message.find("has 2 values, expected 6148914691236517206 tuples of 3"),
            std::string::npos)
      << message;
}

TEST(VtpLimitsTest, PointCountBeyondSignedRangeIsRejected) {
  // 3 * 2^62 is negative as a signed 64-bit count, which the old check took for "any size".
  for (const std::string n :
       {"4611686018427387904", "9223372036854775808", "18446744073709551615"}) {
    const std::string message = ErrorOf(Piece(n, "1", AsciiPoints(kTriangle)));
    EXPECT_NE(message.find("has 9 values, expected " + n + " tuples of 3"), std::string::npos)
        << message;
  }
}

TEST(VtpLimitsTest, PolygonCountBeyondTheOffsetsIsRejected) {
  const std::string message = ErrorOf(Piece("3", "9223372036854775808", AsciiPoints(kTriangle)));
  EXPECT_NE(message.find("'offsets' has 1 values, expected 9223372036854775808 tuples of 1"),
            std::string::npos)
      << message;
}

// Base64 of a binary DataArray: `header` words (UInt32, little-endian) then `body`.
std::string Binary(const std::vector<uint32_t>& header, const std::vector<uint8_t>& body) {
  std::vector<uint8_t> bytes;
  for (uint32_t word : header) {
    for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<uint8_t>(word >> (8 * i)));
  }
  bytes.insert(bytes.end(), body.begin(), body.end());
  return "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">" +
         io::EncodeBase64(bytes.data(), bytes.size()) + "</DataArray>";
}

std::vector<uint8_t> Compress(const std::vector<uint8_t>& data) {
  uLongf size = compressBound(data.size());
  std::vector<uint8_t> out(size);
  EXPECT_EQ(compress(out.data(), &size, data.data(), data.size()), Z_OK);
  out.resize(size);
  return out;
}

const std::string kZlib = " compressor=\"vtkZLibDataCompressor\"";

TEST(VtpLimitsTest, RawBinarySizeMustMatchTheCounts) {
  // 3 points of 3 Float32 are 36 bytes; the header promises (and holds) 40.
  const std::string message = ErrorOf(Piece("3", "1", Binary({40}, std::vector<uint8_t>(40))));
  EXPECT_NE(message.find("promises 40 bytes, the piece's counts call for 36"), std::string::npos)
      << message;
  // The same array with the right size loads.
  EXPECT_EQ(ErrorOf(Piece("3", "1", Binary({36}, std::vector<uint8_t>(36)))), "");
}

TEST(VtpLimitsTest, ZlibIsNotInflatedBeyondTheCounts) {
  // 1 MB of zeros deflates to about 1 kB, within deflate's 1032:1 limit, so only the counts
  // (36 bytes) tell this header is wrong; it must fail before inflating anything.
  const std::vector<uint8_t> block = Compress(std::vector<uint8_t>(1 << 20));
  const uint32_t c = static_cast<uint32_t>(block.size());
  const std::string message =
      ErrorOf(Piece("3", "1", Binary({1, 1 << 20, 1 << 20, c}, block), "3", kZlib));
  EXPECT_NE(message.find("promises 1048576 bytes, the piece's counts call for 36"),
            std::string::npos)
      << message;
}

TEST(VtpLimitsTest, ZlibBlockMustInflateToItsPromisedSize) {
  // The header promises 36 bytes but the stream holds 24: the points would be misaligned.
  const std::vector<uint8_t> block = Compress(std::vector<uint8_t>(24));
  const uint32_t c = static_cast<uint32_t>(block.size());
  const std::string message = ErrorOf(Piece("3", "1", Binary({1, 36, 36, c}, block), "3", kZlib));
  EXPECT_NE(message.find("block 0 does not inflate to the 36 bytes its header promises"),
            std::string::npos)
      << message;
  // A stream longer than promised is cut by zlib at the buffer's end, which is an error too.
  const std::vector<uint8_t> longer = Compress(std::vector<uint8_t>(48));
  const uint32_t l = static_cast<uint32_t>(longer.size());
  EXPECT_NE(
      ErrorOf(Piece("3", "1", Binary({1, 36, 36, l}, longer), "3", kZlib)).find("does not inflate"),
      std::string::npos);
  // And the honest header loads.
  const std::vector<uint8_t> exact = Compress(std::vector<uint8_t>(36));
  EXPECT_EQ(ErrorOf(Piece("3", "1", Binary({1, 36, 36, static_cast<uint32_t>(exact.size())}, exact),
                          "3", kZlib)),
            "");
}

TEST(VtpLimitsTest, ZlibBlockCountBeyondTheHeaderIsRejected) {
  // 2^32 - 1 blocks announced in a 20-byte array.
  const std::string message =
      ErrorOf(Piece("3", "1", Binary({0xFFFFFFFFu, 36, 36, 4}, {1, 2, 3, 4}), "3", kZlib));
  EXPECT_NE(message.find("header is truncated"), std::string::npos) << message;
}

}  // namespace
}  // namespace sinew
