// "cvode" and "cvode-gmres": SUNDIALS CVODE's variable-order BDF (orders 1 to 5) with Newton
// iteration. Implicit and error-controlled: meant for stiff models (muscles with stiff tendons,
// fibers that start far from equilibrium), where an explicit scheme's steps are bounded by
// stability, not accuracy. Newton's linear systems (I - gamma J) x = r are solved
//  - "cvode": by a dense LU of CVODE's difference-quotient Jacobian (one evaluation per column
//    of the n-vector, so n evaluations each time CVODE refreshes it; O(n^3) factorization):
//    best for small models (arm26);
//  - "cvode-gmres": matrix-free by GMRES without a preconditioner (each product J v is one
//    difference-quotient evaluation), no Jacobian is ever formed: best for large models
//    (Rajagopal2016, PushUpToesOnGroundWithMuscles), whose stiff modes are few and isolated.
//  - "cvode-gmres-bd": the same GMRES, preconditioned on the right by P = I - gamma J_zz on the
//    auxiliary states z (identity on positions and velocities), J_zz block-diagonal with one
//    n_k x n_k block per force element (a muscle's activation and fiber length: 2 x 2), each by
//    forward differences of that element's own CalcStateVariableDerivatives over its own z
//    (n_k calls of one element, no full evaluation), recomputed only when CVODE says the kept
//    one is stale (its jok), refactored for every new gamma. Faster than "cvode-gmres" where
//    fibers are far from equilibrium (PushUpToesOnGroundWithMuscles, arm26), slower where the
//    Newton iteration already needs about one GMRES iteration (Rajagopal2016 from
//    equilibrium): docs/benchmarks.md.
//
// It integrates the same vector as rk45 (see state_vector.h) with rtol = atol = accuracy (rk45's
// unit absolute floor; CVODE weighs errors in the RMS norm, rk45 in the max norm). After each
// step CVODE calls a projection (CVodeSetProjFn): positions onto the constraints (Newton),
// velocities by least squares, quaternions normalized; CVODE then corrects its history with
// the projection, so the next step starts on the constraints. Dense output comes from CVODE's
// interpolating polynomial (CVodeGetDky), projected as rk45's is.
//
// A state passed to Advance or StepTo that differs from the one the last step returned (time,
// integrated values, or inputs without a controller) restarts CVODE from it (order 1).
#pragma once

#include <sinew/engine/integrator.h>

#include <memory>

namespace sinew::engine {

/// How Newton's linear systems are solved (see above).
enum class CvodeLinearSolver {
  kDense,                    ///< "cvode"
  kGmres,                    ///< "cvode-gmres"
  kGmresBlockPreconditioned  ///< "cvode-gmres-bd"
};

/// Makes the "cvode" (kDense), "cvode-gmres" (kGmres) or "cvode-gmres-bd" integrator. Throws
/// sinew::Error when CVODE cannot be set up.
std::unique_ptr<Integrator> MakeCvodeIntegrator(const System& system,
                                                const IntegratorSettings& settings,
                                                CvodeLinearSolver linear_solver);

}  // namespace sinew::engine
