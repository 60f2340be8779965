// Small text utilities shared by the file readers.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sinew {

/// True for the XML white-space characters (space, tab, CR, LF).
inline bool IsXmlSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/// `text` without leading and trailing white space.
std::string_view TrimSpace(std::string_view text);

/// Parses one number (a leading '+' allowed); false unless the whole token is a number.
bool ParseNumber(std::string_view token, double* value);

/// Appends the white-space separated numbers of `text` to `values`. On a token that is not a
/// number returns false and sets `bad_token` (when not null) to it.
bool ParseNumbers(std::string_view text, std::vector<double>* values,
                  std::string_view* bad_token = nullptr);

/// Which numbers a model property accepts. NaN never: no OpenSim property means "not a number".
enum class NumberRange {
  kFinite,         ///< masses, lengths, angles, coefficients, knots: almost every property
  kAllowInfinite,  ///< bounds, where OpenSim writes Inf for "none" (min_control, ranges, times)
};

/// The first number of `values` that `range` rejects (NaN, or infinite under kFinite), or null.
const double* FindOutOfRange(const std::vector<double>& values, NumberRange range);

/// "a, b, c and 2 more" from the first `shown` of `names` ("" when empty), for messages.
std::string FirstFew(const std::vector<std::string>& names, size_t shown = 3);

/// `value` for a message: up to 6 significant digits, no trailing zeros ("0.067", "1e-10").
std::string FormatNumber(double value);

/// The names of `candidates` closest to `name`, for "no X named N; close names: ..." messages:
/// those within an edit distance (case-insensitive) of a third of the longer name (at least 2),
/// or containing `name` or contained in it, nearest first, at most `max_count`.
std::vector<std::string> FindCloseNames(std::string_view name,
                                        const std::vector<std::string>& candidates,
                                        size_t max_count = 5);

}  // namespace sinew
