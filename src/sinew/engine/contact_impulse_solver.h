// The contact impulse problem of one NSC step, on the Delassus operator W of the contact rows:
// find gamma (per contact: normal gamma_n, tangential gamma_t in 2D) such that with
// u = u_free + W gamma (per contact: normal speed u_n, tangential velocity u_t)
//   0 <= gamma_n  _|_  u_n - target_n >= 0                  (non-penetration, restitution)
//   |gamma_t| <= mu gamma_n, and u_t = 0 when |gamma_t| < mu gamma_n, else u_t = -k gamma_t
//   with k >= 0                                             (Coulomb's law, circular cone)
// i.e. Coulomb's law itself (not the convexified cone complementarity of Anitescu-Tasora,
// which lets sliding contacts separate at mu |u_t|). Solved by projected block Gauss-Seidel:
// per contact, the normal impulse by a clamped Newton step on its diagonal entry, then the
// tangential impulse by a gradient step of 1 / lambda_max(W_tt) projected onto the disc of
// radius mu gamma_n.
#pragma once

#include <sinew/math/types.h>

namespace sinew::engine {

/// Iteration limits of SolveContactImpulses.
struct ContactSolverSettings {
  int max_iterations = 100;  ///< Gauss-Seidel sweeps at most (>= 1)
  double tolerance = 1e-6;   ///< stop when the residual (m/s) falls to it
};

/// What one solve did.
struct ContactSolverResult {
  int iterations = 0;     ///< sweeps made
  double residual = 0.0;  ///< largest violation of the law above over the contacts, in m/s
};

/// Solves the problem above for m contacts: `W` (3m x 3m, symmetric positive semidefinite;
/// rows per contact: normal, tangent 1, tangent 2), `u_free` (3m), `target_n` (m), `mu` (m).
/// `gamma` (3m) holds the starting guess (zero, or a warm start) and receives the impulses;
/// `u` (3m) receives u_free + W gamma. No heap use. Contacts
/// whose W_nn is not positive (between two bodies that cannot move) get no impulse.
ContactSolverResult SolveContactImpulses(Eigen::Ref<const MatX> W, Eigen::Ref<const VecX> u_free,
                                         Eigen::Ref<const VecX> target_n, Eigen::Ref<const VecX> mu,
                                         const ContactSolverSettings& settings,
                                         Eigen::Ref<VecX> gamma, Eigen::Ref<VecX> u);

}  // namespace sinew::engine
