// The plane a model stands on, for viewing: where the HTML viewer lays its grid and `sinew
// render` its floor.
#pragma once

#include <sinew/math/transform.h>
#include <sinew/model/model_spec.h>

#include <string>
#include <utility>

namespace sinew::viz {

/// A plane in ground: the points p with (p - point) . normal = 0, the floor's solid below it.
struct FloorPlane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitY();  ///< Unit, out of the floor.
  /// Where it comes from: "y = 0" (ground's default), "ContactHalfSpace <name>",
  /// "--ground-plane", or "lowest point" (FloorUnder's fallback).
  std::string source = "y = 0";

  /// Signed height of `p` above the plane (m).
  double HeightOf(const Vec3& p) const { return (p - point).dot(normal); }
};

/// The plane y = `height` of ground, named `source`.
FloorPlane HorizontalFloor(double height, std::string source);

/// The floor `spec` defines: among its ContactHalfSpaces fixed to ground whose outward normal
/// (the -x axis of the half-space's frame, docs/contact.md) points up (y > 0), the one that
/// points most nearly up (the first of equals); without one, the plane y = 0 of ground.
FloorPlane ModelFloor(const model::ModelSpec& spec);

/// `floor` itself, unless it is ground's default y = 0 and the model (`bounds`, the posed bodies'
/// box without ground's parts) reaches below it by more than a tenth of its size: a model
/// hanging from ground's origin (arm26's shoulder) has no floor there, and gets a horizontal
/// floor at its lowest point instead (source "lowest point").
FloorPlane FloorUnder(const FloorPlane& floor, const std::pair<Vec3, Vec3>& bounds);

}  // namespace sinew::viz
