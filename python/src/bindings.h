// The pieces of the extension module sinew._sinew, one function per area (each in its own
// bind_*.cc), called in order by module.cc.
#pragma once

#include <pybind11/pybind11.h>

namespace sinew::python {

namespace py = pybind11;

void BindErrors(py::module_& m);     // sinew.Error and the translation of sinew::Error
void BindFunctions(py::module_& m);  // Constant, Ramp, Sine: excitations of simulate
void BindModel(py::module_& m);      // load, Model (names, report, default_state)
void BindState(py::module_& m);      // State (t, q, u, z, inputs, by name and as arrays)
void BindSimulate(py::module_& m);   // Model.simulate, write_states
void BindSimulator(py::module_& m);  // Model.simulator, Simulator (reset, step)
void BindBatch(py::module_& m);      // Batch (n copies stepped across threads)
void BindMotion(py::module_& m);     // Model.kinematics, Model.export, Model.render

}  // namespace sinew::python
