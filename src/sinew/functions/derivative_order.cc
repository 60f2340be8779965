#include <sinew/common/error.h>
#include <sinew/functions/derivative_order.h>

namespace sinew::functions {

void ThrowBadDerivativeOrder(int order, const std::string& type) {
  throw Error(type + ": derivative order must be 0, 1 or 2, got " + std::to_string(order));
}

}  // namespace sinew::functions
