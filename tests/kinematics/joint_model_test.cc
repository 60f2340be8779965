// Every joint type: X_FM against hand-derived values, and H_FM, N(q) and Hdot*u against
// central finite differences of X_FM along the motion qdot = N(q) u.
#include <gtest/gtest.h>
#include <sinew/functions/linear_function.h>
#include <sinew/kinematics/joint_model.h>
#include <sinew/math/rotation.h>

#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "kinematics/test_functions.h"

namespace sinew {
namespace {

using sinew::testing::TestConstantFunction;
using sinew::testing::TestLinearFunction;
using sinew::testing::TestSmoothFunction;
using sinew::testing::TestTwoArgFunction;

// A model with ground, one body and one joint of `kind` with `n` coordinates.
model::ModelSpec MakeSpec(model::JointType kind, const std::string& type, int n) {
  model::ModelSpec spec;
  spec.bodies.resize(2);
  spec.bodies[0].name = "ground";
  spec.bodies[1].name = "body";
  model::JointSpec joint;
  joint.name = "joint";
  joint.path = "/jointset/joint";
  joint.type = type;
  joint.kind = kind;
  joint.parent_body = 0;
  joint.child_body = 1;
  for (int i = 0; i < n; ++i) {
    model::CoordinateSpec c;
    c.name = "q" + std::to_string(i);
    c.joint = 0;
    spec.coordinates.push_back(c);
    joint.coordinates.push_back(i);
  }
  spec.joints.push_back(joint);
  return spec;
}

model::TransformAxisSpec Axis(const std::string& name, Vec3 axis, std::vector<int> coords,
                              functions::FunctionPtr f) {
  model::TransformAxisSpec a;
  a.name = name;
  a.axis = axis;
  a.coordinates = std::move(coords);
  a.function = std::move(f);
  return a;
}

// A CustomJoint with oblique axes, a one-argument nonlinear function, a two-argument coupling,
// a constant and linear functions of slope -1.
model::ModelSpec MakeCustomSpec() {
  model::ModelSpec spec = MakeSpec(model::JointType::kCustom, "CustomJoint", 3);
  auto& st = spec.joints[0].spatial_transform;
  st.push_back(Axis("rotation1", Vec3(1, 0.2, 0), {0},
                    std::make_shared<TestSmoothFunction>(0.1, 0.9, 0.2, 0.3)));
  st.push_back(Axis("rotation2", Vec3(0, 1, 0.3), {0, 1}, std::make_shared<TestTwoArgFunction>()));
  st.push_back(
      Axis("rotation3", Vec3(0.1, 0, 1), {2}, std::make_shared<TestLinearFunction>(1.0, 0.0)));
  st.push_back(Axis("translation1", Vec3(1, 0, 0), {1},
                    std::make_shared<TestSmoothFunction>(0.01, 0.05, -0.02, 0.01)));
  st.push_back(
      Axis("translation2", Vec3(0, 2, 0), {}, std::make_shared<TestConstantFunction>(0.05)));
  st.push_back(
      Axis("translation3", Vec3(0, 0.3, 1), {2}, std::make_shared<TestLinearFunction>(-1.0, 0.01)));
  return spec;
}

// A CustomJoint on F's coordinate axes (as in most OpenSim models: elementary rotations) with
// a constant nonzero rotation first, a nonlinear function and a coordinate.
model::ModelSpec MakeCustomCoordinateAxesSpec() {
  model::ModelSpec spec = MakeSpec(model::JointType::kCustom, "CustomJoint", 2);
  auto& st = spec.joints[0].spatial_transform;
  st.push_back(Axis("rotation1", Vec3(0, 1, 0), {}, std::make_shared<TestConstantFunction>(0.4)));
  st.push_back(Axis("rotation2", Vec3(0, 0, 1), {0},
                    std::make_shared<TestSmoothFunction>(0.1, 0.9, 0.2, 0.3)));
  st.push_back(
      Axis("rotation3", Vec3(1, 0, 0), {1}, std::make_shared<TestLinearFunction>(1.0, 0.0)));
  st.push_back(Axis("translation1", Vec3(1, 0, 0), {0},
                    std::make_shared<TestSmoothFunction>(0.01, 0.05, -0.02, 0.01)));
  st.push_back(
      Axis("translation2", Vec3(0, 1, 0), {}, std::make_shared<TestConstantFunction>(0.0)));
  st.push_back(
      Axis("translation3", Vec3(0, 0, 1), {1}, std::make_shared<TestLinearFunction>(-1.0, 0.01)));
  return spec;
}

// MakeCustomSpec with its linear axes (and an affine rotation) given as the library's
// LinearFunction, which CustomJointModel evaluates inline instead of through the function; with
// `through_function`, the same axes as a test function of the same values, evaluated through it.
model::ModelSpec MakeCustomLinearSpec(bool through_function) {
  model::ModelSpec spec = MakeCustomSpec();
  auto& st = spec.joints[0].spatial_transform;
  const auto linear = [&](double slope, double intercept) -> functions::FunctionPtr {
    if (through_function) return std::make_shared<TestLinearFunction>(slope, intercept);
    return std::make_shared<functions::LinearFunction>(slope, intercept);
  };
  st[2].function = linear(0.8, 0.1);
  st[5].function = linear(-1.5, 0.02);
  st[4].coordinates = {0};
  st[4].function = linear(1.0, 0.0);
  return spec;
}

struct JointCase {
  std::string name;
  model::ModelSpec spec;
};

std::vector<JointCase> AllJointCases() {
  std::vector<JointCase> cases;
  cases.push_back({"Pin", MakeSpec(model::JointType::kPin, "PinJoint", 1)});
  cases.push_back({"Slider", MakeSpec(model::JointType::kSlider, "SliderJoint", 1)});
  cases.push_back({"Universal", MakeSpec(model::JointType::kUniversal, "UniversalJoint", 2)});
  cases.push_back({"Gimbal", MakeSpec(model::JointType::kGimbal, "GimbalJoint", 3)});
  cases.push_back({"Ball", MakeSpec(model::JointType::kBall, "BallJoint", 3)});
  cases.push_back({"Free", MakeSpec(model::JointType::kFree, "FreeJoint", 6)});
  cases.push_back({"Planar", MakeSpec(model::JointType::kPlanar, "PlanarJoint", 3)});
  JointCase ellipsoid{"Ellipsoid", MakeSpec(model::JointType::kEllipsoid, "EllipsoidJoint", 3)};
  ellipsoid.spec.joints[0].parameters["radii_x_y_z"] = {0.07, 0.15, 0.09};
  cases.push_back(ellipsoid);
  JointCase scap{"Scapulothoracic",
                 MakeSpec(model::JointType::kScapulothoracic, "ScapulothoracicJoint", 4)};
  scap.spec.joints[0].parameters["thoracic_ellipsoid_radii_x_y_z"] = {0.07, 0.15, 0.09};
  scap.spec.joints[0].parameters["scapula_winging_axis_origin"] = {0.02, -0.03};
  scap.spec.joints[0].parameters["scapula_winging_axis_direction"] = {0.4};
  cases.push_back(scap);
  cases.push_back({"Custom", MakeCustomSpec()});
  cases.push_back({"CustomCoordinateAxes", MakeCustomCoordinateAxesSpec()});
  cases.push_back({"CustomLinearFunctions", MakeCustomLinearSpec(false)});
  return cases;
}

// Spatial velocity of M in F, in F, by central differences of X_FM along qdot.
SpatialVec NumericVelocity(const kinematics::JointModel& joint, const std::vector<double>& q,
                           const std::vector<double>& qdot, double h) {
  std::vector<double> qp(q), qm(q);
  for (size_t i = 0; i < q.size(); ++i) {
    qp[i] += h * qdot[i];
    qm[i] -= h * qdot[i];
  }
  const Transform Xp = joint.CalcX_FM(qp), Xm = joint.CalcX_FM(qm), X = joint.CalcX_FM(q);
  const Mat3 W = (Xp.R - Xm.R) / (2 * h) * X.R.transpose();  // [w]x
  SpatialVec V;
  V << 0.5 * (W(2, 1) - W(1, 2)), 0.5 * (W(0, 2) - W(2, 0)), 0.5 * (W(1, 0) - W(0, 1)),
      (Xp.p - Xm.p) / (2 * h);
  return V;
}

std::vector<double> Sample(int n, double scale, double phase) {
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = scale * std::sin(1.3 * i + phase) + 0.1 * scale;
  return v;
}

class JointModelTest : public ::testing::TestWithParam<int> {};

TEST_P(JointModelTest, VelocityMapMatchesFiniteDifferences) {
  const JointCase c = AllJointCases()[GetParam()];
  const auto joint = kinematics::MakeJointModel(c.spec, 0);
  const int n = joint->nq();
  for (int trial = 0; trial < 4; ++trial) {
    const std::vector<double> q = Sample(n, 0.7, 0.4 + trial);
    const std::vector<double> u = Sample(n, 1.1, 2.0 + 0.7 * trial);
    std::vector<double> qdot(n), u_back(n);
    joint->CalcQDot(q, u, qdot);
    joint->CalcU(q, qdot, u_back);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(u_back[i], u[i], 1e-12) << c.name;
    // A model that lets callers skip CalcQDot (constraints take N = I, Ndot u = 0) must mean it.
    if (joint->QDotIsU()) {
      for (int i = 0; i < n; ++i) EXPECT_EQ(qdot[i], u[i]) << c.name;
    }

    const Mat6X H = joint->CalcH_FM(q);
    ASSERT_EQ(H.cols(), n) << c.name;
    const Eigen::Map<const VecX> u_vec(u.data(), n);
    const SpatialVec V = H * u_vec;
    EXPECT_LT((joint->CalcV_FM(q, u) - V).norm(), 1e-14) << c.name;
    // Central differences with h = 1e-5: truncation ~h^2 |X'''| ~ 1e-10, rounding ~1e-11.
    const SpatialVec V_num = NumericVelocity(*joint, q, qdot, 1e-5);
    EXPECT_LT((V - V_num).norm(), 1e-8)
        << c.name << "\nH u = " << V.transpose() << "\nnumeric = " << V_num.transpose();
  }
}

TEST_P(JointModelTest, BiasAccelerationMatchesFiniteDifferences) {
  const JointCase c = AllJointCases()[GetParam()];
  const auto joint = kinematics::MakeJointModel(c.spec, 0);
  const int n = joint->nq();
  for (int trial = 0; trial < 4; ++trial) {
    const std::vector<double> q = Sample(n, 0.6, 1.0 + trial);
    const std::vector<double> u = Sample(n, 0.9, 0.3 + 0.5 * trial);
    std::vector<double> qdot(n);
    joint->CalcQDot(q, u, qdot);
    // With udot = 0, A = d/dt (H(q(t)) u) = dH/dq[qdot] u: central differences along qdot.
    const double h = 1e-5;
    std::vector<double> qp(q), qm(q);
    for (int i = 0; i < n; ++i) {
      qp[i] += h * qdot[i];
      qm[i] -= h * qdot[i];
    }
    const Eigen::Map<const VecX> u_vec(u.data(), n);
    const SpatialVec A_num =
        n == 0 ? SpatialVec(SpatialVec::Zero())
               : SpatialVec((joint->CalcH_FM(qp) * u_vec - joint->CalcH_FM(qm) * u_vec) / (2 * h));
    const SpatialVec A = joint->CalcHDotU(q, u);
    EXPECT_LT((A - A_num).norm(), 1e-8)
        << c.name << "\nHdot u = " << A.transpose() << "\nnumeric = " << A_num.transpose();
  }
}

// Every joint with coordinates (WeldJoint has none: WeldIsTheIdentityWithNoSpeeds below).
INSTANTIATE_TEST_SUITE_P(AllJoints, JointModelTest,
                         ::testing::Range(0, static_cast<int>(AllJointCases().size())),
                         [](const ::testing::TestParamInfo<int>& param_info) {
                           return AllJointCases()[param_info.param].name;
                         });

// ---- X_FM against hand-derived values ----

Mat3 Rot(const Vec3& axis, double angle) { return RotationAboutAxis(axis, angle); }

TEST(JointTransformTest, PinRotatesAboutZ) {
  const auto joint = kinematics::MakeJointModel(MakeSpec(model::JointType::kPin, "PinJoint", 1), 0);
  const double q[] = {0.5};
  const Transform X = joint->CalcX_FM(q);
  Mat3 R;
  R << std::cos(0.5), -std::sin(0.5), 0, std::sin(0.5), std::cos(0.5), 0, 0, 0, 1;
  EXPECT_TRUE(X.R.isApprox(R, 1e-15));
  EXPECT_EQ(X.p.norm(), 0.0);
}

TEST(JointTransformTest, SliderTranslatesAlongX) {
  const auto joint =
      kinematics::MakeJointModel(MakeSpec(model::JointType::kSlider, "SliderJoint", 1), 0);
  const double q[] = {-0.25};
  const Transform X = joint->CalcX_FM(q);
  EXPECT_TRUE(X.R.isIdentity(0));
  EXPECT_TRUE(X.p.isApprox(Vec3(-0.25, 0, 0), 1e-15));
}

TEST(JointTransformTest, WeldIsTheIdentityWithNoSpeeds) {
  // OpenSim's WeldJoint holds M on F: X_FM is the identity whatever the state (the offsets
  // are in X_PF and X_BM), H_FM has no columns, and the joint adds no velocity or bias.
  const auto joint =
      kinematics::MakeJointModel(MakeSpec(model::JointType::kWeld, "WeldJoint", 0), 0);
  ASSERT_EQ(joint->nq(), 0);
  ASSERT_EQ(joint->nu(), 0);
  const std::span<const double> none;
  const Transform X = joint->CalcX_FM(none);
  EXPECT_EQ(X.R, Mat3::Identity());
  EXPECT_EQ(X.p, Vec3::Zero());
  const Mat6X H = joint->CalcH_FM(none);
  EXPECT_EQ(H.rows(), 6);
  EXPECT_EQ(H.cols(), 0);
  EXPECT_EQ(joint->CalcV_FM(none, none), SpatialVec::Zero());
  EXPECT_EQ(joint->CalcHDotU(none, none), SpatialVec::Zero());
  // A weld given a coordinate is an error.
  EXPECT_THROW(kinematics::MakeJointModel(MakeSpec(model::JointType::kWeld, "WeldJoint", 1), 0),
               Error);
}

TEST(JointTransformTest, UniversalGimbalBallFreeAreBodyFixedXYZ) {
  const double q[] = {0.3, -0.7, 1.2, 0.1, 0.2, 0.3};
  const Mat3 R3 = Rot(Vec3::UnitX(), q[0]) * Rot(Vec3::UnitY(), q[1]) * Rot(Vec3::UnitZ(), q[2]);
  const Mat3 R2 = Rot(Vec3::UnitX(), q[0]) * Rot(Vec3::UnitY(), q[1]);
  EXPECT_TRUE(
      kinematics::MakeJointModel(MakeSpec(model::JointType::kUniversal, "UniversalJoint", 2), 0)
          ->CalcX_FM(q)
          .R.isApprox(R2, 1e-14));
  for (model::JointType kind : {model::JointType::kGimbal, model::JointType::kBall}) {
    const Transform X = kinematics::MakeJointModel(MakeSpec(kind, "J", 3), 0)->CalcX_FM(q);
    EXPECT_TRUE(X.R.isApprox(R3, 1e-14));
    EXPECT_EQ(X.p.norm(), 0.0);
  }
  const Transform X =
      kinematics::MakeJointModel(MakeSpec(model::JointType::kFree, "FreeJoint", 6), 0)->CalcX_FM(q);
  EXPECT_TRUE(X.R.isApprox(R3, 1e-14));
  EXPECT_TRUE(X.p.isApprox(Vec3(0.1, 0.2, 0.3), 1e-15));  // in F, not rotated
}

TEST(JointTransformTest, PlanarRotatesAboutZThenTranslatesInF) {
  const auto joint =
      kinematics::MakeJointModel(MakeSpec(model::JointType::kPlanar, "PlanarJoint", 3), 0);
  const double q[] = {0.8, 0.3, -0.4};
  const Transform X = joint->CalcX_FM(q);
  EXPECT_TRUE(X.R.isApprox(Rot(Vec3::UnitZ(), 0.8), 1e-15));
  EXPECT_TRUE(X.p.isApprox(Vec3(0.3, -0.4, 0), 1e-15));
}

TEST(JointTransformTest, EllipsoidKeepsMOnTheSurfaceWithNormalAlongMz) {
  model::ModelSpec spec = MakeSpec(model::JointType::kEllipsoid, "EllipsoidJoint", 3);
  const Vec3 r(0.07, 0.15, 0.09);
  spec.joints[0].parameters["radii_x_y_z"] = {r.x(), r.y(), r.z()};
  const auto joint = kinematics::MakeJointModel(spec, 0);
  const double q0[] = {0, 0, 0};
  EXPECT_TRUE(joint->CalcX_FM(q0).p.isApprox(Vec3(0, 0, r.z()), 1e-15));
  const double q[] = {0.4, -0.3, 0.9};
  const Transform X = joint->CalcX_FM(q);
  const Vec3 p = X.p;
  EXPECT_NEAR(std::pow(p.x() / r.x(), 2) + std::pow(p.y() / r.y(), 2) + std::pow(p.z() / r.z(), 2),
              1.0, 1e-14);
  EXPECT_TRUE(X.R.isApprox(RotationFromBodyFixedXYZ(Vec3(0.4, -0.3, 0.9)), 1e-14));
}

TEST(JointTransformTest, ScapulothoracicFollowsItsSimbodyConstruction) {
  model::ModelSpec spec = MakeSpec(model::JointType::kScapulothoracic, "ScapulothoracicJoint", 4);
  const Vec3 r(0.07, 0.15, 0.09);
  spec.joints[0].parameters["thoracic_ellipsoid_radii_x_y_z"] = {r.x(), r.y(), r.z()};
  spec.joints[0].parameters["scapula_winging_axis_origin"] = {0.02, -0.03};
  spec.joints[0].parameters["scapula_winging_axis_direction"] = {0.4};
  const auto joint = kinematics::MakeJointModel(spec, 0);
  // q = 0: M sits on the ellipsoid's z pole, axes aligned with F.
  const double q0[] = {0, 0, 0, 0};
  const Transform X0 = joint->CalcX_FM(q0);
  EXPECT_TRUE(X0.R.isApprox(Mat3::Identity(), 1e-15));
  EXPECT_TRUE(X0.p.isApprox(Vec3(0, 0, r.z()), 1e-15));
  // General q, built step by step as the Simbody chain: F0 = F Rz(90), ellipsoid mobilizer
  // with radii (ry, rx, rz), M0 = B1 Rz(90), pin about d through o on both sides, weld.
  const double q[] = {0.3, -0.2, 0.5, 0.25};
  const Transform X_FF0 = Transform::Rotation(Rot(Vec3::UnitZ(), std::numbers::pi / 2));
  const Mat3 R_E = RotationFromBodyFixedXYZ(Vec3(q[0], q[1], q[2]));
  const Transform X_F0M0(R_E, Vec3(r.y() * R_E(0, 2), r.x() * R_E(1, 2), r.z() * R_E(2, 2)));
  const Transform X_B1M0 = Transform::Rotation(Rot(Vec3::UnitZ(), std::numbers::pi / 2));
  const Vec3 d(-std::sin(0.4), std::cos(0.4), 0);
  // Any frame W whose z axis is d (the result does not depend on the other two axes).
  const Vec3 wx = d.cross(Vec3::UnitZ()).normalized();
  Mat3 R_W;
  R_W << wx, d.cross(wx), d;
  const Transform X_B1W(R_W, Vec3(0.02, -0.03, 0));
  const Transform X_pin = Transform::Rotation(Rot(Vec3::UnitZ(), q[3]));
  const Transform X_expected = X_FF0 * X_F0M0 * X_B1M0.Inverse() * X_B1W * X_pin * X_B1W.Inverse();
  EXPECT_TRUE(joint->CalcX_FM(q).isApprox(X_expected, 1e-14));
}

TEST(JointTransformTest, CustomJointComposesBodyFixedRotationsAndUnrotatedTranslations) {
  const model::ModelSpec spec = MakeCustomSpec();
  const auto joint = kinematics::MakeJointModel(spec, 0);
  const double q[] = {0.3, -0.5, 0.8};
  const auto& st = spec.joints[0].spatial_transform;
  const double s1 = st[0].function->Calc(q[0]);
  const double x01[] = {q[0], q[1]};
  const double s2 = st[1].function->CalcN(x01);
  const double s3 = q[2];
  const Mat3 R = Rot(st[0].axis, s1) * Rot(st[1].axis, s2) * Rot(st[2].axis, s3);
  const Vec3 p = st[3].function->Calc(q[1]) * Vec3::UnitX() + 0.05 * Vec3::UnitY() +
                 (-q[2] + 0.01) * st[5].axis.normalized();
  const Transform X = joint->CalcX_FM(q);
  EXPECT_TRUE(X.R.isApprox(R, 1e-14));
  EXPECT_TRUE(X.p.isApprox(p, 1e-14));
}

TEST(JointTransformTest, CustomJointOnCoordinateAxesComposesElementaryRotations) {
  const model::ModelSpec spec = MakeCustomCoordinateAxesSpec();
  const auto joint = kinematics::MakeJointModel(spec, 0);
  const double q[] = {0.7, -1.1};
  const auto& st = spec.joints[0].spatial_transform;
  const double s2 = st[1].function->Calc(q[0]);
  // Ry(0.4) Rz(s2) Rx(q1), written out.
  const double cy = std::cos(0.4), sy = std::sin(0.4), cz = std::cos(s2), sz = std::sin(s2);
  const double cx = std::cos(q[1]), sx = std::sin(q[1]);
  Mat3 Ry, Rz, Rx;
  Ry << cy, 0, sy, 0, 1, 0, -sy, 0, cy;
  Rz << cz, -sz, 0, sz, cz, 0, 0, 0, 1;
  Rx << 1, 0, 0, 0, cx, -sx, 0, sx, cx;
  const Vec3 p(st[3].function->Calc(q[0]), 0.0, -q[1] + 0.01);
  const Transform X = joint->CalcX_FM(q);
  EXPECT_TRUE(X.R.isApprox(Ry * Rz * Rx, 1e-14));
  EXPECT_TRUE(X.p.isApprox(p, 1e-14));
}

TEST(JointTransformTest, LinearFunctionsInlineEqualTheFunctionsTheyReplace) {
  // The library's LinearFunction axes are evaluated inline (slope q + intercept); the same
  // values through a test function take the general path. Both must agree to rounding.
  const auto inline_joint = kinematics::MakeJointModel(MakeCustomLinearSpec(false), 0);
  const auto general_joint = kinematics::MakeJointModel(MakeCustomLinearSpec(true), 0);
  for (int trial = 0; trial < 4; ++trial) {
    const std::vector<double> q = Sample(3, 0.9, 0.2 + trial);
    const std::vector<double> u = Sample(3, 1.3, 1.1 + trial);
    const Transform X = inline_joint->CalcX_FM(q), X_ref = general_joint->CalcX_FM(q);
    EXPECT_LT((X.R - X_ref.R).norm(), 1e-15);
    EXPECT_LT((X.p - X_ref.p).norm(), 1e-15);
    EXPECT_LT((inline_joint->CalcH_FM(q) - general_joint->CalcH_FM(q)).norm(), 1e-15);
    EXPECT_LT((inline_joint->CalcHDotU(q, u) - general_joint->CalcHDotU(q, u)).norm(), 1e-14);
  }
}

TEST(JointTransformTest, LinearFunctionWithoutCoordinatesGivesItsSlopeAsOpenSimDoes) {
  // SimTK::Function::Linear called with no arguments returns coefficients[0].
  model::ModelSpec spec = MakeCustomSpec();
  spec.joints[0].spatial_transform[4].function = std::make_shared<TestLinearFunction>(0.3, 0.7);
  const auto joint = kinematics::MakeJointModel(spec, 0);
  const model::ModelSpec reference_spec = MakeCustomSpec();  // translation2 = Constant(0.05)
  const auto reference = kinematics::MakeJointModel(reference_spec, 0);
  const double q[] = {0.3, -0.5, 0.8};
  const Vec3 dp = joint->CalcX_FM(q).p - reference->CalcX_FM(q).p;
  EXPECT_TRUE(dp.isApprox(Vec3(0, 0.3 - 0.05, 0), 1e-15)) << dp.transpose();
}

TEST(JointModelErrorsTest, WrongCoordinateCountNamesTheJoint) {
  model::ModelSpec spec = MakeSpec(model::JointType::kPin, "PinJoint", 2);
  spec.joints[0].where = {"model.osim", 42};
  try {
    kinematics::MakeJointModel(spec, 0);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 42);
    EXPECT_EQ(e.component(), "/jointset/joint");
    EXPECT_NE(std::string(e.what()).find("PinJoint needs 1"), std::string::npos) << e.what();
  }
}

TEST(JointModelErrorsTest, CollinearCustomAxesAndMissingParametersAreErrors) {
  model::ModelSpec spec = MakeCustomSpec();
  spec.joints[0].spatial_transform[1].axis = Vec3(2, 0.4, 0);  // parallel to rotation1
  EXPECT_THROW(kinematics::MakeJointModel(spec, 0), Error);
  EXPECT_THROW(
      kinematics::MakeJointModel(MakeSpec(model::JointType::kEllipsoid, "EllipsoidJoint", 3), 0),
      Error);
  EXPECT_THROW(
      kinematics::MakeJointModel(MakeSpec(model::JointType::kUnknown, "PluginJoint", 1), 0), Error);
}

TEST(JointModelErrorsTest, CustomAxisWithForeignCoordinateOrWrongArityIsAnError) {
  model::ModelSpec foreign = MakeCustomSpec();
  model::CoordinateSpec other;
  other.name = "other";
  foreign.coordinates.push_back(other);
  foreign.joints[0].spatial_transform[0].coordinates = {3};  // not one of the joint's
  EXPECT_THROW(kinematics::MakeJointModel(foreign, 0), Error);
  model::ModelSpec arity = MakeCustomSpec();
  arity.joints[0].spatial_transform[1].coordinates = {0};  // a 2-argument function, 1 coordinate
  EXPECT_THROW(kinematics::MakeJointModel(arity, 0), Error);
}

}  // namespace
}  // namespace sinew
