// The wrap surface factory: OpenSim type names to surfaces, OpenSim's defaults, and clear
// errors naming the object for what cannot be wrapped over.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/paths/wrap_cylinder.h>
#include <sinew/paths/wrap_cylinder_obst.h>
#include <sinew/paths/wrap_double_cylinder_obst.h>
#include <sinew/paths/wrap_ellipsoid.h>
#include <sinew/paths/wrap_sphere.h>
#include <sinew/paths/wrap_sphere_obst.h>
#include <sinew/paths/wrap_surface_factory.h>
#include <sinew/paths/wrap_torus.h>

namespace sinew::paths {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

model::WrapObjectSpec Spec(const std::string& type, model::NumberMap dimensions,
                           const std::string& quadrant = "all") {
  model::WrapObjectSpec spec;
  spec.name = "knee_wrap";
  spec.type = type;
  spec.quadrant = quadrant;
  spec.dimensions = std::move(dimensions);
  spec.where = {"leg.osim", 42};
  return spec;
}

// The message of the sinew::Error `build` throws ("" when it throws none).
template <typename Build>
std::string ErrorOf(Build build) {
  try {
    build();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(WrapSurfaceFactoryTest, BuildsSpheresAndCylindersWithTheirDimensions) {
  const auto sphere = MakeWrapSurface(Spec("WrapSphere", {{"radius", {0.03}}}));
  ASSERT_NE(dynamic_cast<const WrapSphere*>(sphere.get()), nullptr);
  EXPECT_EQ(dynamic_cast<const WrapSphere&>(*sphere).radius(), 0.03);

  const auto cylinder =
      MakeWrapSurface(Spec("WrapCylinder", {{"radius", {0.016}}, {"length", {0.05}}}, "-x"));
  const auto* as_cylinder = dynamic_cast<const WrapCylinder*>(cylinder.get());
  ASSERT_NE(as_cylinder, nullptr);
  EXPECT_EQ(as_cylinder->radius(), 0.016);
  EXPECT_EQ(as_cylinder->length(), 0.05);
  const auto ellipsoid =
      MakeWrapSurface(Spec("WrapEllipsoid", {{"dimensions", {0.035, 0.02, 0.02}}}, "z"));
  ASSERT_NE(dynamic_cast<const WrapEllipsoid*>(ellipsoid.get()), nullptr);
  EXPECT_EQ(dynamic_cast<const WrapEllipsoid&>(*ellipsoid).radii(), Vec3(0.035, 0.02, 0.02));
  EXPECT_EQ(
      SupportedWrapSurfaceTypes(),
      (std::vector<std::string>{"WrapCylinder", "WrapCylinderObst", "WrapDoubleCylinderObst",
                                "WrapEllipsoid", "WrapSphere", "WrapSphereObst", "WrapTorus"}));
  const auto torus =
      MakeWrapSurface(Spec("WrapTorus", {{"inner_radius", {0.035}}, {"outer_radius", {0.08}}}));
  const auto* as_torus = dynamic_cast<const WrapTorus*>(torus.get());
  ASSERT_NE(as_torus, nullptr);
  EXPECT_EQ(as_torus->inner_radius(), 0.035);
  EXPECT_EQ(as_torus->outer_radius(), 0.08);
}

TEST(WrapSurfaceFactoryTest, BuildsObstaclesWithTheirRadiusAndWrapDirection) {
  const auto right = MakeWrapSurface(Spec("WrapCylinderObst", {{"radius", {0.03}}}));
  ASSERT_NE(dynamic_cast<const WrapCylinderObst*>(right.get()), nullptr);
  EXPECT_EQ(dynamic_cast<const WrapCylinderObst&>(*right).radius(), 0.03);
  EXPECT_EQ(dynamic_cast<const WrapCylinderObst&>(*right).direction(),
            WrapCylinderObst::Direction::kRightHand);
  // The reader keeps wrapDirection as wrap_direction: -1 lefthand.
  const auto left = MakeWrapSurface(Spec("WrapCylinderObst", {{"wrap_direction", {-1.0}}}));
  EXPECT_EQ(dynamic_cast<const WrapCylinderObst&>(*left).direction(),
            WrapCylinderObst::Direction::kLeftHand);
  EXPECT_EQ(dynamic_cast<const WrapCylinderObst&>(*left).radius(), 1.0);
  const auto sphere = MakeWrapSurface(Spec("WrapSphereObst", {}));
  ASSERT_NE(dynamic_cast<const WrapSphereObst*>(sphere.get()), nullptr);
  EXPECT_EQ(dynamic_cast<const WrapSphereObst&>(*sphere).radius(), 0.05);
  // The double cylinder: OpenSim's radii 1 m and right-handed directions unless given.
  model::WrapObjectSpec spec =
      Spec("WrapDoubleCylinderObst", {{"radiusVcyl", {0.015}}, {"wrap_ucyl_direction", {-1.0}}});
  spec.second_body = 2;
  const auto both = MakeWrapSurface(spec);
  const auto* as_double = dynamic_cast<const WrapDoubleCylinderObst*>(both.get());
  ASSERT_NE(as_double, nullptr);
  EXPECT_EQ(as_double->radius_u(), 1.0);
  EXPECT_EQ(as_double->radius_v(), 0.015);
  EXPECT_EQ(as_double->direction_u(), WrapDoubleCylinderObst::Direction::kLeftHand);
  EXPECT_EQ(as_double->direction_v(), WrapDoubleCylinderObst::Direction::kRightHand);
}

TEST(WrapSurfaceFactoryTest, MissingDimensionsTakeOpenSimsDefaults) {
  const auto sphere = MakeWrapSurface(Spec("WrapSphere", {}));
  EXPECT_EQ(dynamic_cast<const WrapSphere&>(*sphere).radius(), 0.05);
  const auto cylinder = MakeWrapSurface(Spec("WrapCylinder", {}));
  EXPECT_EQ(dynamic_cast<const WrapCylinder&>(*cylinder).radius(), 1.0);
  EXPECT_EQ(dynamic_cast<const WrapCylinder&>(*cylinder).length(), 1.0);
  const auto ellipsoid = MakeWrapSurface(Spec("WrapEllipsoid", {}));
  EXPECT_EQ(dynamic_cast<const WrapEllipsoid&>(*ellipsoid).radii(), Vec3(0.05, 0.05, 0.05));
}

TEST(WrapSurfaceFactoryTest, BadInputIsAnErrorNamingTheObject) {
  const auto fails_with = [](const model::WrapObjectSpec& spec, const std::string& what) {
    EXPECT_THAT(ErrorOf([&] { MakeWrapSurface(spec); }),
                AllOf(HasSubstr("leg.osim:42"), HasSubstr("knee_wrap"), HasSubstr(what)));
  };
  fails_with(Spec("WrapSphere", {{"radius", {-0.02}}}), "radius must be positive");
  fails_with(Spec("WrapSphere", {{"radius", {0.0}}}), "radius must be positive");
  fails_with(Spec("WrapCylinder", {{"radius", {0.01}}, {"length", {0.0}}}),
             "length must be positive");
  fails_with(Spec("WrapCylinder", {{"radius", {0.01, 0.02}}}), "radius must be one number");
  fails_with(Spec("WrapCylinder", {{"radius", {0.01}}}, "+w"), "unknown quadrant '+w'");
  fails_with(Spec("WrapEllipsoid", {{"dimensions", {0.01, 0.02}}}), "must be three numbers");
  fails_with(Spec("WrapEllipsoid", {{"dimensions", {0.01, 0.0, 0.02}}}), "must be positive");
  // OpenSim's torus has no default radii, and its tube must fit inside its ring.
  fails_with(Spec("WrapTorus", {{"outer_radius", {0.08}}}), "WrapTorus has no inner_radius");
  fails_with(Spec("WrapTorus", {{"inner_radius", {0.08}}, {"outer_radius", {0.05}}}),
             "outer_radius (0.05) must be greater than inner_radius (0.08)");
  fails_with(Spec("WrapTorus", {{"inner_radius", {0.0}}, {"outer_radius", {0.05}}}),
             "inner_radius must be positive");
  fails_with(Spec("WrapSphereObst", {{"length", {0.0}}}), "length must be positive");
  fails_with(Spec("WrapCylinderObst", {{"wrap_direction", {2.0}}}), "wrap_direction must be");
  fails_with(Spec("MyPluginWrapObject", {}), "MyPluginWrapObject is not a wrap surface");
  // The double cylinder needs the body of its V cylinder (the reader resolves
  // wrapVcylHomeBodyName) and positive radii.
  fails_with(Spec("WrapDoubleCylinderObst", {}), "has no body for its V cylinder");
  model::WrapObjectSpec with_body = Spec("WrapDoubleCylinderObst", {{"radiusUcyl", {-0.02}}});
  with_body.second_body = 2;
  fails_with(with_body,
             "WrapDoubleCylinderObst radiusUcyl must be positive and finite (got -0.02)");
  with_body.dimensions = {{"radiusVcyl", {0.0}}};
  fails_with(with_body, "radiusVcyl must be positive");
  with_body.dimensions = {{"wrap_vcyl_direction", {3.0}}};
  fails_with(with_body, "wrap_vcyl_direction must be");
}

TEST(WrapSurfaceFactoryTest, ReadsEveryQuadrantSpellingOpenSimAccepts) {
  EXPECT_FALSE(ParseWrapQuadrant("all", "w").constrained());
  EXPECT_FALSE(ParseWrapQuadrant("ALL", "w").constrained());
  EXPECT_FALSE(ParseWrapQuadrant("", "w").constrained());
  for (const auto& [text, axis, sign] :
       std::vector<std::tuple<std::string, int, int>>{{"x", 0, 1},
                                                      {"+X", 0, 1},
                                                      {"-x", 0, -1},
                                                      {"Y", 1, 1},
                                                      {"-Y", 1, -1},
                                                      {"+z", 2, 1},
                                                      {"-z", 2, -1}}) {
    const WrapQuadrant quadrant = ParseWrapQuadrant(text, "w");
    EXPECT_EQ(quadrant.axis, axis) << text;
    EXPECT_EQ(quadrant.sign, sign) << text;
  }
  EXPECT_THROW(ParseWrapQuadrant("xy", "w"), Error);
  EXPECT_THROW(ParseWrapQuadrant("++x", "w"), Error);
}

}  // namespace
}  // namespace sinew::paths
