// Tests for the .obj and .stl readers and the OpenSim mesh search order.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/mesh_file.h>
#include <sinew/io/mesh_obj.h>
#include <sinew/io/mesh_stl.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace sinew {
namespace {

const std::string kDataDir = SINEW_TEST_DATA_DIR;

TEST(ObjTest, ReadsQuadsNormalsAndNegativeIndices) {
  const std::string obj =
      "# a unit square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 2\nvt 0 0\n"
      "f 1//1 2//1 3//1 4//1\nf -4/1/1 -2/1/1 -1/1/1\n";
  io::TriangleMesh mesh = io::ParseObj(obj, "square.obj");
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.positions.size(), 4u);  // corners shared by (position, normal)
  for (const io::Vec3f& n : mesh.normals) EXPECT_TRUE(n.isApprox(io::Vec3f(0, 0, 1)));
}

TEST(ObjTest, ComputesNormalsWhenAbsentAndReportsBadLines) {
  io::TriangleMesh mesh = io::ParseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "t.obj");
  ASSERT_EQ(mesh.normals.size(), 3u);
  EXPECT_TRUE(mesh.normals[0].isApprox(io::Vec3f(0, 0, 1)));
  try {
    io::ParseObj("v 0 0 0\nv 1 0 0\n\nf 1 2 9\n", "bad.obj");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 4);
    EXPECT_NE(std::string(e.what()).find("bad.obj:4:"), std::string::npos);
  }
  EXPECT_THROW(io::ParseObj("v 0 zero 0\n", "bad.obj"), Error);
}

std::string BinaryStl(const std::vector<std::array<float, 9>>& triangles) {
  std::string bytes(80, 's');  // a header that starts like ASCII "solid" on purpose
  bytes.replace(0, 5, "solid");
  const uint32_t n = static_cast<uint32_t>(triangles.size());
  bytes.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : triangles) {
    const float normal[3] = {0, 0, 0};
    bytes.append(reinterpret_cast<const char*>(normal), 12);
    bytes.append(reinterpret_cast<const char*>(t.data()), 36);
    bytes.append(2, '\0');
  }
  return bytes;
}

TEST(StlTest, BinaryAndAsciiGiveTheSameWeldedMesh) {
  const std::vector<std::array<float, 9>> tris = {{0, 0, 0, 1, 0, 0, 1, 1, 0},
                                                  {0, 0, 0, 1, 1, 0, 0, 1, 0}};
  io::TriangleMesh binary = io::ParseStl(BinaryStl(tris), "square.stl");
  const std::string ascii =
      "solid square\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
      "   vertex 1 1 0\n  endloop\n endfacet\n facet normal 0 0 1\n  outer loop\n"
      "   vertex 0 0 0\n   vertex 1 1 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid square\n";
  io::TriangleMesh text = io::ParseStl(ascii, "square.stl");
  for (const io::TriangleMesh* mesh : {&binary, &text}) {
    EXPECT_EQ(mesh->positions.size(), 4u);  // the shared diagonal is welded
    EXPECT_EQ(mesh->triangles.size(), 2u);
    for (const io::Vec3f& n : mesh->normals) EXPECT_TRUE(n.isApprox(io::Vec3f(0, 0, 1)));
  }
  EXPECT_EQ(binary.triangles, text.triangles);
}

TEST(StlTest, TruncatedOrMalformedFilesThrow) {
  std::string bytes = BinaryStl({{0, 0, 0, 1, 0, 0, 1, 1, 0}});
  bytes[0] = 'x';  // not "solid": must be binary
  EXPECT_THROW(io::ParseStl(bytes.substr(0, bytes.size() - 10), "cut.stl"), Error);
  try {
    io::ParseStl("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 x 0\n", "a.stl");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 5);
  }
}

TEST(MeshNonFinite, ANaNOrInfiniteVertexIsAnErrorNamingTheFile) {
  // A NaN vertex would make the exported .glb invalid glTF: every reader refuses it.
  for (const char* value : {"nan", "inf", "1e39"}) {
    try {
      io::ParseObj(std::string("v 0 0 0\nv 1 0 0\nv 0 ") + value + " 0\nf 1 2 3\n", "n.obj");
      ADD_FAILURE() << value << " was read";
    } catch (const Error& e) {
      EXPECT_EQ(e.where().file, "n.obj") << e.what();
    }
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  try {
    io::ParseStl(BinaryStl({{0, 0, 0, 1, 0, 0, 0, nan, 0}}), "n.stl");
    FAIL() << "a NaN vertex was read";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "n.stl: vertex 2 has a coordinate that is not a finite number");
  }
}

TEST(MeshFileTest, SearchesModelFolderThenGeometryThenExtraDirs) {
  namespace fs = std::filesystem;
  const std::string model =
      kDataDir + "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim";
  const std::string extra = kDataDir + "/opensim-org/opensim-models/Geometry";
  std::vector<std::string> dirs = io::MeshSearchDirs(model, {extra});
  ASSERT_GE(dirs.size(), 3u);
  EXPECT_EQ(fs::path(dirs[1]).filename(), "Geometry");
  // r_pelvis.vtp exists in both the model's Geometry folder and the extra folder (with
  // different contents): the model's own copy wins, as in OpenSim.
  auto found = io::FindMeshFile("r_pelvis.vtp", dirs);
  ASSERT_TRUE(found);
  EXPECT_EQ(fs::path(*found).parent_path(), fs::path(dirs[1]));
  auto patella = io::FindMeshFile("r_patella.vtp", dirs);
  ASSERT_TRUE(patella);
  EXPECT_EQ(fs::path(*patella).parent_path(), fs::path(extra));
  EXPECT_FALSE(io::FindMeshFile("nowhere.vtp", dirs));
  EXPECT_EQ(io::ReadMesh(*patella).triangles.size(), 140u);
  EXPECT_THROW(io::ReadMesh(kDataDir + "/ATTRIBUTION.md"), Error);
  // The environment variable adds folders after the ones given.
  setenv(io::kGeometryPathVariable, "/a:/b", 1);
  dirs = io::MeshSearchDirs(model, {extra});
  unsetenv(io::kGeometryPathVariable);
  ASSERT_EQ(dirs.size(), 5u);
  EXPECT_EQ(dirs[3], "/a");
  EXPECT_EQ(dirs[4], "/b");
}

}  // namespace
}  // namespace sinew
