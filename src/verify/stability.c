/* Fast rotation: centrifugal softening. In the rotating frame the centrifugal term theta'^2 (x + xi)
   lowers the stiffness: a mode with K v = kappa rho M v has the equation rho xi_tt + (kappa rho - rho
   theta'^2) xi = ..., which loses stability when theta'^2 reaches omega_1^2 = kappa_min, the lowest
   natural frequency squared of the annulus clamped on Gamma_D. The DMF step has the same limit: for such
   a mode with the explicit centrifugal term the characteristic roots z satisfy
   (1/dt^2 + kappa/2)(z^2 + 1) = (2/dt^2 + theta'^2) z, whose product is 1, and they stay on the unit
   circle exactly when theta'^2 <= kappa, whatever dt (docs/stability.md). So before stepping, Roller
   computes omega_1 by inverse iteration with a Cholesky factorization of K and refuses a rotation with
   max |theta'| >= omega_1 (with -stability_margin). */
#include "verify/verify.h"

static PetscErrorCode LowestFrequency(Roller ctx, PetscReal *omega1)
{
  KSP       ksp;
  Vec       v, w, Mv;
  PetscReal rq = 0, rq_old = PETSC_MAX_REAL;
  PetscInt  it;

  PetscFunctionBeginUser;
  PetscCall(KSPCreate(ctx->comm, &ksp));
  PetscCall(KSPSetOptionsPrefix(ksp, "stability_"));
  PetscCall(KSPSetOperators(ksp, ctx->ops.K, ctx->ops.K));
  PetscCall(RollerDirectSolverDefaults(ksp, PCCHOLESKY));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(VecDuplicate(ctx->ops.coordinates, &v));
  PetscCall(VecDuplicate(ctx->ops.coordinates, &w));
  PetscCall(VecDuplicate(ctx->ops.coordinates, &Mv));
  PetscCall(VecCopy(ctx->ops.coordinates, v)); /* any start with a component on the lowest mode */
  PetscCall(VecShift(v, 0.1));
  for (it = 0; it < 200; ++it) {
    PetscScalar vKv, vMv;
    PetscReal   norm;

    PetscCall(MatMult(ctx->ops.M, v, Mv));
    PetscCall(KSPSolve(ksp, Mv, w));
    PetscCall(VecNorm(w, NORM_2, &norm));
    PetscCall(VecScale(w, 1.0 / norm));
    PetscCall(VecCopy(w, v));
    PetscCall(MatMult(ctx->ops.K, v, w));
    PetscCall(VecDot(v, w, &vKv));
    PetscCall(MatMult(ctx->ops.M, v, Mv));
    PetscCall(VecDot(v, Mv, &vMv));
    rq = PetscRealPart(vKv / vMv);
    if (PetscAbsReal(rq - rq_old) < 1e-10 * rq) break;
    rq_old = rq;
  }
  *omega1 = PetscSqrtReal(rq / ctx->material.density);
  PetscCall(PetscInfo(ksp, "omega_1 = %g after %" PetscInt_FMT " inverse iterations\n", (double)*omega1, it));
  PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&Mv));
  PetscCall(KSPDestroy(&ksp));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerCheckRotation(Roller ctx)
{
  PetscBool check = PETSC_TRUE, view = PETSC_FALSE;
  PetscReal margin = 0.95, omega1 = 0, max_rate = PetscAbsReal(ctx->rotation.omega) + PetscAbsReal(ctx->rotation.a * ctx->rotation.b);

  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: rotation stability", NULL);
  PetscCall(PetscOptionsBool("-stability_check", "Refuse a rotation faster than the centrifugal-softening limit", NULL, check, &check, NULL));
  PetscCall(PetscOptionsReal("-stability_margin", "Allowed fraction of the limit omega_1", NULL, margin, &margin, NULL));
  PetscCall(PetscOptionsBool("-stability_view", "Print the lowest natural frequency omega_1 and the limit", NULL, view, &view, NULL));
  PetscOptionsEnd();
  RollerCheckOption(ctx->comm, "-stability_margin", margin, margin > 0 && margin <= 1, "in (0, 1]");
  if (!ctx->disc.static_solve && ctx->ts.dt > 0) { /* a step that resolves no mode of the scene: said once */
    PetscReal w_b, w_t;

    PetscCall(RollerModeFrequencies(ctx, &w_b, &w_t)); /* cheap: omega_1 (a solve with K) only past their periods */
    if (ctx->ts.dt > 2 * PETSC_PI / PetscMax(w_b, w_t)) PetscCall(LowestFrequency(ctx, &omega1));
    if (omega1 > 0 && ctx->ts.dt > 2 * PETSC_PI / omega1)
      PetscCall(PetscFPrintf(ctx->comm, PETSC_STDERR, "Warning: -ts_dt %.6g is longer than the period 2 pi/omega_1 = %.6g of the roller's slowest mode: the step resolves no mode of the scene, the transient is meaningless (the accurate default: no -ts_dt)\n",
                             (double)ctx->ts.dt, (double)(2 * PETSC_PI / omega1)));
  }
  if (!check || (max_rate == 0 && !view)) PetscFunctionReturn(0);
  if (omega1 == 0) PetscCall(LowestFrequency(ctx, &omega1));
  if (view) PetscCall(PetscPrintf(ctx->comm, "stability: omega_1 = %.10g, max |theta'| = %.10g, allowed < %.10g\n", (double)omega1, (double)max_rate, (double)(margin * omega1)));
  PetscCheck(max_rate < margin * omega1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-omega %g (max |theta'| = |omega| + |theta_a theta_b| = %g) is beyond the centrifugal-softening limit: the roller's lowest natural frequency is omega_1 = %g, and the rotating-frame model loses stability at |theta'| = omega_1; allowed: max |theta'| < %g (-stability_margin %g)",
             (double)ctx->rotation.omega, (double)max_rate, (double)omega1, (double)(margin * omega1), (double)margin);
  PetscFunctionReturn(0);
}
