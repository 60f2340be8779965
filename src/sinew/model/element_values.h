// Typed values of an Element's child properties (`<optimal_force>1</optimal_force>`), for
// layers that read component-specific properties from the spec's generic element tree.
// Errors name the file, the property's line and the component.
#pragma once

#include <sinew/math/types.h>
#include <sinew/model/element.h>

#include <optional>
#include <string>
#include <string_view>

namespace sinew::model {

/// Reads the children of one element; `file` and `component` name it in errors.
class ElementValues {
 public:
  ElementValues(const Element& element, std::string file, std::string component)
      : element_(element), file_(std::move(file)), component_(std::move(component)) {}

  /// True when the property is present.
  bool Has(std::string_view tag) const { return element_.Child(tag) != nullptr; }
  /// The property's trimmed text, or `fallback` when absent.
  std::string String(std::string_view tag, const std::string& fallback = "") const;
  /// One finite number; `fallback` when absent; throws sinew::Error for anything else.
  double Double(std::string_view tag, double fallback) const;
  /// One number that may be infinite (a bound such as min_control, where OpenSim writes Inf for
  /// none); `fallback` when absent; throws for NaN or text that is not a number.
  double Bound(std::string_view tag, double fallback) const;
  /// Three finite numbers; `fallback` when absent; throws for another count.
  Vec3 Vector3(std::string_view tag, const Vec3& fallback) const;
  /// true/false; `fallback` when absent; throws for other text.
  bool Bool(std::string_view tag, bool fallback) const;
  /// The text of the first present property among `tags`, or nullopt.
  std::optional<std::string> FirstString(std::initializer_list<std::string_view> tags) const;

  /// Throws sinew::Error at `line` (the element's when 0).
  [[noreturn]] void Fail(const std::string& message, int line = 0) const;

 private:
  const Element& element_;
  std::string file_;
  std::string component_;
};

}  // namespace sinew::model
