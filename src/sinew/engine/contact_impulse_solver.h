// The contact impulse problem of one NSC step, on the Delassus operator W of the contact rows:
// find gamma (per contact: normal gamma_n, tangential gamma_t in 2D) such that with
// u = u_free + W gamma (per contact: normal speed u_n, tangential velocity u_t)
//   0 <= gamma_n  _|_  u_n - target_n >= 0                  (non-penetration, restitution)
//   |gamma_t| <= mu gamma_n, and u_t = 0 when |gamma_t| < mu gamma_n, else u_t = -k gamma_t
//   with k >= 0                                             (Coulomb's law, circular cone)
// i.e. Coulomb's law itself (not the convexified cone complementarity of Anitescu-Tasora,
// which lets sliding contacts separate at mu |u_t|). Two solvers:
//  - projected block Gauss-Seidel: per contact, the normal impulse by a clamped Newton step on
//    its diagonal entry, then the tangential impulse by a gradient step of
//    1 / lambda_max(W_tt) projected onto the disc of radius mu gamma_n;
//  - APGD (the default), accelerated projected gradient descent (Nesterov's method with an
//    adaptive step and gradient restarts, as in Mazhar, Heyn, Negrut, Tasora 2015, "Using
//    Nesterov's method to accelerate multibody dynamics with friction and contact"): gradient
//    steps on f(gamma) = 1/2 gamma^T W gamma + gamma^T (u_free - target), scaled per contact
//    by 1 / W_nn (normal row) and 1 / lambda_max(W_tt) (tangential rows), with the momentum
//    restarted on the gradient mapping, each followed by the projection P that clamps gamma_n to >= 0 and then
//    shrinks gamma_t radially onto the disc of radius mu gamma_n. P keeps gamma in the
//    friction cone but is not the Euclidean projection onto it (which would give the relaxed
//    CCP's solution): the fixed points of gamma = P(gamma - t D grad f) are exactly the
//    solutions of the law above (the friction bound mu gamma_n is updated every iteration, a
//    Tresca fixed point). The same residual and stopping rule as Gauss-Seidel; the iterate of
//    the smallest residual is returned. The default since it was measured: on Rajagopal2015
//    lying on the ground it meets the 1e-6 m/s tolerance in tens to hundreds of iterations
//    where Gauss-Seidel mostly stops at its sweep limit short of it (docs/contact.md).
#pragma once

#include <sinew/math/types.h>

#include <optional>
#include <string_view>

namespace sinew::engine {

/// Which iteration SolveContactImpulses runs.
enum class ContactSolverMethod {
  kGaussSeidel,  ///< projected block Gauss-Seidel
  kApgd,         ///< accelerated projected gradient descent (Nesterov; the default)
};

/// The method's name as the CLI (`--nsc-solver`) and Python (`nsc_solver`) spell it: "apgd" or
/// "gauss-seidel".
const char* ContactSolverMethodName(ContactSolverMethod method);
/// The method named `name` (ContactSolverMethodName's spelling); nullopt for any other name.
std::optional<ContactSolverMethod> FindContactSolverMethod(std::string_view name);

/// The method and iteration limits of SolveContactImpulses.
struct ContactSolverSettings {
  ContactSolverMethod method = ContactSolverMethod::kApgd;
  /// Gauss-Seidel sweeps or APGD iterations at most (>= 1). 1000: Rajagopal2015 lying on the
  /// ground needs up to about 600 APGD iterations in a few steps (most take 20-200) and stops
  /// creeping only when they converge; the tolerance ends easier solves early.
  int max_iterations = 1000;
  double tolerance = 1e-6;   ///< stop when the residual (m/s) falls to it
};

/// What one solve did.
struct ContactSolverResult {
  int iterations = 0;     ///< sweeps (Gauss-Seidel) or iterations (APGD) made
  int products = 0;       ///< products W x made (APGD: one per iteration, plus step retries and
                          ///< two to start; Gauss-Seidel: one per sweep, its column updates)
  double residual = 0.0;  ///< largest violation of the law above over the contacts, in m/s
};

/// The buffers of an APGD solve, grown to the largest problem seen and then reused (so a
/// solve allocates nothing once they are sized). Gauss-Seidel uses none.
struct ContactSolverWorkspace {
  /// Grows every buffer to at least `size` (3 per contact).
  void Reserve(Eigen::Index size);
  VecX x, x_previous, y, Wx, Wx_previous, Wy, gradient, scale, best, u_best;
};

/// Solves the problem above for m contacts: `W` (3m x 3m, symmetric positive semidefinite;
/// rows per contact: normal, tangent 1, tangent 2), `u_free` (3m), `target_n` (m), `mu` (m).
/// `gamma` (3m) holds the starting guess (zero, or a warm start) and receives the impulses;
/// `u` (3m) receives u_free + W gamma. With `settings.method` APGD, `workspace` is grown
/// to 3m if smaller (no heap use once it is that large); Gauss-Seidel uses no heap. Contacts
/// whose W_nn is not positive (between two bodies that cannot move) get no impulse.
ContactSolverResult SolveContactImpulses(Eigen::Ref<const MatX> W, Eigen::Ref<const VecX> u_free,
                                         Eigen::Ref<const VecX> target_n, Eigen::Ref<const VecX> mu,
                                         const ContactSolverSettings& settings,
                                         ContactSolverWorkspace& workspace, Eigen::Ref<VecX> gamma,
                                         Eigen::Ref<VecX> u);

}  // namespace sinew::engine
