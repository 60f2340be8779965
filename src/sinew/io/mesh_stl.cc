#include <sinew/common/error.h>
#include <sinew/io/mesh_stl.h>

#include <charconv>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace sinew::io {
namespace {

// Merges corners with identical coordinates into one vertex. A NaN corner would compare equal
// to any other (and break the map's ordering), so non-finite corners are refused here, before
// ValidateMesh could see them; `line` (0 for binary files) says where.
class VertexWelder {
 public:
  VertexWelder(TriangleMesh& mesh, const std::string& file) : mesh_(mesh), file_(file) {}
  uint32_t Add(const Vec3f& p, int line = 0) {
    if (!p.allFinite()) {
      throw Error(SourceLocation{file_, line}, "",
                  "vertex " + std::to_string(mesh_.positions.size()) +
                      " has a coordinate that is not a finite number");
    }
    auto [it, inserted] =
        index_.try_emplace({p.x(), p.y(), p.z()}, static_cast<uint32_t>(mesh_.positions.size()));
    if (inserted) mesh_.positions.push_back(p);
    return it->second;
  }

 private:
  TriangleMesh& mesh_;
  const std::string& file_;
  std::map<std::array<float, 3>, uint32_t> index_;
};

bool LooksBinary(std::string_view bytes) {
  if (bytes.size() < 84) return false;
  uint32_t n;
  std::memcpy(&n, bytes.data() + 80, 4);
  // A binary file's size is fixed by its count; ASCII files often start with "solid" too.
  return bytes.size() == 84 + 50 * static_cast<uint64_t>(n) || bytes.substr(0, 5) != "solid";
}

TriangleMesh ParseBinary(std::string_view bytes, const std::string& file) {
  uint32_t n;
  std::memcpy(&n, bytes.data() + 80, 4);
  if (bytes.size() < 84 + 50 * static_cast<uint64_t>(n)) {
    throw Error(SourceLocation{file, 0}, "",
                "binary STL announces " + std::to_string(n) + " triangles but has only " +
                    std::to_string(bytes.size()) + " bytes");
  }
  TriangleMesh mesh;
  VertexWelder welder(mesh, file);
  for (uint32_t t = 0; t < n; ++t) {
    const char* rec = bytes.data() + 84 + 50 * static_cast<size_t>(t);
    std::array<uint32_t, 3> tri;
    for (int k = 0; k < 3; ++k) {
      float xyz[3];
      std::memcpy(xyz, rec + 12 + 12 * k, 12);  // after the facet normal
      tri[k] = welder.Add(Vec3f(xyz[0], xyz[1], xyz[2]));
    }
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

TriangleMesh ParseAscii(std::string_view text, const std::string& file) {
  TriangleMesh mesh;
  VertexWelder welder(mesh, file);
  std::array<uint32_t, 3> tri{};
  int corner = 0;
  int line_number = 1;
  size_t i = 0;
  auto next_token = [&]() -> std::string_view {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) {
      if (text[i] == '\n') ++line_number;
      ++i;
    }
    const size_t start = i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    return text.substr(start, i - start);
  };
  auto fail = [&](const std::string& message) {
    throw Error(SourceLocation{file, line_number}, "", message);
  };
  for (std::string_view tok = next_token(); !tok.empty(); tok = next_token()) {
    if (tok == "vertex") {
      Vec3f p;
      for (int k = 0; k < 3; ++k) {
        std::string_view num = next_token();
        if (!num.empty() && num.front() == '+') num.remove_prefix(1);
        auto [ptr, ec] = std::from_chars(num.data(), num.data() + num.size(), p[k]);
        if (ec != std::errc() || ptr != num.data() + num.size()) {
          fail("bad vertex coordinate '" + std::string(num) + "'");
        }
      }
      if (corner == 3) fail("a facet has more than three vertices");
      tri[corner++] = welder.Add(p, line_number);
    } else if (tok == "endloop") {
      if (corner != 3) fail("a facet needs three vertices");
      mesh.triangles.push_back(tri);
      corner = 0;
    }
  }
  if (corner != 0) fail("the file ends inside a facet");
  return mesh;
}

}  // namespace

TriangleMesh ParseStl(std::string_view bytes, const std::string& file) {
  TriangleMesh mesh = LooksBinary(bytes) ? ParseBinary(bytes, file) : ParseAscii(bytes, file);
  ComputeVertexNormals(mesh);
  ValidateMesh(mesh, file);
  return mesh;
}

TriangleMesh ReadStl(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(SourceLocation{file, 0}, "", "cannot open file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return ParseStl(buffer.str(), file);
}

}  // namespace sinew::io
