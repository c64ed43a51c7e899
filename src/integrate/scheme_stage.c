/* One stage of the one-step trapezoidal scheme (docs/model.md section 2.1), the building block of -ts_scheme composed
   (scheme_composed.c): the Coriolis force's exact flow and a kick of the rest of the rotational force over half the
   stage, the trapezoidal rule (the contact QP at its end), the kick and the flow over the other half. */
#include "scheme_impl.h"
#include "model/model.h"

/* The loads of the trapezoidal rule at t: rho (theta'' L_euler + theta'^2 L_centrifugal) (+ the manufactured load). */
static PetscErrorCode Load(Roller ctx, PetscReal t, Vec L)
{
  const PetscReal rho = ctx->material.density;
  PetscReal       td, tdd;

  PetscFunctionBeginUser;
  RollerTheta(ctx, t, NULL, &td, &tdd);
  PetscCall(VecAXPBYPCZ(L, rho * tdd, rho * td * td, 0.0, ctx->ops.L_euler, ctx->ops.L_centrifugal));
  if (ctx->init.mms != ROLLER_MMS_NONE) PetscCall(RollerAddMMSLoad(ctx, t, L));
  PetscFunctionReturn(0);
}

/* 1 and 5: v <- R(2 (theta(tb) - theta(ta))) v, and M v alike (the step's working copies cp->V, cp->MV). */
static PetscErrorCode Coriolis(Roller ctx, RollerStageWork *cp, PetscReal ta, PetscReal tb)
{
  PetscReal tha, thb;

  PetscFunctionBeginUser;
  RollerTheta(ctx, ta, &tha, NULL, NULL);
  RollerTheta(ctx, tb, &thb, NULL, NULL);
  if (thb == tha) PetscFunctionReturn(0);
  PetscCall(RollerApplyRotation(cp->V, 2.0 * (thb - tha), cp->V));
  PetscCall(RollerApplyRotation(cp->MV, 2.0 * (thb - tha), cp->MV));
  PetscFunctionReturn(0);
}

/* 2 and 4: v += tau (theta'' R(-pi/2) xi + theta'^2 xi) at t, M v alike from M xi; its work rho dv . M (v + dv/2)
   goes to the load's. */
static PetscErrorCode Kick(Roller ctx, RollerStageWork *cp, PetscReal t, PetscReal tau, Vec x, Vec Mx)
{
  const PetscReal rho = ctx->material.density;
  PetscReal       td, tdd;
  PetscScalar     a, b;

  PetscFunctionBeginUser;
  RollerTheta(ctx, t, NULL, &td, &tdd);
  if (td == 0 && tdd == 0) PetscFunctionReturn(0);
  PetscCall(RollerApplyRotate90(Mx, cp->dv)); /* M dv = tau (tdd R M xi + td^2 M xi) */
  PetscCall(VecAXPBY(cp->dv, tau * td * td, tau * tdd, Mx));
  PetscCall(VecDot(cp->V, cp->dv, &a));
  PetscCall(VecAXPY(cp->MV, 1.0, cp->dv));
  PetscCall(RollerApplyRotate90(x, cp->dv)); /* dv itself */
  PetscCall(VecAXPBY(cp->dv, tau * td * td, tau * tdd, x));
  PetscCall(VecDot(cp->dv, cp->MV, &b)); /* dv . M (v + dv) */
  cp->load_work += 0.5 * rho * (PetscRealPart(a) + PetscRealPart(b));
  PetscCall(VecAXPY(cp->V, 1.0, cp->dv));
  PetscFunctionReturn(0);
}

/* One stage of length h (exactly the h of its matrix: t1 - t0 has the round-off of t, which would break the energy
   identity) from (x0, v) at t0 to x1 at t1 (step 3 with the kicks and Coriolis flows around it). */
PetscErrorCode RollerSchemeStage(Roller ctx, RollerStageWork *cp, RollerStepOperator *op, PetscReal h, PetscReal t0, PetscReal t1, PetscReal delta, PetscBool refresh, Vec x0, Vec Mx0, Vec Kx0, Vec x1, Vec Mx1, Vec Kx1)
{
  const PetscReal rho = ctx->material.density, eta = delta * ctx->disc.damping, tau = delta * ctx->material.viscosity;
  Vec             b = ctx->state.rhs, D = ctx->state.work, v = cp->V, tmp;
  PetscScalar     dot;

  PetscFunctionBeginUser;
  PetscCall(Coriolis(ctx, cp, t0, t0 + 0.5 * h));
  PetscCall(Kick(ctx, cp, t0, 0.5 * h, x0, Mx0));
  /* M v of this v itself at a step's first stage (refresh): the stages' recurrences for M v would drift from it by
     round-off over many steps (and with it the right-hand side, and the energy); within a step they cost no product */
  if (refresh) PetscCall(MatMult(ctx->ops.M, v, cp->MV));
  if (cp->tL0 != t0) PetscCall(Load(ctx, t0, cp->L0));
  PetscCall(Load(ctx, t1, cp->L1));
  if (ctx->contact) {
    const RollerContactStage stage = {
      op, t0, x0, v, {1.0, h},
          {0.0, h}
    };
    PetscErrorCode ierr;

    /* b = (2 rho/h^2 + eta/h) M x0 + 2 rho/h M v0 + (tau/h - 1/2) K x0 + (L0 + L1)/2 */
    PetscCall(VecAXPBYPCZ(b, 2.0 * rho / (h * h) + eta / h, 2.0 * rho / h, 0.0, Mx0, cp->MV));
    PetscCall(VecAXPBYPCZ(b, tau / h - 0.5, 0.5, 1.0, Kx0, cp->L0));
    PetscCall(VecAXPY(b, 0.5, cp->L1));
    PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_CONTACT]));
    ierr = RollerContactSolve(ctx, ctx->contact, &stage, t1, b, x1);
    PetscCall(PetscLogStagePop());
    PetscCall(ierr);
    PetscCall(RollerContactEnergyAdd(ctx, ctx->contact, x0, t0, 1.0, &cp->contact));
    PetscCall(VecWAXPY(D, -1.0, x0, x1));
  } else {
    /* the increment D = x1 - x0 itself, A D = b - A x0 = 2 rho/h M v0 - K x0 + (L0 + L1)/2: without the large
       2 rho/h^2 M x0 that cancels, the velocity 2 D/h - v0 keeps its round-off */
    PetscBool guess;

    PetscCall(VecAXPBYPCZ(b, 2.0 * rho / h, -1.0, 0.0, cp->MV, Kx0));
    PetscCall(VecAXPBYPCZ(b, 0.5, 0.5, 1.0, cp->L0, cp->L1));
    PetscCall(KSPGetInitialGuessNonzero(op->ksp, &guess));
    if (guess) {
      PetscCall(VecCopy(v, D));
      PetscCall(VecScale(D, h));
    }
    PetscCall(RollerStepOperatorSolve(ctx, op, b, D, t1));
    PetscCall(VecWAXPY(x1, 1.0, x0, D));
    /* M x1 = M x0 + M D from the stage's equation c_M M D + c_K K D = b (no product with M: M x only feeds the kicks'
       M v, made anew at every stage, and the diagnostics) */
    PetscCall(MatMult(ctx->ops.K, x1, Kx1));
    PetscCall(VecAXPBYPCZ(b, -op->c_K, op->c_K, 1.0, Kx1, Kx0));
    PetscCall(VecWAXPY(Mx1, 1.0 / op->c_M, b, Mx0));
  }
  if (ctx->contact) { /* c_M M x1 = b + f - c_K K x1, f the contact force */
    PetscCall(MatMult(ctx->ops.K, x1, Kx1));
    PetscCall(RollerContactForceVector(ctx->contact, Mx1));
    PetscCall(VecAXPY(Mx1, 1.0, b));
    PetscCall(VecAXPBY(Mx1, -op->c_K / op->c_M, 1.0 / op->c_M, Kx1));
  }
  /* the stage's energy terms: the loads' work (x1 - x0) . (L0 + L1)/2 and the dampings' dissipation */
  PetscCall(VecWAXPY(b, 1.0, cp->L0, cp->L1));
  PetscCall(VecDot(D, b, &dot));
  cp->load_work += 0.5 * PetscRealPart(dot);
  if (eta > 0) {
    PetscCall(VecWAXPY(b, -1.0, Mx0, Mx1));
    PetscCall(VecDot(D, b, &dot));
    cp->damping_dissipation += eta / h * PetscRealPart(dot);
  }
  if (tau > 0) {
    PetscCall(VecWAXPY(b, -1.0, Kx0, Kx1));
    PetscCall(VecDot(D, b, &dot));
    cp->viscous_dissipation += tau / h * PetscRealPart(dot);
  }
  /* v1 = 2 (x1 - x0)/h - v0, M v alike (for the kick and the energy; made anew at the next stage) */
  PetscCall(VecAXPBY(v, 2.0 / h, -1.0, D));
  PetscCall(VecWAXPY(b, -1.0, Mx0, Mx1));
  PetscCall(VecAXPBY(cp->MV, 2.0 / h, -1.0, b));
  tmp     = cp->L0; /* L(t1) is the next stage's L(t0) */
  cp->L0  = cp->L1;
  cp->L1  = tmp;
  cp->tL0 = t1;
  PetscCall(Kick(ctx, cp, t1, 0.5 * h, x1, Mx1));
  PetscCall(Coriolis(ctx, cp, t0 + 0.5 * h, t1));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerStageWorkCreate(Roller ctx, RollerStageWork *w)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(w, sizeof(*w)));
  PetscCall(VecDuplicate(ctx->state.cur, &w->V));
  PetscCall(VecDuplicate(ctx->state.cur, &w->MV));
  PetscCall(VecDuplicate(ctx->state.cur, &w->dv));
  PetscCall(VecDuplicate(ctx->state.cur, &w->L0));
  PetscCall(VecDuplicate(ctx->state.cur, &w->L1));
  w->tL0 = PETSC_MAX_REAL;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerStageWorkDestroy(RollerStageWork *w)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&w->V));
  PetscCall(VecDestroy(&w->MV));
  PetscCall(VecDestroy(&w->dv));
  PetscCall(VecDestroy(&w->L0));
  PetscCall(VecDestroy(&w->L1));
  PetscFunctionReturn(0);
}
