// Test-only JointModel implementations and small systems for the engine tests: they let the
// engine be tested independently of the kinematics layer.
#pragma once

#include <sinew/engine/constraint.h>
#include <sinew/engine/system.h>
#include <sinew/kinematics/joint_model.h>
#include <sinew/math/rotation.h>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace sinew::engine::testing {

/// The spatial inertia about the body origin ([angular; linear] in G) of mass m, mass centre c
/// and central inertia I, written out independently of the engine's CalcBodyMassMatrix.
inline Eigen::Matrix<double, 6, 6> SpatialInertia(double m, const Vec3& c, const Mat3& I) {
  Eigen::Matrix<double, 6, 6> M;
  const Mat3 cx = Skew(c);
  M << I - m * cx * cx, m * cx, -m * cx, m * Mat3::Identity();
  return M;
}

/// Rotation q about a fixed unit axis of F (a pin about `axis`).
class RevoluteModel final : public kinematics::JointModel {
 public:
  explicit RevoluteModel(const Vec3& axis) : axis_(axis.normalized()) {}
  int nq() const override { return 1; }
  Transform CalcX_FM(std::span<const double> q) const override {
    return Transform::Rotation(Eigen::AngleAxisd(q[0], axis_).toRotationMatrix());
  }
  Mat6X CalcH_FM(std::span<const double>) const override {
    Mat6X H = Mat6X::Zero(6, 1);
    H.block<3, 1>(0, 0) = axis_;
    return H;
  }
  void CalcQDot(std::span<const double>, std::span<const double> u,
                std::span<double> qdot) const override {
    qdot[0] = u[0];
  }
  void CalcU(std::span<const double>, std::span<const double> qdot,
             std::span<double> u) const override {
    u[0] = qdot[0];
  }
  SpatialVec CalcHDotU(std::span<const double>, std::span<const double>) const override {
    return SpatialVec::Zero();
  }

 private:
  Vec3 axis_;
};

/// Rotation q about F's z axis with M's origin translated by a*q along F's x (a wheel that
/// rolls: a coupled rotation and translation, like a CustomJoint with a linear coupling).
class RollingModel final : public kinematics::JointModel {
 public:
  explicit RollingModel(double a) : a_(a) {}
  int nq() const override { return 1; }
  Transform CalcX_FM(std::span<const double> q) const override {
    return {Eigen::AngleAxisd(q[0], Vec3::UnitZ()).toRotationMatrix(), Vec3(a_ * q[0], 0, 0)};
  }
  Mat6X CalcH_FM(std::span<const double>) const override {
    Mat6X H = Mat6X::Zero(6, 1);
    H(2, 0) = 1;
    H(3, 0) = a_;
    return H;
  }
  void CalcQDot(std::span<const double>, std::span<const double> u,
                std::span<double> qdot) const override {
    qdot[0] = u[0];
  }
  void CalcU(std::span<const double>, std::span<const double> qdot,
             std::span<double> u) const override {
    u[0] = qdot[0];
  }
  SpatialVec CalcHDotU(std::span<const double>, std::span<const double>) const override {
    return SpatialVec::Zero();
  }

 private:
  double a_;
};

/// Translation q along F's x axis.
class SliderModel final : public kinematics::JointModel {
 public:
  int nq() const override { return 1; }
  Transform CalcX_FM(std::span<const double> q) const override {
    return Transform::Translation(Vec3(q[0], 0, 0));
  }
  Mat6X CalcH_FM(std::span<const double>) const override {
    Mat6X H = Mat6X::Zero(6, 1);
    H(3, 0) = 1;
    return H;
  }
  void CalcQDot(std::span<const double>, std::span<const double> u,
                std::span<double> qdot) const override {
    qdot[0] = u[0];
  }
  void CalcU(std::span<const double>, std::span<const double> qdot,
             std::span<double> u) const override {
    u[0] = qdot[0];
  }
  SpatialVec CalcHDotU(std::span<const double>, std::span<const double>) const override {
    return SpatialVec::Zero();
  }
};

/// OpenSim's BallJoint: q are body-fixed X-Y-Z angles, u = w_FM expressed in F.
class BallModel final : public kinematics::JointModel {
 public:
  int nq() const override { return 3; }
  Transform CalcX_FM(std::span<const double> q) const override {
    return Transform::Rotation(RotationFromBodyFixedXYZ(Vec3(q[0], q[1], q[2])));
  }
  Mat6X CalcH_FM(std::span<const double>) const override {
    Mat6X H = Mat6X::Zero(6, 3);
    H.topRows<3>().setIdentity();
    return H;
  }
  void CalcQDot(std::span<const double> q, std::span<const double> u,
                std::span<double> qdot) const override {
    const Vec3 r = E(q).inverse() * Vec3(u[0], u[1], u[2]);
    for (int i = 0; i < 3; ++i) qdot[i] = r[i];
  }
  void CalcU(std::span<const double> q, std::span<const double> qdot,
             std::span<double> u) const override {
    const Vec3 r = E(q) * Vec3(qdot[0], qdot[1], qdot[2]);
    for (int i = 0; i < 3; ++i) u[i] = r[i];
  }
  SpatialVec CalcHDotU(std::span<const double>, std::span<const double>) const override {
    return SpatialVec::Zero();
  }

 private:
  // w_FM_F = E(q) qdot for body-fixed X-Y-Z angles.
  static Mat3 E(std::span<const double> q) {
    const Mat3 Rx = Eigen::AngleAxisd(q[0], Vec3::UnitX()).toRotationMatrix();
    const Mat3 Ry = Eigen::AngleAxisd(q[1], Vec3::UnitY()).toRotationMatrix();
    Mat3 e;
    e.col(0) = Vec3::UnitX();
    e.col(1) = Rx * Vec3::UnitY();
    e.col(2) = Rx * Ry * Vec3::UnitZ();
    return e;
  }
};

/// OpenSim's UniversalJoint: rotation q0 about F's x, then q1 about the new y (qdot = u).
class UniversalModel final : public kinematics::JointModel {
 public:
  int nq() const override { return 2; }
  Transform CalcX_FM(std::span<const double> q) const override {
    return Transform::Rotation(Rx(q[0]) *
                               Eigen::AngleAxisd(q[1], Vec3::UnitY()).toRotationMatrix());
  }
  Mat6X CalcH_FM(std::span<const double> q) const override {
    Mat6X H = Mat6X::Zero(6, 2);
    H.block<3, 1>(0, 0) = Vec3::UnitX();
    H.block<3, 1>(0, 1) = Rx(q[0]) * Vec3::UnitY();
    return H;
  }
  void CalcQDot(std::span<const double>, std::span<const double> u,
                std::span<double> qdot) const override {
    qdot[0] = u[0];
    qdot[1] = u[1];
  }
  void CalcU(std::span<const double>, std::span<const double> qdot,
             std::span<double> u) const override {
    u[0] = qdot[0];
    u[1] = qdot[1];
  }
  // d/dt (Rx(q0) y) u1 = (q0' x) x (Rx(q0) y) u1.
  SpatialVec CalcHDotU(std::span<const double> q, std::span<const double> u) const override {
    SpatialVec a = SpatialVec::Zero();
    a.head<3>() = (u[0] * Vec3::UnitX()).cross(Rx(q[0]) * Vec3::UnitY()) * u[1];
    return a;
  }

 private:
  static Mat3 Rx(double a) { return Eigen::AngleAxisd(a, Vec3::UnitX()).toRotationMatrix(); }
};

/// OpenSim's FreeJoint: body-fixed X-Y-Z angles and a translation along F's axes; speeds are
/// w_FM and v_FM, both in F.
class FreeModel final : public kinematics::JointModel {
 public:
  int nq() const override { return 6; }
  Transform CalcX_FM(std::span<const double> q) const override {
    return {ball_.CalcX_FM(q.first(3)).R, Vec3(q[3], q[4], q[5])};
  }
  Mat6X CalcH_FM(std::span<const double>) const override {
    return Mat6X(Eigen::Matrix<double, 6, 6>::Identity());
  }
  void CalcQDot(std::span<const double> q, std::span<const double> u,
                std::span<double> qdot) const override {
    ball_.CalcQDot(q.first(3), u.first(3), qdot.first(3));
    for (int i = 3; i < 6; ++i) qdot[i] = u[i];
  }
  void CalcU(std::span<const double> q, std::span<const double> qdot,
             std::span<double> u) const override {
    ball_.CalcU(q.first(3), qdot.first(3), u.first(3));
    for (int i = 3; i < 6; ++i) u[i] = qdot[i];
  }
  SpatialVec CalcHDotU(std::span<const double>, std::span<const double>) const override {
    return SpatialVec::Zero();
  }

 private:
  BallModel ball_;
};

/// phi = q[a] - ratio q[b] = 0 on two integrated coordinates with qdot = u (sliders, pins):
/// J = [1, -ratio] on their speeds, c = 0, b = -Jdot u = 0.
class LeverConstraint final : public Constraint {
 public:
  LeverConstraint(int a, int b, double ratio) : a_(a), b_(b), ratio_(ratio) {}
  int NumEquations() const override { return 1; }
  std::vector<int> Bodies() const override { return {}; }
  std::vector<int> Coordinates() const override { return {a_, b_}; }
  void CalcPositionError(const System&, const State& state, Eigen::Ref<VecX> phi) const override {
    phi[0] = state.q[a_] - ratio_ * state.q[b_];
  }
  void CalcJacobian(const System&, const State&, Eigen::Ref<MatX> J) const override {
    J(0, 0) = 1.0;
    J(0, 1) = -ratio_;
  }
  void CalcAccelerationRhs(const System&, const State&, Eigen::Ref<VecX> b) const override {
    b[0] = 0.0;
  }

 private:
  int a_, b_;
  double ratio_;
};

/// A free coordinate named `name` with default value q and speed u.
inline CoordinateDesc Coord(const std::string& name, double q = 0.0, double u = 0.0) {
  CoordinateDesc c;
  c.name = name;
  c.default_value = q;
  c.default_speed = u;
  return c;
}

/// A body with mass m, mass centre p_BCm and inertia about it.
inline Body MakeBody(const std::string& name, double m, const Vec3& p_BCm, const Mat3& I) {
  Body b;
  b.name = name;
  b.mass = m;
  b.p_BCm = p_BCm;
  b.I_Bcm_B = I;
  return b;
}

/// Reads a tab-separated OpenSim .sto/.mot file: columns by label (test helper only).
inline std::map<std::string, std::vector<double>> ReadStoColumns(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("endheader", 0) == 0) break;
  }
  std::getline(in, line);
  std::vector<std::string> labels;
  {
    std::istringstream ls(line);
    std::string label;
    while (ls >> label) labels.push_back(label);
  }
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    double x;
    for (size_t i = 0; i < labels.size() && (ls >> x); ++i) columns[labels[i]].push_back(x);
  }
  return columns;
}

}  // namespace sinew::engine::testing
