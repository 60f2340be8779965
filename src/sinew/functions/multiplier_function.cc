#include <sinew/common/error.h>
#include <sinew/functions/multiplier_function.h>

namespace sinew::functions {

MultiplierFunction::MultiplierFunction(FunctionPtr function, double scale)
    : function_(std::move(function)), scale_(scale) {
  if (!function_) throw Error("MultiplierFunction: the inner function is missing");
}

}  // namespace sinew::functions
