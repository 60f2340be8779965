// A generic element tree as read from the file: what the spec keeps of components it has no
// typed form for yet (muscle parameters, controller settings, ...), so nothing is dropped.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sinew::model {

/// One XML element: its tag, `name` attribute, trimmed text and children, with its line.
struct Element {
  std::string tag;   ///< XML element name, e.g. "Thelen2003Muscle" or "optimal_force".
  std::string name;  ///< The `name` attribute ("" when absent).
  std::string text;  ///< Trimmed text content (leaf values), "" for containers.
  int line = 0;      ///< 1-based line in the source file.
  std::vector<Element> children;

  /// The first child with this tag, or nullptr.
  const Element* Child(std::string_view child_tag) const {
    for (const Element& c : children) {
      if (c.tag == child_tag) return &c;
    }
    return nullptr;
  }
};

}  // namespace sinew::model
