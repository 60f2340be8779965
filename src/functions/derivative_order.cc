#include "functions/derivative_order.h"

#include "common/error.h"

namespace sinew {

void CheckDerivativeOrder(int order, const std::string& type) {
  if (order < 0 || order > 2) {
    throw Error(type + ": derivative order must be 0, 1 or 2, got " + std::to_string(order));
  }
}

}  // namespace sinew
