// Errors and diagnostics: every message names the file, the line and the component path,
// formatted as `model.osim:214: /jointset/knee_r: message`.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace sinew {

/// Where something was read from: a file and a 1-based line (0 when unknown).
struct SourceLocation {
  std::string file;
  int line = 0;
};

/// Formats `file:line: component: message`, leaving out the parts that are empty or unknown.
std::string FormatMessage(const SourceLocation& where, const std::string& component,
                          const std::string& message);

/// The exception Sinew throws for bad input or an impossible request. `what()` gives the
/// formatted message; the parts are kept for programs that want them.
class Error : public std::runtime_error {
 public:
  Error(SourceLocation where, std::string component, std::string message);
  explicit Error(std::string message);

  const SourceLocation& where() const { return where_; }
  const std::string& component() const { return component_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string component_;
  std::string message_;
};

/// A warning or note kept for the Report: something approximated, substituted or ignored.
struct Diagnostic {
  SourceLocation where;
  std::string component;
  std::string message;

  /// `file:line: component: message`.
  std::string Format() const { return FormatMessage(where, component, message); }
};

/// An ordered list of diagnostics collected while reading or building a model.
using Diagnostics = std::vector<Diagnostic>;

}  // namespace sinew
