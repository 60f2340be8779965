#include <sinew/common/error.h>
#include <sinew/paths/wrap_quadrant.h>

namespace sinew::paths {

WrapQuadrant ParseWrapQuadrant(const std::string& text, const std::string& wrap_name) {
  // OpenSim reads a missing quadrant as "Unassigned" and treats it as "all".
  if (text.empty() || text == "all" || text == "All" || text == "ALL" || text == "Unassigned") {
    return {};
  }
  // "x", "+x", "-x" (and y, z), either case: an optional sign, then the axis letter.
  std::string axis_text = text;
  int sign = 1;
  if (axis_text.size() == 2 && (axis_text[0] == '+' || axis_text[0] == '-')) {
    sign = axis_text[0] == '-' ? -1 : 1;
    axis_text.erase(0, 1);
  }
  if (axis_text.size() == 1) {
    const char letter = axis_text[0];
    if (letter == 'x' || letter == 'X') return {0, sign};
    if (letter == 'y' || letter == 'Y') return {1, sign};
    if (letter == 'z' || letter == 'Z') return {2, sign};
  }
  throw Error(SourceLocation{}, wrap_name,
              "unknown quadrant '" + text + "' (expected all, x, +x, -x, y, +y, -y, z, +z or -z)");
}

QuadrantEngagement EngageOnActiveSide(const WrapQuadrant& quadrant, const Vec3& p_WP,
                                      const Vec3& p_WS, const Vec3& p_WM, bool segment_crosses) {
  if (segment_crosses) return QuadrantEngagement::kMandatory;
  const bool opposite_sides = quadrant.SideOf(p_WP) != quadrant.SideOf(p_WS);
  if (opposite_sides && !quadrant.OnActiveSide(p_WM)) return QuadrantEngagement::kWrapped;
  return QuadrantEngagement::kNoWrap;
}

}  // namespace sinew::paths
