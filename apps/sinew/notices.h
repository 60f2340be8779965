// What a `sinew` run tells the user about the parts of a model it leaves out or replaces, and
// about tables and meshes it could not use as given: each kind of issue in ONE stderr line with
// a count, the first few names and where to find the rest.
#pragma once

#include <sinew/common/text.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/model/model_spec.h>
#include <sinew/viz/visual_scene.h>

#include <string>
#include <vector>

namespace sinew::cli {

/// A number as a message shows it (stream default: 6 significant digits).
std::string ShowNumber(double value);

/// What `sinew simulate` leaves out of `spec` (opensim::FindNotSimulated: muscles, other
/// forces, constraints, wrap objects, contact geometry, controllers..., and joints replaced by
/// spherical stand-ins) as one warning line on stderr naming `model_path` for `sinew inspect`.
/// With `strict` it is a sinew::Error instead (exit code 2). Nothing when nothing is left out.
/// Forces named in `disabled_forces` (--disable-force) are not counted.
void WarnNotSimulated(const model::ModelSpec& spec, const std::string& model_path, bool strict,
                      const std::vector<std::string>& disabled_forces = {});

/// For the commands that pose bodies from coordinates (kinematics, export, render): replaces
/// the joints the engine cannot model by their stand-ins (opensim::ReplaceWithStandIns), with
/// one warning line naming them, and one note line when the model has constraints, which such
/// commands do not enforce.
void UseStandIns(model::ModelSpec& spec, const std::string& model_path);

/// Prints the warnings of a visual scene: missing mesh files as ONE line (count, first few
/// names, the folders searched, and how to add one with --geometry-dir or
/// $SINEW_GEOMETRY_PATH), each missing mesh on its own line when `verbose`, and every other
/// warning as it is. With `verbose`, first one note per mesh file read saying where from.
void PrintSceneWarnings(const viz::VisualScene& scene, bool verbose);

/// After an NSC run (`simulate --collision --contact nsc`): what its contact impulse solver did
/// over the run (`summary`, with `settings`), on stderr. Steps whose solve stopped at the
/// iteration limit above the tolerance make a loud warning (always: those steps' impulses are
/// approximate) with their count, the worst residual and what to change; otherwise, unless
/// `quiet`, one note with the steps solved, the most iterations and the worst residual. With
/// `strict` (--strict: no silent approximation) such steps are a sinew::Error with the same
/// text instead (exit code 2; call it once the run's files are written).
void ReportNscSolves(const engine::NscSolveSummary& summary, const engine::NscSettings& settings,
                     bool quiet, bool strict = false);

}  // namespace sinew::cli
