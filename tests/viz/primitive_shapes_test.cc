// The unit shapes must be closed-looking, outward facing, and the size their doc says.
#include <gtest/gtest.h>
#include <sinew/viz/primitive_shapes.h>

namespace sinew::viz {
namespace {

// Every face's winding normal agrees with its vertex normals, and the mesh's bounds.
void ExpectOutwardWithBounds(const io::TriangleMesh& m, const io::Vec3f& lo, const io::Vec3f& hi) {
  ASSERT_FALSE(m.empty());
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (const auto& t : m.triangles) {
    const io::Vec3f face =
        (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
    const io::Vec3f vertex = m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]];
    ASSERT_GT(face.norm(), 1e-9f) << "degenerate triangle";
    EXPECT_GT(face.dot(vertex), 0) << "triangle faces inwards";
  }
  io::Vec3f a = m.positions[0], b = m.positions[0];
  for (const io::Vec3f& p : m.positions) {
    a = a.cwiseMin(p);
    b = b.cwiseMax(p);
  }
  EXPECT_TRUE(a.isApprox(lo, 1e-5f)) << a.transpose();
  EXPECT_TRUE(b.isApprox(hi, 1e-5f)) << b.transpose();
}

TEST(PrimitiveShapesTest, UnitShapesFaceOutwardsWithDocumentedSizes) {
  ExpectOutwardWithBounds(*UnitSphere(), io::Vec3f(-1, -1, -1), io::Vec3f(1, 1, 1));
  ExpectOutwardWithBounds(*UnitCylinder(), io::Vec3f(-1, -1, -1), io::Vec3f(1, 1, 1));
  ExpectOutwardWithBounds(*UnitBox(), io::Vec3f(-1, -1, -1), io::Vec3f(1, 1, 1));
  ExpectOutwardWithBounds(*UnitCone(), io::Vec3f(-1, 0, -1), io::Vec3f(1, 1, 1));
  ExpectOutwardWithBounds(*MakeTorus(0.25), io::Vec3f(-1.25f, -0.25f, -1.25f),
                          io::Vec3f(1.25f, 0.25f, 1.25f));
}

TEST(PrimitiveShapesTest, SphereVerticesLieOnTheUnitSphere) {
  for (const io::Vec3f& p : UnitSphere()->positions) EXPECT_NEAR(p.norm(), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace sinew::viz
