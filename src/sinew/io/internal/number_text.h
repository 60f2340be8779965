// Numbers as storage files hold them: the shortest text that reads back to the same double.
#pragma once

#include <charconv>
#include <string>
#include <system_error>

namespace sinew::io::internal {

/// Appends `value` to `out` in the shortest form that reads back exactly ("nan", "inf" too).
inline void AppendNumber(std::string& out, double value) {
  char buffer[32];
  auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, ec == std::errc() ? ptr : buffer);
}

}  // namespace sinew::io::internal
