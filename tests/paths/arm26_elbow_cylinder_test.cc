// Real data: OpenSim's musculotendon lengths and moment arms of arm26's TRIlat, TRImed and BRA
// (MyoConverter's reference tables), whose paths cross the elbow over one unconstrained
// WrapCylinder ("TRI", on the humerus). The path is rebuilt here from the model's geometry with
// OpenSim's rule for one wrap object: the first segment the cylinder wraps (a mandatory wrap)
// is replaced by P-T1, the helix and T2-S.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/paths/wrap_cylinder.h>
#include <sinew/paths/wrap_surface_factory.h>

#include <fstream>
#include <sstream>

#include "wrap_reference.h"

namespace sinew::paths {
namespace {

const std::string kMyoConverter = std::string(SINEW_TEST_DATA_DIR) + "/MyoHub/myoconverter/";

// One row of the reference tables: a muscle, its pose (coordinate = value) and a value (m).
struct ReferenceRow {
  std::string muscle;
  std::vector<std::pair<std::string, double>> pose;
  double value = 0.0;
};

std::vector<std::string> SplitOn(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, separator);) parts.push_back(part);
  return parts;
}

// muscle_kinetics.csv: muscle,activation,pose,mtu_length,... (pose "a=1;b=2").
// moment_arms.csv: muscle,coordinate,value,moment_arm.
std::vector<ReferenceRow> ReadReference(const std::string& file, bool kinetics) {
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  std::vector<ReferenceRow> rows;
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    const std::vector<std::string> fields = SplitOn(line, ',');
    ReferenceRow row;
    row.muscle = fields.at(0);
    if (kinetics) {
      for (const std::string& setting : SplitOn(fields.at(2), ';')) {
        const std::vector<std::string> name_value = SplitOn(setting, '=');
        row.pose.emplace_back(name_value.at(0), std::stod(name_value.at(1)));
      }
      row.value = std::stod(fields.at(3));
    } else {
      row.pose.emplace_back(fields.at(1), std::stod(fields.at(2)));
      row.value = std::stod(fields.at(3));
    }
    rows.push_back(row);
  }
  return rows;
}

// A muscle's path over arm26 at a pose: fixed path points and one wrap object.
class OneWrapPath {
 public:
  OneWrapPath(const model::ModelSpec& spec, const std::string& muscle)
      : spec_(spec), tree_(spec), X_GB_(tree_.num_bodies()) {
    for (const model::ForceSpec& force : spec.forces) {
      if (force.name == muscle) path_ = &*force.geometry_path;
    }
    EXPECT_NE(path_, nullptr) << muscle;
    EXPECT_EQ(path_->wraps.size(), 1u);
    for (const model::BodySpec& body : spec.bodies) {
      for (const model::WrapObjectSpec& wrap : body.wrap_objects) {
        if (wrap.name == path_->wraps.at(0).wrap_object) wrap_ = &wrap;
      }
    }
    EXPECT_NE(wrap_, nullptr);
    surface_ = MakeWrapSurface(*wrap_);
    for (const model::PathPointSpec& point : path_->points) EXPECT_EQ(point.type, "PathPoint");
  }

  // The path length (m) at `q`; with `frozen`, the tangent points (fixed in the wrap object's
  // body) and arc of the wrap found at `frozen_q` are kept instead of wrapping again.
  double Length(const std::vector<double>& q, const std::vector<double>* frozen_q = nullptr) {
    // Tangent points and arc in the wrap body, and the segment wrapped, from the wrap pose.
    kinematics::CalcBodyPoses(tree_, frozen_q ? *frozen_q : q, X_GB_);
    const Transform X_GW = X_GB_[wrap_->body] * wrap_->X_BW;
    std::vector<Vec3> p_W;
    for (const model::PathPointSpec& point : path_->points) {
      p_W.push_back(X_GW.Inverse() * (X_GB_[point.body] * point.location));
    }
    int wrapped_segment = -1;
    WrapResult result;
    for (size_t i = 0; i + 1 < p_W.size() && wrapped_segment < 0; ++i) {
      result = surface_->Wrap(p_W[i], p_W[i + 1], WrapOptions{});
      if (result.wrapped) {
        EXPECT_TRUE(result.mandatory);  // an unconstrained cylinder's wraps are mandatory
        wrapped_segment = static_cast<int>(i);
      }
    }
    last_wrapped_ = wrapped_segment >= 0;
    // How much longer the wrapped segment is than the cylinder's geodesic (0 when unwrapped).
    geodesic_excess_ = 0.0;
    if (last_wrapped_) {
      const Vec3& p = p_W[wrapped_segment];
      const Vec3& s = p_W[wrapped_segment + 1];
      const double radius = dynamic_cast<const WrapCylinder&>(*surface_).radius();
      geodesic_excess_ =
          testing::PathLength(p, s, result) - testing::CylinderGeodesicLength(p, s, radius);
    }
    // The path at q, through the tangent points fixed on the wrap object's body.
    kinematics::CalcBodyPoses(tree_, q, X_GB_);
    const Transform X_GW_q = X_GB_[wrap_->body] * wrap_->X_BW;
    std::vector<Vec3> p_G;
    for (size_t i = 0; i < path_->points.size(); ++i) {
      const model::PathPointSpec& point = path_->points[i];
      p_G.push_back(X_GB_[point.body] * point.location);
      if (static_cast<int>(i) == wrapped_segment) {
        p_G.push_back(X_GW_q * result.p_WT1);
        p_G.push_back(X_GW_q * result.p_WT2);
      }
    }
    double length = wrapped_segment >= 0 ? result.arc_length : 0.0;
    for (size_t i = 0; i + 1 < p_G.size(); ++i) {
      const bool on_surface = wrapped_segment >= 0 && i == static_cast<size_t>(wrapped_segment) + 1;
      if (!on_surface) length += (p_G[i + 1] - p_G[i]).norm();
    }
    return length;
  }

  std::vector<double> Pose(const std::vector<std::pair<std::string, double>>& settings) const {
    std::vector<double> q = tree_.default_q();
    for (const auto& [name, value] : settings) {
      const int index = CoordinateIndex(name);
      EXPECT_GE(index, 0) << name;
      if (index >= 0) q[index] = value;
    }
    return q;
  }

  bool last_wrapped() const { return last_wrapped_; }
  double geodesic_excess() const { return geodesic_excess_; }
  int CoordinateIndex(const std::string& name) const {
    for (size_t i = 0; i < spec_.coordinates.size(); ++i) {
      if (spec_.coordinates[i].name == name) return static_cast<int>(i);
    }
    return -1;
  }

 private:
  const model::ModelSpec& spec_;
  kinematics::KinematicTree tree_;
  std::vector<Transform> X_GB_;
  const model::GeometryPathSpec* path_ = nullptr;
  const model::WrapObjectSpec* wrap_ = nullptr;
  std::unique_ptr<WrapSurface> surface_;
  bool last_wrapped_ = false;
  double geodesic_excess_ = 0.0;
};

class Arm26ElbowCylinderTest : public ::testing::TestWithParam<std::string> {
 protected:
  static void SetUpTestSuite() {
    spec_ = new model::ModelSpec(io::ReadOsim(kMyoConverter + "models/osim/Arm26/arm26.osim"));
  }
  static void TearDownTestSuite() {
    delete spec_;
    spec_ = nullptr;
  }
  static model::ModelSpec* spec_;
};
model::ModelSpec* Arm26ElbowCylinderTest::spec_ = nullptr;

TEST_P(Arm26ElbowCylinderTest, LengthsMatchOpenSim) {
  OneWrapPath path(*spec_, GetParam());
  int compared = 0;
  int wrapped = 0;
  double worst = 0.0;
  double worst_geodesic = 0.0;
  for (const ReferenceRow& row :
       ReadReference(kMyoConverter + "reference-csv/Arm26/muscle_kinetics.csv", true)) {
    if (row.muscle != GetParam()) continue;
    const double length = path.Length(path.Pose(row.pose));
    worst = std::max(worst, std::abs(length - row.value));
    // The same path with the wrapped segment replaced by the exact geodesic.
    worst_geodesic =
        std::max(worst_geodesic, std::abs(length - path.geodesic_excess() - row.value));
    // The table prints 10 significant digits: half a unit of the last is 5e-11 m at these
    // lengths; twice that allows for our own rounding.
    EXPECT_NEAR(length, row.value, 1e-10)
        << row.pose.front().first << " = " << row.pose.front().second;
    ++compared;
    wrapped += path.last_wrapped() ? 1 : 0;
  }
  EXPECT_EQ(compared, 15);
  EXPECT_GT(wrapped, 0);  // the cylinder is used at some of the poses
  // The table tells OpenSim's construction from the exact geodesic, which is off by microns.
  EXPECT_GT(worst_geodesic, 100 * 1e-9);
  std::cout << GetParam() << ": " << compared << " lengths, " << wrapped
            << " wrapped, worst difference " << worst
            << " m (with the exact geodesic instead: " << worst_geodesic << " m)\n";
}

TEST_P(Arm26ElbowCylinderTest, MomentArmsMatchOpenSimWithTangentPointsFixedOnTheBone) {
  // OpenSim's moment arm is -dL/dq with the path's straight segments pulling on the bodies,
  // i.e. the tangent points carried rigidly by the wrap object's body (the contract's rule).
  // Central differences with h = 1e-6 rad: truncation ~1e-13 m, rounding 1e-16 * 0.2 m / h
  // ~ 4e-11 m, and the table's last printed digit 1e-12 m: 2e-10 bounds them all.
  OneWrapPath path(*spec_, GetParam());
  const double h = 1e-6;
  int compared = 0;
  double worst = 0.0;
  double worst_rewrapped = 0.0;
  for (const ReferenceRow& row :
       ReadReference(kMyoConverter + "reference-csv/Arm26/moment_arms.csv", false)) {
    if (row.muscle != GetParam()) continue;
    const std::vector<double> q = path.Pose(row.pose);
    const int coordinate = path.CoordinateIndex(row.pose.front().first);
    std::vector<double> plus = q, minus = q;
    plus[coordinate] += h;
    minus[coordinate] -= h;
    const double moment_arm = -(path.Length(plus, &q) - path.Length(minus, &q)) / (2 * h);
    worst = std::max(worst, std::abs(moment_arm - row.value));
    // For comparison, -dL/dq of the length wrapped afresh at each q: differs from OpenSim's
    // moment arm by the first-order term of OpenSim's tangent-point construction.
    const double rewrapped = -(path.Length(plus) - path.Length(minus)) / (2 * h);
    worst_rewrapped = std::max(worst_rewrapped, std::abs(rewrapped - row.value));
    EXPECT_NEAR(moment_arm, row.value, 2e-10) << row.pose.front().second;
    ++compared;
  }
  EXPECT_EQ(compared, 25);
  std::cout << GetParam() << ": " << compared << " moment arms, worst difference " << worst
            << " m (-dL/dq of the length wrapped afresh: " << worst_rewrapped << " m)\n";
}

INSTANTIATE_TEST_SUITE_P(SingleCylinder, Arm26ElbowCylinderTest,
                         ::testing::Values("TRIlat", "TRImed", "BRA"));

}  // namespace
}  // namespace sinew::paths
