/* One step of the "Crank-Nicolson" discrete Morse flow (docs/model.md section 2, paper (3.1)-(3.2)):
     A xi^k = b^k,  A = rho/dt^2 M + (1/2 + tau/(2 dt)) K (+ eta/(2 dt) M),
     b^k = M w - (1/2 - tau/(2 dt)) K xi^{k-2} + F^{k-1},
     w   = rho/dt^2 (2 xi^{k-1} - xi^{k-2}) (+ eta/(2 dt) xi^{k-2}),
     F^{k-1} = rho M (theta'' R(-pi/2) xi^{k-1} + theta'^2 xi^{k-1} + 2 theta' R(-pi/2) v^{k-1})
               + rho (theta'' L_euler + theta'^2 L_centrifugal),
     v^{k-1} = (xi^{k-1} - xi^{k-2})/dt (the paper) or (3 xi^{k-1} - 4 xi^{k-2} + xi^{k-3})/(2 dt),
   with theta', theta'' at t_{k-1}: the rigid part of rho (f^{k-1}, v) is loaded exactly (L_euler,
   L_centrifugal), the part linear in xi through M since f^{k-1} is interpolated in the FE space; tau K is the
   Kelvin-Voigt damping tau K (xi^k - xi^{k-2})/(2 dt). F^{k-1} is kept (state.load): its work closes the energy
   balance (diagnostics.c). With the centred Coriolis velocity its xi^k half is in A and the rest in w: that
   force does no work on xi^k - xi^{k-2} (G is skew) and is not part of F. With the obstacle, the same A and b
   define the bound-constrained QP that contact.c solves. */
#include "integrate/integrate.h"

static PetscErrorCode StepRightHandSide(Roller ctx, Vec b)
{
  const PetscReal rho = ctx->material.density, dt = ctx->ts.dt, t1 = (ctx->state.step) * dt; /* t_{k-1} */
  PetscReal       td, tdd;
  Vec             w = ctx->state.work, F = ctx->state.load, scratch = ctx->state.next; /* next: free until the solve */

  PetscFunctionBeginUser;
  RollerTheta(ctx, t1, NULL, &td, &tdd);
  /* w = R(-pi/2)(tdd xi^{k-1} + 2 td v^{k-1}) */
  switch (ctx->disc.coriolis) {
  case ROLLER_CORIOLIS_BACKWARD:
    PetscCall(VecAXPBYPCZ(b, tdd + 2.0 * td / dt, -2.0 * td / dt, 0.0, ctx->state.cur, ctx->state.prev));
    break;
  case ROLLER_CORIOLIS_EXTRAPOLATED:
    PetscCall(VecAXPBYPCZ(b, tdd + 3.0 * td / dt, -4.0 * td / dt, 0.0, ctx->state.cur, ctx->state.prev));
    PetscCall(VecAXPY(b, td / dt, ctx->state.prev2));
    break;
  case ROLLER_CORIOLIS_CENTERED: /* the xi^k half is in A (RollerUpdateGyroscopic) */
    PetscCall(VecAXPBYPCZ(b, tdd, -td / dt, 0.0, ctx->state.cur, ctx->state.prev));
    break;
  }
  PetscCall(RollerApplyRotate90(b, w));
  /* the external load F^{k-1} = M (rho (w + td^2 xi^{k-1})) + the rigid loads (+ the MMS load); the centred
     Coriolis force does no work and is left out of F (the header) */
  if (ctx->disc.coriolis == ROLLER_CORIOLIS_CENTERED) {
    PetscCall(RollerApplyRotate90(ctx->state.cur, scratch));
    PetscCall(VecAXPBYPCZ(F, rho * tdd, rho * td * td, 0.0, scratch, ctx->state.cur));
  } else PetscCall(VecAXPBYPCZ(F, rho, rho * td * td, 0.0, w, ctx->state.cur));
  PetscCall(MatMult(ctx->ops.M, F, scratch));
  PetscCall(VecAXPBYPCZ(scratch, rho * tdd, rho * td * td, 1.0, ctx->ops.L_euler, ctx->ops.L_centrifugal));
  PetscCall(VecSwap(scratch, F));
  /* b = M w - (1/2 - tau/(2 dt)) K xi^{k-2} + the rigid loads, in this order (the golden outputs' arithmetic) */
  PetscCall(VecAXPBYPCZ(w, rho * (2.0 / (dt * dt) + td * td), -rho / (dt * dt) + ctx->disc.damping / (2.0 * dt), rho, ctx->state.cur, ctx->state.prev));
  PetscCall(MatMult(ctx->ops.M, w, b));
  PetscCall(VecAXPY(b, -(0.5 - ctx->material.viscosity / (2.0 * dt)), ctx->state.Kprev));
  PetscCall(VecAXPBYPCZ(b, rho * tdd, rho * td * td, 1.0, ctx->ops.L_euler, ctx->ops.L_centrifugal));
  if (ctx->init.mms != ROLLER_MMS_NONE) {
    PetscCall(VecZeroEntries(scratch));
    PetscCall(RollerAddMMSLoad(ctx, t1, scratch));
    PetscCall(VecAXPY(b, 1.0, scratch));
    PetscCall(VecAXPY(F, 1.0, scratch));
  }
  PetscFunctionReturn(0);
}

/* Advance from (xi^{k-1}, xi^{k-2}) to xi^k; on return xi1 = xi^k, xi2 = xi^{k-1}, xi3 = xi^{k-2}. */
PetscErrorCode RollerStep(Roller ctx)
{
  Vec                tmp;
  KSPConvergedReason reason;
  const PetscReal    t = (ctx->state.step + 1) * ctx->ts.dt;

  PetscFunctionBeginUser;
  PetscCall(RollerUpdateGyroscopic(ctx, ctx->state.step * ctx->ts.dt));
  PetscCall(StepRightHandSide(ctx, ctx->state.rhs));
  if (ctx->contact) {
    PetscErrorCode ierr;

    PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_CONTACT]));
    ierr = RollerContactSolve(ctx, ctx->contact, t, ctx->state.rhs, ctx->state.next);
    PetscCall(PetscLogStagePop()); /* also when the solve failed: the driver goes on to write the checkpoint */
    PetscCall(ierr);
  } else {
    PetscBool guess;

    PetscCall(KSPGetInitialGuessNonzero(ctx->ops.ksp, &guess));
    if (guess) PetscCall(VecAXPBYPCZ(ctx->state.next, 2.0, -1.0, 0.0, ctx->state.cur, ctx->state.prev));
    PetscCall(KSPSolve(ctx->ops.ksp, ctx->state.rhs, ctx->state.next));
    PetscCall(KSPGetConvergedReason(ctx->ops.ksp, &reason));
    PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "The step solve diverged at step %" PetscInt_FMT ", t = %g: %s", ctx->state.step + 1, (double)t, KSPConvergedReasons[reason]);
  }
  /* a non-finite solution: keep the last good state and say where it happened */
  {
    PetscReal norm;

    PetscCall(VecNorm(ctx->state.next, NORM_INFINITY, &norm));
    /* the driver writes the last good state to the checkpoint (StepFailed) */
    PetscCheck(!PetscIsInfOrNanReal(norm), ctx->comm, PETSC_ERR_FP, "The solution is not finite at step %" PetscInt_FMT ", t = %g; the last good state (step %" PetscInt_FMT ") is in the checkpoint %s", ctx->state.step + 1, (double)t, ctx->state.step,
               ctx->ck.file);
  }
  /* rotate the history: xi3 <- xi2 <- xi1 <- xi, and K xi likewise */
  tmp               = ctx->state.prev2;
  ctx->state.prev2  = ctx->state.prev;
  ctx->state.prev   = ctx->state.cur;
  ctx->state.cur    = ctx->state.next;
  ctx->state.next   = tmp;
  tmp               = ctx->state.Kprev2;
  ctx->state.Kprev2 = ctx->state.Kprev;
  ctx->state.Kprev  = ctx->state.Kcur;
  ctx->state.Kcur   = tmp;
  PetscCall(MatMult(ctx->ops.K, ctx->state.cur, ctx->state.Kcur));
  ctx->state.step++;
  ctx->state.time = ctx->state.step * ctx->ts.dt;
  PetscFunctionReturn(0);
}
