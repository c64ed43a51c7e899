/* One step of the "Crank-Nicolson" discrete Morse flow (docs/model.md section 2, paper (3.1)-(3.2)):
     A xi^k = b^k,  A = rho/dt^2 M + K/2 (+ eta/(2 dt) M),
     b^k = M w - K xi^{k-2}/2 + rho (theta'' L_euler + theta'^2 L_centrifugal),
     w   = rho/dt^2 (2 xi^{k-1} - xi^{k-2}) (+ eta/(2 dt) xi^{k-2})
           + rho (theta'' R(-pi/2) xi^{k-1} + theta'^2 xi^{k-1} + 2 theta' R(-pi/2) v^{k-1}),
     v^{k-1} = (xi^{k-1} - xi^{k-2})/dt (the paper) or (3 xi^{k-1} - 4 xi^{k-2} + xi^{k-3})/(2 dt),
   with theta', theta'' at t_{k-1}: the rigid part of rho (f^{k-1}, v) is loaded exactly (L_euler,
   L_centrifugal), the part linear in xi through M since f^{k-1} is interpolated in the FE space. With the
   obstacle, the same A and b define the bound-constrained QP that contact.c solves. */
#include "integrate/integrate.h"

static PetscErrorCode StepRightHandSide(Roller ctx, Vec b)
{
  const PetscReal rho = ctx->material.density, dt = ctx->ts.dt, t1 = (ctx->state.step) * dt; /* t_{k-1} */
  PetscReal       td, tdd;
  Vec             w = ctx->state.work;

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
  PetscCall(VecAXPBYPCZ(w, rho * (2.0 / (dt * dt) + td * td), -rho / (dt * dt) + ctx->disc.damping / (2.0 * dt), rho, ctx->state.cur, ctx->state.prev));
  PetscCall(MatMult(ctx->ops.M, w, b));
  PetscCall(VecAXPY(b, -0.5, ctx->state.Kprev));
  PetscCall(VecAXPBYPCZ(b, rho * tdd, rho * td * td, 1.0, ctx->ops.L_euler, ctx->ops.L_centrifugal));
  if (ctx->init.mms != ROLLER_MMS_NONE) PetscCall(RollerAddMMSLoad(ctx, t1, b));
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
  tmp              = ctx->state.prev2;
  ctx->state.prev2 = ctx->state.prev;
  ctx->state.prev  = ctx->state.cur;
  ctx->state.cur   = ctx->state.next;
  ctx->state.next  = tmp;
  tmp              = ctx->state.Kprev;
  ctx->state.Kprev = ctx->state.Kcur;
  ctx->state.Kcur  = tmp;
  PetscCall(MatMult(ctx->ops.K, ctx->state.cur, ctx->state.Kcur));
  ctx->state.step++;
  ctx->state.time = ctx->state.step * ctx->ts.dt;
  PetscFunctionReturn(0);
}
