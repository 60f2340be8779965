// Shared argument checks for Function implementations.
#pragma once

#include <string>

namespace sinew::functions {

/// Throws sinew::Error naming `type` for a derivative order other than 0, 1 or 2.
[[noreturn]] void ThrowBadDerivativeOrder(int order, const std::string& type);

/// Throws sinew::Error unless `order` is 0, 1 or 2 (the orders every Function provides).
/// `type` names the Function class in the message (built only on failure).
template <typename TypeName>
inline void CheckDerivativeOrder(int order, const TypeName& type) {
  if (order < 0 || order > 2) ThrowBadDerivativeOrder(order, std::string(type));
}

}  // namespace sinew::functions
