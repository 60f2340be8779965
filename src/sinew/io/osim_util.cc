// Small helpers shared by the .osim reader's parts.
#include <sinew/io/internal/osim_context.h>
#include <sinew/math/rotation.h>

#include <algorithm>
#include <cctype>
#include <charconv>

namespace sinew::io::internal {

std::string Lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::vector<pugi::xml_node> ObjectsOf(const pugi::xml_node& set_or_list) {
  std::vector<pugi::xml_node> result;
  if (!set_or_list) return result;
  pugi::xml_node list = set_or_list.child("objects");
  if (!list) list = set_or_list;
  for (pugi::xml_node child : list.children()) {
    if (child.type() == pugi::node_element) result.push_back(child);
  }
  return result;
}

model::Element ToElement(const XmlDocument& doc, const pugi::xml_node& node) {
  model::Element element;
  element.tag = node.name();
  element.name = NameOf(node);
  element.line = doc.LineOf(node);
  bool has_child_element = false;
  for (pugi::xml_node child : node.children()) {
    if (child.type() != pugi::node_element) continue;
    has_child_element = true;
    element.children.push_back(ToElement(doc, child));
  }
  if (!has_child_element) element.text = std::string(XmlDocument::Text(node));
  return element;
}

namespace {

// A property element that is present and not empty (OpenSim reads `<x></x>` as the default).
bool IsSet(const pugi::xml_node& node) { return node && !XmlDocument::Text(node).empty(); }

}  // namespace

Vec3 ReadVec3Or(const XmlDocument& doc, const pugi::xml_node& parent, const char* tag,
                const std::string& component, const Vec3& fallback) {
  pugi::xml_node node = parent.child(tag);
  return IsSet(node) ? doc.ReadVec3(node, component) : fallback;
}

double ReadDoubleOr(const XmlDocument& doc, const pugi::xml_node& parent, const char* tag,
                    const std::string& component, double fallback) {
  pugi::xml_node node = parent.child(tag);
  return IsSet(node) ? doc.ReadDouble(node, component) : fallback;
}

bool ReadBoolOr(const XmlDocument& doc, const pugi::xml_node& parent, const char* tag,
                const std::string& component, bool fallback) {
  pugi::xml_node node = parent.child(tag);
  return IsSet(node) ? doc.ReadBool(node, component) : fallback;
}

bool ReadEnabledFlag(const XmlDocument& doc, const pugi::xml_node& node, const char* current_tag,
                     const std::string& path, bool fallback) {
  if (pugi::xml_node current = node.child(current_tag)) return doc.ReadBool(current, path);
  if (pugi::xml_node disabled = node.child("isDisabled")) return !doc.ReadBool(disabled, path);
  return fallback;
}

std::string TextOf(const pugi::xml_node& parent, const char* tag) {
  pugi::xml_node node = parent.child(tag);
  return node ? std::string(XmlDocument::Text(node)) : std::string();
}

Transform MakeTransform(const Vec3& angles, const Vec3& p) {
  return Transform(RotationFromBodyFixedXYZ(angles), p);
}

bool IsNumberList(std::string_view text) {
  size_t i = 0;
  int count = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    const size_t start = i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (start == i) break;
    std::string_view token = text.substr(start, i - start);
    if (token.front() == '+') token.remove_prefix(1);
    double value = 0;
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || ptr != token.data() + token.size()) return false;
    ++count;
  }
  return count > 0;
}

model::NumberMap ReadNumericLeaves(const XmlDocument& doc, const pugi::xml_node& node,
                                   const std::string& component,
                                   std::initializer_list<std::string_view> skip) {
  model::NumberMap result;
  for (pugi::xml_node child : node.children()) {
    if (child.type() != pugi::node_element || child.first_child().type() == pugi::node_element) {
      continue;
    }
    const std::string_view tag = child.name();
    if (std::find(skip.begin(), skip.end(), tag) != skip.end()) continue;
    if (!IsNumberList(XmlDocument::Text(child))) continue;
    // Kept for the builders, which check each value; here only NaN is refused, since OpenSim
    // writes Inf for an absent bound (min_control, max_control).
    result[std::string(tag)] = doc.ReadNumbers(child, component, -1, NumberRange::kAllowInfinite);
  }
  return result;
}

}  // namespace sinew::io::internal
