// The seed's NSC contact method (non-smooth contact, as in Chrono's ChSystemNSC): a fixed-step
// semi-implicit Euler step at the velocity level in which contacts are impulses solved by
// complementarity together with the joints and model constraints.
//
// One step of length h from (x, v):
//  1. v_free: the velocities of the constrained step without contact (the "euler" scheme:
//     M (v_free - v) = h f - J^T mu, J v_free = c(t + h)).
//  2. Contacts from the ContactProvider at x; per contact three rows D_i (normal, two tangents)
//     over the bodies' twists, each body's at its own surface point (p_G -+ depth/2 n_G, not
//     the midway p_G: the lever its impulse has when the gap closes).
//  3. The Delassus operator W = D A^-1 D^T, where A^-1 is the inverse mass *constrained by the
//     joints*: its 6x6 blocks between the bodies in contact, from the KKT system factorized at
//     x with unit loads on each body in contact (KktSolver::SolveUnitLoadResponses: only the
//     tree paths from those bodies to ground are visited; model constraints outside the tree
//     add a small Schur-complement correction per pair of bodies, from products the
//     factorization keeps, no further solve).
//  4. The impulses gamma by SolveContactImpulses (Coulomb's law, circular cone, Gauss-Seidel or
//     APGD, warm-started from the previous step's impulses of the same contacts), with the normal
//     target speed per contact (gap g = -depth)
//        target = -g / h                          g >= 0 (stop where the surfaces meet)
//        target = min(-g / h, max_recovery_speed) g < 0  (push out an overlap, at most that fast)
//     and, when the contact closes during the step while approaching faster than
//     min_bounce_speed, target = max(target, -e v_n) with v_n the normal speed at the step's
//     start (Newton's restitution).
//  5. v+ = v_free + A^-1 D^T gamma (one more solve); positions move with h v+ and are projected
//  onto the
//     constraints (as "euler").
#pragma once

#include <sinew/engine/contact_impulse_solver.h>
#include <sinew/engine/fixed_step_integrator.h>
#include <sinew/engine/unilateral_contact.h>

#include <memory>
#include <vector>

namespace sinew::engine {

/// Settings of the NSC contact method.
struct NscSettings {
  /// Method (Gauss-Seidel or APGD), iterations and tolerance (m/s) of the impulse solve.
  ContactSolverSettings solver;
  /// Largest normal speed (m/s) at which an overlap is pushed out (stabilization).
  double max_recovery_speed = 0.1;
  /// Restitution acts only on contacts approaching faster than this (m/s), so that resting
  /// contacts do not chatter.
  double min_bounce_speed = 0.01;
};

/// What the last step did.
struct NscStepReport {
  double step = 0.0;      ///< the step's length h (s; 0 before the first step)
  int contacts = 0;       ///< contacts the provider gave
  int iterations = 0;     ///< sweeps or iterations of the impulse solve (0 without contacts,
                          ///< or when the warm start already met the tolerance, APGD)
  int products = 0;       ///< products W x of the impulse solve (ContactSolverResult)
  double residual = 0.0;  ///< its final residual (m/s; see ContactSolverResult)
};

/// The impulse solves of every step taken so far. A solve has converged when its final
/// residual is at most the tolerance (the solver's own stopping rule); one that has not stopped
/// at the iteration limit with the best impulses it found.
struct NscSolveSummary {
  long solves = 0;              ///< steps with contacts (one impulse solve each)
  long unconverged = 0;         ///< solves that ended above the tolerance (at the limit)
  int most_iterations = 0;      ///< the most iterations one solve made
  double worst_residual = 0.0;  ///< the largest final residual of a solve (m/s)
};

/// The impulse the last step's contacts gave one body: N s, and N m s about the body's origin
/// (at the step's start), in G. Divided by the step, the mean force and torque over the step.
struct BodyContactImpulse {
  Vec3 linear = Vec3::Zero();
  Vec3 angular = Vec3::Zero();
};

/// The NSC stepper: an Integrator (so engine::Simulate drives it) of fixed step
/// `settings.step`. Keeps a reference to the System and shares the provider.
class NscIntegrator final : public FixedStepIntegrator {
 public:
  /// Throws sinew::Error for a step that is not > 0, a null provider or bad NSC settings.
  NscIntegrator(const System& system, std::shared_ptr<const ContactProvider> provider,
                const IntegratorSettings& settings, const NscSettings& nsc = {});

  const NscSettings& nsc_settings() const { return nsc_; }
  /// The last step's contact count, solver iterations and residual.
  const NscStepReport& last_step() const { return report_; }
  /// The impulse solves of every step so far: how many did not reach the tolerance, the most
  /// iterations and the worst residual.
  const NscSolveSummary& solve_summary() const { return summary_; }
  /// The contacts of the last step (at its start) and their impulses (N s), three per contact:
  /// along n_G, then along two tangents (see ContactFrame).
  const std::vector<UnilateralContact>& last_contacts() const { return contacts_; }
  VecX last_impulses() const {
    return gamma_.head(3 * static_cast<Eigen::Index>(contacts_.size()));
  }
  /// The impulse of the last step's contacts on every body of the system, ground included
  /// (`per_body` resized to System::num_bodies()); zero before the first step and after a step
  /// without contacts.
  void LastBodyImpulses(std::vector<BodyContactImpulse>& per_body) const;
  /// The contact provider.
  const std::shared_ptr<const ContactProvider>& provider() const { return provider_; }
  /// The two unit tangents the stepper uses with normal `n_G` (t1 x t2 = n_G).
  static void ContactFrame(const Vec3& n_G, Vec3& t1, Vec3& t2);

 private:
  void Step(State& state, double h, double t_new) override;
  // Step 2-5: turns v_free_ into v+ for the contacts of `state` (v0_ its velocities).
  void SolveContacts(const State& state, double h);
  // The blocks of A^-1 between the twists of every pair of bodies in contact, into X_.
  void SolveBodyBlocks();
  // Starts gamma_ from the previous step's impulse of the same contact (same bodies, point
  // within 1 cm, normal within 8 degrees), zero for new contacts.
  void WarmStart();

  std::shared_ptr<const ContactProvider> provider_;
  NscSettings nsc_;
  NscStepReport report_;
  NscSolveSummary summary_;
  std::vector<UnilateralContact> contacts_;
  // The previous step's contacts and impulses, to warm-start the solve (WarmStart).
  std::vector<UnilateralContact> previous_contacts_;
  VecX previous_gamma_;
  // Per contact: its two bodies' 3x6 rows (sign included) and their slots in bodies_ (-1 for
  // ground).
  struct Rows {
    Eigen::Matrix<double, 3, 6> J[2];
    int slot[2] = {-1, -1};
    Vec3 arm[2];  // from each body's origin (ground's too) to its surface point, in G
  };
  std::vector<Rows> rows_;
  std::vector<int> bodies_;     // bodies in contact (not ground)
  std::vector<int> body_slot_;  // per System body: its slot in bodies_, or -1
  MatX X_;                      // nv x 6 per body in contact: A^-1 columns
  MatX Y_;                      // 6 per body in contact x 3 per contact: A^-1 D^T there
  MatX W_;                      // Delassus operator
  VecX rhs_, solution_;         // the contact impulses' solves
  VecX u_free_, u_, target_, mu_, gamma_;
  ContactSolverWorkspace workspace_;  // APGD's buffers
};

}  // namespace sinew::engine
