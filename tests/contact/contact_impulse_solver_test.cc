// The contact impulse solver (engine::SolveContactImpulses), both methods, on the Delassus
// operator of one free rigid body, W = J M^-1 J^T (J: per contact the normal and two tangent
// rows of the contact point's velocity over the body's twist [w; v] about its centre of mass),
// against closed forms: a ball's normal impulse m g h and its friction impulse (sticking: the
// one that stops the slip; sliding: mu m g h against the slip), a frictionless table on three
// legs carried by the lever rule, a table on four legs stopped by friction (its resultant
// impulse is -M v_free), and a table on three legs sliding (APGD and Gauss-Seidel agree).
#include <gtest/gtest.h>
#include <sinew/engine/contact_impulse_solver.h>

#include <iostream>
#include <vector>

namespace sinew::engine {
namespace {

constexpr double kG = 9.80665, kH = 1e-3;

// One free rigid body (mass m, principal inertia I at the centre of mass) touching the
// ground y = 0 at points p_i (from its centre, in G), normal +y, tangents +x and +z.
struct RigidBodyProblem {
  MatX J;  // 3m x 6, over the twist [w; v]
  Eigen::Matrix<double, 6, 6> M_inv = Eigen::Matrix<double, 6, 6>::Zero();
  MatX W;
  VecX u_free;
  VecX target;
  VecX mu;
};

RigidBodyProblem MakeProblem(double mass, const Vec3& inertia, const std::vector<Vec3>& points,
                             const Vec3& w_free, const Vec3& v_free, double mu) {
  const int m = static_cast<int>(points.size());
  RigidBodyProblem p;
  p.J.setZero(3 * m, 6);
  const Vec3 d[3] = {Vec3::UnitY(), Vec3::UnitX(), Vec3::UnitZ()};
  for (int i = 0; i < m; ++i) {
    for (int k = 0; k < 3; ++k) {
      // d . (v + w x p) = (p x d) . w + d . v
      p.J.block<1, 3>(3 * i + k, 0) = points[i].cross(d[k]).transpose();
      p.J.block<1, 3>(3 * i + k, 3) = d[k].transpose();
    }
  }
  p.M_inv.diagonal() << inertia.cwiseInverse(), Vec3::Constant(1.0 / mass);
  p.W = p.J * p.M_inv * p.J.transpose();
  Eigen::Matrix<double, 6, 1> twist;
  twist << w_free, v_free;
  p.u_free = p.J * twist;
  p.target.setZero(m);  // resting contacts: the gap stays closed
  p.mu.setConstant(m, mu);
  return p;
}

struct Solved {
  VecX gamma, u;
  ContactSolverResult result;
};

Solved Solve(const RigidBodyProblem& p, ContactSolverMethod method, double tolerance = 1e-12) {
  ContactSolverSettings settings;
  settings.method = method;
  settings.max_iterations = 100000;
  settings.tolerance = tolerance;
  ContactSolverWorkspace workspace;
  Solved s;
  s.gamma.setZero(p.u_free.size());
  s.u.setZero(p.u_free.size());
  s.result = SolveContactImpulses(p.W, p.u_free, p.target, p.mu, settings, workspace, s.gamma, s.u);
  return s;
}

const ContactSolverMethod kMethods[] = {ContactSolverMethod::kGaussSeidel,
                                        ContactSolverMethod::kApgd};
const char* Name(ContactSolverMethod method) {
  return method == ContactSolverMethod::kApgd ? "APGD" : "Gauss-Seidel";
}

TEST(ContactImpulseSolverTest, BallSticksOrSlidesWithCoulombsImpulse) {
  // A solid ball (m = 2 kg, r = 0.1 m, I = 2/5 m r^2) on the ground, falling g h during the
  // step and moving along (vx, vz): W_nn = 1/m, W_tt = 1/m + r^2 / I = 7 / (2 m), no coupling.
  // Normal impulse m g h; the slip is stopped by -u_t / W_tt when that is within mu m g h
  // (sticking), else the friction impulse is mu m g h against the slip (sliding).
  constexpr double kM = 2.0, kR = 0.1, kMu = 0.4;
  const double limit = kMu * kM * kG * kH;
  for (const Vec3& v : {Vec3(0.004, -kG * kH, -0.003), Vec3(0.6, -kG * kH, 0.8)}) {
    const RigidBodyProblem p = MakeProblem(kM, Vec3::Constant(0.4 * kM * kR * kR),
                                           {Vec3(0, -kR, 0)}, Vec3::Zero(), v, kMu);
    const Eigen::Vector2d slip(v.x(), v.z());
    const double stop = slip.norm() / (3.5 / kM);
    const Eigen::Vector2d gamma_t = stop <= limit ? Eigen::Vector2d(-slip / 3.5 * kM)
                                                  : Eigen::Vector2d(-limit * slip.normalized());
    for (ContactSolverMethod method : kMethods) {
      const Solved s = Solve(p, method);
      SCOPED_TRACE(Name(method));
      // Residual 1e-12 m/s; W^-1 at most 2 m/s per N s: impulses within 2e-12 N s.
      EXPECT_LE(s.result.residual, 1e-12);
      EXPECT_NEAR(s.gamma[0], kM * kG * kH, 2e-12);
      EXPECT_NEAR(s.gamma[1], gamma_t.x(), 2e-12) << "slip " << slip.norm();
      EXPECT_NEAR(s.gamma[2], gamma_t.y(), 2e-12) << "slip " << slip.norm();
    }
  }
}

TEST(ContactImpulseSolverTest, FrictionlessTableOnThreeLegsFollowsTheLeverRule) {
  // A table (m = 10 kg) on three legs 0.5 m below its centre, frictionless, falling g h: it
  // stops, so the legs' impulses carry m g h with no moment about the centre (statics: three
  // equations, three unknowns; the centre lies inside the legs' triangle, so all are > 0).
  constexpr double kM = 10.0;
  const std::vector<Vec3> legs = {Vec3(0.5, -0.5, 0.1), Vec3(-0.3, -0.5, 0.4),
                                  Vec3(-0.2, -0.5, -0.6)};
  const RigidBodyProblem p =
      MakeProblem(kM, Vec3(0.6, 1.0, 0.8), legs, Vec3::Zero(), Vec3(0, -kG * kH, 0), 0.0);
  Eigen::Matrix3d statics;
  statics << 1, 1, 1, legs[0].x(), legs[1].x(), legs[2].x(), legs[0].z(), legs[1].z(), legs[2].z();
  const Vec3 lever = statics.fullPivLu().solve(Vec3(kM * kG * kH, 0, 0));
  ASSERT_TRUE((lever.array() > 0.0).all());
  for (ContactSolverMethod method : kMethods) {
    const Solved s = Solve(p, method);
    SCOPED_TRACE(Name(method));
    EXPECT_LE(s.result.residual, 1e-12);
    // W_nn's smallest eigenvalue is above 1/m: impulses within m x 1e-12 m/s.
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(s.gamma[3 * i], lever[i], kM * 1e-12) << "leg " << i;
      EXPECT_EQ(s.gamma.segment<2>(3 * i + 1).norm(), 0.0) << "leg " << i;
    }
    std::cout << Name(method) << " three legs: " << s.result.iterations << " iterations, "
              << s.result.products << " products, residual " << s.result.residual << "\n";
  }
}

TEST(ContactImpulseSolverTest, FrictionStopsATableOnFourLegs) {
  // A table (m = 10 kg) on four legs, mu = 0.5, falling g h and drifting sideways and
  // turning slowly: friction stops it (the drift needs far less than mu m g h), so v+ = 0
  // and the resultant impulse J^T gamma is -M v_free. Four legs make the impulses
  // themselves indeterminate (a table on four legs is statically indeterminate), so the
  // solvers are compared on the resultant, which is unique, and on the slip.
  constexpr double kM = 10.0;
  const std::vector<Vec3> legs = {Vec3(0.5, -0.5, 0.4), Vec3(-0.5, -0.5, 0.4),
                                  Vec3(-0.5, -0.5, -0.4), Vec3(0.4, -0.5, -0.4)};
  const Vec3 inertia(0.6, 1.0, 0.8), w_free(0.0, 0.002, 0.0), v_free(0.0015, -kG * kH, -0.001);
  const RigidBodyProblem p = MakeProblem(kM, inertia, legs, w_free, v_free, 0.5);
  Eigen::Matrix<double, 6, 1> resultant;
  resultant << -inertia.cwiseProduct(w_free), -kM * v_free;
  for (ContactSolverMethod method : kMethods) {
    const Solved s = Solve(p, method);
    SCOPED_TRACE(Name(method));
    EXPECT_LE(s.result.residual, 1e-12);
    EXPECT_LE(s.u.cwiseAbs().maxCoeff(), 1e-12);  // every leg stops
    // v+ - 0 = M^-1 (J^T gamma - resultant) is within the residual: the resultant within
    // the largest of m, I times 1e-12 m/s over the legs' lever (about 1 m).
    const Eigen::Matrix<double, 6, 1> error = p.J.transpose() * s.gamma - resultant;
    EXPECT_LE(error.cwiseAbs().maxCoeff(), 4 * kM * 1e-12) << error.transpose();
    for (int i = 0; i < 4; ++i) {
      EXPECT_LE(s.gamma.segment<2>(3 * i + 1).norm(), 0.5 * s.gamma[3 * i] * (1 + 1e-12));
    }
    std::cout << Name(method) << " four legs: " << s.result.iterations << " iterations, "
              << s.result.products << " products, residual " << s.result.residual << "\n";
  }
}

TEST(ContactImpulseSolverTest, ApgdAndGaussSeidelAgreeOnASlidingTable) {
  // The table on three legs thrown sideways at 1 m/s, mu = 0.3: every leg slides, so its
  // friction impulse is mu times its normal one against its slip, and the impulses are
  // determined (three normal impulses from the statics of the fall, now with friction's
  // moment). Both solvers, converged to 1e-12 m/s, give the same impulses to W^-1 times that.
  constexpr double kM = 10.0;
  const std::vector<Vec3> legs = {Vec3(0.5, -0.5, 0.1), Vec3(-0.3, -0.5, 0.4),
                                  Vec3(-0.2, -0.5, -0.6)};
  const RigidBodyProblem p =
      MakeProblem(kM, Vec3(0.6, 1.0, 0.8), legs, Vec3(0, 0.5, 0), Vec3(1.0, -kG * kH, 0.2), 0.3);
  const Solved gs = Solve(p, ContactSolverMethod::kGaussSeidel);
  const Solved apgd = Solve(p, ContactSolverMethod::kApgd);
  EXPECT_LE(gs.result.residual, 1e-12);
  EXPECT_LE(apgd.result.residual, 1e-12);
  for (int i = 0; i < 3; ++i) {
    const auto g = gs.gamma.segment<3>(3 * i);
    EXPECT_GT(g[0], 0.0) << "leg " << i;
    EXPECT_NEAR(g.tail<2>().norm(), 0.3 * g[0], 1e-12) << "leg " << i << " slides";
  }
  EXPECT_LE((gs.gamma - apgd.gamma).cwiseAbs().maxCoeff(), kM * 1e-11)
      << gs.gamma.transpose() << "\n"
      << apgd.gamma.transpose();
  std::cout << "sliding table: Gauss-Seidel " << gs.result.iterations << " sweeps, APGD "
            << apgd.result.iterations << " iterations (" << apgd.result.products
            << " products); largest impulse difference "
            << (gs.gamma - apgd.gamma).cwiseAbs().maxCoeff() << " N s\n";
}

TEST(ContactImpulseSolverTest, ContactsThatCannotMoveGetNoImpulse) {
  // The resting ball's contact plus a contact between two bodies that cannot move (its rows of
  // W zero, its u_free approaching): that contact gets no impulse and is left out of the
  // residual; the ball's impulse is m g h as alone.
  constexpr double kM = 2.0;
  const RigidBodyProblem ball = MakeProblem(kM, Vec3::Constant(0.008), {Vec3(0, -0.1, 0)},
                                            Vec3::Zero(), Vec3(0, -kG * kH, 0), 0.4);
  MatX W = MatX::Zero(6, 6);
  W.topLeftCorner<3, 3>() = ball.W;
  VecX u_free(6), target = VecX::Zero(2), mu = VecX::Constant(2, 0.4);
  u_free << ball.u_free, -1.0, 0.5, 0.0;
  for (ContactSolverMethod method : kMethods) {
    SCOPED_TRACE(Name(method));
    ContactSolverSettings settings;
    settings.method = method;
    settings.tolerance = 1e-12;
    ContactSolverWorkspace workspace;
    VecX gamma = VecX::Constant(6, 1.0), u(6);  // a warm start that the second cannot keep
    const ContactSolverResult r =
        SolveContactImpulses(W, u_free, target, mu, settings, workspace, gamma, u);
    EXPECT_LE(r.residual, 1e-12);
    EXPECT_NEAR(gamma[0], kM * kG * kH, 2e-12);
    EXPECT_EQ(gamma.tail<3>().norm(), 0.0);
  }
}

TEST(ContactImpulseSolverTest, ApgdStartsFromAWarmStartThatSolvesTheProblem) {
  // A solution given as the starting guess is returned as it is, without an iteration.
  const RigidBodyProblem p = MakeProblem(2.0, Vec3::Constant(0.008), {Vec3(0, -0.1, 0)},
                                         Vec3::Zero(), Vec3(0, -kG * kH, 0), 0.4);
  ContactSolverSettings settings;
  settings.method = ContactSolverMethod::kApgd;
  ContactSolverWorkspace workspace;
  VecX gamma = Vec3(2.0 * kG * kH, 0, 0), u(3);
  const ContactSolverResult r =
      SolveContactImpulses(p.W, p.u_free, p.target, p.mu, settings, workspace, gamma, u);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_LE(r.residual, 1e-15);
  EXPECT_NEAR(gamma[0], 2.0 * kG * kH, 1e-15);
}

}  // namespace
}  // namespace sinew::engine
