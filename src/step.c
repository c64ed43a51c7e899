/* One step of the "Crank-Nicolson" discrete Morse flow (docs/model.md section 2, paper (3.1)-(3.2)):
     A xi^k = b^k,  A = rho/dt^2 M + K/2 (+ eta/(2 dt) M),
     b^k = M w - K xi^{k-2}/2 + rho (theta'' L_euler + theta'^2 L_centrifugal),
     w   = rho/dt^2 (2 xi^{k-1} - xi^{k-2}) (+ eta/(2 dt) xi^{k-2})
           + rho (theta'' R(-pi/2) xi^{k-1} + theta'^2 xi^{k-1} + 2 theta' R(-pi/2) v^{k-1}),
     v^{k-1} = (xi^{k-1} - xi^{k-2})/dt (the paper) or (3 xi^{k-1} - 4 xi^{k-2} + xi^{k-3})/(2 dt),
   with theta', theta'' at t_{k-1}: the rigid part of rho (f^{k-1}, v) is loaded exactly (L_euler,
   L_centrifugal), the part linear in xi through M since f^{k-1} is interpolated in the FE space. With the
   obstacle, the same A and b define the bound-constrained QP that contact.c solves. */
#include <roller_impl.h>

/* xi^0 and xi^{-1} = xi^0 - dt eta^0 (docs/model.md section 2). */
PetscErrorCode RollerInitialState(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(ctx->dm, &ctx->xi));
  PetscCall(PetscObjectSetName((PetscObject)ctx->xi, "displacement"));
  PetscCall(VecDuplicate(ctx->xi, &ctx->xi1));
  PetscCall(VecDuplicate(ctx->xi, &ctx->xi2));
  PetscCall(VecDuplicate(ctx->xi, &ctx->xi3));
  PetscCall(VecDuplicate(ctx->xi, &ctx->Kxi1));
  PetscCall(VecDuplicate(ctx->xi, &ctx->Kxi2));
  PetscCall(VecDuplicate(ctx->xi, &ctx->rhs));
  PetscCall(VecDuplicate(ctx->xi, &ctx->work));
  switch (ctx->ic) {
  case ROLLER_IC_REST:
    PetscCall(VecZeroEntries(ctx->xi1));
    PetscCall(VecZeroEntries(ctx->xi2));
    PetscCall(VecZeroEntries(ctx->xi3));
    break;
  case ROLLER_IC_BUMP: /* at rest: xi^{-2} = xi^{-1} = xi^0 */
    PetscCall(RollerMMSExact(ctx, 0.0, ctx->xi1));
    PetscCall(VecCopy(ctx->xi1, ctx->xi2));
    PetscCall(VecCopy(ctx->xi1, ctx->xi3));
    break;
  case ROLLER_IC_MMS: /* the exact solution at t = 0, -dt, -2 dt */
    PetscCall(RollerMMSExact(ctx, 0.0, ctx->xi1));
    PetscCall(RollerMMSExact(ctx, -ctx->dt, ctx->xi2));
    PetscCall(RollerMMSExact(ctx, -2.0 * ctx->dt, ctx->xi3));
    break;
  }
  PetscCall(MatMult(ctx->K, ctx->xi1, ctx->Kxi1));
  PetscCall(MatMult(ctx->K, ctx->xi2, ctx->Kxi2));
  ctx->step = 0;
  ctx->time = 0.0;
  PetscFunctionReturn(0);
}

static PetscErrorCode StepRightHandSide(Roller ctx, Vec b)
{
  const PetscReal rho = ctx->density, dt = ctx->dt, t1 = (ctx->step) * dt; /* t_{k-1} */
  PetscReal       td, tdd;
  Vec             w = ctx->work;

  PetscFunctionBeginUser;
  RollerTheta(ctx, t1, NULL, &td, &tdd);
  /* w = R(-pi/2)(tdd xi^{k-1} + 2 td v^{k-1}) */
  switch (ctx->coriolis) {
  case ROLLER_CORIOLIS_BACKWARD:
    PetscCall(VecAXPBYPCZ(b, tdd + 2.0 * td / dt, -2.0 * td / dt, 0.0, ctx->xi1, ctx->xi2));
    break;
  case ROLLER_CORIOLIS_EXTRAPOLATED:
    PetscCall(VecAXPBYPCZ(b, tdd + 3.0 * td / dt, -4.0 * td / dt, 0.0, ctx->xi1, ctx->xi2));
    PetscCall(VecAXPY(b, td / dt, ctx->xi3));
    break;
  case ROLLER_CORIOLIS_CENTERED: /* the xi^k half is in A (RollerUpdateGyroscopic) */
    PetscCall(VecAXPBYPCZ(b, tdd, -td / dt, 0.0, ctx->xi1, ctx->xi2));
    break;
  }
  PetscCall(RollerApplyRotate90(b, w));
  PetscCall(VecAXPBYPCZ(w, rho * (2.0 / (dt * dt) + td * td), -rho / (dt * dt) + ctx->damping / (2.0 * dt), rho, ctx->xi1, ctx->xi2));
  PetscCall(MatMult(ctx->M, w, b));
  PetscCall(VecAXPY(b, -0.5, ctx->Kxi2));
  PetscCall(VecAXPBYPCZ(b, rho * tdd, rho * td * td, 1.0, ctx->L_euler, ctx->L_centrifugal));
  if (ctx->mms != ROLLER_MMS_NONE) PetscCall(RollerAddMMSLoad(ctx, t1, b));
  PetscFunctionReturn(0);
}

/* Advance from (xi^{k-1}, xi^{k-2}) to xi^k; on return xi1 = xi^k, xi2 = xi^{k-1}, xi3 = xi^{k-2}. */
PetscErrorCode RollerStep(Roller ctx)
{
  Vec                tmp;
  KSPConvergedReason reason;
  const PetscReal    t = (ctx->step + 1) * ctx->dt;

  PetscFunctionBeginUser;
  PetscCall(RollerUpdateGyroscopic(ctx, ctx->step * ctx->dt));
  PetscCall(StepRightHandSide(ctx, ctx->rhs));
  if (ctx->contact) {
    PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_CONTACT]));
    PetscCall(RollerContactSolve(ctx, ctx->contact, t, ctx->rhs, ctx->xi));
    PetscCall(PetscLogStagePop());
  } else {
    PetscBool guess;

    PetscCall(KSPGetInitialGuessNonzero(ctx->ksp, &guess));
    if (guess) PetscCall(VecAXPBYPCZ(ctx->xi, 2.0, -1.0, 0.0, ctx->xi1, ctx->xi2));
    PetscCall(KSPSolve(ctx->ksp, ctx->rhs, ctx->xi));
    PetscCall(KSPGetConvergedReason(ctx->ksp, &reason));
    PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "The step solve diverged at step %" PetscInt_FMT ", t = %g: %s", ctx->step + 1, (double)t, KSPConvergedReasons[reason]);
  }
  /* a non-finite solution: keep the last good state and say where it happened */
  {
    PetscReal norm;

    PetscCall(VecNorm(ctx->xi, NORM_INFINITY, &norm));
    /* the driver writes the last good state to the checkpoint (StepFailed) */
    PetscCheck(!PetscIsInfOrNanReal(norm), ctx->comm, PETSC_ERR_FP, "The solution is not finite at step %" PetscInt_FMT ", t = %g; the last good state (step %" PetscInt_FMT ") is in the checkpoint %s", ctx->step + 1, (double)t, ctx->step, ctx->checkpoint);
  }
  /* rotate the history: xi3 <- xi2 <- xi1 <- xi, and K xi likewise */
  tmp       = ctx->xi3;
  ctx->xi3  = ctx->xi2;
  ctx->xi2  = ctx->xi1;
  ctx->xi1  = ctx->xi;
  ctx->xi   = tmp;
  tmp       = ctx->Kxi2;
  ctx->Kxi2 = ctx->Kxi1;
  ctx->Kxi1 = tmp;
  PetscCall(MatMult(ctx->K, ctx->xi1, ctx->Kxi1));
  ctx->step++;
  ctx->time = ctx->step * ctx->dt;
  PetscFunctionReturn(0);
}
