// Tests for the .vtp reader: a real OpenSim mesh (ascii), and the same small mesh written in
// every binary variant (base64, zlib blocks, UInt64 headers, big-endian) must read alike.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/mesh_base64.h>
#include <sinew/io/mesh_vtp.h>
#include <zlib.h>

#include <cstring>
#include <string>
#include <vector>

namespace sinew {
namespace {

const std::string kDataDir = SINEW_TEST_DATA_DIR;

TEST(Base64Test, MatchesRfc4648Vectors) {
  const std::pair<std::string, std::string> cases[] = {
      {"", ""}, {"f", "Zg=="}, {"fo", "Zm8="}, {"foo", "Zm9v"}, {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, coded] : cases) {
    EXPECT_EQ(io::EncodeBase64(reinterpret_cast<const uint8_t*>(plain.data()), plain.size()),
              coded);
    auto back = io::DecodeBase64(coded);
    ASSERT_TRUE(back);
    EXPECT_EQ(std::string(back->begin(), back->end()), plain);
  }
  EXPECT_FALSE(io::DecodeBase64("Zm9v!"));
  EXPECT_FALSE(io::DecodeBase64("Zm9"));
  // Two padded blocks back to back (VTK's separate header and data encodings).
  auto joined = io::DecodeBase64("Zg==Zm8=");
  ASSERT_TRUE(joined);
  EXPECT_EQ(std::string(joined->begin(), joined->end()), "ffo");
}

TEST(VtpTest, ReadsRealOpenSimMesh) {
  // r_patella.vtp: 72 points, 80 polygons that fan into 140 triangles (counted with a Python
  // script).
  const std::string file = kDataDir + "/opensim-org/opensim-models/Geometry/r_patella.vtp";
  io::TriangleMesh mesh = io::ReadVtp(file);
  EXPECT_EQ(mesh.positions.size(), 72u);
  EXPECT_EQ(mesh.triangles.size(), 140u);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const io::Vec3f& n : mesh.normals) EXPECT_NEAR(n.norm(), 1.0f, 1e-5f);
  // A patella is a few centimetres across: the file is in metres.
  io::Vec3f lo = mesh.positions[0], hi = mesh.positions[0];
  for (const io::Vec3f& p : mesh.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  EXPECT_GT((hi - lo).maxCoeff(), 0.02f);
  EXPECT_LT((hi - lo).maxCoeff(), 0.08f);
}

// A unit square made of one quad polygon and one 4-vertex strip, with normals.
const float kPoints[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const float kNormals[] = {0, 0, 2, 0, 0, 1, 0, 0, 1, 0, 0, 1};  // first one unnormalized
const int32_t kPolyConn[] = {0, 1, 2, 3};
const int32_t kPolyOffsets[] = {4};
const int64_t kStripConn[] = {0, 1, 3, 2};
const int64_t kStripOffsets[] = {4};

struct Variant {
  bool zlib = false;
  bool header64 = false;
  bool big_endian = false;
  size_t block_size = 1 << 15;
};

std::vector<uint8_t> Bytes(const void* data, size_t size, int word, bool big_endian) {
  std::vector<uint8_t> out(static_cast<const uint8_t*>(data),
                           static_cast<const uint8_t*>(data) + size);
  if (big_endian) {
    for (size_t i = 0; i < size; i += word) std::reverse(out.begin() + i, out.begin() + i + word);
  }
  return out;
}

void AppendHeader(std::vector<uint8_t>& out, uint64_t value, const Variant& v) {
  const int n = v.header64 ? 8 : 4;
  for (int i = 0; i < n; ++i) {
    const int shift = v.big_endian ? 8 * (n - 1 - i) : 8 * i;
    out.push_back(static_cast<uint8_t>(value >> shift));
  }
}

// Encodes an array the way VTK does: header and data as two separate base64 blocks.
std::string EncodeArray(const std::vector<uint8_t>& data, const Variant& v) {
  std::vector<uint8_t> header, body;
  if (!v.zlib) {
    AppendHeader(header, data.size(), v);
    body = data;
  } else {
    const size_t n_blocks = (data.size() + v.block_size - 1) / v.block_size;
    std::vector<uint64_t> sizes;
    for (size_t b = 0; b < n_blocks; ++b) {
      const size_t len = std::min(v.block_size, data.size() - b * v.block_size);
      uLongf bound = compressBound(len);
      std::vector<uint8_t> block(bound);
      EXPECT_EQ(compress(block.data(), &bound, data.data() + b * v.block_size, len), Z_OK);
      body.insert(body.end(), block.begin(), block.begin() + bound);
      sizes.push_back(bound);
    }
    AppendHeader(header, n_blocks, v);
    AppendHeader(header, v.block_size, v);
    AppendHeader(header, data.size() - (n_blocks - 1) * v.block_size, v);
    for (uint64_t s : sizes) AppendHeader(header, s, v);
  }
  return io::EncodeBase64(header.data(), header.size()) +
         io::EncodeBase64(body.data(), body.size());
}

std::string MakeVtp(const Variant& v) {
  auto array = [&](const char* name, const char* type, int comps, const void* data, size_t size,
                   int word) {
    return std::string("<DataArray type=\"") + type + "\" Name=\"" + name +
           "\" NumberOfComponents=\"" + std::to_string(comps) + "\" format=\"binary\">\n" +
           EncodeArray(Bytes(data, size, word, v.big_endian), v) + "\n</DataArray>\n";
  };
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\"";
  xml += v.big_endian ? " byte_order=\"BigEndian\"" : " byte_order=\"LittleEndian\"";
  if (v.header64) xml += " header_type=\"UInt64\"";
  if (v.zlib) xml += " compressor=\"vtkZLibDataCompressor\"";
  xml += ">\n<PolyData>\n<Piece NumberOfPoints=\"4\" NumberOfPolys=\"1\" NumberOfStrips=\"1\">\n";
  xml += "<PointData Normals=\"N\">" + array("N", "Float32", 3, kNormals, sizeof kNormals, 4) +
         "</PointData>\n";
  xml += "<Points>" + array("Points", "Float32", 3, kPoints, sizeof kPoints, 4) + "</Points>\n";
  xml += "<Polys>" + array("connectivity", "Int32", 1, kPolyConn, sizeof kPolyConn, 4) +
         array("offsets", "Int32", 1, kPolyOffsets, sizeof kPolyOffsets, 4) + "</Polys>\n";
  xml += "<Strips>" + array("connectivity", "Int64", 1, kStripConn, sizeof kStripConn, 8) +
         array("offsets", "Int64", 1, kStripOffsets, sizeof kStripOffsets, 8) + "</Strips>\n";
  xml += "</Piece>\n</PolyData>\n</VTKFile>\n";
  return xml;
}

void ExpectUnitSquare(const io::TriangleMesh& mesh) {
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.positions[2], io::Vec3f(1, 1, 0));
  // Quad fan (0,1,2),(0,2,3); strip (0,1,3),(3,1,2) with alternating winding fixed.
  const std::vector<std::array<uint32_t, 3>> expected = {
      {0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {3, 1, 2}};
  EXPECT_EQ(mesh.triangles, expected);
  for (const auto& t : mesh.triangles) {
    const io::Vec3f n = (mesh.positions[t[1]] - mesh.positions[t[0]])
                            .cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
    EXPECT_GT(n.z(), 0) << "every triangle faces +z";
  }
  ASSERT_EQ(mesh.normals.size(), 4u);
  EXPECT_TRUE(mesh.normals[0].isApprox(io::Vec3f(0, 0, 1)));
}

TEST(VtpTest, ReadsEveryBinaryVariantAlike) {
  for (bool zlib : {false, true}) {
    for (bool header64 : {false, true}) {
      for (bool big_endian : {false, true}) {
        Variant v{zlib, header64, big_endian};
        SCOPED_TRACE(MakeVtp(v));
        ExpectUnitSquare(io::ParseVtp(MakeVtp(v), "square.vtp"));
      }
    }
  }
  // Several zlib blocks, the last one shorter.
  ExpectUnitSquare(io::ParseVtp(MakeVtp({true, false, false, 20}), "square.vtp"));
}

TEST(VtpTest, AsciiWithoutNormalsGetsComputedNormals) {
  const std::string xml = R"(<VTKFile type="PolyData"><PolyData>
<Piece NumberOfPoints="3" NumberOfPolys="1"><Points>
<DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0</DataArray>
</Points><Polys>
<DataArray type="Int32" Name="connectivity" format="ascii">0 1 2</DataArray>
<DataArray type="Int32" Name="offsets" format="ascii">3</DataArray>
</Polys></Piece></PolyData></VTKFile>)";
  io::TriangleMesh mesh = io::ParseVtp(xml, "tri.vtp");
  ASSERT_EQ(mesh.triangles.size(), 1u);
  ASSERT_EQ(mesh.normals.size(), 3u);
  EXPECT_TRUE(mesh.normals[1].isApprox(io::Vec3f(0, 0, 1)));
}

// Parses `xml` and returns the error message (empty when none was thrown).
std::string ErrorOf(const std::string& xml) {
  try {
    io::ParseVtp(xml, "bad.vtp");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(VtpTest, BadInputGivesErrorsWithFileAndLine) {
  const std::string head =
      "<VTKFile type=\"PolyData\">\n<PolyData>\n<Piece NumberOfPoints=\"3\" "
      "NumberOfPolys=\"1\">\n<Points>\n";
  const std::string points =
      "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 "
      "0</DataArray>\n";
  const std::string tail = "</Points>\n</Piece></PolyData></VTKFile>";
  auto polys = [](const std::string& conn) {
    return "</Points><Polys>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">" +
           conn + "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" " +
           "format=\"ascii\">3</DataArray></Polys>\n</Piece></PolyData></VTKFile>";
  };
  EXPECT_NE(ErrorOf(head + tail).find("bad.vtp:3:"), std::string::npos) << ErrorOf(head + tail);
  EXPECT_NE(ErrorOf(head + points + polys("0 1 7")).find("refers to point 7"), std::string::npos);
  EXPECT_NE(ErrorOf(head + points + polys("0 1")).find("offsets"), std::string::npos);
  EXPECT_NE(ErrorOf("<VTKFile type=\"UnstructuredGrid\"/>").find("not PolyData"),
            std::string::npos);
  const std::string bad_base64 =
      "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">@@@@</DataArray>\n";
  EXPECT_NE(ErrorOf(head + bad_base64 + tail).find("bad.vtp:5:"), std::string::npos);
  // A compressed block that is not zlib data.
  Variant v{true};
  std::vector<uint8_t> header;
  AppendHeader(header, 1, v);
  AppendHeader(header, 36, v);
  AppendHeader(header, 36, v);
  AppendHeader(header, 4, v);
  header.insert(header.end(), {1, 2, 3, 4});
  const std::string corrupt = "<VTKFile type=\"PolyData\" compressor=\"vtkZLibDataCompressor\">" +
                              head.substr(head.find('\n')) +
                              "<DataArray type=\"Float32\" NumberOfComponents=\"3\" "
                              "format=\"binary\">" +
                              io::EncodeBase64(header.data(), header.size()) + "</DataArray>\n" +
                              tail;
  EXPECT_NE(ErrorOf(corrupt).find("does not inflate"), std::string::npos) << ErrorOf(corrupt);
  // A header that claims a block far larger than zlib can expand its bytes to.
  std::vector<uint8_t> huge;
  AppendHeader(huge, 1, v);
  AppendHeader(huge, 0xFFFFFFF0u, v);
  AppendHeader(huge, 0xFFFFFFF0u, v);
  AppendHeader(huge, 4, v);
  huge.insert(huge.end(), {1, 2, 3, 4});
  const std::string claim = corrupt.substr(0, corrupt.find("format=\"binary\">") + 16) +
                            io::EncodeBase64(huge.data(), huge.size()) + "</DataArray>\n" + tail;
  EXPECT_NE(ErrorOf(claim).find("impossible block size"), std::string::npos) << ErrorOf(claim);
  // NaN is not a cell offset.
  const std::string nan_offsets =
      head + points +
      "</Points><Polys>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 "
      "2</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">nan"
      "</DataArray></Polys>\n</Piece></PolyData></VTKFile>";
  EXPECT_NE(ErrorOf(nan_offsets).find("offsets"), std::string::npos) << ErrorOf(nan_offsets);
  EXPECT_THROW(io::ReadVtp(kDataDir + "/no_such_mesh.vtp"), Error);
}

}  // namespace
}  // namespace sinew
