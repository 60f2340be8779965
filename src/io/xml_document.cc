#include "io/xml_document.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <fstream>

namespace sinew {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string_view Trim(std::string_view s) {
  while (!s.empty() && IsSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && IsSpace(s.back())) s.remove_suffix(1);
  return s;
}

// Parses one number token; accepts a leading '+', which from_chars does not.
bool ParseNumber(std::string_view token, double* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, *value);
  return ec == std::errc() && ptr == end;
}

// Makes nested comments (`<!-- a <!-- b --> c -->`) one comment, as a reader that counts
// `<!--` and `-->` would see them: the inner markers become spaces, so pugixml sees one comment
// and no stray `c -->` text lands in a value. Only whole, balanced nests are rewritten; when the
// nest never closes, the comment ends at its first `-->` (what TinyXML, OpenSim's parser, does).
// Every other byte, newlines included, is kept, so line numbers do not move.
void MergeNestedComments(std::string& text) {
  size_t pos = 0;
  while ((pos = text.find("<!--", pos)) != std::string::npos) {
    const size_t body = pos + 4;
    const size_t first_end = text.find("-->", body);
    if (first_end == std::string::npos) return;  // unterminated: pugixml reports it
    const size_t inner = text.find("<!--", body);
    if (inner == std::string::npos || inner > first_end) {
      pos = first_end + 3;
      continue;
    }
    // Count the nest depth until it returns to zero.
    int depth = 1;
    size_t i = body;
    std::vector<size_t> markers;  // offsets of inner "<!--" and non-final "-->"
    size_t close = std::string::npos;
    while (i < text.size()) {
      if (text.compare(i, 4, "<!--") == 0) {
        ++depth;
        markers.push_back(i);
        i += 4;
      } else if (text.compare(i, 3, "-->") == 0) {
        if (--depth == 0) {
          close = i;
          break;
        }
        markers.push_back(i);
        i += 3;
      } else {
        ++i;
      }
    }
    if (close == std::string::npos) {
      pos = first_end + 3;
      continue;
    }
    for (size_t m : markers) {
      const size_t len = text[m] == '<' ? 4 : 3;
      for (size_t k = 0; k < len; ++k) text[m + k] = ' ';
    }
    pos = close + 3;
  }
}

}  // namespace

XmlDocument XmlDocument::Load(const std::string& file) {
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
  result.text_ = std::move(text);
  MergeNestedComments(result.text_);
  result.IndexLines();
  result.doc_ = std::make_shared<pugi::xml_document>();
  const unsigned options = pugi::parse_default | pugi::parse_ws_pcdata_single;
  pugi::xml_parse_result parsed = result.doc_->load_buffer(
      result.text_.data(), result.text_.size(), options, pugi::encoding_utf8);
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
  result.CheckDepth();
  return result;
}

void XmlDocument::CheckDepth() const {
  // Readers walk the tree recursively; a hostile file must not exhaust the stack. Iterative walk.
  const pugi::xml_node root = doc_->document_element();
  pugi::xml_node node = root;
  int depth = 0;
  while (node) {
    if (pugi::xml_node child = node.first_child()) {
      node = child;
      if (++depth > kMaxDepth) {
        Fail(node, "", "elements are nested deeper than " + std::to_string(kMaxDepth) + " levels");
      }
      continue;
    }
    while (node && node != root && !node.next_sibling()) {
      node = node.parent();
      --depth;
    }
    if (!node || node == root) break;
    node = node.next_sibling();
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
  return Trim(node.child_value());
}

double XmlDocument::ReadDouble(const pugi::xml_node& node, const std::string& component) const {
  std::vector<double> values = ReadNumbers(node, component, 1);
  return values[0];
}

std::vector<double> XmlDocument::ReadNumbers(const pugi::xml_node& node,
                                             const std::string& component, int count) const {
  std::vector<double> values;
  std::string_view text = Text(node);
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && IsSpace(text[i])) ++i;
    size_t start = i;
    while (i < text.size() && !IsSpace(text[i])) ++i;
    if (start == i) break;
    double value = 0;
    std::string_view token = text.substr(start, i - start);
    if (!ParseNumber(token, &value)) {
      Fail(node, component,
           "<" + std::string(node.name()) + "> expects numbers, found '" + std::string(token) + "'");
    }
    values.push_back(value);
  }
  if (count >= 0 && static_cast<int>(values.size()) != count) {
    Fail(node, component,
         "<" + std::string(node.name()) + "> expects " + std::to_string(count) + " number" +
             (count == 1 ? "" : "s") + ", found " + std::to_string(values.size()));
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

}  // namespace sinew
