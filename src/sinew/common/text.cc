#include <sinew/common/text.h>

#include <charconv>
#include <cmath>

namespace sinew {

std::string_view TrimSpace(std::string_view text) {
  while (!text.empty() && IsXmlSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && IsXmlSpace(text.back())) text.remove_suffix(1);
  return text;
}

bool ParseNumber(std::string_view token, double* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, *value);
  return !token.empty() && ec == std::errc() && ptr == end;
}

bool ParseNumbers(std::string_view text, std::vector<double>* values, std::string_view* bad_token) {
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && IsXmlSpace(text[i])) ++i;
    const size_t start = i;
    while (i < text.size() && !IsXmlSpace(text[i])) ++i;
    if (start == i) break;
    double value = 0;
    const std::string_view token = text.substr(start, i - start);
    if (!ParseNumber(token, &value)) {
      if (bad_token) *bad_token = token;
      return false;
    }
    values->push_back(value);
  }
  return true;
}

const double* FindOutOfRange(const std::vector<double>& values, NumberRange range) {
  for (const double& v : values) {
    if (std::isnan(v) || (range == NumberRange::kFinite && std::isinf(v))) return &v;
  }
  return nullptr;
}

}  // namespace sinew
