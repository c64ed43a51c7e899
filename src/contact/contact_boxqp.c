/* The dual of a Tresca step (docs/friction.md): a small dense QP with bounds only,
     min 1/2 x^T G x + d^T x   s.t.  lo <= x <= up,
   x = (lambda_N, lambda_T) of the m contact candidates, lo = (0, -g), up = (+inf, g), G = B^T S B symmetric
   positive definite (B: the normal and tangent of every candidate). Three solvers (-contact_friction_qp):
   activeset  the primal-dual active-set method on the box (each bound a state: at lo, free, at up), warm-started,
              with the primal active-set method (Nocedal & Wright 16.3 on the box) as its fallback: exact
   tao        a TAO bound-constrained solver (tron: gpcg stalls at round-off on this problem; prefix contact_condensed_)
   vi         SNES VI (vinewtonrsls) on G x + d = 0 with the bounds (prefix contact_friction_vi_) */
#include "contact_impl.h"

const char *const RollerBoxQPTypes[] = {"activeset", "tao", "vi", "lemke", "RollerBoxQPType", "ROLLER_BOXQP_", NULL};

PetscErrorCode RollerContactBoxQPCreate(PetscInt n, RollerContactLCP *qp)
{
  PetscFunctionBeginUser;
  PetscCall(RollerContactLCPCreate(n, qp));
  PetscCall(PetscMalloc2(n, &qp->lo, n, &qp->up));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactBoxQPDestroy(RollerContactLCP *qp)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(qp->lo, qp->up));
  PetscCall(RollerContactLCPDestroy(qp));
  PetscFunctionReturn(0);
}

/* x at its bound where state != 0 (and where lo = up), x_F = G_FF^{-1} (-d_F - G_FB x_B) on the free set. */
static PetscErrorCode SolveFree(RollerContactLCP *qp, PetscInt n, const PetscInt state[], PetscReal x[])
{
  PetscInt nf = 0;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < n; ++j) {
    if (state[j] < 0 || qp->lo[j] == qp->up[j]) x[j] = qp->lo[j];
    else if (state[j] > 0) x[j] = qp->up[j];
    else qp->F[nf++] = j;
  }
  if (!nf) PetscFunctionReturn(0);
  for (PetscInt q = 0; q < nf; ++q) {
    PetscReal r = -qp->d[qp->F[q]];

    for (PetscInt j = 0; j < n; ++j)
      if (state[j] != 0 || qp->lo[j] == qp->up[j]) r -= qp->G[qp->F[q] + (size_t)j * n] * x[j];
    qp->w[q] = r;
  }
  PetscCall(RollerContactDenseSolve(qp->G, n, qp->F, nf, PETSC_TRUE, qp->Gff, qp->w, qp->mu2));
  for (PetscInt q = 0; q < nf; ++q) x[qp->F[q]] = qp->mu2[q];
  PetscFunctionReturn(0);
}

/* The primal active-set method on the box from x = the projection of 0: monotone and finite. */
static PetscErrorCode PrimalActiveSet(RollerContactLCP *qp, PetscInt n, PetscReal tol, PetscInt state[], PetscReal x[], PetscInt *its)
{
  PetscReal *y = qp->mu;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < n; ++j) {
    x[j]     = PetscMin(PetscMax(0.0, qp->lo[j]), qp->up[j]);
    state[j] = x[j] == qp->lo[j] ? -1 : (x[j] == qp->up[j] ? 1 : 0);
  }
  for (PetscBool at_min = PETSC_FALSE; *its < 20 * n + 100; ++*its) {
    if (!at_min) {
      PetscReal alpha = 1.0;
      PetscInt  block = -1;

      PetscCall(SolveFree(qp, n, state, y));
      for (PetscInt j = 0; j < n; ++j) {
        const PetscReal p = y[j] - x[j];

        if (state[j] || p == 0.0) continue;
        if (p < 0.0 && (qp->lo[j] - x[j]) / p < alpha) {
          alpha = (qp->lo[j] - x[j]) / p;
          block = -(j + 1);
        }
        if (p > 0.0 && qp->up[j] < PETSC_MAX_REAL && (qp->up[j] - x[j]) / p < alpha) {
          alpha = (qp->up[j] - x[j]) / p;
          block = j + 1;
        }
      }
      for (PetscInt j = 0; j < n; ++j)
        if (!state[j]) x[j] += alpha * (y[j] - x[j]);
      if (block) {
        const PetscInt j = PetscAbsInt(block) - 1;

        state[j] = block < 0 ? -1 : 1;
        x[j]     = block < 0 ? qp->lo[j] : qp->up[j];
        continue;
      }
      at_min = PETSC_TRUE;
    }
    { /* the minimizer on the working set: release the bound whose multiplier has the wrong sign most */
      PetscInt  jmax = -1;
      PetscReal vmax = tol;

      RollerContactLCPSlack(qp, n, x, qp->w);
      for (PetscInt j = 0; j < n; ++j) {
        const PetscReal v = state[j] < 0 ? -qp->w[j] : (state[j] > 0 ? qp->w[j] : 0.0);

        if (qp->lo[j] < qp->up[j] && v > vmax) {
          vmax = v;
          jmax = j;
        }
      }
      if (jmax < 0) PetscFunctionReturn(0);
      state[jmax] = 0;
      at_min      = PETSC_FALSE;
    }
  }
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "Friction box QP: the active-set method did not terminate in %" PetscInt_FMT " iterations", *its);
}

/* The primal-dual active-set method (a semismooth Newton method on the box projection), from state[]; the primal
   active-set method if it has not settled in n + 10 iterations. On return state[] holds the active bounds. */
static PetscErrorCode BoxActiveSet(RollerContactLCP *qp, PetscInt n, PetscReal tol, PetscInt state[], PetscReal x[], PetscInt *its)
{
  PetscFunctionBeginUser;
  for (*its = 1; *its <= n + 10; ++*its) {
    PetscInt changed = 0;

    PetscCall(SolveFree(qp, n, state, x));
    RollerContactLCPSlack(qp, n, x, qp->w);
    for (PetscInt j = 0; j < n; ++j) {
      PetscInt next;

      if (qp->lo[j] == qp->up[j]) next = -1;
      else if (state[j] == 0) next = x[j] < qp->lo[j] ? -1 : (x[j] > qp->up[j] ? 1 : 0);
      else if (state[j] < 0) next = qp->w[j] < -tol ? 0 : -1;
      else next = qp->w[j] > tol ? 0 : 1;
      if (next != state[j]) changed++;
      state[j] = next;
    }
    if (!changed) PetscFunctionReturn(0);
  }
  PetscCall(PetscInfo(NULL, "Friction box QP: PDAS did not settle in %" PetscInt_FMT " iterations, primal active-set method\n", n + 10));
  PetscCall(PrimalActiveSet(qp, n, tol, state, x, its));
  PetscFunctionReturn(0);
}

/* SNES VI callbacks: F(x) = G x + d, J = G. */
static PetscErrorCode VIFunction(SNES snes, Vec x, Vec f, void *ctx)
{
  RollerContactLCP *qp = (RollerContactLCP *)ctx;

  PetscFunctionBeginUser;
  PetscCall(MatMultAdd(qp->tG, x, qp->td, f));
  PetscFunctionReturn(0);
}

static PetscErrorCode VIJacobian(SNES snes, Vec x, Mat J, Mat P, void *ctx)
{
  PetscFunctionBeginUser;
  PetscFunctionReturn(0);
}

/* SNES VI (vinewtonrsls) on G x + d = 0 with the bounds, from x = the projection of 0, to the absolute residual
   tolerance atol (a length). The unknown is scaled to y = x/s, s the largest finite bound: SNES VI counts a
   component within an absolute 1e-8 of its bound as on it, which for forces of 1e-5 would pin sticking nodes to
   the cone (a law residual of 1e-6 on the feeder). */
static PetscErrorCode BoxVI(RollerContactLCP *qp, PetscInt n, PetscReal atol, PetscReal t, PetscReal x[], PetscInt *its)
{
  SNESConvergedReason reason;
  PetscReal           s;
  const PetscScalar  *xa;
  KSP                 ksp;
  PC                  pc;

  PetscFunctionBeginUser;
  PetscCall(RollerContactLCPWork(qp, n));
  if (!qp->snes) {
    Vec r;

    PetscCall(SNESCreate(PETSC_COMM_SELF, &qp->snes));
    PetscCall(SNESSetOptionsPrefix(qp->snes, "contact_friction_vi_"));
    PetscCall(SNESSetType(qp->snes, SNESVINEWTONRSLS));
    PetscCall(VecDuplicate(qp->tx, &r));
    PetscCall(SNESSetFunction(qp->snes, r, VIFunction, qp)); /* the SNES keeps r */
    PetscCall(VecDestroy(&r));
    PetscCall(SNESSetJacobian(qp->snes, qp->tG, qp->tG, VIJacobian, qp));
    PetscCall(SNESGetKSP(qp->snes, &ksp));
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCLU));
    PetscCall(SNESSetFromOptions(qp->snes));
  }
  {
    PetscReal scale = 0.0;

    for (PetscInt j = 0; j < n; ++j) {
      if (qp->lo && qp->lo[j] > -PETSC_MAX_REAL) scale = PetscMax(scale, PetscAbsReal(qp->lo[j]));
      if (qp->up && qp->up[j] < PETSC_MAX_REAL) scale = PetscMax(scale, PetscAbsReal(qp->up[j]));
    }
    s = scale > 0.0 ? scale : 1.0;
  }
  PetscCall(MatScale(qp->tG, s)); /* F(y) = s G y + d */
  PetscCall(VecScale(qp->tlb, 1.0 / s));
  PetscCall(VecScale(qp->tub, 1.0 / s));
  PetscCall(SNESVISetVariableBounds(qp->snes, qp->tlb, qp->tub));
  PetscCall(SNESSetTolerances(qp->snes, atol, 0.0, 0.0, 200, 10000));
  PetscCall(VecZeroEntries(qp->tx));
  PetscCall(VecPointwiseMax(qp->tx, qp->tx, qp->tlb));
  PetscCall(VecPointwiseMin(qp->tx, qp->tx, qp->tub));
  PetscCall(SNESSolve(qp->snes, NULL, qp->tx));
  PetscCall(SNESGetConvergedReason(qp->snes, &reason));
  PetscCall(SNESGetIterationNumber(qp->snes, its));
  PetscCheck(reason > 0, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "Friction box QP at t = %g: SNES VI did not converge: %s", (double)t, SNESConvergedReasons[reason]);
  PetscCall(VecGetArrayRead(qp->tx, &xa));
  for (PetscInt j = 0; j < n; ++j) x[j] = PetscMin(PetscMax(qp->lo[j], s * PetscRealPart(xa[j])), qp->up[j]);
  PetscCall(VecRestoreArrayRead(qp->tx, &xa));
  PetscFunctionReturn(0);
}

/* Solve the box QP held in qp (G, d, lo, up of size n) with the solver of type; tol is the absolute tolerance of
   the gradient G x + d (a length), t the step's time (messages); state[] warm-starts the active set. */
PetscErrorCode RollerContactBoxQPSolve(RollerContactLCP *qp, RollerBoxQPType type, PetscInt n, PetscReal tol, PetscReal t, PetscInt state[], PetscReal x[], PetscInt *its)
{
  PetscFunctionBeginUser;
  *its = 0;
  if (!n) PetscFunctionReturn(0);
  switch (type) {
  case ROLLER_BOXQP_TAO:
    PetscCall(RollerContactLCPTao(qp, n, tol, t, x, its));
    break;
  case ROLLER_BOXQP_VI:
    PetscCall(BoxVI(qp, n, tol, t, x, its));
    break;
  default:
    PetscCall(BoxActiveSet(qp, n, tol, state, x, its));
  }
  PetscFunctionReturn(0);
}
