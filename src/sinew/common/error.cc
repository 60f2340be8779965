#include <sinew/common/error.h>

#include <utility>

namespace sinew {

std::string FormatMessage(const SourceLocation& where, const std::string& component,
                          const std::string& message) {
  std::string out;
  if (!where.file.empty()) {
    out += where.file;
    if (where.line > 0) out += ":" + std::to_string(where.line);
    out += ": ";
  }
  if (!component.empty()) out += component + ": ";
  out += message;
  return out;
}

Error::Error(SourceLocation where, std::string component, std::string message)
    : std::runtime_error(FormatMessage(where, component, message)),
      where_(std::move(where)),
      component_(std::move(component)),
      message_(std::move(message)) {}

Error::Error(std::string message) : Error(SourceLocation{}, "", std::move(message)) {}

}  // namespace sinew
