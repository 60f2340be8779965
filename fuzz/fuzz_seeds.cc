// Writes the generated seeds of the fuzz corpora, for formats and encodings tests/data has no
// file in: .vtp with inline binary arrays (raw, zlib in one or several blocks, UInt64 headers,
// big-endian), .obj, ASCII and binary .stl. Usage: fuzz_seeds MESH_CORPUS_DIR. Each file starts
// with the format byte fuzz_mesh_reader dispatches on ('0' .vtp, '1' .obj, '2' .stl).
#include <sinew/io/mesh_base64.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

struct Encoding {
  bool zlib = false;
  bool header64 = false;
  bool big_endian = false;
  size_t block_size = 1 << 15;
};

void AppendWord(std::vector<uint8_t>& out, uint64_t value, int bytes, bool big_endian) {
  for (int i = 0; i < bytes; ++i) {
    out.push_back(static_cast<uint8_t>(value >> (big_endian ? 8 * (bytes - 1 - i) : 8 * i)));
  }
}

// `count` scalars of `word` bytes each, from `data` (host little-endian), as VTK writes a binary
// DataArray: base64 of the size header, then base64 of the (possibly compressed) bytes.
std::string EncodeArray(const void* data, size_t count, int word, const Encoding& e) {
  std::vector<uint8_t> bytes(static_cast<const uint8_t*>(data),
                             static_cast<const uint8_t*>(data) + count * word);
  if (e.big_endian) {
    for (size_t i = 0; i < bytes.size(); i += word) {
      std::reverse(bytes.begin() + i, bytes.begin() + i + word);
    }
  }
  const int hb = e.header64 ? 8 : 4;
  std::vector<uint8_t> header, body;
  if (!e.zlib) {
    AppendWord(header, bytes.size(), hb, e.big_endian);
    body = bytes;
  } else {
    const size_t n_blocks = (bytes.size() + e.block_size - 1) / e.block_size;
    std::vector<uint64_t> sizes;
    for (size_t b = 0; b < n_blocks; ++b) {
      const size_t len = std::min(e.block_size, bytes.size() - b * e.block_size);
      uLongf bound = compressBound(len);
      std::vector<uint8_t> block(bound);
      compress(block.data(), &bound, bytes.data() + b * e.block_size, len);
      body.insert(body.end(), block.begin(), block.begin() + bound);
      sizes.push_back(bound);
    }
    AppendWord(header, n_blocks, hb, e.big_endian);
    AppendWord(header, e.block_size, hb, e.big_endian);
    AppendWord(header, bytes.size() - (n_blocks - 1) * e.block_size, hb, e.big_endian);
    for (uint64_t s : sizes) AppendWord(header, s, hb, e.big_endian);
  }
  return sinew::io::EncodeBase64(header.data(), header.size()) +
         sinew::io::EncodeBase64(body.data(), body.size());
}

// A unit square: one quad polygon and one 4-vertex strip, with point normals.
std::string SquareVtp(const Encoding& e) {
  const float points[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const float normals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  const int32_t poly_conn[] = {0, 1, 2, 3}, poly_offsets[] = {4};
  const int64_t strip_conn[] = {0, 1, 3, 2}, strip_offsets[] = {4};
  auto array = [&](const char* name, const char* type, int comps, const void* data, size_t count,
                   int word) {
    return std::string("<DataArray type=\"") + type + "\" Name=\"" + name +
           "\" NumberOfComponents=\"" + std::to_string(comps) + "\" format=\"binary\">" +
           EncodeArray(data, count, word, e) + "</DataArray>\n";
  };
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\"";
  xml += e.big_endian ? " byte_order=\"BigEndian\"" : " byte_order=\"LittleEndian\"";
  if (e.header64) xml += " header_type=\"UInt64\"";
  if (e.zlib) xml += " compressor=\"vtkZLibDataCompressor\"";
  xml += ">\n<PolyData>\n<Piece NumberOfPoints=\"4\" NumberOfPolys=\"1\" NumberOfStrips=\"1\">\n";
  xml += "<PointData Normals=\"N\">" + array("N", "Float32", 3, normals, 12, 4) + "</PointData>\n";
  xml += "<Points>" + array("Points", "Float32", 3, points, 12, 4) + "</Points>\n";
  xml += "<Polys>" + array("connectivity", "Int32", 1, poly_conn, 4, 4) +
         array("offsets", "Int32", 1, poly_offsets, 1, 4) + "</Polys>\n";
  xml += "<Strips>" + array("connectivity", "Int64", 1, strip_conn, 4, 8) +
         array("offsets", "Int64", 1, strip_offsets, 1, 8) + "</Strips>\n";
  xml += "</Piece>\n</PolyData>\n</VTKFile>\n";
  return xml;
}

// A binary STL of two triangles (80-byte header, count, 50 bytes per facet).
std::string BinaryStl() {
  std::string out(80, ' ');
  out.replace(0, 11, "fuzz seed 2");
  const uint32_t count = 2;
  out.append(reinterpret_cast<const char*>(&count), 4);
  const float facets[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0},
                               {0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0}};
  for (const auto& f : facets) {
    out.append(reinterpret_cast<const char*>(f), sizeof f);
    out.append(2, '\0');  // attribute byte count
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: fuzz_seeds MESH_CORPUS_DIR\n";
    return 2;
  }
  const std::string dir = argv[1];
  auto write = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(dir + "/" + name, std::ios::binary) << bytes;
  };
  // A minimal ascii triangle: small inputs let mutations reach the counts and arrays quickly.
  write("vtp_ascii_triangle",
        "0<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\">"
        "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 "
        "0 1 0</DataArray></Points><Polys><DataArray type=\"Int32\" Name=\"connectivity\" "
        "format=\"ascii\">0 1 2</DataArray><DataArray type=\"Int32\" Name=\"offsets\" "
        "format=\"ascii\">3</DataArray></Polys></Piece></PolyData></VTKFile>");
  write("vtp_binary", "0" + SquareVtp({}));
  write("vtp_zlib", "0" + SquareVtp({true}));
  write("vtp_zlib_blocks", "0" + SquareVtp({true, false, false, 20}));
  write("vtp_uint64_big_endian", "0" + SquareVtp({false, true, true}));
  write("vtp_zlib_uint64_big_endian", "0" + SquareVtp({true, true, true}));
  write("obj_square",
        "1# square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
        "f 1//1 2//1 3//1 4//1\nf -4 -3 -2\ng group\nusemtl m\n");
  write("stl_ascii",
        "2solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
        "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\n"
        "vertex 0 1 0\nendloop\nendfacet\nendsolid s\n");
  write("stl_binary", "2" + BinaryStl());
  return 0;
}
