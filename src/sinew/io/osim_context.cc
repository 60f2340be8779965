#include <sinew/io/internal/osim_context.h>

#include <iterator>

namespace sinew::io::internal {

void ReadContext::Warn(const pugi::xml_node& node, const std::string& component,
                       const std::string& message, const std::string& dedupe_key) {
  if (!dedupe_key.empty() && !warned_.insert(dedupe_key).second) return;
  spec_.warnings.push_back(Diagnostic{doc_->Where(node), component, message});
}

void ReadContext::AddBodyFrame(const std::string& path, int body, const pugi::xml_node& node) {
  FrameEntry entry;
  entry.node = node;
  entry.component = path;
  entry.body = body;
  entry.state = 2;
  frames_[path] = std::move(entry);
  frame_names_.emplace(path.substr(path.rfind('/') + 1), path);
}

bool ReadContext::AddOffsetFrame(const std::string& path, FrameEntry entry) {
  if (frames_.count(path) != 0) return false;
  frames_.emplace(path, std::move(entry));
  offset_order_.push_back(path);
  frame_names_.emplace(path.substr(path.rfind('/') + 1), path);
  return true;
}

std::string ReadContext::JoinPath(const std::string& owner_path, std::string_view path) {
  std::vector<std::string_view> parts;
  auto push_segments = [&parts](std::string_view s) {
    size_t i = 0;
    while (i <= s.size()) {
      size_t j = s.find('/', i);
      if (j == std::string_view::npos) j = s.size();
      std::string_view seg = s.substr(i, j - i);
      if (seg == "..") {
        if (parts.empty()) return false;
        parts.pop_back();
      } else if (!seg.empty() && seg != ".") {
        parts.push_back(seg);
      }
      i = j + 1;
    }
    return true;
  };
  if (path.empty() || path.front() != '/') {
    if (!push_segments(owner_path)) return "";
  }
  if (!push_segments(path)) return "";
  std::string result;
  for (std::string_view seg : parts) {
    result += '/';
    result += seg;
  }
  return result.empty() ? "/" : result;
}

std::string ReadContext::ResolveFrame(const std::string& owner_path, std::string_view path,
                                      const pugi::xml_node& socket, const std::string& component,
                                      const FrameEntry** entry) {
  const std::string tag = socket.name();
  if (path.empty()) doc_->Fail(socket, component, "<" + tag + "> is empty");
  std::string absolute = JoinPath(owner_path, path);
  auto it = frames_.find(absolute);
  if (it == frames_.end() && path.find('/') == std::string_view::npos) {
    // OpenSim 4.0 also connected a bare name to the one frame of that name anywhere in the model.
    auto match = frames_.end();
    const auto [first, last] = frame_names_.equal_range(std::string(path));
    const int count = static_cast<int>(std::distance(first, last));
    if (count == 1) match = frames_.find(first->second);
    if (count == 1) {
      Warn(socket, component,
           "<" + tag + "> '" + std::string(path) + "' found by name at '" + match->first + "'");
      it = match;
    } else if (count > 1) {
      doc_->Fail(socket, component,
                "<" + tag + "> '" + std::string(path) + "' is ambiguous: " + std::to_string(count) +
                    " frames have that name");
    }
  }
  if (it == frames_.end()) {
    doc_->Fail(socket, component,
              "<" + tag + "> '" + std::string(path) + "' does not exist" +
                  (absolute.empty() || absolute == path ? "" : " (looked for '" + absolute + "')"));
  }
  FrameEntry& resolved = Resolve(it->first, it->second);
  if (entry) *entry = &resolved;
  return it->first;
}

FrameEntry& ReadContext::Resolve(const std::string& path, FrameEntry& entry) {
  if (entry.state == 2) return entry;
  if (entry.state == 1) {
    doc_->Fail(entry.node, entry.component, "offset frames form a cycle through '" + path + "'");
  }
  entry.state = 1;
  // Each offset resolves its parent first: bound the chain so a hostile file cannot exhaust
  // the stack (real models chain two or three).
  constexpr int kMaxChain = 500;
  if (resolve_depth_ >= kMaxChain) {
    doc_->Fail(entry.node, entry.component,
              "offset frames chained deeper than " + std::to_string(kMaxChain) + " levels");
  }
  struct DepthGuard {
    int& depth;
    explicit DepthGuard(int& d) : depth(d) { ++depth; }
    ~DepthGuard() { --depth; }
  } guard(resolve_depth_);
  if (entry.station_frame) {
    ResolveStationDefined(path, entry);
    return entry;
  }
  const FrameEntry* parent = nullptr;
  const std::string parent_path =
      ResolveFrame(path, entry.parent_path, entry.parent_node, entry.component, &parent);
  entry.body = parent->body;
  entry.X_BF = parent->X_BF * entry.X_PF;
  entry.state = 2;
  model::FrameSpec frame;
  const size_t slash = path.rfind('/');
  frame.name = path.substr(slash + 1);
  frame.path = path;
  frame.parent = parent_path;
  frame.X_PF = entry.X_PF;
  frame.body = entry.body;
  frame.X_BF = entry.X_BF;
  frame.where = doc_->Where(entry.node);
  entry.spec_frame = static_cast<int>(spec_.frames.size());
  spec_.frames.push_back(std::move(frame));
  return entry;
}

std::pair<int, Vec3> ReadContext::ResolveStation(const std::string& owner,
                                                 const pugi::xml_node& socket,
                                                 const std::string& component) {
  const std::string_view text = XmlDocument::Text(socket);
  const std::string path = JoinPath(owner, text);
  auto it = stations_.find(path);
  if (it == stations_.end()) {
    doc_->Fail(socket, component,
              "<" + std::string(socket.name()) + "> '" + std::string(text) + "' is not a Station");
  }
  const pugi::xml_node station = it->second;
  pugi::xml_node frame_socket = station.child("socket_parent_frame");
  if (!frame_socket) doc_->Fail(station, path, "Station has no <socket_parent_frame>");
  const FrameEntry* frame = nullptr;
  ResolveFrame(path, XmlDocument::Text(frame_socket), frame_socket, path, &frame);
  const Vec3 location = ReadVec3Or(*doc_, station, "location", path, Vec3::Zero());
  return {frame->body, frame->X_BF * location};
}

void ReadContext::ResolveStationDefined(const std::string& path, FrameEntry& entry) {
  // OpenSim 4.5 StationDefinedFrame: with stations a, b, c and an origin point, the unit vector
  // along b - a is the `ab_axis` (default +x) and the unit normal (b - a) x (c - a) is the
  // `ab_x_ac_axis` (default +y); the third axis completes a right-handed frame.
  const pugi::xml_node node = entry.station_frame;
  const char* sockets[4] = {"socket_point_a", "socket_point_b", "socket_point_c",
                            "socket_origin_point"};
  int body = model::kNone;
  Vec3 p[4];
  for (int i = 0; i < 4; ++i) {
    pugi::xml_node socket = node.child(sockets[i]);
    if (!socket)
      doc_->Fail(node, path, std::string("StationDefinedFrame has no <") + sockets[i] + ">");
    auto [station_body, p_BS] = ResolveStation(path, socket, path);
    if (body != model::kNone && station_body != body) {
      doc_->Fail(socket, path, "the stations of a StationDefinedFrame are on different bodies");
    }
    body = station_body;
    p[i] = p_BS;
  }
  auto axis_of = [&](const char* tag, const char* fallback, int* index, double* sign) {
    std::string text = TextOf(node, tag);
    if (text.empty()) text = fallback;
    *sign = 1.0;
    if (text[0] == '+' || text[0] == '-') {
      *sign = text[0] == '-' ? -1.0 : 1.0;
      text = text.substr(1);
    }
    if (text != "x" && text != "y" && text != "z") {
      doc_->Fail(node.child(tag), path,
                "<" + std::string(tag) + "> must be one of x, y, z, -x, ...");
    }
    *index = text[0] - 'x';
  };
  int i_ab, i_n;
  double s_ab, s_n;
  axis_of("ab_axis", "+x", &i_ab, &s_ab);
  axis_of("ab_x_ac_axis", "+y", &i_n, &s_n);
  if (i_ab == i_n) doc_->Fail(node, path, "ab_axis and ab_x_ac_axis are the same axis");
  const Vec3 ab = p[1] - p[0];
  const Vec3 normal = ab.cross(p[2] - p[0]);
  if (ab.norm() < 1e-12 || normal.norm() < 1e-12 * (1 + ab.norm())) {
    doc_->Fail(node, path, "the stations of a StationDefinedFrame are collinear or coincident");
  }
  Mat3 R;
  R.col(i_ab) = s_ab * ab.normalized();
  R.col(i_n) = s_n * normal.normalized();
  const int k = 3 - i_ab - i_n;
  R.col(k) = R.col((k + 1) % 3).cross(R.col((k + 2) % 3));
  entry.body = body;
  entry.X_BF = Transform(R, p[3]);
  entry.X_PF = entry.X_BF;
  entry.state = 2;
  model::FrameSpec frame;
  frame.name = path.substr(path.rfind('/') + 1);
  frame.path = path;
  frame.parent = spec_.bodies[body].path;
  frame.X_PF = entry.X_BF;
  frame.body = body;
  frame.X_BF = entry.X_BF;
  frame.where = doc_->Where(node);
  entry.spec_frame = static_cast<int>(spec_.frames.size());
  spec_.frames.push_back(std::move(frame));
}

void ReadContext::ResolveAllFrames() {
  for (const std::string& path : offset_order_) Resolve(path, frames_.at(path));
}

const std::vector<int>& ReadContext::CoordinatesNamed(const std::string& name) const {
  static const std::vector<int> kEmpty;
  auto it = coordinate_names_.find(name);
  return it == coordinate_names_.end() ? kEmpty : it->second;
}

}  // namespace sinew::io::internal
