#include <sinew/paths/path_set.h>

#include <string_view>

namespace sinew::paths {

PathSet::PathSet(const model::ModelSpec& spec, CylinderRefinement refinement) {
  for (const model::ForceSpec& force : spec.forces) {
    if (force.geometry_path || force.function_based_path) {
      paths_.emplace_back(spec, force, refinement);
    }
  }
}

Diagnostics PathSet::ListOmissions(const model::ModelSpec& spec) const {
  Diagnostics out;
  for (const model::ForceSpec& force : spec.forces) {
    if (force.geometry_path || force.function_based_path) continue;
    // The reader keeps other path kinds (a child element whose tag ends in "Path") unread.
    for (const model::Element& child : force.element.children) {
      const std::string_view tag = child.tag;
      if (tag.size() >= 4 && tag.substr(tag.size() - 4) == "Path") {
        out.push_back({force.where, force.path,
                       "path of type " + child.tag +
                           " is not computed (no length, speed or "
                           "moment arm for " +
                           force.name + ")"});
      }
    }
  }
  for (const GeometryPath& path : paths_) {
    for (const PathWrap& wrap : path.wraps()) {
      if (wrap.surface || !wrap.active) continue;
      out.push_back({path.where(), path.component(),
                     "wrap object '" + wrap.wrap_object + "' (" + wrap.type +
                         ") is not applied yet (Sinew does not wrap over this type): the path "
                         "is computed straight past it"});
    }
  }
  return out;
}

}  // namespace sinew::paths
