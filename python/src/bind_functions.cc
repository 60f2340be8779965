// Excitation functions of time for Model.simulate(excitations=...): sinew.Constant(value),
// sinew.Ramp(start, slope) and sinew.Sine(amplitude, frequency_hz, phase, offset), the
// library's functions::Constant, Ramp and SineExcitation. They pickle (sinew.sweep ships them
// to other processes).
#include <pybind11/stl.h>
#include <sinew/functions/constant.h>
#include <sinew/functions/excitations.h>

#include "bindings.h"

namespace sinew::python {

void BindFunctions(py::module_& m) {
  using functions::Function;
  py::class_<Function, std::shared_ptr<Function>>(m, "Function",
                                                  "A function of time u(t) (an excitation).")
      .def("__call__", &Function::Calc, py::arg("t"), "The value at time t (s).");
  py::class_<functions::Constant, Function, std::shared_ptr<functions::Constant>>(m, "Constant",
                                                                                  "u(t) = value.")
      .def(py::init<double>(), py::arg("value"))
      .def_property_readonly("value", &functions::Constant::value)
      .def(py::pickle([](const functions::Constant& f) { return py::make_tuple(f.value()); },
                      [](const py::tuple& t) {
                        return std::make_shared<functions::Constant>(t[0].cast<double>());
                      }));
  py::class_<functions::Ramp, Function, std::shared_ptr<functions::Ramp>>(
      m, "Ramp", "u(t) = 0 before start, slope * (t - start) from start on (not clamped).")
      .def(py::init<double, double>(), py::arg("start"), py::arg("slope"))
      .def_property_readonly("start", &functions::Ramp::start)
      .def_property_readonly("slope", &functions::Ramp::slope)
      .def(py::pickle([](const functions::Ramp& f) { return py::make_tuple(f.start(), f.slope()); },
                      [](const py::tuple& t) {
                        return std::make_shared<functions::Ramp>(t[0].cast<double>(),
                                                                 t[1].cast<double>());
                      }));
  using functions::SineExcitation;
  py::class_<SineExcitation, Function, std::shared_ptr<SineExcitation>>(
      m, "Sine", "u(t) = amplitude * sin(2 pi frequency_hz t + phase) + offset.")
      .def(py::init<double, double, double, double>(), py::arg("amplitude"),
           py::arg("frequency_hz"), py::arg("phase") = 0.0, py::arg("offset") = 0.0)
      .def_property_readonly("amplitude", &SineExcitation::amplitude)
      .def_property_readonly("frequency_hz", &SineExcitation::frequency_hz)
      .def_property_readonly("phase", &SineExcitation::phase)
      .def_property_readonly("offset", &SineExcitation::offset)
      .def(py::pickle(
          [](const SineExcitation& f) {
            return py::make_tuple(f.amplitude(), f.frequency_hz(), f.phase(), f.offset());
          },
          [](const py::tuple& t) {
            return std::make_shared<SineExcitation>(t[0].cast<double>(), t[1].cast<double>(),
                                                    t[2].cast<double>(), t[3].cast<double>());
          }));
}

}  // namespace sinew::python
