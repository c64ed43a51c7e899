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
  PetscCall(RollerApplyRotate90(ctx, Mx, cp->dv)); /* M dv = tau (tdd R M xi + td^2 M xi) */
  PetscCall(VecAXPBY(cp->dv, tau * td * td, tau * tdd, Mx));
  PetscCall(VecDot(cp->V, cp->dv, &a));
  PetscCall(VecAXPY(cp->MV, 1.0, cp->dv));
  PetscCall(RollerApplyRotate90(ctx, x, cp->dv)); /* dv itself */
  PetscCall(VecAXPBY(cp->dv, tau * td * td, tau * tdd, x));
  PetscCall(VecDot(cp->dv, cp->MV, &b)); /* dv . M (v + dv) */
  cp->load_work += 0.5 * rho * (PetscRealPart(a) + PetscRealPart(b));
  PetscCall(VecAXPY(cp->V, 1.0, cp->dv));
  PetscFunctionReturn(0);
}

/* y += a x/h entry by entry: each entry's rounding is its own, not a rounded a/h shared by all. */
static PetscErrorCode AddDivided(Vec y, PetscReal a, Vec x, PetscReal h)
{
  PetscScalar       *ya;
  const PetscScalar *xa;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(y, &n));
  PetscCall(VecGetArray(y, &ya));
  PetscCall(VecGetArrayRead(x, &xa));
  for (PetscInt i = 0; i < n; ++i) ya[i] += a * xa[i] / h;
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCall(VecRestoreArray(y, &ya));
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
    /* c_M M x1 = b + f - c_K K x1, f the contact force */
    PetscCall(MatMult(ctx->ops.K, x1, Kx1));
    PetscCall(RollerContactForceVector(ctx->contact, Mx1));
    PetscCall(VecAXPY(Mx1, 1.0, b));
    PetscCall(VecAXPBY(Mx1, -op->c_K / op->c_M, 1.0 / op->c_M, Kx1));
    /* v1 = 2 (x1 - x0)/h - v0, M v alike (for the kick and the energy; made anew at the next stage) */
    PetscCall(VecAXPBY(v, 2.0 / h, -1.0, D));
    PetscCall(VecWAXPY(b, -1.0, Mx0, Mx1));
    PetscCall(VecAXPBY(cp->MV, 2.0 / h, -1.0, b));
  } else {
    /* Delta = x1 - x0 - h v0, the velocity's increment times h/2 (b - A (x0 + h v0)):
         A Delta = -K (x0 + (h/2 + tau) v0) - eta M v0 + (L0 + L1)/2,
       the same stage; but without a scalar of h in front of M: b's 2 rho/h M v0 and the update v1 = 2 D/h - v0, rounded
       once for the run, do not cancel A's rounded entries, and the mismatch, the same every stage, drifted the energy
       linearly (5.5e-16 E a step; 2e-15 over 2000 steps in this form, docs/model.md section 2.1) */
    Vec       y = x1, KDM = cp->dv; /* scratch: x1 until set; dv (free until the kick) holds K y, then K Delta, then M Delta */
    PetscReal s = h / (0.5 * h + tau);

    PetscCall(VecWAXPY(y, 0.5 * h + tau, v, x0));
    PetscCall(MatMult(ctx->ops.K, y, KDM));
    PetscCall(VecAXPBYPCZ(b, 0.5, 0.5, 0.0, cp->L0, cp->L1));
    PetscCall(VecAXPY(b, -1.0, KDM));
    if (eta != 0) PetscCall(VecAXPY(b, -eta, cp->MV));
    PetscCall(VecZeroEntries(cp->Delta));
    PetscCall(RollerStepOperatorSolve(ctx, op, b, cp->Delta, t1));
    PetscCall(VecWAXPY(D, h, v, cp->Delta));
    PetscCall(VecWAXPY(x1, 1.0, x0, D));
    PetscCall(MatMult(ctx->ops.K, x1, Kx1));
    /* M x1 = M x0 + h M v0 + M Delta, M Delta from the equation, c_M M Delta = b - c_K K Delta, K Delta = K x1 - K x0 -
       h K v0, h K v0 = s (K y - K x0) (no product with M: M x feeds the kicks, the damping and the diagnostics) */
    PetscCall(VecAXPBYPCZ(KDM, 1.0, s - 1.0, -s, Kx1, Kx0));        /* K Delta */
    PetscCall(VecAXPBY(KDM, 1.0 / op->c_M, -op->c_K / op->c_M, b)); /* M Delta */
    PetscCall(VecWAXPY(Mx1, h, cp->MV, Mx0));
    PetscCall(VecAXPY(Mx1, 1.0, KDM));
    /* v1 = v0 + 2 Delta/h, divided entry by entry (a rounded 2/h, the same every stage, would drift the energy), M v
       alike (for the kick and the energy; made anew at the next step) */
    PetscCall(AddDivided(v, 2.0, cp->Delta, h));
    PetscCall(VecAXPY(cp->MV, 2.0 / h, KDM));
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
  PetscCall(VecDuplicate(ctx->state.cur, &w->Delta));
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
  PetscCall(VecDestroy(&w->Delta));
  PetscCall(VecDestroy(&w->L0));
  PetscCall(VecDestroy(&w->L1));
  PetscFunctionReturn(0);
}
