#include <sinew/common/error.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/nsc_integrator.h>
#include <sinew/engine/projection.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace sinew::engine {
namespace {

// The buffers sized by the number of contacts never shrink (a step with fewer contacts than an
// earlier one allocates nothing; callers use their top-left corners) and grow to twice what is
// asked: a run whose contacts keep rising by one or two reallocates about log2 of its largest
// count times, not at every new largest count.
Eigen::Index Grown(Eigen::Index have, Eigen::Index need) {
  return need <= have ? have : 2 * need;
}
void Reserve(MatX& m, Eigen::Index rows, Eigen::Index cols) {
  if (m.rows() < rows || m.cols() < cols) m.resize(Grown(m.rows(), rows), Grown(m.cols(), cols));
}
void Reserve(VecX& v, Eigen::Index size) {
  if (v.size() < size) v.resize(Grown(v.size(), size));
}

}  // namespace

NscIntegrator::NscIntegrator(const System& system, std::shared_ptr<const ContactProvider> provider,
                             const IntegratorSettings& settings, const NscSettings& nsc)
    : FixedStepIntegrator(system, settings, "nsc"), provider_(std::move(provider)), nsc_(nsc) {
  if (!provider_) throw Error("integrator 'nsc': no contact provider");
  if (nsc.solver.max_iterations < 1) {
    throw Error("integrator 'nsc': the impulse solver needs max_iterations >= 1");
  }
  if (nsc.solver.method != ContactSolverMethod::kGaussSeidel &&
      nsc.solver.method != ContactSolverMethod::kApgd) {
    throw Error("integrator 'nsc': unknown impulse solver method");
  }
  if (!(nsc.solver.tolerance >= 0.0)) throw Error("integrator 'nsc': tolerance must be >= 0");
  if (!(nsc.max_recovery_speed >= 0.0)) {
    throw Error("integrator 'nsc': max_recovery_speed must be >= 0");
  }
  if (!(nsc.min_bounce_speed >= 0.0)) {
    throw Error("integrator 'nsc': min_bounce_speed must be >= 0");
  }
  body_slot_.assign(system.num_bodies(), -1);
}

void NscIntegrator::ContactFrame(const Vec3& n_G, Vec3& t1, Vec3& t2) {
  // The axis least aligned with n, crossed with n.
  Eigen::Index axis = 0;
  n_G.cwiseAbs().minCoeff(&axis);
  t1 = n_G.cross(Vec3::Unit(axis)).normalized();
  t2 = n_G.cross(t1);
}

void NscIntegrator::Step(State& state, double h, double t_new) {
  // 1. The step without contact (as "euler").
  SolveFreeVelocities(state, h, t_new);
  // 2-5. Contacts.
  contacts_.clear();
  provider_->FindContacts(system_, state, contacts_);
  report_ = NscStepReport{h, static_cast<int>(contacts_.size()), 0, 0, 0.0};
  if (!contacts_.empty()) {
    SolveContacts(state, h);
    ++summary_.solves;
    // The solver's own test: it stops once the residual is at most the tolerance.
    if (!(report_.residual <= nsc_.solver.tolerance)) ++summary_.unconverged;
    summary_.most_iterations = std::max(summary_.most_iterations, report_.iterations);
    summary_.worst_residual = std::max(summary_.worst_residual, report_.residual);
  } else {
    previous_contacts_.clear();
  }
  FinishStep(state, h);
}

void NscIntegrator::SolveContacts(const State& state, double h) {
  const int m = static_cast<int>(contacts_.size());
  const int nv = kkt_.num_velocities();
  // Rows of each contact over its bodies' twists [w; v] (about the body origin, in G): the
  // velocity of body2's point minus body1's, along n, t1, t2.
  rows_.resize(m);
  for (int b : bodies_) body_slot_[b] = -1;
  bodies_.clear();
  for (int i = 0; i < m; ++i) {
    const UnilateralContact& c = contacts_[i];
    if (c.body1 < 0 || c.body2 < 0 || c.body1 >= system_.num_bodies() ||
        c.body2 >= system_.num_bodies() || !(c.friction >= 0.0) ||
        !(c.restitution >= 0.0 && c.restitution <= 1.0) || !std::isfinite(c.depth) ||
        !c.p_G.allFinite() || !(std::abs(c.n_G.norm() - 1.0) < 1e-6)) {
      throw Error("integrator 'nsc': contact " + std::to_string(i) + " between bodies " +
                  std::to_string(c.body1) + " and " + std::to_string(c.body2) +
                  " at t = " + std::to_string(state.t) +
                  " s is invalid (needs bodies of the system, a unit normal, finite point and "
                  "depth, friction >= 0, restitution in [0, 1])");
    }
    Vec3 t1, t2;
    ContactFrame(c.n_G, t1, t2);
    const Vec3 d[3] = {c.n_G, t1, t2};
    const int body[2] = {c.body1, c.body2};
    // Each body's impulse acts at its own surface point, half the depth from the midway point
    // p_G (body1's along +n, body2's along -n), where it is when the gap closes: so a ball's
    // friction impulse has the ball's radius as its lever however far above the floor its
    // landing step starts, and a sphere's normal impulse passes through its centre.
    const Vec3 p_G[2] = {c.p_G + 0.5 * c.depth * c.n_G, c.p_G - 0.5 * c.depth * c.n_G};
    for (int s = 0; s < 2; ++s) {
      Rows& r = rows_[i];
      r.slot[s] = -1;
      r.arm[s] = p_G[s] - state.bodies[body[s]].p_GB;
      if (body[s] == 0) continue;
      const double sign = s == 0 ? -1.0 : 1.0;
      const Vec3& arm = r.arm[s];
      for (int k = 0; k < 3; ++k) {
        r.J[s].block<1, 3>(k, 0) = sign * arm.cross(d[k]).transpose();
        r.J[s].block<1, 3>(k, 3) = sign * d[k].transpose();
      }
      if (body_slot_[body[s]] < 0) {
        body_slot_[body[s]] = static_cast<int>(bodies_.size());
        bodies_.push_back(body[s]);
      }
      r.slot[s] = body_slot_[body[s]];
    }
  }
  SolveBodyBlocks();
  // Y = A^-1 D^T on the bodies in contact: the twists of each under each contact's unit
  // impulses (6 rows per body, 3 columns per contact), from the blocks of A^-1.
  const int nb = static_cast<int>(bodies_.size());
  Reserve(Y_, 6 * nb, 3 * m);
  for (int i = 0; i < m; ++i) {
    for (int target = 0; target < nb; ++target) {
      Eigen::Matrix<double, 6, 3> Y_ti = Eigen::Matrix<double, 6, 3>::Zero();
      for (int t = 0; t < 2; ++t) {
        const int source = rows_[i].slot[t];
        if (source < 0) continue;
        Y_ti.noalias() += X_.block<6, 6>(6 * target, 6 * source) * rows_[i].J[t].transpose();
      }
      Y_.block<6, 3>(6 * target, 3 * i) = Y_ti;
    }
  }
  // W = D A^-1 D^T = D Y block by block (symmetric: the blocks below the diagonal are the
  // transposes of those above), u_free = D v_free, and the targets.
  Reserve(W_, 3 * m, 3 * m);
  workspace_.Reserve(W_.rows());  // the impulse solver's buffers grow with W's
  for (VecX* v : {&u_free_, &u_, &gamma_}) Reserve(*v, 3 * m);
  Reserve(target_, m);
  Reserve(mu_, m);
  for (int k = 0; k < m; ++k) {
    const UnilateralContact& c = contacts_[k];
    const int body_of[2] = {c.body1, c.body2};
    Eigen::Vector3d u_free = Eigen::Vector3d::Zero(), u_start = Eigen::Vector3d::Zero();
    for (int i = k; i < m; ++i) {
      Eigen::Matrix3d W_ki = Eigen::Matrix3d::Zero();
      for (int s = 0; s < 2; ++s) {
        const int target = rows_[k].slot[s];
        if (target < 0) continue;
        W_ki.noalias() += rows_[k].J[s] * Y_.block<6, 3>(6 * target, 3 * i);
      }
      W_.block<3, 3>(3 * k, 3 * i) = W_ki;
      if (i != k) W_.block<3, 3>(3 * i, 3 * k) = W_ki.transpose();
    }
    for (int s = 0; s < 2; ++s) {
      if (rows_[k].slot[s] < 0) continue;
      const int col = kkt_.BodyColumn(body_of[s]);
      u_free += rows_[k].J[s] * v_free_.segment<6>(col);
      u_start += rows_[k].J[s] * v0_.segment<6>(col);
    }
    u_free_.segment<3>(3 * k) = u_free;
    mu_[k] = c.friction;
    // Normal target: the gap closes at most within the step; an overlap opens at most at the
    // recovery speed; an impact that closes the gap during the step rebounds at e times its
    // approach speed.
    const double gap = -c.depth;
    double target = gap >= 0.0 ? -gap / h : std::min(-gap / h, nsc_.max_recovery_speed);
    if (c.restitution > 0.0 && u_start[0] < -nsc_.min_bounce_speed && gap + h * u_free[0] <= 0.0) {
      target = std::max(target, -c.restitution * u_start[0]);
    }
    target_[k] = target;
  }
  WarmStart();
  auto gamma = gamma_.head(3 * m);
  const ContactSolverResult result =
      SolveContactImpulses(W_.topLeftCorner(3 * m, 3 * m), u_free_.head(3 * m), target_.head(m),
                           mu_.head(m), nsc_.solver, workspace_, gamma, u_.head(3 * m));
  report_.iterations = result.iterations;
  report_.products = result.products;
  report_.residual = result.residual;
  // v+ = v_free + A^-1 D^T gamma.
  rhs_.setZero(nv + kkt_.num_equations());
  for (int i = 0; i < m; ++i) {
    const int body_of[2] = {contacts_[i].body1, contacts_[i].body2};
    for (int s = 0; s < 2; ++s) {
      if (rows_[i].slot[s] < 0) continue;
      rhs_.segment<6>(kkt_.BodyColumn(body_of[s])) +=
          rows_[i].J[s].transpose() * gamma.segment<3>(3 * i);
    }
  }
  kkt_.Solve(rhs_, solution_);
  v_free_ += solution_.head(nv);
  // A copy assignment would size the vector exactly: grow it as the buffers above.
  if (previous_contacts_.capacity() < contacts_.size())
    previous_contacts_.reserve(2 * contacts_.size());
  previous_contacts_ = contacts_;
  Reserve(previous_gamma_, 3 * m);
  previous_gamma_.head(3 * m) = gamma;
}

void NscIntegrator::LastBodyImpulses(std::vector<BodyContactImpulse>& per_body) const {
  per_body.assign(system_.num_bodies(), BodyContactImpulse{});
  for (size_t i = 0; i < contacts_.size(); ++i) {
    const UnilateralContact& c = contacts_[i];
    Vec3 t1, t2;
    ContactFrame(c.n_G, t1, t2);
    const Eigen::Vector3d gamma = gamma_.segment<3>(3 * static_cast<Eigen::Index>(i));
    // On body2 along +n and the tangents, on body1 the opposite (the rows are body2's point
    // velocity minus body1's).
    const Vec3 p = gamma[0] * c.n_G + gamma[1] * t1 + gamma[2] * t2;
    const int body[2] = {c.body1, c.body2};
    for (int s = 0; s < 2; ++s) {
      const Vec3 p_s = s == 0 ? Vec3(-p) : p;
      per_body[body[s]].linear += p_s;
      per_body[body[s]].angular += rows_[i].arm[s].cross(p_s);
    }
  }
}

void NscIntegrator::WarmStart() {
  const int m = static_cast<int>(contacts_.size());
  for (int i = 0; i < m; ++i) {
    const UnilateralContact& c = contacts_[i];
    gamma_.segment<3>(3 * i).setZero();
    for (size_t k = 0; k < previous_contacts_.size(); ++k) {
      const UnilateralContact& p = previous_contacts_[k];
      if (p.body1 == c.body1 && p.body2 == c.body2 && (p.p_G - c.p_G).norm() < 1e-2 &&
          p.n_G.dot(c.n_G) > 0.99) {
        gamma_.segment<3>(3 * i) = previous_gamma_.segment<3>(3 * static_cast<int>(k));
        break;
      }
    }
  }
}

void NscIntegrator::SolveBodyBlocks() {
  const Eigen::Index nb = static_cast<Eigen::Index>(bodies_.size());
  Reserve(X_, 6 * nb, 6 * nb);
  for (Eigen::Index source = 0; source < nb; ++source) {
    auto X_source = X_.block(0, 6 * source, 6 * nb, 6);
    if (kkt_.SolveUnitLoadResponses(bodies_[source], bodies_, X_source)) continue;
    // The dense method (cross-checks only): six full solves, keeping the rows of the bodies in
    // contact.
    const int nv = kkt_.num_velocities();
    rhs_.setZero(nv + kkt_.num_equations());
    const int col = kkt_.BodyColumn(bodies_[source]);
    for (int j = 0; j < 6; ++j) {
      rhs_[col + j] = 1.0;
      kkt_.Solve(rhs_, solution_);
      rhs_[col + j] = 0.0;
      for (Eigen::Index target = 0; target < nb; ++target) {
        X_source.block<6, 1>(6 * target, j) =
            solution_.segment<6>(kkt_.BodyColumn(bodies_[target]));
      }
    }
  }
}

}  // namespace sinew::engine
