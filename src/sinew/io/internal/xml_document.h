// An XML file loaded for reading OpenSim documents: pugixml tree plus line numbers, and the
// value parsers every reader shares. Every failure throws sinew::Error naming file, line and
// component.
#pragma once

#include <sinew/common/error.h>
#include <sinew/common/text.h>
#include <sinew/math/types.h>

#include <memory>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace sinew::io::internal {

/// A parsed XML document that knows the line of every node.
class XmlDocument {
 public:
  /// Reads and parses `file`. OpenSim's lenient inputs load (see the semantics notes); a file
  /// with a UTF-16 byte order mark is converted to UTF-8 first.
  /// Throws sinew::Error when the file cannot be read or is not XML.
  static XmlDocument Load(const std::string& file);
  /// Parses XML held in memory; `file` names it in messages.
  static XmlDocument Parse(std::string text, const std::string& file);

  const std::string& file() const { return file_; }
  pugi::xml_node root() const { return doc_->document_element(); }

  /// 1-based line of `node` in the file (0 if unknown).
  int LineOf(const pugi::xml_node& node) const;
  SourceLocation Where(const pugi::xml_node& node) const { return {file_, LineOf(node)}; }

  /// Throws sinew::Error at `node`.
  [[noreturn]] void Fail(const pugi::xml_node& node, const std::string& component,
                         const std::string& message) const;

  /// The trimmed text of `node`.
  static std::string_view Text(const pugi::xml_node& node);
  /// The text of `node` as one finite number; throws on anything else.
  double ReadDouble(const pugi::xml_node& node, const std::string& component) const;
  /// Whitespace-separated numbers; `count` >= 0 requires exactly that many. Every number must be
  /// finite unless `range` allows infinities (bounds); NaN is always an error. This is where
  /// every number of a model file is checked.
  std::vector<double> ReadNumbers(const pugi::xml_node& node, const std::string& component,
                                  int count = -1, NumberRange range = NumberRange::kFinite) const;
  /// Exactly three finite numbers.
  Vec3 ReadVec3(const pugi::xml_node& node, const std::string& component) const;
  /// "true"/"false" (also "1"/"0"); throws on anything else.
  bool ReadBool(const pugi::xml_node& node, const std::string& component) const;

 private:
  XmlDocument() = default;
  void IndexLines();
  // Fails when elements nest deeper than kMaxDepth (real models nest about 15 levels), or when
  // CheckElement fails for one of them.
  void CheckTree() const;
  // Fails for a `name` attribute holding a control character (tab, newline, ...) and for text
  // split in pieces by a comment, processing instruction or element.
  void CheckElement(const pugi::xml_node& node) const;
  static constexpr int kMaxDepth = 200;

  std::string file_;
  std::string text_;                 // the buffer pugixml parsed (kept for offsets)
  std::vector<size_t> line_starts_;  // offset of each line's first character
  std::shared_ptr<pugi::xml_document> doc_;
};

}  // namespace sinew::io::internal
