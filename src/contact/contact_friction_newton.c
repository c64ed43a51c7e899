/* The semismooth Newton solve of one step's Coulomb law with velocity weakening, and the fixed points about it
   (docs/friction.md section 3), for contact_friction.c: Newton with mu(v) inside it (its first iterate at mu of the
   last step's slip speeds, RollerContactFrictionLaggedMu), else mu frozen per Newton solve and iterated about them
   by Anderson's acceleration (contact_anderson.c); the image (lambda_N, mu(v)) of an iterate and the accelerated
   next iterate, which the fixed point of Tresca steps uses too. */
#include "contact_impl.h"

/* The slips of the iterate fr->x (into fr->box.w) and the fixed point's image g = (lambda_N, mu(v)) (into fr->g); the
   largest change of lambda_N (against lam_n) and of mu (against mu_n, at the nodes in contact), and the largest lambda_N. */
void RollerContactFrictionUpdate(RollerContactFriction fr, PetscInt m, PetscReal dt, PetscReal *change, PetscReal *lmax, PetscReal *dmu)
{
  RollerContactLCPSlack(&fr->box, 2 * m, fr->x, fr->box.w);
  *change = *lmax = *dmu = 0.0;
  for (PetscInt a = 0; a < m; ++a) {
    fr->g[a]     = fr->x[a];
    fr->g[m + a] = RollerFrictionMu(fr->law, PetscAbsReal(fr->box.w[m + a]) / (2.0 * dt), NULL);
    *change      = PetscMax(*change, PetscAbsReal(fr->x[a] - fr->lam_n[a]));
    *lmax        = PetscMax(*lmax, fr->x[a]);
    if (fr->x[a] > 0.0) *dmu = PetscMax(*dmu, PetscAbsReal(fr->g[m + a] - fr->mu_n[a])); /* a free node's mu bounds no force */
  }
}

/* The next iterate of a fixed point from its image fr->g (RollerContactFrictionUpdate), by Anderson's step: of (lambda_N, mu) (the
   Tresca steps: with_lambda) or of mu alone (about Coulomb solves); lambda_N >= 0 and mu within the law's range. */
PetscErrorCode RollerContactFrictionNext(RollerContactFriction fr, PetscInt m, PetscBool with_lambda)
{
  const PetscReal lo = fr->range[0], hi = fr->range[1];
  const PetscInt  o = with_lambda ? m : 0;

  PetscFunctionBeginUser;
  if (with_lambda) PetscCall(PetscArraycpy(fr->y, fr->lam_n, m));
  PetscCall(PetscArraycpy(fr->y + o, fr->mu_n, m));
  PetscCall(RollerContactAndersonStep(&fr->aa, fr->y, fr->g + m - o));
  for (PetscInt a = 0; a < m; ++a) {
    if (with_lambda) fr->lam_n[a] = PetscMax(0.0, fr->y[a]);
    fr->mu_n[a] = PetscMin(PetscMax(fr->y[o + a], lo), hi);
  }
  PetscFunctionReturn(0);
}

/* The last fallback with -friction_decay: mu at the slip speeds of the last step, v = |Delta_1 s|/dt over
   [t_{k-2}, t_{k-1}] (xi^{k-1} = state.cur, xi^{k-2} = state.prev, gathered in c->nodes.red2 by FrictionData), into
   mu_n: the weakening lagged by one step. Where the step's own mu(v) has no attracting solution (the fixed point's
   gain above 1: the steep weakening makes the step's problem non-unique, docs/friction.md section 3), this picks
   the one continuous with the last step; it is a function of the state, so a restart repeats it. */
PetscErrorCode RollerContactFrictionLaggedMu(Roller ctx, RollerContact c, PetscInt m)
{
  RollerContactFriction fr = c->friction;
  const PetscReal       t = c->step.t, dt = ctx->ts.dt, *xc = c->nodes.xc;
  const PetscScalar    *u1, *u2;
  PetscReal             t1[2], t2[2], dX;

  PetscFunctionBeginUser;
  RollerContactSheetTangent(ctx, t - dt, t1);
  RollerContactSheetTangent(ctx, t - 2.0 * dt, t2);
  dX = RollerContactSheetMoves(c) ? c->sheet.X[0] - c->sheet.X[1] : RollerSheetPosition(ctx, t - dt) - RollerSheetPosition(ctx, t - 2.0 * dt);
  PetscCall(RollerContactGather(c, ctx->state.cur, c->nodes.red1));
  PetscCall(VecGetArrayRead(c->nodes.red1, &u1));
  PetscCall(VecGetArrayRead(c->nodes.red2, &u2));
  for (PetscInt a = 0; a < m; ++a) {
    const PetscInt  i  = c->step.cand[a];
    const PetscReal s1 = RollerContactAlong(xc, u1, i, t1) - RollerContactAlong(xc, u2, i, t2) - dX;

    fr->mu_n[a] = RollerFrictionMu(fr->law, PetscAbsReal(s1) / dt, NULL);
  }
  PetscCall(VecRestoreArrayRead(c->nodes.red1, &u1));
  PetscCall(VecRestoreArrayRead(c->nodes.red2, &u2));
  PetscFunctionReturn(0);
}

/* The first iterate of the Newton solve: at the candidates that were in contact after the last solve its multipliers
   (lambda_N, lambda_T) (fr->warm), at the others the frictionless lambda_N and no friction. In rolling the stick and
   slip states barely change from one step to the next, so the iteration starts at them (docs/performance.md,
   "Reduced-order transient": 8 iterations a step on the printer instead of 14). With velocity weakening the warm
   nodes' first mu is that of their slips at this iterate (the lagged mu reads a sticking node's slip over one dt,
   which is not the step's slip over 2 dt, and starts it at mu's wrong end). */
static void WarmStart(Roller ctx, RollerContact c, PetscInt m)
{
  RollerContactFriction fr  = c->friction;
  const PetscInt        nc  = c->nodes.nc;
  PetscBool             any = PETSC_FALSE;

  for (PetscInt a = 0; a < m; ++a) {
    const PetscInt i = c->step.cand[a];

    fr->x[a]     = fr->warm[i] > 0.0 ? fr->warm[i] : fr->lam_n[a];
    fr->x[m + a] = fr->warm[i] > 0.0 ? fr->warm[nc + i] : 0.0;
    any          = (PetscBool)(any || fr->warm[i] > 0.0);
  }
  if (!fr->varies || !any) return;
  RollerContactLCPSlack(&fr->box, 2 * m, fr->x, fr->box.w);
  for (PetscInt a = 0; a < m; ++a)
    if (fr->warm[c->step.cand[a]] > 0.0) fr->mu_n[a] = RollerFrictionMu(fr->law, PetscAbsReal(fr->box.w[m + a]) / (2.0 * ctx->ts.dt), NULL);
}

/* Coulomb by the semismooth Newton method (friction/coulomb.c) from the last solve's multipliers, with mu(v) of the
   velocity weakening linearized inside it. Where that fails (the weakening's slope makes the iteration stall at
   a small slip: docs/friction.md section 3), mu is frozen in each Newton solve and iterated about them, accelerated
   (RollerContactFrictionNext). *done false if both fail (fr->x, lam_n, mu_n are then reset for the fixed point). */
PetscErrorCode RollerContactFrictionNewton(Roller ctx, RollerContact c, PetscInt m, PetscBool *done)
{
  RollerContactFriction fr  = c->friction;
  const RollerObstacle *law = fr->varies ? fr->law : NULL; /* mu(v) inside Newton, else mu as given */
  const PetscReal       tol = c->opt.friction_rtol * fr->range[1], two_dt = 2.0 * ctx->ts.dt;
  PetscReal             change, lmax, dmu;
  PetscInt              its;
  PetscBool             converged;

  PetscFunctionBeginUser;
  *done = PETSC_FALSE;
  if (fr->varies) PetscCall(RollerContactFrictionLaggedMu(ctx, c, m)); /* the first iterate's mu: of the last step's slip speeds */
  WarmStart(ctx, c, m);
  PetscCall(RollerFrictionCoulombNewton(m, fr->box.G, fr->box.d, law, two_dt, fr->mu_n, fr->x, 4 * m + 20, &its, &converged));
  fr->its += its;
  if (converged) {
    RollerContactFrictionUpdate(fr, m, ctx->ts.dt, &change, &lmax, &dmu);
    if (dmu <= tol) {
      *done = PETSC_TRUE;
      PetscFunctionReturn(0);
    }
  }
  if (fr->varies) {
    PetscCall(PetscInfo(NULL, "Friction at t = %g: the semismooth Newton method with mu(v) inside failed after %" PetscInt_FMT " iterations; mu frozen per solve, accelerated\n", (double)c->step.t, its));
    RollerContactAndersonReset(&fr->aa, m);
    PetscCall(RollerContactFrictionLaggedMu(ctx, c, m));
    RollerContactFrictionStart(m, fr->lam_n, fr->x);
    for (PetscInt pass = 0; pass < c->opt.friction_max_it; ++pass) {
      PetscCall(RollerFrictionCoulombNewton(m, fr->box.G, fr->box.d, NULL, two_dt, fr->mu_n, fr->x, 4 * m + 20, &its, &converged));
      fr->its += its;
      if (!converged) break;
      RollerContactFrictionUpdate(fr, m, ctx->ts.dt, &change, &lmax, &dmu);
      PetscCall(PetscInfo(NULL, "Friction at t = %g: pass %" PetscInt_FMT " (%" PetscInt_FMT " Newton its): change of mu %g\n", (double)c->step.t, pass, its, (double)dmu));
      if (dmu <= tol) {
        *done = PETSC_TRUE;
        PetscFunctionReturn(0);
      }
      PetscCall(RollerContactFrictionNext(fr, m, PETSC_FALSE));
    }
  }
  PetscCall(PetscInfo(NULL, "Friction at t = %g: the semismooth Newton method failed after %" PetscInt_FMT " iterations; fixed point of Tresca steps\n", (double)c->step.t, fr->its));
  fr->count.newton_failures++;
  fr->fallback = 1;
  for (PetscInt a = 0; a < m; ++a) fr->mu_n[a] = RollerFrictionMu(fr->law, 0.0, NULL);
  PetscFunctionReturn(0);
}
