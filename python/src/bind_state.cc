// sinew.State: time, coordinate values and speeds, auxiliary state variables and inputs, as
// NumPy arrays (copies) and by name. Setting q or u places the bodies again
// (engine::PlaceBodies), so the state stays consistent.
#include <pybind11/stl.h>
#include <sinew/engine/assemble.h>

#include "arrays.h"
#include "bindings.h"
#include "state_handle.h"

namespace sinew::python {

void BindState(py::module_& m) {
  py::class_<StateHandle>(m, "State",
                          "A state of a model (Model.default_state makes one); a plain value.")
      .def_property(
          "t", [](const StateHandle& s) { return s.state.t; },
          [](StateHandle& s, double t) { s.state.t = t; }, "Time (s).")
      .def_property(
          "q", [](const StateHandle& s) { return ToArray(s.state.q); },
          [](StateHandle& s, const DoubleArray& q) {
            CopyArray(q, s.state.q, "q");
            engine::PlaceBodies(s.model->system(), s.state);
          },
          "Coordinate values (rad or m), in Model.coordinates order (a copy).")
      .def_property(
          "u", [](const StateHandle& s) { return ToArray(s.state.u); },
          [](StateHandle& s, const DoubleArray& u) {
            CopyArray(u, s.state.u, "u");
            engine::PlaceBodies(s.model->system(), s.state);
          },
          "Coordinate speeds (rad/s or m/s), in Model.coordinates order (a copy).")
      .def_property(
          "z", [](const StateHandle& s) { return ToArray(s.state.z); },
          [](StateHandle& s, const DoubleArray& z) { CopyArray(z, s.state.z, "z"); },
          "Auxiliary state variables, in Model.state_variables order (a copy).")
      .def_property(
          "inputs", [](const StateHandle& s) { return ToArray(s.state.inputs); },
          [](StateHandle& s, const DoubleArray& inputs) {
            CopyArray(inputs, s.state.inputs, "inputs");
          },
          "Actuator excitations, in Model.actuators order (a copy).")
      .def_property_readonly("model", [](const StateHandle& s) { return s.model; })
      .def(
          "value",
          [](const StateHandle& s, const std::string& name) {
            return s.state.q[s.model->CoordinateIndex(name)];
          },
          py::arg("coordinate"), "The value of a coordinate (rad or m).")
      .def(
          "speed",
          [](const StateHandle& s, const std::string& name) {
            return s.state.u[s.model->CoordinateIndex(name)];
          },
          py::arg("coordinate"), "The speed of a coordinate (rad/s or m/s).")
      .def(
          "set_value",
          [](StateHandle& s, const std::string& name, double q) {
            s.state.q[s.model->CoordinateIndex(name)] = q;
            engine::PlaceBodies(s.model->system(), s.state);
          },
          py::arg("coordinate"), py::arg("value"), "Sets a coordinate's value; places the bodies.")
      .def(
          "set_speed",
          [](StateHandle& s, const std::string& name, double u) {
            s.state.u[s.model->CoordinateIndex(name)] = u;
            engine::PlaceBodies(s.model->system(), s.state);
          },
          py::arg("coordinate"), py::arg("speed"), "Sets a coordinate's speed; places the bodies.")
      .def(
          "copy", [](const StateHandle& s) { return s; }, "An independent copy.")
      .def("__copy__", [](const StateHandle& s) { return s; })
      .def("__deepcopy__", [](const StateHandle& s, const py::dict&) { return s; })
      .def("__repr__", [](const StateHandle& s) {
        return "<sinew.State t=" + std::to_string(s.state.t) + " of " +
               std::to_string(s.state.q.size()) + " coordinates>";
      });
}

}  // namespace sinew::python
