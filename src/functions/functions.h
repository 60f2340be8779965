// All of Sinew's Function types in one include, for users building functions from C++
// (e.g. excitations: std::make_shared<SimmSpline>(times, values)).
#pragma once

#include "functions/constant.h"                          // IWYU pragma: export
#include "functions/excitations.h"                       // IWYU pragma: export
#include "functions/function.h"                          // IWYU pragma: export
#include "functions/gcv_spline.h"                        // IWYU pragma: export
#include "functions/linear_function.h"                   // IWYU pragma: export
#include "functions/multiplier_function.h"               // IWYU pragma: export
#include "functions/multivariate_polynomial_function.h"  // IWYU pragma: export
#include "functions/piecewise_constant_function.h"       // IWYU pragma: export
#include "functions/piecewise_linear_function.h"         // IWYU pragma: export
#include "functions/polynomial_function.h"               // IWYU pragma: export
#include "functions/simm_spline.h"                       // IWYU pragma: export
#include "functions/sine.h"                              // IWYU pragma: export
#include "functions/step_function.h"                     // IWYU pragma: export
