#include <sinew/engine/contact_impulse_solver.h>

#include <algorithm>
#include <cmath>

namespace sinew::engine {
namespace {

// Largest eigenvalue of the symmetric 2x2 block [a b; b c].
double LargestEigenvalue(double a, double b, double c) {
  const double mean = 0.5 * (a + c), half = 0.5 * (a - c);
  return mean + std::sqrt(half * half + b * b);
}

// Violation (m/s) of the law at contact i for impulse g and velocity u.
double ContactResidual(int i, const Eigen::Ref<VecX>& gamma, const Eigen::Ref<VecX>& u,
                       double target, double mu) {
  const double gn = gamma[3 * i], un = u[3 * i];
  double r = gn > 0.0 ? std::abs(un - target) : std::max(0.0, target - un);
  const Eigen::Vector2d gt = gamma.segment<2>(3 * i + 1), ut = u.segment<2>(3 * i + 1);
  const double radius = mu * gn;
  if (radius <= 0.0) return r;  // no friction to hold anything
  const double norm = gt.norm();
  if (norm < radius * (1.0 - 1e-9)) {
    r = std::max(r, ut.norm());  // sticking: no slip
  } else if (norm > 0.0) {
    r = std::max(r, (ut + ut.norm() * gt / norm).norm());  // sliding: slip opposes the impulse
  }
  return r;
}

}  // namespace

ContactSolverResult SolveContactImpulses(Eigen::Ref<const MatX> W, Eigen::Ref<const VecX> u_free,
                                         Eigen::Ref<const VecX> target_n, Eigen::Ref<const VecX> mu,
                                         const ContactSolverSettings& settings,
                                         Eigen::Ref<VecX> gamma, Eigen::Ref<VecX> u) {
  const int m = static_cast<int>(target_n.size());
  ContactSolverResult result;
  if (m == 0) return result;
  u = u_free;
  u.noalias() += W * gamma;
  const double scale = W.diagonal().cwiseAbs().maxCoeff();
  for (int sweep = 0; sweep < std::max(settings.max_iterations, 1); ++sweep) {
    for (int i = 0; i < m; ++i) {
      const int n = 3 * i;
      const double w_nn = W(n, n);
      if (!(w_nn > 1e-14 * scale)) {
        gamma.segment<3>(n).setZero();
        continue;
      }
      // Normal: the impulse that makes u_n = target, clamped to >= 0.
      const double dn = std::max(0.0, gamma[n] - (u[n] - target_n[i]) / w_nn) - gamma[n];
      if (dn != 0.0) {
        gamma[n] += dn;
        u.noalias() += W.col(n) * dn;
      }
      // Tangential: a gradient step, projected onto the disc |gamma_t| <= mu gamma_n.
      const double step =
          1.0 / std::max(LargestEigenvalue(W(n + 1, n + 1), W(n + 1, n + 2), W(n + 2, n + 2)),
                         1e-14 * scale);
      Eigen::Vector2d gt = gamma.segment<2>(n + 1) - step * u.segment<2>(n + 1);
      const double radius = mu[i] * gamma[n], norm = gt.norm();
      if (norm > radius) gt *= norm > 0.0 ? radius / norm : 0.0;
      const Eigen::Vector2d dt = gt - gamma.segment<2>(n + 1);
      if (dt.x() != 0.0 || dt.y() != 0.0) {
        gamma.segment<2>(n + 1) = gt;
        u.noalias() += W.middleCols<2>(n + 1) * dt;
      }
    }
    result.iterations = sweep + 1;
    result.residual = 0.0;
    for (int i = 0; i < m; ++i) {
      if (W(3 * i, 3 * i) > 1e-14 * scale) {
        result.residual =
            std::max(result.residual, ContactResidual(i, gamma, u, target_n[i], mu[i]));
      }
    }
    if (result.residual <= settings.tolerance) break;
  }
  return result;
}

}  // namespace sinew::engine
