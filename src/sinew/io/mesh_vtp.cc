#include <sinew/io/internal/xml_document.h>
#include <sinew/io/mesh_base64.h>
#include <sinew/io/mesh_vtp.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

namespace sinew::io {
namespace {

// How the document stores binary data (attributes of <VTKFile>).
struct Encoding {
  bool big_endian = false;
  int header_bytes = 4;  // header_type UInt32 or UInt64
  bool zlib = false;     // compressor="vtkZLibDataCompressor"
};

// Size in bytes and kind of a VTK scalar type name.
struct ScalarType {
  int bytes = 0;
  char kind = 0;  // 'f' float, 'i' signed, 'u' unsigned
};

ScalarType ParseScalarType(std::string_view name) {
  static constexpr struct {
    const char* name;
    ScalarType type;
  } kTypes[] = {{"Float32", {4, 'f'}}, {"Float64", {8, 'f'}}, {"Int8", {1, 'i'}},
                {"Int16", {2, 'i'}},   {"Int32", {4, 'i'}},   {"Int64", {8, 'i'}},
                {"UInt8", {1, 'u'}},   {"UInt16", {2, 'u'}},  {"UInt32", {4, 'u'}},
                {"UInt64", {8, 'u'}},  {"Float", {4, 'f'}},   {"Double", {8, 'f'}}};
  for (const auto& t : kTypes) {
    if (name == t.name) return t.type;
  }
  return {};
}

// Reads an unsigned little/big-endian integer of `bytes` bytes.
uint64_t ReadUnsigned(const uint8_t* p, int bytes, bool big_endian) {
  uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) {
    const int shift = big_endian ? 8 * (bytes - 1 - i) : 8 * i;
    v |= uint64_t{p[i]} << shift;
  }
  return v;
}

// Converts one binary scalar to double.
double ReadScalar(const uint8_t* p, ScalarType type, bool big_endian) {
  uint8_t buf[8];
  for (int i = 0; i < type.bytes; ++i) buf[i] = big_endian ? p[type.bytes - 1 - i] : p[i];
  // buf now holds the value little-endian; memcpy into float/double assumes a little-endian
  // host (every platform Sinew builds on).
  switch (type.kind) {
    case 'f':
      if (type.bytes == 4) {
        float f;
        std::memcpy(&f, buf, 4);
        return f;
      } else {
        double d;
        std::memcpy(&d, buf, 8);
        return d;
      }
    case 'i': {
      uint64_t u = ReadUnsigned(buf, type.bytes, false);
      if (type.bytes < 8 && (u >> (8 * type.bytes - 1)) & 1) u |= ~uint64_t{0} << (8 * type.bytes);
      return static_cast<double>(static_cast<int64_t>(u));
    }
    default:
      return static_cast<double>(ReadUnsigned(buf, type.bytes, false));
  }
}

class VtpReader {
 public:
  explicit VtpReader(const internal::XmlDocument& doc) : doc_(doc) {}

  TriangleMesh Read() {
    pugi::xml_node root = doc_.root();
    if (std::string_view(root.name()) != "VTKFile") {
      doc_.Fail(root, "",
                "expected a <VTKFile> root element, found <" + std::string(root.name()) + ">");
    }
    if (std::string_view type = root.attribute("type").value(); type != "PolyData") {
      doc_.Fail(root, "", "VTK file type '" + std::string(type) + "' is not PolyData");
    }
    encoding_.big_endian = std::string_view(root.attribute("byte_order").value()) == "BigEndian";
    if (std::string_view h = root.attribute("header_type").value(); h == "UInt64") {
      encoding_.header_bytes = 8;
    } else if (!h.empty() && h != "UInt32") {
      doc_.Fail(root, "", "unsupported header_type '" + std::string(h) + "'");
    }
    if (std::string_view c = root.attribute("compressor").value(); c == "vtkZLibDataCompressor") {
      encoding_.zlib = true;
    } else if (!c.empty()) {
      doc_.Fail(root, "", "unsupported compressor '" + std::string(c) + "'");
    }
    pugi::xml_node poly = root.child("PolyData");
    if (!poly) doc_.Fail(root, "", "missing <PolyData>");
    TriangleMesh mesh;
    bool all_normals = true;
    for (pugi::xml_node piece : poly.children("Piece")) ReadPiece(piece, mesh, all_normals);
    if (!all_normals) mesh.normals.clear();
    if (mesh.normals.empty()) ComputeVertexNormals(mesh);
    ValidateMesh(mesh, doc_.file());
    return mesh;
  }

 private:
  void ReadPiece(pugi::xml_node piece, TriangleMesh& mesh, bool& all_normals) {
    const size_t base = mesh.positions.size();
    // The declared count is only trusted once an array holding that many points was read.
    const uint64_t n_points = piece.attribute("NumberOfPoints").as_ullong();
    pugi::xml_node points = piece.child("Points").child("DataArray");
    if (n_points > 0 && !points) doc_.Fail(piece, "", "missing <Points><DataArray>");
    if (n_points > 0) {
      std::vector<double> xyz = ReadArray(points, n_points, 3);
      // Triangles index vertices with 32 bits.
      if (n_points > std::numeric_limits<uint32_t>::max() - base) {
        doc_.Fail(piece, "", "the mesh has more than 2^32 points");
      }
      for (size_t i = 0; i < n_points; ++i) {
        mesh.positions.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
      }
    }
    // Point normals: the array the PointData names as Normals, else one called "Normals".
    pugi::xml_node point_data = piece.child("PointData");
    std::string normals_name = point_data.attribute("Normals").value();
    if (normals_name.empty()) normals_name = "Normals";
    pugi::xml_node normals_array =
        point_data.find_child_by_attribute("DataArray", "Name", normals_name.c_str());
    if (normals_array && n_points > 0) {
      std::vector<double> n = ReadArray(normals_array, n_points, 3);
      for (size_t i = 0; i < n_points; ++i) {
        Vec3f v(n[3 * i], n[3 * i + 1], n[3 * i + 2]);
        const float length = v.norm();
        mesh.normals.push_back(length > 0 ? Vec3f(v / length) : Vec3f(0, 0, 1));
      }
    } else {
      all_normals = false;
    }
    ReadCells(piece, "Polys", "NumberOfPolys", base, n_points, mesh, false);
    ReadCells(piece, "Strips", "NumberOfStrips", base, n_points, mesh, true);
  }

  void ReadCells(pugi::xml_node piece, const char* tag, const char* count_attr, size_t base,
                 size_t n_points, TriangleMesh& mesh, bool strips) {
    const uint64_t n_cells = piece.attribute(count_attr).as_ullong();
    if (n_cells == 0) return;
    pugi::xml_node cells = piece.child(tag);
    if (!cells) doc_.Fail(piece, "", std::string("missing <") + tag + ">");
    pugi::xml_node offsets_node = cells.find_child_by_attribute("DataArray", "Name", "offsets");
    pugi::xml_node conn_node = cells.find_child_by_attribute("DataArray", "Name", "connectivity");
    if (!offsets_node || !conn_node) {
      doc_.Fail(cells, "", std::string("<") + tag + "> needs 'connectivity' and 'offsets' arrays");
    }
    std::vector<double> offsets = ReadArray(offsets_node, n_cells, 1);
    std::vector<double> conn = ReadArray(conn_node, std::nullopt, 1);
    size_t start = 0;
    for (size_t c = 0; c < n_cells; ++c) {
      const double end_d = offsets[c];
      // Written as a negation so that NaN fails too.
      if (!(end_d >= static_cast<double>(start) && end_d <= static_cast<double>(conn.size()))) {
        doc_.Fail(offsets_node, "", "cell offsets are not increasing within the connectivity");
      }
      const size_t end = static_cast<size_t>(end_d);
      auto vertex = [&](size_t k) {
        const double v = conn[start + k];
        if (!(v >= 0 && v < static_cast<double>(n_points))) {
          doc_.Fail(conn_node, "",
                    "connectivity refers to point " + std::to_string(v) + " of " +
                        std::to_string(n_points));
        }
        return static_cast<uint32_t>(base + static_cast<size_t>(v));
      };
      const size_t n = end - start;
      for (size_t k = 2; k < n; ++k) {
        if (!strips) {
          mesh.triangles.push_back({vertex(0), vertex(k - 1), vertex(k)});  // fan
        } else if (k % 2 == 0) {
          mesh.triangles.push_back({vertex(k - 2), vertex(k - 1), vertex(k)});
        } else {
          mesh.triangles.push_back({vertex(k - 1), vertex(k - 2), vertex(k)});  // keep winding
        }
      }
      start = end;
    }
  }

  // The values of a <DataArray>. With `tuples` set, the array must hold exactly that many
  // tuples of `components` values. The check divides the values present instead of multiplying
  // the declared count, so no count in the file can overflow it.
  std::vector<double> ReadArray(pugi::xml_node array, std::optional<uint64_t> tuples,
                                int components) {
    const std::string_view format = array.attribute("format").value();
    std::vector<double> values;
    if (format == "ascii") {
      values = doc_.ReadNumbers(array, array.attribute("Name").value());
    } else if (format == "binary") {
      const ScalarType type = ParseScalarType(array.attribute("type").value());
      if (type.bytes == 0) {
        doc_.Fail(
            array, "",
            "unsupported DataArray type '" + std::string(array.attribute("type").value()) + "'");
      }
      // The bytes the piece's counts call for, when known and representable (a count beyond
      // that cannot match the data present and fails below).
      std::optional<uint64_t> expected_bytes;
      const uint64_t tuple_bytes = static_cast<uint64_t>(components) * type.bytes;
      if (tuples && *tuples <= std::numeric_limits<uint64_t>::max() / tuple_bytes) {
        expected_bytes = *tuples * tuple_bytes;
      }
      std::vector<uint8_t> bytes = DecodeBinary(array, expected_bytes);
      const size_t n = bytes.size() / type.bytes;
      values.resize(n);
      for (size_t i = 0; i < n; ++i) {
        values[i] = ReadScalar(bytes.data() + i * type.bytes, type, encoding_.big_endian);
      }
    } else {
      doc_.Fail(array, "",
                "DataArray format '" + std::string(format) +
                    "' is not supported (ascii or inline binary only)");
    }
    if (tuples && (values.size() % components != 0 || values.size() / components != *tuples)) {
      doc_.Fail(array, "",
                "DataArray '" + std::string(array.attribute("Name").value()) + "' has " +
                    std::to_string(values.size()) + " values, expected " + std::to_string(*tuples) +
                    " tuples of " + std::to_string(components));
    }
    return values;
  }

  // The payload bytes of an inline binary array: base64 of a size header then the data,
  // the data made of zlib blocks when the file is compressed. `expected_bytes`, when known, is
  // the size the piece's counts call for; a header promising another size fails before any
  // allocation.
  //
  // Decompression cap: nothing is inflated beyond the total the header promises,
  // (n_blocks - 1) * block_size + last_block_size, and each block inflates into a buffer of
  // exactly its promised size (zlib stops there). The promise itself is bounded by the data
  // present: a block's size may not exceed what deflate can expand its compressed bytes to
  // (1032:1, plus a small allowance for empty streams), and must equal `expected_bytes` when
  // that is known. So a file of B bytes inflates to at most ~1032 B bytes, and to exactly the
  // declared array size when the counts are known.
  std::vector<uint8_t> DecodeBinary(pugi::xml_node array, std::optional<uint64_t> expected_bytes) {
    // Header and data may be encoded as one base64 stream or as two padded ones; the
    // decoder continues across padding, so both give the same bytes.
    std::optional<std::vector<uint8_t>> decoded = DecodeBase64(internal::XmlDocument::Text(array));
    if (!decoded) doc_.Fail(array, "", "binary DataArray is not valid base64");
    const std::vector<uint8_t>& raw = *decoded;
    const size_t hb = static_cast<size_t>(encoding_.header_bytes);
    auto header = [&](uint64_t i) -> uint64_t {
      if (i >= raw.size() / hb) doc_.Fail(array, "", "binary DataArray header is truncated");
      return ReadUnsigned(raw.data() + i * hb, encoding_.header_bytes, encoding_.big_endian);
    };
    auto check_promise = [&](uint64_t promised) {
      if (expected_bytes && promised != *expected_bytes) {
        doc_.Fail(array, "",
                  "binary DataArray header promises " + std::to_string(promised) +
                      " bytes, the piece's counts call for " + std::to_string(*expected_bytes));
      }
    };
    if (!encoding_.zlib) {
      const uint64_t size = header(0);
      if (size > raw.size() - hb) doc_.Fail(array, "", "binary DataArray is truncated");
      check_promise(size);
      return {raw.begin() + hb, raw.begin() + hb + static_cast<ptrdiff_t>(size)};
    }
    // Compressed: [n_blocks, block_size, last_size, compressed_size[n_blocks]].
    const uint64_t n_blocks = header(0);
    const uint64_t block_size = header(1);
    const uint64_t last_size = header(2);
    if (n_blocks > raw.size() / hb) doc_.Fail(array, "", "binary DataArray header is truncated");
    // The uncompressed size of each block and their total, checked before inflating anything.
    constexpr uint64_t kMaxDeflateRatio = 1032;  // deflate's best case, zlib's technical report
    constexpr uint64_t kEmptyStreamAllowance = 64;
    std::vector<uint64_t> compressed(n_blocks), inflated(n_blocks);
    uint64_t offset = (3 + n_blocks) * hb, total = 0;
    for (uint64_t b = 0; b < n_blocks; ++b) {
      compressed[b] = header(3 + b);
      inflated[b] = (b + 1 == n_blocks && last_size != 0) ? last_size : block_size;
      if (offset > raw.size() || compressed[b] > raw.size() - offset) {
        doc_.Fail(array, "", "compressed DataArray is truncated");
      }
      offset += compressed[b];
      if (inflated[b] > kMaxDeflateRatio * compressed[b] + kEmptyStreamAllowance) {
        doc_.Fail(array, "", "compressed DataArray header claims an impossible block size");
      }
      total += inflated[b];  // cannot wrap: each term is below 1032 * raw.size() + 64
    }
    check_promise(total);
    std::vector<uint8_t> out(total);
    offset = (3 + n_blocks) * hb;
    uint64_t at = 0;
    for (uint64_t b = 0; b < n_blocks; ++b) {
      uLongf size = inflated[b];
      if (uncompress(out.data() + at, &size, raw.data() + offset, compressed[b]) != Z_OK ||
          size != inflated[b]) {
        doc_.Fail(array, "",
                  "compressed DataArray block " + std::to_string(b) + " does not inflate to the " +
                      std::to_string(inflated[b]) + " bytes its header promises (corrupt data)");
      }
      at += inflated[b];
      offset += compressed[b];
    }
    return out;
  }

  const internal::XmlDocument& doc_;
  Encoding encoding_;
};

}  // namespace

TriangleMesh ParseVtp(std::string text, const std::string& file) {
  internal::XmlDocument doc = internal::XmlDocument::Parse(std::move(text), file);
  return VtpReader(doc).Read();
}

TriangleMesh ReadVtp(const std::string& file) {
  internal::XmlDocument doc = internal::XmlDocument::Load(file);
  return VtpReader(doc).Read();
}

}  // namespace sinew::io
