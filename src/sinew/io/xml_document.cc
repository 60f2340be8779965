#include <sinew/common/text.h>
#include <sinew/io/internal/xml_document.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace sinew::io::internal {
namespace {

// Makes nested comments (`<!-- a <!-- b --> c -->`) one comment, as a reader that counts
// `<!--` and `-->` would see them: the inner markers become spaces, so pugixml sees one comment
// and no stray `c -->` text lands in a value. Only whole, balanced nests are rewritten; when the
// nest never closes, the comment ends at its first `-->` (what TinyXML, OpenSim's parser, does).
// Every other byte, newlines included, is kept, so line numbers do not move.
void MergeNestedComments(std::string& text) {
  // All comment markers in text order (an overlapping "-->" inside "<!--" is not one). Two
  // substring searches and a merge: '<' and '-' are too common in XML to test byte by byte.
  struct Marker {
    size_t at;
    bool open;
  };
  std::vector<size_t> opens, closes;
  for (size_t i = text.find("<!--"); i != std::string::npos; i = text.find("<!--", i + 4)) {
    opens.push_back(i);
  }
  if (opens.empty()) return;
  for (size_t i = text.find("-->"); i != std::string::npos; i = text.find("-->", i + 3)) {
    closes.push_back(i);
  }
  std::vector<Marker> markers;
  markers.reserve(opens.size() + closes.size());
  size_t a = 0, b = 0;
  while (a < opens.size() || b < closes.size()) {
    if (b == closes.size() || (a < opens.size() && opens[a] < closes[b])) {
      markers.push_back({opens[a++], true});
    } else {
      const size_t at = closes[b++];
      if (!markers.empty() && markers.back().open && at < markers.back().at + 4) continue;
      markers.push_back({at, false});
    }
  }
  const size_t m = markers.size();
  if (m == 0) return;
  constexpr size_t kNever = static_cast<size_t>(-1);
  // depth[k]: opens minus closes among markers[0, k). The nest opened at marker k closes at the
  // first j > k with depth[j + 1] == depth[k] (the depth moves by one per marker). One pass from
  // the right finds it for every k, and the first close marker after every k: linear time, so
  // no input can make this quadratic.
  std::vector<long> depth(m + 1, 0);
  for (size_t k = 0; k < m; ++k) depth[k + 1] = depth[k] + (markers[k].open ? 1 : -1);
  std::vector<size_t> first_at(2 * m + 3, kNever);  // depth value (offset m+1) -> index
  std::vector<size_t> close_of(m, kNever), first_close(m, kNever);
  size_t next_close = kNever;
  for (size_t k = m; k-- > 0;) {
    first_close[k] = next_close;
    if (markers[k].open) close_of[k] = first_at[depth[k] + static_cast<long>(m) + 1];
    first_at[depth[k + 1] + static_cast<long>(m) + 1] = k;
    if (!markers[k].open) next_close = k;
  }
  size_t k = 0;
  while (k < m) {
    if (!markers[k].open) {  // a stray "-->" outside comments is text
      ++k;
      continue;
    }
    if (first_close[k] == kNever) return;     // unterminated: pugixml reports it
    const bool nested = markers[k + 1].open;  // an inner "<!--" before the first "-->"
    if (!nested || close_of[k] == kNever) {
      k = first_close[k] + 1;  // plain, or a nest that never closes: ends at its first "-->"
      continue;
    }
    for (size_t j = k + 1; j < close_of[k]; ++j) {
      const size_t len = markers[j].open ? 4 : 3;
      for (size_t c = 0; c < len; ++c) text[markers[j].at + c] = ' ';
    }
    k = close_of[k] + 1;
  }
}

// Appends code point `c` to `out` as UTF-8.
void AppendUtf8(char32_t c, std::string& out) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// A file that starts with a UTF-16 byte order mark (as some Windows editors save XML) becomes
// UTF-8 without it, so the parser, the line index and every message see one encoding. Each
// newline stays one newline, so line numbers do not move; a lone surrogate becomes U+FFFD.
// Other text is returned unchanged.
std::string ConvertUtf16(std::string text, const std::string& file) {
  const auto byte = [&text](size_t i) { return static_cast<unsigned char>(text[i]); };
  if (text.size() < 2) return text;
  const bool little = byte(0) == 0xFF && byte(1) == 0xFE;
  const bool big = byte(0) == 0xFE && byte(1) == 0xFF;
  if (!little && !big) return text;
  if (text.size() % 2 != 0) {
    throw Error(SourceLocation{file, 0}, "",
                "a UTF-16 file (it starts with a byte order mark) "
                "has an odd number of bytes");
  }
  const auto unit = [&](size_t i) -> char32_t {
    return little ? byte(i) | (byte(i + 1) << 8) : (byte(i) << 8) | byte(i + 1);
  };
  std::string out;
  out.reserve(text.size() / 2);
  for (size_t i = 2; i < text.size(); i += 2) {
    char32_t c = unit(i);
    if (c >= 0xD800 && c < 0xDC00 && i + 2 < text.size() && unit(i + 2) >= 0xDC00 &&
        unit(i + 2) < 0xE000) {
      c = 0x10000 + ((c - 0xD800) << 10) + (unit(i + 2) - 0xDC00);
      i += 2;
    } else if (c >= 0xD800 && c < 0xE000) {
      c = 0xFFFD;
    }
    AppendUtf8(c, out);
  }
  return out;
}

// "a\tb" for a name holding a tab: control characters shown as escapes in messages.
std::string ShowEscaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '\t') {
      out += "\\t";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
      out +=
          "\\x" + std::string(1, "0123456789abcdef"[(c >> 4) & 0xF]) + "0123456789abcdef"[c & 0xF];
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

XmlDocument XmlDocument::Load(const std::string& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw Error(SourceLocation{file, 0}, "", "is a directory, not a file");
  }
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) throw Error(SourceLocation{file, 0}, "", "cannot open file");
  const std::streamoff size = in.tellg();
  if (size < 0) throw Error(SourceLocation{file, 0}, "", "cannot read file");
  std::string text(static_cast<size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(text.data(), size)) throw Error(SourceLocation{file, 0}, "", "cannot read file");
  return Parse(std::move(text), file);
}

XmlDocument XmlDocument::Parse(std::string text, const std::string& file) {
  XmlDocument result;
  result.file_ = file;
  result.text_ = ConvertUtf16(std::move(text), file);
  MergeNestedComments(result.text_);
  result.IndexLines();
  result.doc_ = std::make_shared<pugi::xml_document>();
  const unsigned options = pugi::parse_default | pugi::parse_ws_pcdata_single;
  pugi::xml_parse_result parsed = result.doc_->load_buffer(result.text_.data(), result.text_.size(),
                                                           options, pugi::encoding_utf8);
  if (!parsed) {
    int line = 1;
    if (parsed.offset >= 0) {
      auto it = std::upper_bound(result.line_starts_.begin(), result.line_starts_.end(),
                                 static_cast<size_t>(parsed.offset));
      line = static_cast<int>(it - result.line_starts_.begin());
    }
    throw Error(SourceLocation{file, line}, "",
                std::string("not a well-formed XML document: ") + parsed.description());
  }
  if (!result.doc_->document_element()) {
    throw Error(SourceLocation{file, 1}, "", "the document has no root element");
  }
  result.CheckTree();
  return result;
}

void XmlDocument::CheckElement(const pugi::xml_node& node) const {
  if (node.type() != pugi::node_element) return;
  // Names become column labels of .sto files, which tabs and newlines would break apart (XML
  // turns literal ones in attributes into spaces; &#9; and &#10; survive).
  const std::string_view name = node.attribute("name").value();
  for (const char c : name) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
      Fail(node, "",
           "the name '" + ShowEscaped(name) +
               "' holds a tab, newline or other control character; names become column labels "
               "of .sto files, where these would break the columns");
    }
  }
  // A value split by a comment or processing instruction (<mass>1<!-- c -->0</mass>) is two
  // pieces of text; reading the first alone would take 1 for 10.
  int pieces = 0;
  for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
    const pugi::xml_node_type type = child.type();
    if ((type == pugi::node_pcdata || type == pugi::node_cdata) &&
        !TrimSpace(child.value()).empty() && ++pieces == 2) {
      Fail(node, "",
           "the text of <" + std::string(node.name()) +
               "> is split by a comment, processing instruction or element; write the value "
               "in one piece");
    }
  }
}

void XmlDocument::CheckTree() const {
  // Readers walk the tree recursively; a hostile file must not exhaust the stack. Iterative walk.
  const pugi::xml_node root = doc_->document_element();
  pugi::xml_node node = root;
  int depth = 0;
  CheckElement(root);
  while (node) {
    if (pugi::xml_node child = node.first_child()) {
      node = child;
      if (++depth > kMaxDepth) {
        Fail(node, "", "elements are nested deeper than " + std::to_string(kMaxDepth) + " levels");
      }
      CheckElement(node);
      continue;
    }
    while (node && node != root && !node.next_sibling()) {
      node = node.parent();
      --depth;
    }
    if (!node || node == root) break;
    node = node.next_sibling();
    CheckElement(node);
  }
}

void XmlDocument::IndexLines() {
  line_starts_.clear();
  line_starts_.push_back(0);
  const char* begin = text_.data();
  const char* end = begin + text_.size();
  for (const char* p = begin; p < end;) {
    p = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
    if (!p) break;
    ++p;
    line_starts_.push_back(static_cast<size_t>(p - begin));
  }
}

int XmlDocument::LineOf(const pugi::xml_node& node) const {
  const ptrdiff_t offset = node.offset_debug();
  if (offset < 0) return 0;
  auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), static_cast<size_t>(offset));
  return static_cast<int>(it - line_starts_.begin());
}

void XmlDocument::Fail(const pugi::xml_node& node, const std::string& component,
                       const std::string& message) const {
  throw Error(Where(node), component, message);
}

std::string_view XmlDocument::Text(const pugi::xml_node& node) {
  return TrimSpace(node.child_value());
}

double XmlDocument::ReadDouble(const pugi::xml_node& node, const std::string& component) const {
  std::vector<double> values = ReadNumbers(node, component, 1);
  return values[0];
}

std::vector<double> XmlDocument::ReadNumbers(const pugi::xml_node& node,
                                             const std::string& component, int count,
                                             NumberRange range) const {
  std::vector<double> values;
  std::string_view bad_token;
  if (!ParseNumbers(Text(node), &values, &bad_token)) {
    Fail(node, component,
         "<" + std::string(node.name()) + "> expects numbers, found '" + std::string(bad_token) +
             "'");
  }
  if (count >= 0 && static_cast<int>(values.size()) != count) {
    Fail(node, component,
         "<" + std::string(node.name()) + "> expects " + std::to_string(count) + " number" +
             (count == 1 ? "" : "s") + ", found " + std::to_string(values.size()));
  }
  if (const double* bad = FindOutOfRange(values, range)) {
    Fail(node, component,
         "<" + std::string(node.name()) + "> expects " +
             (range == NumberRange::kFinite ? "finite numbers" : "numbers (Inf allowed, not NaN)") +
             ", found " + std::to_string(*bad));
  }
  return values;
}

Vec3 XmlDocument::ReadVec3(const pugi::xml_node& node, const std::string& component) const {
  std::vector<double> v = ReadNumbers(node, component, 3);
  return {v[0], v[1], v[2]};
}

bool XmlDocument::ReadBool(const pugi::xml_node& node, const std::string& component) const {
  std::string_view text = Text(node);
  if (text == "true" || text == "1") return true;
  if (text == "false" || text == "0") return false;
  Fail(node, component,
       "<" + std::string(node.name()) + "> expects true or false, found '" + std::string(text) +
           "'");
}

}  // namespace sinew::io::internal
