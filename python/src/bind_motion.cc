// Model.kinematics, Model.analyze, Model.export and Model.render: body poses and marker
// positions along a motion, its paths' lengths, speeds and moment arms and its muscles' tables
// (opensim::MuscleAnalysis, as `sinew analyze`), its glTF/HTML export and a PNG picture, through
// the library's viz::MotionFromTable and
// viz::PosesAtTime (coordinates by name or OpenSim 4 state path, degrees converted,
// coupler-driven coordinates following their drivers), kinematics::CalcMarkerLocationRow,
// viz::ExportAnimation and viz::RenderFramed (with the contact arrows of a contacts table,
// viz::ContactArrowPartsAt), on the spec the model's System was built from (stand-ins
// included), as `sinew kinematics`, `export` and `render` use them.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <sinew/io/storage.h>
#include <sinew/kinematics/body_kinematics.h>
#include <sinew/kinematics/coordinate_couplers.h>
#include <sinew/opensim/muscle_analysis.h>
#include <sinew/paths/geometry_path.h>
#include <sinew/viz/contact_arrows.h>
#include <sinew/viz/export_animation.h>
#include <sinew/viz/gltf_writer.h>
#include <sinew/viz/image.h>
#include <sinew/viz/motion_poses.h>
#include <sinew/viz/rasterizer.h>
#include <sinew/viz/view_hints.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "arrays.h"
#include "bindings.h"
#include "model_handle.h"

namespace sinew::python {
namespace {

// Warns (Python's warnings) with the first of `notes` and how many there are.
void WarnNotes(const Diagnostics& notes, const std::string& what) {
  if (notes.empty()) return;
  std::string message = what + ": " + notes.front().Format();
  if (notes.size() > 1) message += " (and " + std::to_string(notes.size() - 1) + " more)";
  if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 2) != 0) throw py::error_already_set();
}

// The table `source` gives: the path of a table file, or a sinew.Result's table `values`
// (the attribute holding it, [n, labels]) with its column names `labels`, over its `time`.
io::Storage TableOf(const py::object& source, const char* name, const char* labels,
                    const char* values) {
  if (!py::hasattr(source, values) || !py::hasattr(source, labels)) {
    return io::ReadStorage(py::str(py::module_::import("os").attr("fspath")(source)));
  }
  io::Storage table;
  table.name = name;
  table.labels = source.attr(labels).cast<std::vector<std::string>>();
  const auto time = source.attr("time").cast<DoubleArray>();
  const auto data = source.attr(values).cast<DoubleArray>();
  table.time.assign(time.data(), time.data() + time.size());
  table.values.assign(data.data(), data.data() + data.size());
  return table;
}

// The table of `motion`: the path of a motion or states table, or a sinew.Result (its states).
io::Storage TableOf(const py::object& motion) {
  return TableOf(motion, "states", "labels", "states");
}

// The table of `contacts`: the path of a contacts table (contacts.sto), or a sinew.Result (its
// contacts, which must have columns).
io::Storage ContactsTableOf(const py::object& contacts) {
  io::Storage table = TableOf(contacts, "Contacts", "contact_labels", "contacts");
  if (table.labels.empty() && py::hasattr(contacts, "contact_labels")) {
    throw Error("contacts: this run has no contacts table");
  }
  return table;
}

// The body poses along `motion`: None (the default pose) or as TableOf.
viz::BodyMotion MotionOf(const ModelHandle& model, const py::object& motion) {
  if (motion.is_none()) return viz::DefaultPoseMotion(model.spec());
  Diagnostics notes;
  viz::BodyMotion poses = viz::MotionFromTable(model.spec(), TableOf(motion), &notes);
  WarnNotes(notes, "motion");
  return poses;
}

py::dict Kinematics(const ModelPtr& model, const py::object& motion) {
  const viz::BodyMotion poses = MotionOf(*model, motion);
  const model::ModelSpec& spec = model->spec();
  const size_t n = poses.times.size(), nb = spec.bodies.size(), nm = spec.markers.size();
  py::array_t<double> time(n), p_GB({n, nb, size_t{3}}), R_GB({n, nb, size_t{3}, size_t{3}}),
      markers({n, nm, size_t{3}});
  auto p = p_GB.mutable_unchecked<3>();
  auto R = R_GB.mutable_unchecked<4>();
  auto m = markers.mutable_unchecked<3>();
  for (size_t i = 0; i < n; ++i) {
    time.mutable_data()[i] = poses.times[i];
    for (size_t b = 0; b < nb; ++b) {
      const Transform& X = poses.X_GB[i][b];
      for (int r = 0; r < 3; ++r) {
        p(i, b, r) = X.p[r];
        for (int c = 0; c < 3; ++c) R(i, b, r, c) = X.R(r, c);
      }
    }
    const std::vector<double> row = kinematics::CalcMarkerLocationRow(spec, poses.X_GB[i]);
    for (size_t k = 0; k < 3 * nm; ++k) m(i, k / 3, k % 3) = row[k];
  }
  std::vector<std::string> bodies, marker_names;
  for (const auto& b : spec.bodies) bodies.push_back(b.name);
  for (const auto& k : spec.markers) marker_names.push_back(k.name);
  return py::dict(py::arg("time") = time, py::arg("bodies") = bodies, py::arg("p_GB") = p_GB,
                  py::arg("R_GB") = R_GB, py::arg("markers") = marker_names,
                  py::arg("marker_positions") = markers);
}

// A table's values as an array [rows, columns].
py::array_t<double> TableArray(const io::Storage& table) {
  const size_t rows = table.time.size(), columns = table.labels.size();
  py::array_t<double> array({rows, columns});
  std::copy(table.values.begin(), table.values.end(), array.mutable_data());
  return array;
}

py::dict Analyze(const ModelPtr& model, const py::object& motion,
                 const std::optional<std::vector<std::string>>& coordinates) {
  const model::ModelSpec& spec = model->spec();
  const io::Storage table = TableOf(motion);
  const std::string motion_name =
      py::hasattr(motion, "states")
          ? std::string("motion")
          : std::string(py::str(py::module_::import("os").attr("fspath")(motion)));
  Diagnostics notes;
  const opensim::MuscleAnalysis analysis(
      spec, model->path(), *paths::FindCylinderRefinement(model->options().cylinder_refinement),
      table, motion_name, &notes);
  WarnNotes(analysis.paths().ListOmissions(spec), "analyze");
  const kinematics::CoordinateCouplers couplers(spec);
  std::vector<int> chosen;
  try {
    chosen = opensim::ChooseMomentArmCoordinates(spec, couplers,
                                                 coordinates.value_or(std::vector<std::string>{}));
  } catch (const Error& e) {
    throw Error(std::string("coordinates: ") + e.what());
  }
  const opensim::MuscleAnalysisTables tables = analysis.Run(chosen, &notes);
  WarnNotes(notes, "analyze");
  py::dict moment_arms;
  for (size_t k = 0; k < chosen.size(); ++k) {
    moment_arms[py::str(spec.coordinates[chosen[k]].name)] = TableArray(tables.moment_arms[k]);
  }
  const std::vector<double>& time = tables.length.time;
  py::dict out(py::arg("time") = py::array_t<double>(time.size(), time.data()),
               py::arg("paths") = tables.length.labels,
               py::arg("length") = TableArray(tables.length),
               py::arg("lengthening_speed") = TableArray(tables.lengthening_speed),
               py::arg("moment_arm") = moment_arms);
  out["muscles"] = tables.muscles.empty() ? std::vector<std::string>{} : tables.muscles[0].labels;
  const char* keys[] = {"fiber_length", "tendon_length", "active_fiber_force",
                        "passive_fiber_force", "tendon_force"};
  for (size_t k = 0; k < tables.muscles.size(); ++k) out[keys[k]] = TableArray(tables.muscles[k]);
  return out;
}

void Export(const ModelPtr& model, const std::filesystem::path& path, const py::object& motion,
            const std::string& visualization, const std::vector<std::string>& geometry_dirs,
            double fps, const py::object& contacts) {
  viz::ExportOptions options;
  options.visual.mode = viz::ParseVisType(visualization);
  options.visual.geometry_dirs = geometry_dirs;
  options.max_fps = fps;
  io::Storage contacts_table;
  if (!contacts.is_none()) {
    if (motion.is_none()) throw Error("export: contacts need a motion");
    contacts_table = ContactsTableOf(contacts);
    options.contacts = &contacts_table;  // groups found by name, as `sinew export --contacts`
  }
  const viz::BodyMotion poses = MotionOf(*model, motion);
  WarnNotes(viz::ExportAnimation(model->spec(), poses, path.string(), options).warnings, "export");
}

void Render(const ModelPtr& model, const std::filesystem::path& path, const py::object& motion,
            std::optional<double> time, const std::string& visualization,
            const std::vector<std::string>& geometry_dirs, int width, int height,
            const std::string& view, bool floor, const py::object& contacts) {
  viz::RenderOptions options;
  options.width = width;
  options.height = height;
  options.floor = floor;
  options.view_direction = viz::ParseViewDirection(view);
  viz::CheckRenderSize(width, height);
  const model::ModelSpec& spec = model->spec();
  viz::BodyMotion frame;
  io::Storage table;
  if (motion.is_none()) {
    if (time) throw Error("render: a time needs a motion");
    if (!contacts.is_none()) throw Error("render: contacts need a motion");
    frame = viz::DefaultPoseMotion(spec);
  } else {
    table = TableOf(motion);
    Diagnostics notes;
    frame = viz::MotionAtTime(spec, table, time.value_or(table.time.empty() ? 0.0 : table.time[0]),
                              &notes);
    WarnNotes(notes, "motion");
  }
  viz::VisualOptions visual;
  visual.mode = viz::ParseVisType(visualization);
  visual.geometry_dirs = geometry_dirs;
  viz::VisualScene scene = viz::BuildVisualScene(spec, visual);
  options.floor_plane = viz::ViewFloor(spec, scene, frame);  // as `sinew render`
  if (!contacts.is_none()) {
    options.overlay = viz::ContactArrowPartsAt(spec, ContactsTableOf(contacts), table, frame, scene,
                                               *options.floor_plane, &scene.warnings);
  }
  WarnNotes(scene.warnings, "render");
  viz::WriteFileBytes(path.string(),
                      viz::EncodePng(viz::RenderFramed(scene, frame.X_GB[0], options)));
}

}  // namespace

void BindMotion(py::module_& m) {
  py::class_<ModelHandle, ModelPtr> model =
      py::reinterpret_borrow<py::class_<ModelHandle, ModelPtr>>(m.attr("Model"));
  model.def("kinematics", &Kinematics, py::arg("motion") = py::none(),
            "Body poses and marker positions in ground along `motion` (None: the default pose; "
            "a .mot/.sto path; a sinew.Result): a dict of time [n], bodies, p_GB [n, bodies, 3] "
            "(m), R_GB [n, bodies, 3, 3], markers, marker_positions [n, markers, 3] (m).");
  model.def("analyze", &Analyze, py::arg("motion"), py::kw_only(),
            py::arg("coordinates") = py::none(),
            "OpenSim MuscleAnalysis-style tables of every geometry path along `motion` (a "
            ".mot/.sto path or a sinew.Result), as `sinew analyze`: a dict of time [n], paths, "
            "length and lengthening_speed [n, paths] (m, m/s), moment_arm (a dict from each "
            "coordinate of `coordinates`, default every one not locked or coupled, to [n, paths] "
            "in m), and muscles (those whose activation and fiber_length the table holds, as a "
            "states table or a Result does) with fiber_length, tendon_length (m), "
            "active_fiber_force, passive_fiber_force and tendon_force (N), each [n, muscles].");
  model.def("export", &Export, py::arg("path"), py::arg("motion") = py::none(), py::kw_only(),
            py::arg("visualization") = "mesh",
            py::arg("geometry_dirs") = std::vector<std::string>{}, py::arg("fps") = 0.0,
            py::arg("contacts") = py::none(),
            "Writes `motion` (as for kinematics) as a glTF (.glb) or a self-contained HTML "
            "viewer (.html), as `sinew export` does; `contacts` (a contacts.sto path or a "
            "sinew.Result) adds the contact force arrows, as `sinew export --contacts`.");
  model.def("render", &Render, py::arg("path"), py::arg("motion") = py::none(), py::kw_only(),
            py::arg("time") = py::none(), py::arg("visualization") = "mesh",
            py::arg("geometry_dirs") = std::vector<std::string>{}, py::arg("width") = 800,
            py::arg("height") = 800, py::arg("view") = "iso", py::arg("floor") = true,
            py::arg("contacts") = py::none(),
            "Writes a PNG picture of the model at `time` of `motion` (default: its first row; "
            "no motion: the default pose), as `sinew render` does; `contacts` (a contacts.sto "
            "path or a sinew.Result) adds the contact force arrows, as `--contacts`.");
}

}  // namespace sinew::python
