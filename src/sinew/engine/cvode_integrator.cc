#include <cvode/cvode.h>
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

#include <cstdlib>
#include <exception>
#include <limits>
#include <string>
#include <utility>

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
        name_(linear_solver == CvodeLinearSolver::kDense ? "cvode" : "cvode-gmres"),
        vector_(system, kkt_) {
    if (SUNContext_Create(nullptr, &context_) != 0) Fail("SUNContext_Create", -1);
    const int n = vector_.size();
    y_ = N_VNew_Serial(n, context_);
    dky_ = N_VNew_Serial(n, context_);
    if (linear_solver == CvodeLinearSolver::kDense) {
      matrix_ = SUNDenseMatrix(n, n, context_);
      solver_ = SUNLinSol_Dense(y_, matrix_, context_);
    } else {
      solver_ = SUNLinSol_SPGMR(y_, SUN_PREC_NONE, 0, context_);  // 0: CVODE's default basis
    }
    memory_ = CVodeCreate(CV_BDF, context_);
    if (!y_ || !dky_ || !solver_ || !memory_ ||
        (linear_solver == CvodeLinearSolver::kDense && !matrix_)) {
      Release();
      throw Error("integrator '" + name_ + "': CVODE could not be set up (out of memory)");
    }
    zdot_.resize(vector_.num_state_variables());
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

  // (Re)starts CVODE at `state`.
  void Restart(const State& state);
  bool IsWhereLastStepEnded(const State& state) const;
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
  VecX last_inputs_;
  double last_t_ = 0.0;
  long counted_rejections_ = 0;  // CVODE's failure counters since the last restart
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
}

bool CvodeIntegrator::IsWhereLastStepEnded(const State& state) const {
  if (!initialized_ || state.t != last_t_) return false;
  if (!controller_ && state.inputs != last_inputs_) return false;
  return vector_.Pack(state) == last_end_;
}

void CvodeIntegrator::TakeStep(State& state, double t_limit) {
  message_.clear();
  if (!IsWhereLastStepEnded(state)) Restart(state);
  step_start_ = state;
  scratch_.inputs = state.inputs;
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
  ++stats_.steps;
  vector_.Unpack(View(y_), t_reached, state);
  last_t_ = t_reached;
  last_end_ = vector_.Pack(state);
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
