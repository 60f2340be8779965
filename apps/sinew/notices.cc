#include "apps/sinew/notices.h"

#include <sinew/common/error.h>
#include <sinew/opensim/support.h>

#include <iostream>
#include <set>
#include <sstream>

namespace sinew::cli {

std::string ShowNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}
namespace {

// "1 joint is replaced by a spherical stand-in (/jointset/j: FancyJoint)", or "".
std::string StandInPhrase(const std::vector<opensim::NotSimulatedElement>& elements) {
  std::vector<std::string> joints;
  for (const opensim::NotSimulatedElement& e : elements) {
    if (e.kind == opensim::ElementKind::kJoint) joints.push_back(e.path + ": " + e.type);
  }
  if (joints.empty()) return "";
  const bool one = joints.size() == 1;
  return std::to_string(joints.size()) + (one ? " joint is" : " joints are") +
         " replaced by a spherical stand-in (" + FirstFew(joints, joints.size()) + ")";
}

// "6 muscles and 1 constraint are NOT simulated" for the elements other than joints, or "".
std::string LeftOutPhrase(const std::vector<opensim::NotSimulatedElement>& elements,
                          const char* verb) {
  std::vector<opensim::NotSimulatedElement> others;
  for (const opensim::NotSimulatedElement& e : elements) {
    if (e.kind != opensim::ElementKind::kJoint) others.push_back(e);
  }
  if (others.empty()) return "";
  return opensim::CountByKind(others) + (others.size() == 1 ? " is " : " are ") + verb;
}

std::string JoinPhrases(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return a + b;
  return a + " and " + b;
}

}  // namespace

void WarnNotSimulated(const model::ModelSpec& spec, const std::string& model_path, bool strict,
                      const std::vector<std::string>& disabled_forces) {
  const std::vector<opensim::NotSimulatedElement> elements =
      opensim::FindNotSimulated(spec, disabled_forces);
  if (elements.empty()) return;
  const std::string left_out = LeftOutPhrase(elements, "NOT simulated");
  const std::string standins = StandInPhrase(elements);
  std::string consequence = "results are those of the skeleton without them";
  if (left_out.empty()) {
    consequence = "results are those of the skeleton with a ball joint in its place";
  } else if (!standins.empty()) {
    consequence += ", and with ball joints for the stand-ins";
  }
  const std::string message = JoinPhrases(left_out, standins) + ": " + consequence +
                              ". List them with: sinew inspect " + model_path;
  if (strict) throw Error(SourceLocation{model_path, 0}, "", "--strict: " + message);
  std::cerr << "sinew: warning: " << message << "\n";
}

void UseStandIns(model::ModelSpec& spec, const std::string& model_path) {
  const std::vector<opensim::NotSimulatedElement> elements = opensim::FindNotSimulated(spec);
  const std::string standins = StandInPhrase(elements);
  if (!standins.empty()) {
    opensim::ReplaceWithStandIns(spec);
    std::cerr << "sinew: warning: " << standins
              << "; a stand-in holds its child body at the joint's frames, whatever the"
                 " coordinates. List them with: sinew inspect "
              << model_path << "\n";
  }
  std::vector<opensim::NotSimulatedElement> constraints;
  for (const opensim::NotSimulatedElement& e : elements) {
    if (e.kind == opensim::ElementKind::kConstraint) constraints.push_back(e);
  }
  if (!constraints.empty()) {
    std::cerr << "sinew: note: " << LeftOutPhrase(constraints, "not enforced")
              << ": bodies are placed from the coordinate values as given\n";
  }
}

void PrintSceneWarnings(const viz::VisualScene& scene, bool verbose) {
  if (verbose) {
    for (const viz::ReadMeshFile& mesh : scene.read_meshes) {
      std::cerr << "sinew: note: mesh '" << mesh.file << "' read from " << mesh.path << "\n";
    }
  }
  std::set<size_t> missing_warnings;
  std::vector<std::string> files;
  std::set<std::string> seen;
  for (const viz::MissingMesh& m : scene.missing_meshes) {
    missing_warnings.insert(m.warning);
    if (seen.insert(m.file).second) files.push_back(m.file);
  }
  for (size_t i = 0; i < scene.warnings.size(); ++i) {
    if (verbose || missing_warnings.count(i) == 0) {
      std::cerr << "sinew: warning: " << scene.warnings[i].Format() << "\n";
    }
  }
  if (files.empty()) return;
  std::string searched;
  for (const std::string& dir : scene.mesh_dirs) searched += (searched.empty() ? "" : ", ") + dir;
  std::cerr << "sinew: warning: " << files.size()
            << (files.size() == 1 ? " mesh file was" : " mesh files were") << " not found ("
            << FirstFew(files) << "); their bodies are drawn as primitives. Searched: " << searched
            << ". Add the folder that holds them with --geometry-dir DIR or $SINEW_GEOMETRY_PATH"
            << (verbose ? "" : "; --verbose lists every one") << "\n";
}

void ReportNscSolves(const engine::NscSolveSummary& summary, const engine::NscSettings& settings,
                     bool quiet, bool strict) {
  const char* solver = engine::ContactSolverMethodName(settings.solver.method);
  const std::string tolerance = ShowNumber(settings.solver.tolerance) + " m/s";
  if (summary.unconverged > 0) {
    std::ostringstream message;
    message << "NSC's contact impulse solver (" << solver << ") did NOT reach its tolerance of "
            << tolerance << " in " << summary.unconverged << " of " << summary.solves
            << " steps with contacts: it stopped at its limit of " << settings.solver.max_iterations
            << (settings.solver.max_iterations == 1 ? " iteration" : " iterations")
            << " with a residual up to " << ShowNumber(summary.worst_residual)
            << " m/s, so those steps' contact impulses are approximate (contacts.sto's "
               "nsc_contact.unconverged_steps counts them over time). Allow more with "
               "--nsc-iterations, or loosen --nsc-tolerance";
    if (strict) {
      throw Error("--strict: " + message.str() +
                  ". The output files were written (the whole run), but are not what --strict "
                  "asks for");
    }
    std::cerr << "sinew: warning: " << message.str() << "\n";
    return;
  }
  if (quiet) return;
  if (summary.solves == 0) {
    std::cerr << "sinew: note: NSC: no step had contacts (no impulse solve)\n";
    return;
  }
  std::cerr << "sinew: note: NSC's contact impulse solver (" << solver
            << ") reached its tolerance of " << tolerance << " in all " << summary.solves
            << " steps with contacts, in at most " << summary.most_iterations
            << (summary.most_iterations == 1 ? " iteration" : " iterations") << " (worst residual "
            << ShowNumber(summary.worst_residual) << " m/s)\n";
}

}  // namespace sinew::cli
