#include <sinew/common/error.h>
#include <sinew/common/text.h>
#include <sinew/model/element_values.h>

#include <vector>

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

namespace {

// The numbers of `child`, which must be `count` numbers in `range`.
std::vector<double> ReadChecked(const ElementValues& v, std::string_view tag, const Element& child,
                                size_t count, NumberRange range) {
  std::vector<double> values;
  if (!ParseNumbers(child.text, &values) || values.size() != count ||
      FindOutOfRange(values, range) != nullptr) {
    const std::string what = count == 1 ? "one " : std::to_string(count) + " ";
    const std::string kind = range == NumberRange::kFinite ? "finite number" : "number";
    v.Fail("<" + std::string(tag) + "> expects " + what + kind + (count == 1 ? "" : "s") +
               ", found '" + child.text + "'",
           child.line);
  }
  return values;
}

}  // namespace

double ElementValues::Double(std::string_view tag, double fallback) const {
  const Element* child = element_.Child(tag);
  return child ? ReadChecked(*this, tag, *child, 1, NumberRange::kFinite)[0] : fallback;
}

double ElementValues::Bound(std::string_view tag, double fallback) const {
  const Element* child = element_.Child(tag);
  return child ? ReadChecked(*this, tag, *child, 1, NumberRange::kAllowInfinite)[0] : fallback;
}

Vec3 ElementValues::Vector3(std::string_view tag, const Vec3& fallback) const {
  const Element* child = element_.Child(tag);
  if (!child) return fallback;
  const std::vector<double> values = ReadChecked(*this, tag, *child, 3, NumberRange::kFinite);
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
