// A formula in named variables, as OpenSim's expression-based forces hold them (OpenSim parses
// them with Lepton; Sinew with muparser, given Lepton's extra functions).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace sinew::forces {

/// A parsed formula in the variables named at construction. Evaluation is thread-safe (one
/// Expression may be shared by the threads that share a System).
class Expression {
 public:
  /// Parses `text` after removing its whitespace (as OpenSim does). Throws sinew::Error naming
  /// the problem and its position for a malformed formula or a name that is neither one of
  /// `variables` nor a known function or constant.
  Expression(const std::string& text, std::vector<std::string> variables);
  ~Expression();
  Expression(const Expression&) = delete;
  Expression& operator=(const Expression&) = delete;

  /// The formula as parsed (without whitespace).
  const std::string& text() const;
  /// The value for `values` (one per variable, in the constructor's order).
  double Evaluate(std::span<const double> values) const;

 private:
  struct Parsed;
  std::unique_ptr<Parsed> parsed_;
};

}  // namespace sinew::forces
