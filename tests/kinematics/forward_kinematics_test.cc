// Forward kinematics on hand-built models: poses derived by hand, reversed joints, and body
// velocities against finite differences of the poses.
#include <gtest/gtest.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/math/rotation.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "kinematics/test_functions.h"

namespace sinew {
namespace {

int AddBody(model::ModelSpec& spec, const std::string& name, const Vec3& mass_center) {
  model::BodySpec b;
  b.name = name;
  b.path = "/bodyset/" + name;
  b.mass = 1.0;
  b.mass_center = mass_center;
  spec.bodies.push_back(b);
  return static_cast<int>(spec.bodies.size()) - 1;
}

int AddJoint(model::ModelSpec& spec, const std::string& name, model::JointType kind, int parent,
             int child, const Transform& X_PF, const Transform& X_BM, int num_coordinates) {
  model::JointSpec j;
  j.name = name;
  j.path = "/jointset/" + name;
  j.kind = kind;
  j.type = name;
  j.parent_body = parent;
  j.child_body = child;
  j.X_PF = X_PF;
  j.X_BM = X_BM;
  for (int i = 0; i < num_coordinates; ++i) {
    model::CoordinateSpec c;
    c.name = name + "_q" + std::to_string(i);
    c.joint = static_cast<int>(spec.joints.size());
    j.coordinates.push_back(static_cast<int>(spec.coordinates.size()));
    spec.coordinates.push_back(c);
  }
  spec.joints.push_back(j);
  return static_cast<int>(spec.joints.size()) - 1;
}

// OpenSim's double pendulum: pins about z, each rod hangs 0.5 m below its pin (child frame at
// y = +0.5 in the rod), mass centres at the rod origins.
model::ModelSpec DoublePendulum(bool reverse_second) {
  model::ModelSpec spec;
  AddBody(spec, "ground", Vec3::Zero());
  const int rod1 = AddBody(spec, "rod1", Vec3::Zero());
  const int rod2 = AddBody(spec, "rod2", Vec3::Zero());
  const Transform pin_in_rod = Transform::Translation(Vec3(0, 0.5, 0));
  AddJoint(spec, "pin1", model::JointType::kPin, 0, rod1, Transform(), pin_in_rod, 1);
  if (reverse_second) {
    // As OpenSim 4 reads a 3.x joint with reverse=true: parent and child frames swapped.
    AddJoint(spec, "pin2", model::JointType::kPin, rod2, rod1, pin_in_rod, Transform(), 1);
  } else {
    AddJoint(spec, "pin2", model::JointType::kPin, rod1, rod2, Transform(), pin_in_rod, 1);
  }
  return spec;
}

TEST(ForwardKinematicsTest, DoublePendulumByHand) {
  const model::ModelSpec spec = DoublePendulum(false);
  const kinematics::KinematicTree tree(spec);
  const double q1 = -0.78539816, q2 = -1.04719755;
  const std::vector<double> q = {q1, q2};
  std::vector<Transform> X(3);
  kinematics::CalcBodyPoses(tree, q, X);
  // rod1 origin 0.5 m from the pivot along its -y axis, rotated by q1; rod2 likewise from
  // rod1's origin, rotated by q1 + q2.
  const Vec3 p1(0.5 * std::sin(q1), -0.5 * std::cos(q1), 0);
  const Vec3 p2 = p1 + Vec3(0.5 * std::sin(q1 + q2), -0.5 * std::cos(q1 + q2), 0);
  EXPECT_TRUE(X[1].p.isApprox(p1, 1e-15));
  EXPECT_TRUE(X[2].p.isApprox(p2, 1e-15));
  EXPECT_TRUE(X[2].R.isApprox(RotationAboutAxis(Vec3::UnitZ(), q1 + q2), 1e-15));
}

TEST(ForwardKinematicsTest, ReversedJointInvertsItsTransform) {
  // With parent and child swapped, X_FM(q) maps rod2's frame to rod1's: rod2 turns by -q2.
  const kinematics::KinematicTree forward(DoublePendulum(false)), reversed(DoublePendulum(true));
  ASSERT_TRUE(reversed.joints()[1].reversed);
  ASSERT_FALSE(forward.joints()[1].reversed);
  std::vector<Transform> Xf(3), Xr(3);
  const std::vector<double> qf = {0.3, -0.9}, qr = {0.3, 0.9};
  kinematics::CalcBodyPoses(forward, qf, Xf);
  kinematics::CalcBodyPoses(reversed, qr, Xr);
  for (int b = 0; b < 3; ++b) EXPECT_TRUE(Xf[b].isApprox(Xr[b], 1e-14)) << b;
}

// A chain with every kind of joint, one of them reversed, and a CustomJoint.
model::ModelSpec MixedChain() {
  model::ModelSpec spec;
  AddBody(spec, "ground", Vec3::Zero());
  const Transform X1(RotationFromBodyFixedXYZ(Vec3(0.1, 0.2, -0.3)), Vec3(0.1, -0.2, 0.05));
  const Transform X2(RotationFromBodyFixedXYZ(Vec3(-0.4, 0.3, 0.2)), Vec3(-0.05, 0.3, 0.1));
  int prev = 0;
  const std::vector<std::pair<model::JointType, int>> kinds = {
      {model::JointType::kFree, 6},      {model::JointType::kBall, 3},
      {model::JointType::kPin, 1},       {model::JointType::kGimbal, 3},
      {model::JointType::kEllipsoid, 3}, {model::JointType::kUniversal, 2},
      {model::JointType::kPlanar, 3},    {model::JointType::kCustom, 2},
      {model::JointType::kSlider, 1}};
  for (size_t i = 0; i < kinds.size(); ++i) {
    const int body = AddBody(spec, "b" + std::to_string(i), Vec3(0.01, 0.02 * i, -0.03));
    const bool reverse = (i == 2 || i == 5);
    const int j = reverse ? AddJoint(spec, "j" + std::to_string(i), kinds[i].first, body, prev, X2,
                                     X1, kinds[i].second)
                          : AddJoint(spec, "j" + std::to_string(i), kinds[i].first, prev, body, X1,
                                     X2, kinds[i].second);
    model::JointSpec& joint = spec.joints[j];
    if (kinds[i].first == model::JointType::kEllipsoid)
      joint.parameters["radii_x_y_z"] = {0.1, 0.2, 0.15};
    if (kinds[i].first == model::JointType::kCustom) {
      using testing::TestConstantFunction;
      using testing::TestSmoothFunction;
      const int c0 = joint.coordinates[0], c1 = joint.coordinates[1];
      auto axis = [](const char* name, Vec3 a, std::vector<int> c, functions::FunctionPtr f) {
        model::TransformAxisSpec t;
        t.name = name;
        t.axis = a;
        t.coordinates = std::move(c);
        t.function = std::move(f);
        return t;
      };
      auto zero = std::make_shared<TestConstantFunction>(0.0);
      joint.spatial_transform = {
          axis("rotation1", Vec3(0, 0, 1), {c0}, std::make_shared<TestSmoothFunction>(0, 1, 0, 0)),
          axis("rotation2", Vec3(1, 0, 0), {c0},
               std::make_shared<TestSmoothFunction>(0, .2, .1, .3)),
          axis("rotation3", Vec3(0, 1, 0), {}, zero),
          axis("translation1", Vec3(1, 0, 0), {c0},
               std::make_shared<TestSmoothFunction>(0, .01, .02, -.01)),
          axis("translation2", Vec3(0, 1, 0), {c1},
               std::make_shared<TestSmoothFunction>(0, 1, 0, 0)),
          axis("translation3", Vec3(0, 0, 1), {}, zero)};
    }
    prev = body;
  }
  return spec;
}

TEST(ForwardKinematicsTest, BodyVelocitiesMatchFiniteDifferencesOfPoses) {
  const model::ModelSpec spec = MixedChain();
  const kinematics::KinematicTree tree(spec);
  const int nb = tree.num_bodies(), nq = tree.num_coordinates();
  std::vector<double> q(nq), u(nq), qdot(nq);
  for (int i = 0; i < nq; ++i) {
    q[i] = 0.5 * std::sin(1.7 * i + 0.3);
    u[i] = 0.8 * std::cos(0.9 * i + 0.1);
  }
  // qdot = N(q) u joint by joint.
  for (const kinematics::TreeJoint& t : tree.joints()) {
    double ql[6], ul[6], qdl[6];
    for (int k = 0; k < t.nq; ++k) {
      ql[k] = q[t.q_index[k]];
      ul[k] = u[t.q_index[k]];
    }
    t.model->CalcQDot(std::span<const double>(ql, t.nq), std::span<const double>(ul, t.nq),
                      std::span<double>(qdl, t.nq));
    for (int k = 0; k < t.nq; ++k) qdot[t.q_index[k]] = qdl[k];
  }
  std::vector<Transform> X(nb), Xp(nb), Xm(nb);
  std::vector<SpatialVec> V(nb);
  kinematics::CalcBodyPoses(tree, q, X);
  kinematics::CalcBodyVelocities(tree, q, u, X, V);
  const double h = 1e-6;
  std::vector<double> qp(q), qm(q);
  for (int i = 0; i < nq; ++i) {
    qp[i] += h * qdot[i];
    qm[i] -= h * qdot[i];
  }
  kinematics::CalcBodyPoses(tree, qp, Xp);
  kinematics::CalcBodyPoses(tree, qm, Xm);
  for (int b = 1; b < nb; ++b) {
    const Mat3 W = (Xp[b].R - Xm[b].R) / (2 * h) * X[b].R.transpose();
    const Vec3 w(0.5 * (W(2, 1) - W(1, 2)), 0.5 * (W(0, 2) - W(2, 0)), 0.5 * (W(1, 0) - W(0, 1)));
    const Vec3 v = (Xp[b].p - Xm[b].p) / (2 * h);
    // Truncation h^2 |X'''| ~ 1e-12 and rounding 1e-16 / h ~ 1e-10.
    EXPECT_LT((V[b].head<3>() - w).norm(), 1e-8) << spec.bodies[b].name;
    EXPECT_LT((V[b].tail<3>() - v).norm(), 1e-8) << spec.bodies[b].name;
    // A station's velocity agrees with the same differences.
    const Vec3 s(0.1, -0.2, 0.3);
    const Vec3 vs = (Xp[b] * s - Xm[b] * s) / (2 * h);
    EXPECT_LT((kinematics::CalcStationVelocity(X[b], V[b], s) - vs).norm(), 1e-8);
  }
}

// The velocity columns (one unit speed at a time) are the velocities of those unit speeds, and
// their combination with u the velocities of u, on the mixed chain and across a reversed joint.
TEST(ForwardKinematicsTest, VelocityColumnsAreTheVelocitiesOfUnitSpeeds) {
  for (const model::ModelSpec& spec : {MixedChain(), DoublePendulum(true)}) {
    const kinematics::KinematicTree tree(spec);
    const int nb = tree.num_bodies(), nq = tree.num_coordinates();
    std::vector<double> q(nq), u(nq);
    for (int i = 0; i < nq; ++i) {
      q[i] = 0.5 * std::sin(1.7 * i + 0.3);
      u[i] = 0.8 * std::cos(0.9 * i + 0.1);
    }
    std::vector<Transform> X(nb);
    kinematics::CalcBodyPoses(tree, q, X);
    std::vector<SpatialVec> columns(static_cast<size_t>(nb * nq)), V(nb), combined(nb);
    kinematics::CalcBodyVelocityColumns(tree, q, X, columns);
    for (auto& v : combined) v.setZero();
    for (int k = 0; k < nq; ++k) {
      std::vector<double> unit(nq, 0.0);
      unit[k] = 1.0;
      kinematics::CalcBodyVelocities(tree, q, unit, X, V);
      for (int b = 0; b < nb; ++b) {
        // The same sums in another order: rounding (velocities of order 1).
        EXPECT_LT((columns[k * nb + b] - V[b]).norm(), 1e-14) << k << " " << b;
        combined[b] += u[k] * columns[k * nb + b];
      }
    }
    kinematics::CalcBodyVelocities(tree, q, u, X, V);
    for (int b = 0; b < nb; ++b) EXPECT_LT((combined[b] - V[b]).norm(), 1e-14) << b;
  }
}

// The support columns are the dense columns where these are not zero: body b's column k is
// the same arithmetic in both for every k of tree.support(b), and the dense column is zero at
// b for every other k (that speed moves no joint between b and ground).
TEST(ForwardKinematicsTest, SupportColumnsAreTheNonzeroVelocityColumns) {
  for (const model::ModelSpec& spec : {MixedChain(), DoublePendulum(true)}) {
    const kinematics::KinematicTree tree(spec);
    const int nb = tree.num_bodies(), nq = tree.num_coordinates();
    std::vector<double> q(nq);
    for (int i = 0; i < nq; ++i) q[i] = 0.5 * std::sin(1.7 * i + 0.3);
    std::vector<Transform> X(nb);
    kinematics::CalcBodyPoses(tree, q, X);
    std::vector<SpatialVec> dense(static_cast<size_t>(nb * nq));
    std::vector<SpatialVec> support(static_cast<size_t>(tree.support_offset(nb)));
    kinematics::CalcBodyVelocityColumns(tree, q, X, dense);
    kinematics::CalcSupportVelocityColumns(tree, q, X, support);
    EXPECT_TRUE(tree.support(model::kGroundIndex).empty());
    for (int b = 0; b < nb; ++b) {
      const std::span<const int> coordinates = tree.support(b);
      for (int k = 0; k < nq; ++k) {
        const auto at = std::find(coordinates.begin(), coordinates.end(), k);
        const SpatialVec& V = dense[k * nb + b];
        if (at == coordinates.end()) {
          EXPECT_TRUE(V.isZero(0.0)) << k << " " << b;
        } else {
          EXPECT_EQ(V, support[tree.support_offset(b) + (at - coordinates.begin())])
              << k << " " << b;
        }
      }
    }
    // Filled for the last body only (and so its inboard ones): the same columns there, and
    // the joints listed are those between it and ground.
    const int last = tree.joints().back().outboard;
    const std::vector<int> joints = kinematics::ListJointsToBodies(tree, std::vector<int>{last});
    EXPECT_EQ(joints.back(), static_cast<int>(tree.joints().size()) - 1);
    EXPECT_TRUE(std::is_sorted(joints.begin(), joints.end()));
    std::vector<SpatialVec> some(support.size(), SpatialVec::Constant(std::nan("")));
    kinematics::CalcSupportVelocityColumns(tree, q, X, some, joints);
    for (int i = 0; i < static_cast<int>(tree.support(last).size()); ++i) {
      EXPECT_EQ(some[tree.support_offset(last) + i], support[tree.support_offset(last) + i]);
    }
  }
}

TEST(ForwardKinematicsTest, MassCentresAndMarkers) {
  model::ModelSpec spec = DoublePendulum(false);
  spec.bodies[2].mass_center = Vec3(0.1, 0, 0);
  model::MarkerSpec m;
  m.name = "tip";
  m.body = 2;
  m.location = Vec3(0, -0.5, 0);
  spec.markers.push_back(m);
  const kinematics::KinematicTree tree(spec);
  std::vector<Transform> X(3);
  const std::vector<double> q = {0.0, std::acos(-1.0) / 2};
  kinematics::CalcBodyPoses(tree, q, X);
  // rod1 hangs at (0, -0.5); rod2 turned 90 deg: its -y axis points along +x.
  const std::vector<Vec3> com = kinematics::CalcMassCenterLocations(spec, X);
  EXPECT_TRUE(com[2].isApprox(Vec3(0.5, -0.5, 0) + Vec3(0, 0.1, 0), 1e-15));
  const std::vector<Vec3> markers = kinematics::CalcMarkerLocations(spec, X);
  EXPECT_TRUE(markers[0].isApprox(Vec3(1.0, -0.5, 0), 1e-15));
}

TEST(KinematicTreeTest, DisconnectedBodyIsAnErrorAndLoopJointsAreListed) {
  model::ModelSpec spec = DoublePendulum(false);
  AddBody(spec, "floating", Vec3::Zero());
  spec.bodies.back().where = {"m.osim", 7};
  try {
    kinematics::KinematicTree tree(spec);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 7);
    EXPECT_EQ(e.component(), "/bodyset/floating");
  }
  model::ModelSpec loop = DoublePendulum(false);
  const int closing =
      AddJoint(loop, "closing", model::JointType::kWeld, 2, 0, Transform(), Transform(), 0);
  const kinematics::KinematicTree tree(loop);
  EXPECT_EQ(tree.loop_joints(), std::vector<int>{closing});
  EXPECT_EQ(tree.joints().size(), 2u);  // the loop joint places nothing
}

}  // namespace
}  // namespace sinew
