#include <sinew/common/text.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

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

namespace sinew {
namespace {

char LowerChar(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

// Levenshtein distance between a and b, ignoring case.
size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitute = diagonal + (LowerChar(a[i - 1]) == LowerChar(b[j - 1]) ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

}  // namespace

std::vector<std::string> FindCloseNames(std::string_view name,
                                        const std::vector<std::string>& candidates,
                                        size_t max_count) {
  std::vector<std::pair<size_t, std::string>> close;
  for (const std::string& candidate : candidates) {
    if (candidate.empty()) continue;
    const size_t distance = EditDistance(name, candidate);
    const size_t limit = std::max<size_t>(2, std::max(name.size(), candidate.size()) / 3);
    const bool contains = !name.empty() && (candidate.find(name) != std::string::npos ||
                                            name.find(candidate) != std::string_view::npos);
    if (distance <= limit || contains) close.emplace_back(distance, candidate);
  }
  std::stable_sort(close.begin(), close.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> names;
  for (size_t i = 0; i < close.size() && i < max_count; ++i) names.push_back(close[i].second);
  return names;
}

std::string FirstFew(const std::vector<std::string>& names, size_t shown) {
  std::string text;
  const size_t n = std::min(shown, names.size());
  for (size_t i = 0; i < n; ++i) text += (i ? ", " : "") + names[i];
  if (names.size() > n) text += " and " + std::to_string(names.size() - n) + " more";
  return text;
}

std::string FormatNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

}  // namespace sinew
