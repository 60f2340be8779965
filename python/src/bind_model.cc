// sinew.load and sinew.Model: a parsed model, its names (coordinates, bodies, actuators, state
// variables), the parser's Report as plain data, and its default state.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/nsc_integrator.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include "bindings.h"
#include "simulation_inputs.h"
#include "state_handle.h"

namespace sinew::python {
namespace {

py::dict WarningToDict(const Diagnostic& d) {
  py::dict out;
  out["file"] = d.where.file;
  out["line"] = d.where.line;
  out["component"] = d.component;
  out["message"] = d.message;
  return out;
}

// The Report as dicts and lists: bodies, joints, forces, constraints, stand_ins (joint names),
// warnings, not_simulated.
py::dict ReportToDict(const opensim::Report& report) {
  py::dict out;
  py::list bodies, joints, forces, constraints, stand_ins, warnings;
  for (const auto& [key, body] : report.bodies()) {
    bodies.append(py::dict(py::arg("name") = key, py::arg("index") = body.body));
  }
  for (const auto& [key, joint] : report.joints()) {
    joints.append(py::dict(py::arg("name") = key, py::arg("type") = joint.type,
                           py::arg("form") = opensim::JointFormName(joint.form),
                           py::arg("stand_in") = joint.standin));
    if (joint.standin) stand_ins.append(key);
  }
  for (const auto& [key, force] : report.forces()) {
    forces.append(py::dict(py::arg("name") = key, py::arg("type") = force.type,
                           py::arg("simulated") = force.load != nullptr,
                           py::arg("actuator") = force.actuator != nullptr,
                           py::arg("excitation_source") = force.excitation_source,
                           py::arg("disabled") = force.disabled));
  }
  for (const auto& [key, constraint] : report.constraints()) {
    constraints.append(py::dict(py::arg("name") = key, py::arg("type") = constraint.type,
                                py::arg("simulated") = constraint.constraint != nullptr));
  }
  for (const Diagnostic& d : report.warnings()) warnings.append(WarningToDict(d));
  out["bodies"] = bodies;
  out["joints"] = joints;
  out["forces"] = forces;
  out["constraints"] = constraints;
  out["stand_ins"] = stand_ins;
  out["warnings"] = warnings;
  out["not_simulated"] = report.not_simulated();
  return out;
}

// One number of a parameter's value: a Python number (not a bool), as a double.
double ParameterNumber(const std::string& path, const std::string& key, py::handle value) {
  if (!PyBool_Check(value.ptr()) && !PyUnicode_Check(value.ptr())) {
    const double number = PyFloat_AsDouble(value.ptr());
    if (!(number == -1.0 && PyErr_Occurred())) return number;
    PyErr_Clear();
  }
  throw Error({path, 0}, key,
              "parameter '" + key + "': expects a number or a sequence of numbers, not " +
                  std::string(py::str(py::repr(value))));
}

// sinew.load's `parameters` ({"<component>/<property>": number or sequence}) as overrides.
std::vector<model::ParameterOverride> ToParameterOverrides(const std::string& path,
                                                           const py::dict& parameters) {
  std::vector<model::ParameterOverride> overrides;
  for (const auto& [key_object, value] : parameters) {
    if (!PyUnicode_Check(key_object.ptr())) {
      throw Error({path, 0}, "",
                  "a parameter is named by a string '<component>/<property>', not " +
                      std::string(py::str(py::repr(key_object))));
    }
    model::ParameterOverride& override = overrides.emplace_back();
    override.key = key_object.cast<std::string>();
    const bool is_sequence = py::isinstance<py::iterable>(value) && !PyUnicode_Check(value.ptr());
    if (!is_sequence) {
      override.values.push_back(ParameterNumber(path, override.key, value));
      continue;
    }
    for (py::handle item : value) {
      override.values.push_back(ParameterNumber(path, override.key, item));
    }
  }
  return overrides;
}

// The name of the library's default NSC impulse solver, as `nsc_solver` takes it.
// A contact material from {"friction": ..., "kt": ..., ...}: the keys `sinew simulate`'s
// material options have, every other one an error naming it.
contact::CollisionMaterial ToContactMaterial(const std::string& path, const py::dict& values) {
  contact::CollisionMaterial m;
  const std::vector<std::pair<const char*, double*>> fields = {{"friction", &m.friction},
                                                               {"restitution", &m.restitution},
                                                               {"young_modulus", &m.young_modulus},
                                                               {"poisson_ratio", &m.poisson_ratio},
                                                               {"kn", &m.kn},
                                                               {"gn", &m.gn},
                                                               {"kt", &m.kt},
                                                               {"gt", &m.gt}};
  for (const auto& [key, value] : values) {
    const std::string name = py::str(key);
    const auto field =
        std::find_if(fields.begin(), fields.end(), [&](const auto& f) { return name == f.first; });
    if (field == fields.end()) {
      throw Error({path, 0}, "contact_material",
                  "unknown key '" + name +
                      "' (friction, restitution, young_modulus, poisson_ratio, kn, gn, kt, gt)");
    }
    if (!py::isinstance<py::float_>(value) && !py::isinstance<py::int_>(value)) {
      throw Error({path, 0}, "contact_material",
                  "'" + name + "' must be a number, not " + py::repr(value).cast<std::string>());
    }
    *field->second = value.cast<double>();
  }
  return m;
}

std::string DefaultNscSolver() {
  return engine::ContactSolverMethodName(engine::NscSettings{}.solver.method);
}

}  // namespace

void BindModel(py::module_& m) {
  m.def(
      "load",
      [](const std::filesystem::path& path, const std::optional<std::string>& visualization,
         bool collision, const std::string& contact, bool strict,
         const std::optional<py::dict>& parameters,
         const std::vector<std::filesystem::path>& geometry_dirs,
         const std::string& cylinder_refinement, const std::string& nsc_solver, int nsc_iterations,
         double nsc_tolerance, double nsc_max_recovery_speed, double nsc_min_bounce_speed,
         const std::optional<py::dict>& contact_material, std::optional<double> slip_speed,
         const std::vector<std::filesystem::path>& external_loads,
         const std::vector<std::string>& disabled_forces,
         const std::map<std::string, std::string>& rename_force_classes) {
        LoadOptions options;
        for (const auto& renamed : rename_force_classes)
          options.renamed_force_classes.push_back(renamed);
        for (const std::filesystem::path& file : external_loads)
          options.external_loads.push_back(file.string());
        options.disabled_forces = disabled_forces;
        if (contact_material) {
          options.contact_material = ToContactMaterial(path.string(), *contact_material);
        }
        options.slip_speed = slip_speed;
        options.nsc_solver = nsc_solver;
        options.nsc.solver.max_iterations = nsc_iterations;
        options.nsc.solver.tolerance = nsc_tolerance;
        options.nsc.max_recovery_speed = nsc_max_recovery_speed;
        options.nsc.min_bounce_speed = nsc_min_bounce_speed;
        for (const std::filesystem::path& dir : geometry_dirs)
          options.geometry_dirs.push_back(dir.string());
        options.visualization = visualization.value_or("none");
        options.collision = collision;
        options.contact = contact;
        options.strict = strict;
        options.cylinder_refinement = cylinder_refinement;
        if (parameters) options.parameters = ToParameterOverrides(path.string(), *parameters);
        return ModelHandle::Load(path.string(), options);
      },
      py::arg("path"), py::kw_only(), py::arg("visualization") = py::none(),
      py::arg("collision") = false, py::arg("contact") = "nsc", py::arg("strict") = false,
      py::arg("parameters") = py::none(),
      py::arg("geometry_dirs") = std::vector<std::filesystem::path>{},
      py::arg("cylinder_refinement") = "several-wraps", py::arg("nsc_solver") = DefaultNscSolver(),
      py::arg("nsc_iterations") = engine::NscSettings{}.solver.max_iterations,
      py::arg("nsc_tolerance") = engine::NscSettings{}.solver.tolerance,
      py::arg("nsc_max_recovery_speed") = engine::NscSettings{}.max_recovery_speed,
      py::arg("nsc_min_bounce_speed") = engine::NscSettings{}.min_bounce_speed,
      py::arg("contact_material") = py::none(), py::arg("slip_speed") = py::none(),
      py::arg("external_loads") = std::vector<std::filesystem::path>{},
      py::arg("disabled_forces") = std::vector<std::string>{},
      py::arg("rename_force_classes") = std::map<std::string, std::string>{},
      "Reads an OpenSim model (.osim) and builds what Sinew simulates of it, with `parameters` "
      "({'<component>/<property>': number or sequence}) overriding the file's values; "
      "ContactMesh files are also searched in `geometry_dirs`; the nsc_* settings are NSC's "
      "stepper's (collision=True, contact='nsc'), as `sinew simulate --nsc-*`; "
      "contact_material ({'friction': ..., 'kt': ..., ...}) and slip_speed are the collision "
      "contact's, as --friction, --kt, ... and --slip-speed; external_loads (OpenSim "
      "ExternalLoads .xml files) act on the bodies they name, as --external-loads; the forces "
      "named in disabled_forces are left out, as --disable-force; rename_force_classes "
      "({'Thelen2003Muscle': 'Thelen2003Muscle_Deprecated'}) reads forces of one class as "
      "another, as --rename-force-class.");

  py::class_<ModelHandle, ModelPtr>(m, "Model", "A parsed OpenSim model (sinew.load makes one).")
      .def_property_readonly("path", &ModelHandle::path, "The .osim file it was read from.")
      .def_property_readonly("name", [](const ModelHandle& h) { return h.spec().name; })
      .def_property_readonly("coordinates", &ModelHandle::CoordinateNames,
                             "Coordinate names, in the column order of q and u.")
      .def_property_readonly(
          "bodies",
          [](const ModelHandle& h) {
            std::vector<std::string> names;
            for (const auto& b : h.system().bodies()) names.push_back(b.name);
            return names;
          },
          "Body names, ground first.")
      .def_property_readonly("actuators", &ModelHandle::actuators,
                             "Actuator names, in the column order of controls.")
      .def_property_readonly(
          "state_variables", [](const ModelHandle& h) { return h.system().state_variable_names(); },
          "Auxiliary state variable names (<element>/<variable>), the column order of z.")
      .def_property_readonly(
          "report", [](const ModelHandle& h) { return ReportToDict(h.parser().GetReport()); },
          "What the parser built: bodies, joints, forces, constraints, stand_ins, warnings, "
          "not_simulated.")
      .def(
          "default_state",
          [](const ModelPtr& h) {
            return StateHandle{h, h->DefaultState()};
          },
          "The state with every coordinate at its default value and speed, assembled.")
      .def(
          "equilibrate_muscles",
          [](const ModelPtr& h, const StateHandle& state) {
            engine::CheckState(h->system(), state.state);
            StateHandle out{h, state.state};
            EquilibrateMusclesWarning(*h, out.state);
            return out;
          },
          py::arg("state"),
          "A copy of `state` with every muscle's fiber at muscle-tendon equilibrium at its "
          "pose, speeds and activations (OpenSim's equilibrateMuscles).")
      .def("__repr__", [](const ModelHandle& h) {
        return "<sinew.Model '" + h.spec().name + "' from " + h.path() + ": " +
               std::to_string(h.system().num_coordinates()) + " coordinates, " +
               std::to_string(h.system().num_inputs()) + " actuators>";
      });
}

}  // namespace sinew::python
