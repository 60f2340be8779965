// NumPy arrays to and from the engine's vectors: copies, checked for length with a sinew::Error
// that names what was expected.
#pragma once

#include <pybind11/numpy.h>
#include <sinew/common/error.h>
#include <sinew/math/types.h>

#include <cstring>
#include <string>

namespace sinew::python {

namespace py = pybind11;

/// A C-contiguous float64 array, converted from any sequence of numbers.
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// A new 1-D array holding a copy of `values`.
inline py::array_t<double> ToArray(const VecX& values) {
  py::array_t<double> array(values.size());
  if (values.size() > 0) {
    std::memcpy(array.mutable_data(), values.data(), sizeof(double) * values.size());
  }
  return array;
}

/// Copies the 1-D `array` into `values`; throws sinew::Error unless it has `values.size()`
/// entries (`what` names it: "q", "controls").
inline void CopyArray(const DoubleArray& array, VecX& values, const std::string& what) {
  if (array.ndim() != 1 || array.shape(0) != values.size()) {
    throw Error(what + " must be a 1-D array of " + std::to_string(values.size()) +
                " values, not of shape " + std::to_string(array.ndim() == 0 ? 0 : array.shape(0)) +
                (array.ndim() > 1 ? " x ..." : ""));
  }
  if (values.size() > 0) std::memcpy(values.data(), array.data(), sizeof(double) * values.size());
}

}  // namespace sinew::python
