// ReadExternalLoads and the data an ExternalForce reads: the pendulum files of opensim-core's
// Forward tests, and the ExternalLoads files of the corpus (4.0 form and a 3.x-era file with
// the kinematics options OpenSim 4 ignores), every identifier naming its 3 columns.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/io/external_loads.h>

#include <filesystem>
#include <string>
#include <vector>

#include "corpus.h"

namespace sinew::io {
namespace {

const std::string kForward = std::string(SINEW_TEST_DATA_DIR) +
                             "/opensim-org/opensim-core/Applications/Forward/tests/resources/";

TEST(ExternalLoadsReaderTest, ReadsThePendulumLoadsAndTheirDataBesideThem) {
  const ExternalLoads loads = ReadExternalLoads(kForward + "pendulum_external_load.xml");
  EXPECT_EQ(loads.name, "pendulum_gravity");
  EXPECT_EQ(std::filesystem::path(loads.data_file),
            std::filesystem::path(kForward + "pendulum_external_load.sto").lexically_normal());
  ASSERT_EQ(loads.forces.size(), 1u);
  const model::ForceSpec& force = loads.forces[0];
  EXPECT_EQ(force.name, "gravity");
  EXPECT_EQ(force.type, "ExternalForce");
  EXPECT_EQ(force.path, "/pendulum_gravity/gravity");
  EXPECT_TRUE(force.applies_force);
  EXPECT_EQ(force.where.line, 5);
  ASSERT_NE(force.element.Child("point_expressed_in_body"), nullptr);
  EXPECT_EQ(force.element.Child("point_expressed_in_body")->text, "pendulum");
  EXPECT_EQ(FindIdentifierColumns(loads.data, "force"), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(FindIdentifierColumns(loads.data, "torque"), (std::vector<int>{6, 7, 8}));
  EXPECT_TRUE(loads.notes.empty());
}

TEST(ExternalLoadsReaderTest, IdentifiersAreUnsetWhenBlankOrUnassigned) {
  EXPECT_FALSE(IsIdentifierSet(""));
  EXPECT_FALSE(IsIdentifierSet(" \t"));
  EXPECT_FALSE(IsIdentifierSet("Unassigned"));
  EXPECT_TRUE(IsIdentifierSet("ground_force_v"));
}

TEST(ExternalLoadsReaderTest, ColumnsAreFittedAsOpenSimDoesByRowCount) {
  // 3 rows: piecewise linear; 14 rows: the interpolating natural cubic spline (through every
  // sample, zero second derivative at both ends).
  const Storage three = ReadStorage(kForward + "pendulum_external_load.sto");
  EXPECT_EQ(FitExternalForceColumn(three, 1)->TypeName(), "PiecewiseLinearFunction");
  const Storage fourteen = ReadStorage(kForward + "pendulum_external_load_point_in_ground.sto");
  const int x = fourteen.FindColumn("pointX");
  const functions::FunctionPtr spline = FitExternalForceColumn(fourteen, x);
  EXPECT_EQ(spline->TypeName(), "GCVSpline");
  for (int row = 0; row < fourteen.NumRows(); ++row) {
    EXPECT_NEAR(spline->Calc(fourteen.time[row]), fourteen.Value(row, x), 1e-12) << row;
  }
  EXPECT_NEAR(spline->CalcDerivative(fourteen.time.front(), 2), 0.0, 1e-9);
  EXPECT_NEAR(spline->CalcDerivative(fourteen.time.back(), 2), 0.0, 1e-9);
  Storage one = three;
  one.time.resize(1);
  one.values.resize(one.labels.size());
  EXPECT_EQ(FitExternalForceColumn(one, 1)->TypeName(), "Constant");
}

TEST(ExternalLoadsReaderTest, ANonExternalLoadsFileIsRefusedAtItsLine) {
  try {
    ReadExternalLoads(kForward + "pendulum.osim");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("not an ExternalLoads file (root element"),
              std::string::npos)
        << error.what();
  }
}

// Every ExternalLoads file of the corpus reads, and each of its identifiers names exactly the
// 3 columns OpenSim needs.
TEST(ExternalLoadsReaderTest, ReadsEveryExternalLoadsFileOfTheCorpus) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const std::filesystem::path root = testing::CorpusDir();
  struct Expected {
    std::string file;
    size_t forces;
    size_t notes;
  };
  const std::vector<Expected> files = {
      {"opensim-org/opensim-core/Applications/Forward/tests/resources/subject01_GRFs.xml", 2, 0},
      {"clnsmith/opensim-jam/models/lenhart2015/motion_data/overground_17_ext_loads.xml", 3, 0},
  };
  for (const Expected& expected : files) {
    const ExternalLoads loads = ReadExternalLoads((root / expected.file).string());
    EXPECT_EQ(loads.forces.size(), expected.forces) << expected.file;
    EXPECT_EQ(loads.notes.size(), expected.notes) << expected.file;
    for (const model::ForceSpec& force : loads.forces) {
      for (const char* tag : {"force_identifier", "point_identifier", "torque_identifier"}) {
        const model::Element* identifier = force.element.Child(tag);
        ASSERT_NE(identifier, nullptr) << expected.file << " " << force.name << " " << tag;
        EXPECT_EQ(FindIdentifierColumns(loads.data, identifier->text).size(), 3u)
            << expected.file << " " << force.name << " " << tag;
      }
    }
  }
}

}  // namespace
}  // namespace sinew::io
