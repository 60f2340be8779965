// sinew._sinew: the compiled half of the Python package `sinew` (python/sinew/__init__.py
// re-exports it with the pure-Python parts: Result, sweep).
#include "bindings.h"

PYBIND11_MODULE(_sinew, m) {
  m.doc() = "Sinew's C++ library: load OpenSim models, simulate them, step them in batches.";
  using namespace sinew::python;
  BindErrors(m);
  BindFunctions(m);
  BindModel(m);
  BindState(m);
  BindSimulate(m);
  BindSimulator(m);
  BindBatch(m);
  BindMotion(m);
}
