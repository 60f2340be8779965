// All of Sinew's Function types in one include, for users building functions from C++
// (e.g. excitations: std::make_shared<SimmSpline>(times, values)).
#pragma once

#include <sinew/functions/constant.h>                          // IWYU pragma: export
#include <sinew/functions/excitations.h>                       // IWYU pragma: export
#include <sinew/functions/function.h>                          // IWYU pragma: export
#include <sinew/functions/gcv_spline.h>                        // IWYU pragma: export
#include <sinew/functions/linear_function.h>                   // IWYU pragma: export
#include <sinew/functions/multiplier_function.h>               // IWYU pragma: export
#include <sinew/functions/multivariate_polynomial_function.h>  // IWYU pragma: export
#include <sinew/functions/piecewise_constant_function.h>       // IWYU pragma: export
#include <sinew/functions/piecewise_linear_function.h>         // IWYU pragma: export
#include <sinew/functions/polynomial_function.h>               // IWYU pragma: export
#include <sinew/functions/simm_spline.h>                       // IWYU pragma: export
#include <sinew/functions/sine.h>                              // IWYU pragma: export
#include <sinew/functions/step_function.h>                     // IWYU pragma: export
