#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <cvode/cvode_proj.h>
#include <nvector/nvector_serial.h>
#include <sinew/common/error.h>
#include <sinew/common/text.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/cvode_integrator.h>
#include <sinew/engine/dynamics.h>
#include <sinew/engine/projection.h>
#include <sinew/engine/state_vector.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace sinew::engine {
namespace {

using VecMap = Eigen::Map<VecX>;

VecMap View(N_Vector v) { return VecMap(N_VGetArrayPointer(v), N_VGetLength(v)); }

std::string FlagName(int flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string text = name ? name : std::to_string(flag);
  std::free(name);
  return text;
}

class CvodeIntegrator final : public Integrator {
 public:
  CvodeIntegrator(const System& system, const IntegratorSettings& settings,
                  CvodeLinearSolver linear_solver)
      : Integrator(system, settings),
        name_(SolverName(linear_solver)),
        vector_(system, kkt_),
        preconditioned_(linear_solver == CvodeLinearSolver::kGmresBlockPreconditioned) {
    if (SUNContext_Create(nullptr, &context_) != 0) Fail("SUNContext_Create", -1);
    const int n = vector_.size();
    y_ = N_VNew_Serial(n, context_);
    dky_ = N_VNew_Serial(n, context_);
    if (linear_solver == CvodeLinearSolver::kDense) {
      matrix_ = SUNDenseMatrix(n, n, context_);
      solver_ = SUNLinSol_Dense(y_, matrix_, context_);
    } else {
      // 0: CVODE's default basis (5 vectors). The preconditioner is applied on the right, so
      // GMRES still stops on the residual of Newton's system itself, as without one (left
      // preconditioning, which tests P^-1 times the residual, took 17% more steps on
      // Rajagopal2016 and as many on arm26 and PushUpToesOnGroundWithMuscles).
      solver_ = SUNLinSol_SPGMR(y_, preconditioned_ ? SUN_PREC_RIGHT : SUN_PREC_NONE, 0, context_);
    }
    memory_ = CVodeCreate(CV_BDF, context_);
    if (!y_ || !dky_ || !solver_ || !memory_ ||
        (linear_solver == CvodeLinearSolver::kDense && !matrix_)) {
      Release();
      throw Error("integrator '" + name_ + "': CVODE could not be set up (out of memory)");
    }
    zdot_.resize(vector_.num_state_variables());
    last_end_.resize(n);
    packed_.resize(n);
    if (preconditioned_) LayOutBlocks();
  }
  ~CvodeIntegrator() override { Release(); }
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  bool HasDenseOutput() const override { return true; }
  void Interpolate(double t, State& out) override;

 protected:
  void TakeStep(State& state, double t_limit) override;

 private:
  // CVODE's callbacks; exceptions are caught, kept, and rethrown after CVODE returns.
  static int Rhs(double t, N_Vector y, N_Vector ydot, void* self);
  static int Project(double t, N_Vector y, N_Vector correction, double eps, N_Vector err,
                     void* self);
  static void KeepMessage(int code, const char* module, const char* function, char* message,
                          void* self);
  static int SetUpPreconditioner(double t, N_Vector y, N_Vector fy, sunbooleantype jok,
                                 sunbooleantype* jcur, double gamma, void* self);
  static int SolvePreconditioner(double t, N_Vector y, N_Vector fy, N_Vector r, N_Vector z,
                                 double gamma, double delta, int lr, void* self);

  static const char* SolverName(CvodeLinearSolver solver) {
    switch (solver) {
      case CvodeLinearSolver::kDense:
        return "cvode";
      case CvodeLinearSolver::kGmres:
        return "cvode-gmres";
      case CvodeLinearSolver::kGmresBlockPreconditioned:
        return "cvode-gmres-bd";
    }
    return "cvode";
  }
  // One block per force element with state variables: where its z start and how many.
  void LayOutBlocks();
  // J_zz's blocks at `state` by forward differences, each element's z alone (its zdot at the
  // unperturbed z is `zdot0`).
  void CalcStateVariableJacobian(State& state, Eigen::Ref<const VecX> zdot0);
  // The blocks of P^-1 = (I - gamma J_zz)^-1 from the kept J_zz; false when one is singular.
  bool InvertBlocks(double gamma);

  // (Re)starts CVODE at `state`.
  void Restart(const State& state);
  bool IsWhereLastStepEnded(const State& state);
  void Check(int flag, const char* call);
  [[noreturn]] void Fail(const char* call, int flag);
  void Release();

  std::string name_;  // "cvode" or "cvode-gmres", for messages
  StateVector vector_;
  SUNContext context_ = nullptr;
  N_Vector y_ = nullptr;
  N_Vector dky_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver solver_ = nullptr;
  void* memory_ = nullptr;
  bool initialized_ = false;

  State scratch_;     // the state at which the right-hand side is evaluated
  VecX zdot_;         // the state variables' derivatives of one evaluation
  State step_start_;  // the state the last step started from (inputs, angle branches)
  VecX last_end_;     // Pack of the state the last step returned, and its inputs
  VecX packed_;       // Pack of the state passed in (preallocated: steps do not allocate)
  VecX last_inputs_;
  double last_t_ = 0.0;
  long counted_rejections_ = 0;  // CVODE's failure counters since the last restart
  long counted_linear_iterations_ = 0;
  long counted_preconditioner_setups_ = 0;

  // The block-diagonal preconditioner (kGmresBlockPreconditioned): per force element with
  // state variables, its z's place in y and its block of J_zz = d(zdot)/dz and of P^-1, both
  // packed column-major, n_k^2 entries from `offset`.
  struct Block {
    int row = 0;     // first row of the element's z in y
    int size = 0;    // n_k
    int offset = 0;  // into jacobian_ and inverse_
  };
  bool preconditioned_ = false;
  std::vector<Block> blocks_;
  std::vector<int> block_elements_;  // force element of each block
  VecX jacobian_, inverse_;
  VecX zdot_moved_;  // one element's zdot at a perturbed z
  std::exception_ptr callback_error_;
  std::string message_;  // CVODE's last error message
};

void CvodeIntegrator::Release() {
  if (memory_) CVodeFree(&memory_);
  if (solver_) SUNLinSolFree(solver_);
  if (matrix_) SUNMatDestroy(matrix_);
  if (dky_) N_VDestroy(dky_);
  if (y_) N_VDestroy(y_);
  if (context_) SUNContext_Free(&context_);
}

void CvodeIntegrator::Fail(const char* call, int flag) {
  double t = last_t_;
  if (memory_) CVodeGetCurrentTime(memory_, &t);
  std::string text = "integrator '" + name_ + "': " + std::string(call) + " failed with " +
                     FlagName(flag) + " at t = " + FormatNumber(t) + " s";
  if (!message_.empty()) text += ": " + message_;
  throw Error(text);
}

void CvodeIntegrator::Check(int flag, const char* call) {
  if (flag < 0) Fail(call, flag);
}

int CvodeIntegrator::Rhs(double t, N_Vector y, N_Vector ydot, void* self) {
  auto& me = *static_cast<CvodeIntegrator*>(self);
  try {
    me.vector_.Unpack(View(y), t, me.scratch_);
    const Accelerations& acc = me.Evaluate(me.scratch_, me.zdot_);
    VecMap yd = View(ydot);
    me.vector_.Derivative(View(y), me.scratch_, acc.vdot, me.zdot_, yd);
    // A non-finite derivative (e.g. a trial state far outside a muscle's curves): recoverable,
    // CVODE retries with a smaller step.
    return yd.allFinite() ? 0 : 1;
  } catch (const NonFiniteForceError& e) {
    me.message_ = e.what();  // recoverable too; named if CVODE gives up
    return 1;
  } catch (...) {
    me.callback_error_ = std::current_exception();
    return -1;
  }
}

int CvodeIntegrator::Project(double t, N_Vector y, N_Vector correction, double, N_Vector,
                             void* self) {
  auto& me = *static_cast<CvodeIntegrator*>(self);
  try {
    const VecMap yv = View(y);
    me.vector_.Unpack(yv, t, me.scratch_);
    if (!me.system_.constraints().empty()) {
      if (!ProjectPositions(me.system_, me.scratch_, me.ConstraintTolerance(), me.kkt_, 10,
                            &me.stats_.projection_factorizations)) {
        ++me.stats_.projection_failures;
        return 1;  // recoverable: CVODE retries the step with a smaller one
      }
      ProjectVelocities(me.system_, me.scratch_, me.kkt_);
      UpdateDirectCoordinates(me.system_, me.scratch_);
    }
    VecMap corr = View(correction);
    me.vector_.PackInto(me.scratch_, corr);
    corr -= yv;
    return 0;
  } catch (...) {
    me.callback_error_ = std::current_exception();
    return -1;
  }
}

void CvodeIntegrator::LayOutBlocks() {
  const int z_row = vector_.size() - vector_.num_state_variables();
  int offset = 0, largest = 0;
  for (int k = 0; k < static_cast<int>(system_.force_elements().size()); ++k) {
    const int n = system_.NumStateVariables(k);
    if (n == 0) continue;
    blocks_.push_back({z_row + system_.StateVariableBegin(k), n, offset});
    block_elements_.push_back(k);
    offset += n * n;
    largest = std::max(largest, n);
  }
  jacobian_ = VecX::Zero(offset);
  inverse_ = VecX::Zero(offset);
  zdot_moved_.resize(largest);
}

void CvodeIntegrator::CalcStateVariableJacobian(State& state, Eigen::Ref<const VecX> zdot0) {
  const int z_row = vector_.size() - vector_.num_state_variables();
  for (size_t i = 0; i < blocks_.size(); ++i) {
    const Block& block = blocks_[i];
    const int k = block_elements_[i];
    const int begin = block.row - z_row;
    const ForceContext context = system_.MakeForceContext(k, state);
    auto moved = zdot_moved_.head(block.size);
    for (int j = 0; j < block.size; ++j) {
      // CVODE's own difference-quotient increment: sqrt(unit roundoff) relative, with the
      // tolerance's unit floor.
      double& zj = state.z[begin + j];
      const double kept = zj;
      const double h =
          std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(std::abs(zj), 1.0);
      zj = kept + h;
      const double dz = zj - kept;  // the increment as represented
      system_.force_elements()[k]->CalcStateVariableDerivatives(context, moved);
      zj = kept;
      for (int r = 0; r < block.size; ++r) {
        jacobian_[block.offset + j * block.size + r] = (moved[r] - zdot0[begin + r]) / dz;
      }
    }
  }
}

bool CvodeIntegrator::InvertBlocks(double gamma) {
  for (const Block& block : blocks_) {
    const int n = block.size;
    const double* J = jacobian_.data() + block.offset;
    double* inv = inverse_.data() + block.offset;
    if (n == 1) {
      const double p = 1.0 - gamma * J[0];
      if (!(std::abs(p) > 1e-12)) return false;
      inv[0] = 1.0 / p;
    } else if (n == 2) {
      const double a = 1.0 - gamma * J[0], c = -gamma * J[1];  // column-major: J[1] is (1, 0)
      const double b = -gamma * J[2], d = 1.0 - gamma * J[3];
      const double det = a * d - b * c;
      if (!(std::abs(det) > 1e-12 * (std::abs(a * d) + std::abs(b * c)))) return false;
      inv[0] = d / det;
      inv[1] = -c / det;
      inv[2] = -b / det;
      inv[3] = a / det;
    } else {
      const Eigen::Map<const MatX> Jk(J, n, n);
      const MatX P = MatX::Identity(n, n) - gamma * Jk;
      Eigen::FullPivLU<MatX> lu(P);
      if (!lu.isInvertible()) return false;
      Eigen::Map<MatX>(inv, n, n) = lu.inverse();
    }
  }
  return true;
}

int CvodeIntegrator::SetUpPreconditioner(double t, N_Vector y, N_Vector fy, sunbooleantype jok,
                                         sunbooleantype* jcur, double gamma, void* self) {
  auto& me = *static_cast<CvodeIntegrator*>(self);
  try {
    if (jok) {
      *jcur = SUNFALSE;  // CVODE judged the kept J_zz good enough: only gamma changed
    } else {
      me.vector_.Unpack(View(y), t, me.scratch_);
      me.ApplyController(me.scratch_);  // the inputs of the evaluation that gave fy
      const VecMap fyv = View(fy);
      me.CalcStateVariableJacobian(me.scratch_, fyv.tail(me.vector_.num_state_variables()));
      *jcur = SUNTRUE;
    }
    // A singular block: recoverable, CVODE retries (with a fresh J_zz or a smaller step).
    return me.InvertBlocks(gamma) ? 0 : 1;
  } catch (...) {
    me.callback_error_ = std::current_exception();
    return -1;
  }
}

int CvodeIntegrator::SolvePreconditioner(double, N_Vector, N_Vector, N_Vector r, N_Vector z, double,
                                         double, int, void* self) {
  auto& me = *static_cast<CvodeIntegrator*>(self);
  const VecMap rv = View(r);
  VecMap zv = View(z);
  zv = rv;  // identity on positions and velocities
  for (const Block& block : me.blocks_) {
    const int n = block.size;
    const double* inv = me.inverse_.data() + block.offset;
    for (int i = 0; i < n; ++i) {
      double sum = 0.0;
      for (int j = 0; j < n; ++j) sum += inv[j * n + i] * rv[block.row + j];
      zv[block.row + i] = sum;
    }
  }
  return 0;
}

void CvodeIntegrator::KeepMessage(int, const char*, const char* function, char* message,
                                  void* self) {
  auto& me = *static_cast<CvodeIntegrator*>(self);
  me.message_ = std::string(function) + ": " + message;
}

void CvodeIntegrator::Restart(const State& state) {
  scratch_ = state;
  vector_.PackInto(state, View(y_));
  if (!initialized_) {
    Check(CVodeSetErrHandlerFn(memory_, &KeepMessage, this), "CVodeSetErrHandlerFn");
    Check(CVodeInit(memory_, &Rhs, state.t, y_), "CVodeInit");
    Check(CVodeSetUserData(memory_, this), "CVodeSetUserData");
    Check(CVodeSStolerances(memory_, settings_.accuracy, settings_.accuracy), "CVodeSStolerances");
    Check(CVodeSetLinearSolver(memory_, solver_, matrix_), "CVodeSetLinearSolver");
    if (preconditioned_) {
      Check(CVodeSetPreconditioner(memory_, &SetUpPreconditioner, &SolvePreconditioner),
            "CVodeSetPreconditioner");
    }
    if (settings_.step > 0.0) Check(CVodeSetMaxStep(memory_, settings_.step), "CVodeSetMaxStep");
    Check(CVodeSetMinStep(memory_, settings_.min_step), "CVodeSetMinStep");
    Check(CVodeSetProjFn(memory_, &Project), "CVodeSetProjFn");
    // The projection does not project CVODE's error estimate: keep the unprojected one.
    Check(CVodeSetProjErrEst(memory_, SUNFALSE), "CVodeSetProjErrEst");
    initialized_ = true;
  } else {
    Check(CVodeReInit(memory_, state.t, y_), "CVodeReInit");
  }
  counted_rejections_ = 0;
  counted_linear_iterations_ = 0;
  counted_preconditioner_setups_ = 0;
}

bool CvodeIntegrator::IsWhereLastStepEnded(const State& state) {
  if (!initialized_ || state.t != last_t_) return false;
  if (!controller_ && state.inputs != last_inputs_) return false;
  vector_.PackInto(state, packed_);
  return packed_ == last_end_;
}

void CvodeIntegrator::TakeStep(State& state, double t_limit) {
  message_.clear();
  if (!IsWhereLastStepEnded(state)) Restart(state);
  step_start_ = state;
  scratch_.inputs = state.inputs;
  scratch_.discrete = state.discrete;  // the force elements' data for this step
  Check(CVodeSetStopTime(memory_, t_limit), "CVodeSetStopTime");
  double t_reached = state.t;
  const int flag = CVode(memory_, t_limit, y_, &t_reached, CV_ONE_STEP);
  if (callback_error_) {
    const std::exception_ptr error = std::exchange(callback_error_, nullptr);
    last_t_ = std::numeric_limits<double>::quiet_NaN();  // restart from the caller's state
    std::rethrow_exception(error);
  }
  if (flag < 0) {
    last_t_ = std::numeric_limits<double>::quiet_NaN();  // restart next time
    Fail("CVode", flag);
  }
  long error_fails = 0, convergence_fails = 0;
  CVodeGetNumErrTestFails(memory_, &error_fails);
  CVodeGetNumNonlinSolvConvFails(memory_, &convergence_fails);
  stats_.rejected += error_fails + convergence_fails - counted_rejections_;
  counted_rejections_ = error_fails + convergence_fails;
  if (!matrix_) {
    long linear_iterations = 0, setups = 0;
    CVodeGetNumLinIters(memory_, &linear_iterations);
    CVodeGetNumPrecEvals(memory_, &setups);
    stats_.linear_iterations += linear_iterations - counted_linear_iterations_;
    stats_.preconditioner_setups += setups - counted_preconditioner_setups_;
    counted_linear_iterations_ = linear_iterations;
    counted_preconditioner_setups_ = setups;
  }
  ++stats_.steps;
  vector_.Unpack(View(y_), t_reached, state);
  last_t_ = t_reached;
  vector_.PackInto(state, last_end_);
  last_inputs_ = state.inputs;
}

void CvodeIntegrator::Interpolate(double t, State& out) {
  const int flag = initialized_ ? CVodeGetDky(memory_, t, 0, dky_) : CV_BAD_T;
  if (flag != CV_SUCCESS) {
    throw Error("integrator '" + name_ + "': Interpolate at t = " + FormatNumber(t) +
                " s, outside the last step (" + FlagName(flag) + ")");
  }
  out = step_start_;
  vector_.Unpack(View(dky_), t, out);
  if (!system_.constraints().empty()) {
    if (!ProjectPositions(system_, out, ConstraintTolerance(), kkt_, 10,
                          &stats_.projection_factorizations)) {
      throw Error("integrator '" + name_ + "': the interpolated state at t = " + FormatNumber(t) +
                  " s could not be projected onto the constraints");
    }
    ProjectVelocities(system_, out, kkt_);
    UpdateDirectCoordinates(system_, out);
  }
  ApplyController(out);
}

}  // namespace

std::unique_ptr<Integrator> MakeCvodeIntegrator(const System& system,
                                                const IntegratorSettings& settings,
                                                CvodeLinearSolver linear_solver) {
  return std::make_unique<CvodeIntegrator>(system, settings, linear_solver);
}

}  // namespace sinew::engine
