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
double ContactResidual(int i, const Eigen::Ref<const VecX>& gamma, const Eigen::Ref<const VecX>& u,
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

// The largest residual over the contacts that can move (W_nn > 1e-14 of the largest diagonal
// entry, `scale`).
double LargestResidual(const Eigen::Ref<const MatX>& W, const Eigen::Ref<const VecX>& gamma,
                       const Eigen::Ref<const VecX>& u, const Eigen::Ref<const VecX>& target_n,
                       const Eigen::Ref<const VecX>& mu, double scale) {
  double residual = 0.0;
  for (int i = 0; i < static_cast<int>(target_n.size()); ++i) {
    if (W(3 * i, 3 * i) > 1e-14 * scale) {
      residual = std::max(residual, ContactResidual(i, gamma, u, target_n[i], mu[i]));
    }
  }
  return residual;
}

ContactSolverResult SolveGaussSeidel(Eigen::Ref<const MatX> W, Eigen::Ref<const VecX> u_free,
                                     Eigen::Ref<const VecX> target_n, Eigen::Ref<const VecX> mu,
                                     const ContactSolverSettings& settings, Eigen::Ref<VecX> gamma,
                                     Eigen::Ref<VecX> u) {
  const int m = static_cast<int>(target_n.size());
  ContactSolverResult result;
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
    result.iterations = result.products = sweep + 1;  // a sweep's column updates: one product
    result.residual = LargestResidual(W, gamma, u, target_n, mu, scale);
    if (result.residual <= settings.tolerance) break;
  }
  return result;
}

// P: gamma_n clamped to >= 0, then gamma_t shrunk radially onto the disc of radius mu gamma_n;
// contacts that cannot move (zero `scale`) get nothing.
void ProjectOntoCone(Eigen::Ref<VecX> gamma, const Eigen::Ref<const VecX>& mu,
                     const Eigen::Ref<const VecX>& scale) {
  for (int i = 0; i < static_cast<int>(mu.size()); ++i) {
    auto g = gamma.segment<3>(3 * i);
    if (scale[3 * i] == 0.0) {
      g.setZero();
      continue;
    }
    g[0] = std::max(0.0, g[0]);
    const double radius = mu[i] * g[0], norm = g.tail<2>().norm();
    if (norm > radius) g.tail<2>() *= norm > 0.0 ? radius / norm : 0.0;
  }
}

ContactSolverResult SolveApgd(Eigen::Ref<const MatX> W, Eigen::Ref<const VecX> u_free,
                              Eigen::Ref<const VecX> target_n, Eigen::Ref<const VecX> mu,
                              const ContactSolverSettings& settings,
                              ContactSolverWorkspace& workspace, Eigen::Ref<VecX> gamma,
                              Eigen::Ref<VecX> u) {
  const int m = static_cast<int>(target_n.size());
  const Eigen::Index n = 3 * m;
  ContactSolverResult result;
  workspace.Reserve(n);
  auto x = workspace.x.head(n), x_previous = workspace.x_previous.head(n), y = workspace.y.head(n);
  auto Wx = workspace.Wx.head(n), Wx_previous = workspace.Wx_previous.head(n);
  auto Wy = workspace.Wy.head(n), gradient = workspace.gradient.head(n);
  auto D = workspace.scale.head(n), best = workspace.best.head(n),
       u_best = workspace.u_best.head(n);
  // The step's scaling D: per contact 1 / W_nn on the normal row and 1 / lambda_max(W_tt) on
  // both tangential rows (a scalar on the tangent plane keeps P's fixed points Coulomb's law:
  // the slip stays opposite gamma_t), 0 for contacts that cannot move. One scalar 1 / W_nn for
  // all three rows left L set by contacts whose W_tt is 40-50 times their W_nn (an elbow
  // folded on itself in Rajagopal2015's resting pose), a short step for every other contact.
  const double largest = W.diagonal().cwiseAbs().maxCoeff();
  for (int i = 0; i < m; ++i) {
    const int r = 3 * i;
    const double w_nn = W(r, r);
    if (!(w_nn > 1e-14 * largest)) {
      D.segment<3>(r).setZero();
      continue;
    }
    D[r] = 1.0 / w_nn;
    D[r + 1] = D[r + 2] =
        1.0 / std::max(LargestEigenvalue(W(r + 1, r + 1), W(r + 1, r + 2), W(r + 2, r + 2)),
                       1e-14 * largest);
  }
  // The gradient of f at v, from W v: u_free + W v - target on the normal rows.
  auto gradient_at = [&](const auto& Wv) {
    gradient = u_free + Wv;
    for (int i = 0; i < m; ++i) gradient[3 * i] -= target_n[i];
  };
  // Start from the warm start, projected.
  x = gamma;
  ProjectOntoCone(x, mu, D);
  Wx.noalias() = W * x;
  u_best = u_free + Wx;
  best = x;
  double best_residual = LargestResidual(W, x, u_best, target_n, mu, largest);
  result.products = 1;
  // L: the Lipschitz constant of the scaled gradient, lambda_max(A) with A = D^1/2 W D^1/2,
  // first estimated as |A e| / |e| for e the ones of the contacts that can move (at most
  // lambda_max), then doubled while the step overshoots (backtracking) and lowered by 10% per
  // iteration, as Chrono's APGD.
  double L = 1.0;
  const double rows = static_cast<double>((D.array() > 0.0).count());
  if (rows > 0.0) {
    y = D.cwiseSqrt();  // D^1/2 e (y is free until the loop)
    Wy.noalias() = W * y;
    ++result.products;
    L = std::max(D.cwiseSqrt().cwiseProduct(Wy).norm() / std::sqrt(rows), 1e-12);
  }
  y = x;
  Wy = Wx;
  x_previous = x;
  Wx_previous = Wx;
  double theta = 1.0;
  for (int k = 0; k < std::max(settings.max_iterations, 1) && best_residual > settings.tolerance;
       ++k) {
    gradient_at(Wy);
    // x = P(y - D grad / L), with L doubled until the quadratic model bounds f from above:
    // f(x) - f(y) - grad . (x - y) = 1/2 dx^T W dx <= L/2 dx^T D^-1 dx.
    for (int retry = 0;; ++retry) {
      x = y - D.cwiseProduct(gradient) / L;
      ProjectOntoCone(x, mu, D);
      Wx.noalias() = W * x;
      ++result.products;
      double curvature = 0.0, metric = 0.0;
      for (Eigen::Index j = 0; j < n; ++j) {
        const double dx = x[j] - y[j];
        curvature += dx * (Wx[j] - Wy[j]);
        if (D[j] > 0.0) metric += dx * dx / D[j];
      }
      if (curvature <= L * metric * (1.0 + 1e-12) || retry >= 60) break;
      L *= 2.0;
    }
    result.iterations = k + 1;
    u = u_free + Wx;
    const double residual = LargestResidual(W, x, u, target_n, mu, largest);
    if (residual < best_residual) {
      best_residual = residual;
      best = x;
      u_best = u;
    }
    if (residual <= settings.tolerance) break;
    // Nesterov's momentum, restarted (theta = 1, no momentum) when the step went uphill:
    // when the gradient mapping G = L D^-1 (y - x), the step P actually took, points along
    // x - x_previous (O'Donoghue-Candes' gradient scheme with G for the gradient, as for
    // projected steps). The raw gradient would restart nearly every iteration at contacts
    // the projection holds (a sliding contact's gradient is its slip, which P turns into
    // a step along the disc's edge), leaving plain projected gradient steps.
    const double theta_next = 0.5 * theta * (std::sqrt(theta * theta + 4.0) - theta);
    const double beta = theta * (1.0 - theta) / (theta * theta + theta_next);
    double uphill = 0.0;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (D[j] > 0.0) uphill += (y[j] - x[j]) * (x[j] - x_previous[j]) / D[j];
    }
    if (uphill > 0.0) {
      y = x;
      Wy = Wx;
      theta = 1.0;
    } else {
      y = x + beta * (x - x_previous);
      Wy = Wx + beta * (Wx - Wx_previous);
      theta = theta_next;
    }
    x_previous = x;
    Wx_previous = Wx;
    L *= 0.9;
  }
  gamma = best;
  u = u_best;
  result.residual = best_residual;
  return result;
}

}  // namespace

void ContactSolverWorkspace::Reserve(Eigen::Index size) {
  for (VecX* v : {&x, &x_previous, &y, &Wx, &Wx_previous, &Wy, &gradient, &scale, &best, &u_best}) {
    if (v->size() < size) v->resize(size);
  }
}

ContactSolverResult SolveContactImpulses(Eigen::Ref<const MatX> W, Eigen::Ref<const VecX> u_free,
                                         Eigen::Ref<const VecX> target_n, Eigen::Ref<const VecX> mu,
                                         const ContactSolverSettings& settings,
                                         ContactSolverWorkspace& workspace, Eigen::Ref<VecX> gamma,
                                         Eigen::Ref<VecX> u) {
  if (target_n.size() == 0) return {};
  if (settings.method == ContactSolverMethod::kApgd) {
    return SolveApgd(W, u_free, target_n, mu, settings, workspace, gamma, u);
  }
  return SolveGaussSeidel(W, u_free, target_n, mu, settings, gamma, u);
}

const char* ContactSolverMethodName(ContactSolverMethod method) {
  return method == ContactSolverMethod::kGaussSeidel ? "gauss-seidel" : "apgd";
}

std::optional<ContactSolverMethod> FindContactSolverMethod(std::string_view name) {
  for (ContactSolverMethod method :
       {ContactSolverMethod::kApgd, ContactSolverMethod::kGaussSeidel}) {
    if (name == ContactSolverMethodName(method)) return method;
  }
  return std::nullopt;
}

}  // namespace sinew::engine
