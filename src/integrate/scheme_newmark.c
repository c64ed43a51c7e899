/* The three-level schemes (docs/model.md sections 2, 2.1, 2.2): Newmark with gamma = 1/2 in three-level form,
     rho (xi^k - 2 xi^{k-1} + xi^{k-2})/dt^2 + K (beta xi^k + (1 - 2 beta) xi^{k-1} + beta xi^{k-2})
       + eta M (xi^k - xi^{k-2})/(2 dt) + tau K (xi^k - xi^{k-2})/(2 dt) = F^{k-1} (+ the contact force at t_k),
   (+ the Maxwell branches' forces, scheme_maxwell.c), each step the minimization of a convex quadratic with the
   constant SPD matrix A = rho/dt^2 M + (beta + tau/(2 dt)) K + eta/(2 dt) M (+ c_D K_d):
     dmf          beta = 1/2, the paper's "Crank-Nicolson" discrete Morse flow (paper (3.1)-(3.2)); bit-identical to
                  Roller's step before the schemes were components (tests/regression.py);
     trapezoidal  beta = 1/4, the trapezoidal rule: cos(W dt) = (1 - x^2/4)/(1 + x^2/4), x = w dt, a phase error x^3/12
                  per step instead of the DMF's 5 x^3/24, the same cost per step.
   Energy: E^k = rho/2 |xi^k - xi^{k-1}|^2_M/dt^2 + beta/2 (a(xi^k, xi^k) + a(xi^{k-1}, xi^{k-1})) + (1 - 2 beta)/2
   a(xi^k, xi^{k-1}) (+ the branches'); the step times (xi^k - xi^{k-2})/2 gives the balance of docs/model.md section 2
   for any beta (the beta terms telescope). The products M xi of the last three levels are kept (M xi^k from the step's
   equation), so that the load F^{k-1}, the trapezoidal right-hand side and the angular momentum cost no product with
   M; the energy costs one, when a row is written. */
#include "scheme_newmark.h"
#include "model/model.h"

/* v^{k-1} of the explicit Coriolis term, c1 xi^{k-1} + c2 xi^{k-2} + c3 xi^{k-3} (docs/model.md section 2; centred: in A) */
static void CoriolisVelocity(Roller ctx, PetscReal c[3])
{
  static const PetscReal coefficients[3][3] = {
    {1.0, -1.0, 0.0}, /* backward */
    {1.5, -2.0, 0.5}, /* extrapolated: (3 xi^{k-1} - 4 xi^{k-2} + xi^{k-3})/(2 dt) */
    {0.0, 0.0,  0.0}  /* centred */
  };

  for (PetscInt i = 0; i < 3; ++i) c[i] = coefficients[ctx->disc.coriolis][i] / ctx->ts.dt;
}

/* rot = R(-pi/2) M (theta'' xi^{k-1} + 2 theta' v^{k-1}) from the kept products (M commutes with R(-pi/2)), and the
   external load F^{k-1} = rho (rot + theta'^2 M xi^{k-1}) + rho (theta'' L_euler + theta'^2 L_centrifugal) (the
   manufactured load: the caller's), whose work closes the energy balance. Before the levels move: Mcur = M xi^{k-1}. */
static PetscErrorCode LoadFromProducts(Roller ctx, Newmark *nm, PetscReal t1, Vec rot)
{
  const PetscReal rho = ctx->material.density;
  PetscReal       td, tdd, c[3];
  Vec             F = ctx->state.load;

  PetscFunctionBeginUser;
  RollerTheta(ctx, t1, NULL, &td, &tdd);
  CoriolisVelocity(ctx, c);
  PetscCall(VecAXPBYPCZ(nm->Mv, tdd + 2.0 * td * c[0], 2.0 * td * c[1], 0.0, ctx->state.Mcur, nm->Mprev));
  if (c[2] != 0) PetscCall(VecAXPY(nm->Mv, 2.0 * td * c[2], nm->Mprev2));
  PetscCall(RollerApplyRotate90(nm->Mv, rot));
  PetscCall(VecAXPBYPCZ(F, rho, rho * td * td, 0.0, rot, ctx->state.Mcur));
  PetscCall(VecAXPBYPCZ(F, rho * tdd, rho * td * td, 1.0, ctx->ops.L_euler, ctx->ops.L_centrifugal));
  PetscFunctionReturn(0);
}

/* The DMF's right-hand side in its historical arithmetic (the golden outputs' bits; the caller adds the MMS load):
     b = M w - (1/2 - tau/(2 dt)) K xi^{k-2} + rho (theta'' L_euler + theta'^2 L_centrifugal),
     w = rho/dt^2 (2 xi^{k-1} - xi^{k-2}) + eta/(2 dt) xi^{k-2} + rho (R(-pi/2)(theta'' xi^{k-1} + 2 theta' v^{k-1}) + theta'^2 xi^{k-1}). */
static PetscErrorCode RightHandSideDMF(Roller ctx, PetscReal t1, Vec b)
{
  const PetscReal rho = ctx->material.density, dt = ctx->ts.dt;
  PetscReal       td, tdd;
  Vec             w = ctx->state.work;

  PetscFunctionBeginUser;
  RollerTheta(ctx, t1, NULL, &td, &tdd);
  switch (ctx->disc.coriolis) {
  case ROLLER_CORIOLIS_BACKWARD:
    PetscCall(VecAXPBYPCZ(b, tdd + 2.0 * td / dt, -2.0 * td / dt, 0.0, ctx->state.cur, ctx->state.prev));
    break;
  case ROLLER_CORIOLIS_EXTRAPOLATED:
    PetscCall(VecAXPBYPCZ(b, tdd + 3.0 * td / dt, -4.0 * td / dt, 0.0, ctx->state.cur, ctx->state.prev));
    PetscCall(VecAXPY(b, td / dt, ctx->state.prev2));
    break;
  case ROLLER_CORIOLIS_CENTERED: /* the xi^k half is in A */
    PetscCall(VecAXPBYPCZ(b, tdd, -td / dt, 0.0, ctx->state.cur, ctx->state.prev));
    break;
  }
  PetscCall(RollerApplyRotate90(b, w));
  PetscCall(VecAXPBYPCZ(w, rho * (2.0 / (dt * dt) + td * td), -rho / (dt * dt) + ctx->disc.damping / (2.0 * dt), rho, ctx->state.cur, ctx->state.prev));
  PetscCall(MatMult(ctx->ops.M, w, b));
  PetscCall(VecAXPY(b, -(0.5 - ctx->material.viscosity / (2.0 * dt)), ctx->state.Kprev));
  PetscCall(VecAXPBYPCZ(b, rho * tdd, rho * td * td, 1.0, ctx->ops.L_euler, ctx->ops.L_centrifugal));
  PetscFunctionReturn(0);
}

/* Any beta, from the kept products (no product with M): b = M w - (1 - 2 beta) K xi^{k-1} - (beta - tau/(2 dt)) K xi^{k-2}
   + the rigid loads, i.e. (M w = rho 2/dt^2 M xi^{k-1} + (eta/(2 dt) - rho/dt^2) M xi^{k-2} + F^{k-1} - the rigid loads)
     b = rho 2/dt^2 M xi^{k-1} + (eta/(2 dt) - rho/dt^2) M xi^{k-2} - (1 - 2 beta) K xi^{k-1} - (beta - tau/(2 dt)) K xi^{k-2} + F^{k-1}. */
static PetscErrorCode RightHandSide(Roller ctx, Newmark *nm, Vec b)
{
  const PetscReal rho = ctx->material.density, dt = ctx->ts.dt;

  PetscFunctionBeginUser;
  PetscCall(VecAXPBYPCZ(b, 2.0 * rho / (dt * dt), ctx->disc.damping / (2.0 * dt) - rho / (dt * dt), 0.0, ctx->state.Mcur, nm->Mprev));
  PetscCall(VecAXPBYPCZ(b, -(1.0 - 2.0 * nm->beta), -(nm->beta - ctx->material.viscosity / (2.0 * dt)), 1.0, ctx->state.Kcur, ctx->state.Kprev));
  PetscCall(VecAXPY(b, 1.0, ctx->state.load));
  PetscFunctionReturn(0);
}

static PetscErrorCode HubStepBegin(Roller ctx, Newmark *nm, PetscReal t1)
{
  PetscReal c[3];

  PetscFunctionBeginUser;
  CoriolisVelocity(ctx, c);
  PetscCall(RollerHubStepBegin(ctx, nm->op, nm->mx, nm->beta, t1, c, ctx->state.rhs, ctx->state.load, ctx->state.work));
  PetscFunctionReturn(0);
}

/* Without contact (and the centred Coriolis term) the trapezoidal family solves for the second difference
   Delta = xi^k - 2 xi^{k-1} + xi^{k-2} (b - A (2 xi^{k-1} - xi^{k-2}), no scalar of dt in front of M):
     A Delta = F^{k-1} - K xi^{k-1} - tau/dt K (xi^{k-1} - xi^{k-2}) - eta/dt M (xi^{k-1} - xi^{k-2}).
   The same scheme; but b's rho/dt^2 M xi terms, rounded once for the run, do not cancel A's rounded entries, and the
   mismatch, the same every step, drifted the energy linearly (docs/model.md section 2.1: 5.2e-12 over 1e5 steps, 1.1e-13 in this form). */
static PetscErrorCode RightHandSideSecondDifference(Roller ctx, Newmark *nm, Vec r)
{
  const PetscReal dt = ctx->ts.dt, eta = ctx->disc.damping, tau = ctx->material.viscosity;

  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(r, -1.0, ctx->state.Kcur, ctx->state.load));
  if (tau != 0) PetscCall(VecAXPBYPCZ(r, -tau / dt, tau / dt, 1.0, ctx->state.Kcur, ctx->state.Kprev));
  if (eta != 0) PetscCall(VecAXPBYPCZ(r, -eta / dt, eta / dt, 1.0, ctx->state.Mcur, nm->Mprev));
  PetscFunctionReturn(0);
}

/* After the levels moved up (cur = xi^k): K xi^k, M xi^k and the velocity (xi^k - xi^{k-1})/dt. M xi^k comes from the
   step's own equation, c_M M xi^k = b + f - c_K K xi^k (f the contact force; no product with M: the products are of the
   level itself, never summed from increments, which would drift from it by round-off over many steps), except with
   the centred Coriolis term, -static (A = K) or the second-difference form (product: the equation is Delta's). */
static PetscErrorCode NewLevel(Roller ctx, Newmark *nm, PetscBool product)
{
  const RollerStepOperator *op = nm->op;
  Vec                       tmp;

  PetscFunctionBeginUser;
  PetscCall(MatMult(ctx->ops.K, ctx->state.cur, ctx->state.Kcur));
  if (nm->mx) PetscCall(RollerMaxwellNewLevel(nm->mx, ctx)); /* K_d xi^k, the branches' update */
  tmp             = nm->Mprev2;
  nm->Mprev2      = nm->Mprev;
  nm->Mprev       = ctx->state.Mcur;
  ctx->state.Mcur = tmp;
  if (op->G || op->c_M == 0 || product) PetscCall(MatMult(ctx->ops.M, ctx->state.cur, ctx->state.Mcur));
  else {
    if (ctx->contact) {
      PetscCall(RollerContactForceVector(ctx->contact, ctx->state.Mcur));
      PetscCall(VecAXPY(ctx->state.Mcur, 1.0, ctx->state.rhs));
    } else PetscCall(VecCopy(ctx->state.rhs, ctx->state.Mcur));
    if (nm->mx) PetscCall(VecAXPY(ctx->state.Mcur, -op->c_D, RollerMaxwellKdCur(nm->mx)));
    if (op->border) PetscCall(VecMAXPY(ctx->state.Mcur, 3, ctx->axle.hub->s.delta, op->border->C)); /* b = b_eff + C Dz b_q, minus C q^k */
    PetscCall(VecAXPBY(ctx->state.Mcur, -op->c_K / op->c_M, 1.0 / op->c_M, ctx->state.Kcur));
  }
  PetscCall(VecWAXPY(ctx->state.velocity, -1.0, ctx->state.prev, ctx->state.cur));
  PetscCall(VecScale(ctx->state.velocity, 1.0 / ctx->ts.dt));
  nm->kinetic_step = -1;
  PetscFunctionReturn(0);
}

/* Advance from (xi^{k-1}, xi^{k-2}) to xi^k; on return cur = xi^k, prev = xi^{k-1}, prev2 = xi^{k-2}. */
static PetscErrorCode NewmarkStep(RollerScheme s, Roller ctx)
{
  Newmark        *nm = (Newmark *)s->data;
  const PetscReal dt = ctx->ts.dt, t1 = ctx->state.step * dt, t = (ctx->state.step + 1) * dt;
  const PetscBool second = (PetscBool)(nm->beta != 0.5 && !ctx->contact && !nm->op->G && nm->op->c_M != 0 && !ctx->axle.on);
  Vec             tmp;
  PetscReal       norm;

  PetscFunctionBeginUser;
  if (nm->op->G && ctx->rotation.a * ctx->rotation.b != 0) { /* centred Coriolis with a varying theta': A - rho theta'(t_{k-1})/dt G */
    PetscReal td;

    RollerTheta(ctx, t1, NULL, &td, NULL);
    PetscCall(RollerStepOperatorUpdateGyroscopic(nm->op, ctx->material.density * td / dt));
  }
  PetscCall(LoadFromProducts(ctx, nm, t1, ctx->state.rhs));
  if (nm->beta == 0.5) PetscCall(RightHandSideDMF(ctx, t1, ctx->state.rhs));
  else if (!second) PetscCall(RightHandSide(ctx, nm, ctx->state.rhs));
  if (ctx->init.mms != ROLLER_MMS_NONE) { /* the manufactured load at t_{k-1}, in b and in F */
    PetscCall(VecZeroEntries(ctx->state.next));
    PetscCall(RollerAddMMSLoad(ctx, t1, ctx->state.next));
    if (!second) PetscCall(VecAXPY(ctx->state.rhs, 1.0, ctx->state.next));
    PetscCall(VecAXPY(ctx->state.load, 1.0, ctx->state.next));
  }
  if (second) PetscCall(RightHandSideSecondDifference(ctx, nm, ctx->state.rhs));
  if (nm->mx) PetscCall(RollerMaxwellRightHandSide(nm->mx, second, ctx->state.rhs));
  if (ctx->axle.on) PetscCall(HubStepBegin(ctx, nm, t1)); /* the hub's load, history and elimination (scheme_hub.c) */
  if (ctx->contact) {
    const RollerContactStage stage = {
      nm->op, ctx->state.time, ctx->state.cur, ctx->state.prev, {2.0, -1.0},
          {1.0, -1.0}
    };
    PetscErrorCode ierr;

    PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_CONTACT]));
    ierr = RollerContactSolve(ctx, ctx->contact, &stage, t, ctx->state.rhs, ctx->state.next);
    PetscCall(PetscLogStagePop()); /* also when the solve failed: the driver goes on to write the checkpoint */
    PetscCall(ierr);
  } else if (second) {
    PetscCall(VecZeroEntries(ctx->state.next));
    PetscCall(RollerStepOperatorSolve(ctx, nm->op, ctx->state.rhs, ctx->state.next, t));
    PetscCall(VecAXPBYPCZ(ctx->state.next, 2.0, -1.0, 1.0, ctx->state.cur, ctx->state.prev));
  } else {
    PetscBool guess;

    PetscCall(KSPGetInitialGuessNonzero(nm->op->ksp, &guess));
    if (guess) PetscCall(VecAXPBYPCZ(ctx->state.next, 2.0, -1.0, 0.0, ctx->state.cur, ctx->state.prev));
    PetscCall(RollerStepOperatorSolve(ctx, nm->op, ctx->state.rhs, ctx->state.next, t));
  }
  /* a non-finite solution: keep the last good state (the driver checkpoints it) and say where it happened */
  PetscCall(VecNorm(ctx->state.next, NORM_INFINITY, &norm));
  PetscCheck(!PetscIsInfOrNanReal(norm), ctx->comm, PETSC_ERR_FP, "The solution is not finite at step %" PetscInt_FMT ", t = %g; the last good state (step %" PetscInt_FMT ") is in the checkpoint %s", ctx->state.step + 1, (double)t, ctx->state.step,
             ctx->ck.file);
  if (ctx->axle.on) PetscCall(RollerHubStepEnd(ctx, nm->op, nm->beta, ctx->state.next));
  tmp               = ctx->state.prev2;
  ctx->state.prev2  = ctx->state.prev;
  ctx->state.prev   = ctx->state.cur;
  ctx->state.cur    = ctx->state.next;
  ctx->state.next   = tmp;
  tmp               = ctx->state.Kprev2;
  ctx->state.Kprev2 = ctx->state.Kprev;
  ctx->state.Kprev  = ctx->state.Kcur;
  ctx->state.Kcur   = tmp;
  if (ctx->axle.on) PetscCall(RollerHubShift(ctx, ctx->state.cur)); /* before NewLevel: the branches' update reads q^k */
  PetscCall(NewLevel(ctx, nm, second));
  ctx->state.step++;
  ctx->state.time = ctx->state.step * dt;
  PetscFunctionReturn(0);
}

/* The step matrix (A = K for -static: the step from rest is min 1/2 xi^T K xi over the admissible set) and the
   M products of the levels (the initial ones, or the checkpoint's). */
static PetscErrorCode NewmarkSetUp(RollerScheme s, Roller ctx)
{
  Newmark        *nm = (Newmark *)s->data;
  const PetscReal dt = ctx->ts.dt, rho = ctx->material.density;

  PetscFunctionBeginUser;
  PetscCall(RollerMaxwellCreate(ctx, nm->beta, &nm->mx));
  if (ctx->disc.static_solve) PetscCall(RollerSchemeAddOperator(s, ctx, 0.0, 1.0, 0.0, NULL, 0.0, &nm->op));
  else {
    PetscReal td0;

    RollerTheta(ctx, 0.0, NULL, &td0, NULL); /* centred Coriolis: theta'(0), re-made every step only if theta' varies */
    PetscCall(RollerSchemeAddOperator(s, ctx, rho / (dt * dt) + ctx->disc.damping / (2.0 * dt), nm->beta + ctx->material.viscosity / (2.0 * dt), RollerMaxwellStiffness(nm->mx), ctx->ops.G, rho * td0 / dt, &nm->op));
  }
  PetscCall(VecDuplicate(ctx->state.cur, &nm->Mprev));
  PetscCall(VecDuplicate(ctx->state.cur, &nm->Mprev2));
  PetscCall(VecDuplicate(ctx->state.cur, &nm->Mv));
  PetscCall(MatMult(ctx->ops.M, ctx->state.cur, ctx->state.Mcur));
  PetscCall(MatMult(ctx->ops.M, ctx->state.prev, nm->Mprev));
  PetscCall(MatMult(ctx->ops.M, ctx->state.prev2, nm->Mprev2));
  PetscCall(VecWAXPY(ctx->state.velocity, -1.0, ctx->state.prev, ctx->state.cur));
  PetscCall(VecScale(ctx->state.velocity, 1.0 / dt));
  nm->kinetic_step = -1;
  if (ctx->axle.on) PetscCall(RollerHubSetUp(ctx));
  PetscFunctionReturn(0);
}

static PetscErrorCode NewmarkPhase(RollerScheme s, PetscReal x, PetscReal *e)
{
  Newmark *nm = (Newmark *)s->data;

  PetscFunctionBeginUser;
  /* cos(W dt) = (1 - (1/2 - beta) x^2)/(1 + beta x^2) for the undamped mode */
  *e = PetscAbsReal(PetscAcosReal(PetscMax(-1.0, (1.0 - (0.5 - nm->beta) * x * x) / (1.0 + nm->beta * x * x))) - x);
  PetscFunctionReturn(0);
}

static PetscErrorCode NewmarkView(RollerScheme s, Roller ctx, PetscViewer viewer)
{
  Newmark *nm = (Newmark *)s->data;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, ", three-level Newmark beta = %g, -coriolis_velocity %s", (double)nm->beta, RollerCoriolisVelocities[ctx->disc.coriolis]));
  PetscFunctionReturn(0);
}

static PetscErrorCode NewmarkDestroy(RollerScheme s)
{
  Newmark *nm = (Newmark *)s->data;

  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&nm->Mprev));
  PetscCall(VecDestroy(&nm->Mprev2));
  PetscCall(VecDestroy(&nm->Mv));
  PetscCall(RollerMaxwellDestroy(&nm->mx));
  PetscFunctionReturn(0);
}

/* The trapezoidal rule keeps the DMF's options except -static (the DMF's) and the centred Coriolis term. */
static PetscErrorCode TrapezoidalUsable(RollerScheme s, Roller ctx, const char **why)
{
  PetscFunctionBeginUser;
  *why = NULL;
  if (ctx->disc.static_solve) *why = "-static is the DMF's one step with A = K";
  else if (ctx->disc.coriolis == ROLLER_CORIOLIS_CENTERED) *why = "the centred Coriolis velocity is the DMF's";
  PetscFunctionReturn(0);
}

static PetscErrorCode NewmarkCreate(RollerScheme s, PetscReal beta)
{
  Newmark *nm;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&nm));
  nm->beta        = beta;
  s->data         = nm;
  s->stages       = 1;
  s->order        = 2;
  s->ops->phase   = NewmarkPhase;
  s->ops->setup   = NewmarkSetUp;
  s->ops->step    = NewmarkStep;
  s->ops->energy  = RollerNewmarkEnergy;
  s->ops->balance = RollerNewmarkBalance;
  s->ops->kept    = RollerNewmarkKept;
  s->ops->view    = NewmarkView;
  s->ops->destroy = NewmarkDestroy;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSchemeCreate_DMF(RollerScheme s)
{
  PetscFunctionBeginUser;
  PetscCall(NewmarkCreate(s, 0.5));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSchemeCreate_Trapezoidal(RollerScheme s)
{
  PetscFunctionBeginUser;
  PetscCall(NewmarkCreate(s, 0.25));
  s->ops->usable = TrapezoidalUsable;
  PetscFunctionReturn(0);
}
