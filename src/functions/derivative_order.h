// Shared argument checks for Function implementations.
#pragma once

#include <string>

namespace sinew {

/// Throws sinew::Error unless `order` is 0, 1 or 2 (the orders every Function provides).
/// `type` names the Function class in the message.
void CheckDerivativeOrder(int order, const std::string& type);

}  // namespace sinew
