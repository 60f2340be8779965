#include <sinew/common/error.h>
#include <sinew/io/mesh_obj.h>

#include <charconv>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

namespace sinew::io {
namespace {

std::vector<std::string_view> SplitWhitespace(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

bool ParseFloat(std::string_view token, float* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return ec == std::errc() && ptr == token.data() + token.size();
}

bool ParseInt(std::string_view token, long* value) {
  auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return ec == std::errc() && ptr == token.data() + token.size() && !token.empty();
}

}  // namespace

TriangleMesh ParseObj(std::string_view text, const std::string& file) {
  std::vector<Vec3f> v, vn;
  TriangleMesh mesh;
  // One output vertex per distinct (position, normal) pair used by the faces.
  std::map<std::pair<long, long>, uint32_t> corners;
  bool all_normals = true;
  int line_number = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (const size_t hash = line.find('#'); hash != std::string_view::npos) {
      line = line.substr(0, hash);
    }
    std::vector<std::string_view> tok = SplitWhitespace(line);
    if (tok.empty()) continue;
    auto fail = [&](const std::string& message) {
      throw Error(SourceLocation{file, line_number}, "", message);
    };
    if (tok[0] == "v" || tok[0] == "vn") {
      if (tok.size() < 4) fail("'" + std::string(tok[0]) + "' needs three numbers");
      Vec3f p;
      for (int k = 0; k < 3; ++k) {
        if (!ParseFloat(tok[k + 1], &p[k])) fail("bad number '" + std::string(tok[k + 1]) + "'");
      }
      (tok[0] == "v" ? v : vn).push_back(p);
    } else if (tok[0] == "f") {
      if (tok.size() < 4) fail("a face needs at least three vertices");
      std::vector<uint32_t> face;
      for (size_t k = 1; k < tok.size(); ++k) {
        // v, v/vt, v//vn or v/vt/vn; indices are 1-based, negative ones count from the end.
        std::string_view corner = tok[k];
        const size_t s1 = corner.find('/');
        long iv = 0, in = 0;
        if (!ParseInt(corner.substr(0, s1), &iv))
          fail("bad face vertex '" + std::string(corner) + "'");
        if (s1 != std::string_view::npos) {
          const size_t s2 = corner.find('/', s1 + 1);
          if (s2 != std::string_view::npos && s2 + 1 < corner.size() &&
              !ParseInt(corner.substr(s2 + 1), &in)) {
            fail("bad face normal index in '" + std::string(corner) + "'");
          }
        }
        if (iv < 0) iv += static_cast<long>(v.size()) + 1;
        if (in < 0) in += static_cast<long>(vn.size()) + 1;
        if (iv < 1 || iv > static_cast<long>(v.size())) {
          fail("face refers to vertex " + std::string(corner) + " but only " +
               std::to_string(v.size()) + " are defined");
        }
        if (in > static_cast<long>(vn.size())) fail("face refers to an undefined normal");
        if (in == 0) all_normals = false;
        auto [it, inserted] =
            corners.try_emplace({iv, in}, static_cast<uint32_t>(mesh.positions.size()));
        if (inserted) {
          mesh.positions.push_back(v[iv - 1]);
          mesh.normals.push_back(in > 0 ? Vec3f(vn[in - 1].normalized()) : Vec3f::Zero());
        }
        face.push_back(it->second);
      }
      for (size_t k = 2; k < face.size(); ++k)
        mesh.triangles.push_back({face[0], face[k - 1], face[k]});
    }
    // Everything else (vt, o, g, s, usemtl, mtllib, l, p) carries no geometry we draw.
  }
  if (!all_normals) ComputeVertexNormals(mesh);
  ValidateMesh(mesh, file);
  return mesh;
}

TriangleMesh ReadObj(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(SourceLocation{file, 0}, "", "cannot open file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return ParseObj(buffer.str(), file);
}

}  // namespace sinew::io
