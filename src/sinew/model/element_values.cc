#include <sinew/model/element_values.h>

#include <vector>

#include <sinew/common/error.h>
#include <sinew/common/text.h>

namespace sinew::model {

void ElementValues::Fail(const std::string& message, int line) const {
  throw Error(SourceLocation{file_, line > 0 ? line : element_.line}, component_, message);
}

std::string ElementValues::String(std::string_view tag, const std::string& fallback) const {
  const Element* child = element_.Child(tag);
  return child ? child->text : fallback;
}

std::optional<std::string> ElementValues::FirstString(
    std::initializer_list<std::string_view> tags) const {
  for (std::string_view tag : tags) {
    if (const Element* child = element_.Child(tag)) return child->text;
  }
  return std::nullopt;
}

double ElementValues::Double(std::string_view tag, double fallback) const {
  const Element* child = element_.Child(tag);
  if (!child) return fallback;
  std::vector<double> values;
  if (!ParseNumbers(child->text, &values) || values.size() != 1) {
    Fail("<" + std::string(tag) + "> expects one number, found '" + child->text + "'", child->line);
  }
  return values[0];
}

Vec3 ElementValues::Vector3(std::string_view tag, const Vec3& fallback) const {
  const Element* child = element_.Child(tag);
  if (!child) return fallback;
  std::vector<double> values;
  if (!ParseNumbers(child->text, &values) || values.size() != 3) {
    Fail("<" + std::string(tag) + "> expects 3 numbers, found '" + child->text + "'", child->line);
  }
  return {values[0], values[1], values[2]};
}

bool ElementValues::Bool(std::string_view tag, bool fallback) const {
  const Element* child = element_.Child(tag);
  if (!child) return fallback;
  if (child->text == "true" || child->text == "1") return true;
  if (child->text == "false" || child->text == "0") return false;
  Fail("<" + std::string(tag) + "> expects true or false, found '" + child->text + "'",
       child->line);
}

}  // namespace sinew::model
