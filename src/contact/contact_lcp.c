/* The small dense LCP of the condensed solver (contact_condensed.c): with G = N^T S N on the m candidates
   (symmetric positive definite) and d their gaps of the free solution, find
     lam >= 0,  w = G lam + d >= 0,  lam . w = 0   (min 1/2 lam^T G lam + d^T lam over lam >= 0),
   exactly by an active-set method, or by a sequential TAO (-contact_condensed_qp tao). G and d are filled by
   the caller, column-major m x m in the arrays sized for nc. */
#include "contact_impl.h"
#include <petscblaslapack.h>

PetscErrorCode RollerContactLCPCreate(PetscInt nc, RollerContactLCP *cd)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(cd, sizeof(*cd)));
  PetscCall(PetscMalloc4((size_t)nc * nc, &cd->G, (size_t)nc * nc, &cd->Gff, nc, &cd->d, nc, &cd->lam));
  PetscCall(PetscMalloc5(nc, &cd->mu, nc, &cd->mu2, nc, &cd->w, nc, &cd->F, nc, &cd->act));
  PetscFunctionReturn(0);
}

/* y = G_FF^{-1} r on the index set F (nf of the m x m column-major G) by dense Cholesky (LAPACK potrf; spd) or LU
   (getrf); Gff is scratch of nf^2 entries. */
PetscErrorCode RollerContactDenseSolve(const PetscReal G[], PetscInt m, const PetscInt F[], PetscInt nf, PetscBool spd, PetscReal Gff[], PetscReal r[], PetscReal y[])
{
  PetscBLASInt n, one = 1, info, *piv = NULL;

  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < nf; ++q)
    for (PetscInt p = 0; p < nf; ++p) Gff[p + (size_t)q * nf] = G[F[p] + (size_t)F[q] * m];
  PetscCall(PetscBLASIntCast(nf, &n));
  PetscCall(PetscArraycpy(y, r, nf));
  /* LAPACK directly, as a dense Mat's factor and solve do it (a Mat made for each small solve cost more than it) */
  if (spd) {
    PetscCallBLAS("LAPACKpotrf", LAPACKpotrf_("L", &n, Gff, &n, &info));
    PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_MAT_CH_ZRPVT, "Contact: the condensed matrix of %" PetscInt_FMT " multipliers is not positive definite (LAPACK potrf info %d)", nf, (int)info);
    PetscCallBLAS("LAPACKpotrs", LAPACKpotrs_("L", &n, &one, Gff, &n, y, &n, &info));
  } else {
    PetscCall(PetscMalloc1(nf, &piv));
    PetscCallBLAS("LAPACKgetrf", LAPACKgetrf_(&n, &n, Gff, &n, piv, &info));
    PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_MAT_LU_ZRPVT, "Contact: the condensed matrix of %" PetscInt_FMT " unknowns is singular (LAPACK getrf info %d)", nf, (int)info);
    PetscCallBLAS("LAPACKgetrs", LAPACKgetrs_("N", &n, &one, Gff, &n, piv, y, &n, &info));
    PetscCall(PetscFree(piv));
  }
  PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "Contact: LAPACK's dense solve, info %d", (int)info);
  PetscFunctionReturn(0);
}

/* lam_F = -G_FF^{-1} d_F on the free set F = {act}, lam = 0 elsewhere. */
static PetscErrorCode SolveFreeSet(RollerContactLCP *cd, PetscInt m, const PetscBool act[], PetscReal lam[])
{
  PetscInt nf = 0;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < m; ++a) {
    lam[a] = 0.0;
    if (act[a]) cd->F[nf++] = a;
  }
  if (!nf) PetscFunctionReturn(0);
  for (PetscInt q = 0; q < nf; ++q) cd->w[q] = -cd->d[cd->F[q]];
  PetscCall(RollerContactDenseSolve(cd->G, m, cd->F, nf, PETSC_TRUE, cd->Gff, cd->w, cd->mu2));
  for (PetscInt q = 0; q < nf; ++q) lam[cd->F[q]] = cd->mu2[q];
  PetscFunctionReturn(0);
}

/* w = G lam + d */
void RollerContactLCPSlack(RollerContactLCP *cd, PetscInt m, const PetscReal lam[], PetscReal w[])
{
  RollerDenseMultAdd(m, cd->G, cd->d, 1.0, lam, w);
}

/* The LCP  lam >= 0, w = G lam + d >= 0, lam . w = 0 with G symmetric positive definite.
   First the primal-dual active set method (Hintermueller, Ito, Kunisch 2003: a semismooth Newton method on
   min(lam, w) = 0), warm-started from the nodes on the obstacle at the previous level (the act[] given): it
   finds the solution of a contact problem in a few iterations, each a dense Cholesky of the active block. PDAS is only guaranteed to terminate for
   M-matrices, so if it has not settled in m + 10 iterations the primal active-set method (Nocedal & Wright,
   Algorithm 16.3, on the bounds lam >= 0) takes over from lam = 0: monotone, finite. On return act marks
   lam > 0. */
PetscErrorCode RollerContactLCPActiveSet(RollerContactLCP *cd, PetscInt m, PetscReal tol, PetscBool act[], PetscReal lam[], PetscInt *its)
{
  PetscInt it;

  PetscFunctionBeginUser;
  for (it = 1; it <= m + 10; ++it) {
    PetscInt changed = 0;

    PetscCall(SolveFreeSet(cd, m, act, lam));
    RollerContactLCPSlack(cd, m, lam, cd->w);
    for (PetscInt a = 0; a < m; ++a) {
      const PetscBool next = act[a] ? (lam[a] > 0.0 ? PETSC_TRUE : PETSC_FALSE) : (cd->w[a] < -tol ? PETSC_TRUE : PETSC_FALSE);

      if (next != act[a]) changed++;
      act[a] = next;
    }
    if (!changed) {
      *its = it;
      PetscFunctionReturn(0);
    }
  }
  PetscCall(PetscInfo(NULL, "Contact condensed: PDAS did not settle in %" PetscInt_FMT " iterations, primal active-set method\n", m + 10));
  for (PetscInt a = 0; a < m; ++a) {
    act[a] = PETSC_FALSE;
    lam[a] = 0.0;
  }
  for (PetscBool full_step = PETSC_TRUE; it < 10 * m + 100; ++it) {
    if (!full_step) {
      PetscReal alpha = 1.0;
      PetscInt  block = -1;

      PetscCall(SolveFreeSet(cd, m, act, cd->mu));
      for (PetscInt a = 0; a < m; ++a)
        if (act[a] && cd->mu[a] < 0.0) {
          const PetscReal ratio = lam[a] / (lam[a] - cd->mu[a]);

          if (ratio < alpha) {
            alpha = ratio;
            block = a;
          }
        }
      for (PetscInt a = 0; a < m; ++a)
        if (act[a]) lam[a] += alpha * (cd->mu[a] - lam[a]);
      if (block >= 0) {
        lam[block] = 0.0;
        act[block] = PETSC_FALSE;
        continue;
      }
    }
    /* a minimizer on the working set: the most violated multiplier of a bound in it enters the free set */
    {
      PetscInt  amin = -1;
      PetscReal wmin = -tol;

      RollerContactLCPSlack(cd, m, lam, cd->w);
      for (PetscInt a = 0; a < m; ++a)
        if (!act[a] && cd->w[a] < wmin) {
          wmin = cd->w[a];
          amin = a;
        }
      if (amin < 0) {
        *its = it;
        for (PetscInt a = 0; a < m; ++a) act[a] = lam[a] > 0.0 ? PETSC_TRUE : PETSC_FALSE;
        PetscFunctionReturn(0);
      }
      act[amin] = PETSC_TRUE;
      full_step = PETSC_FALSE;
    }
  }
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "Condensed contact QP: the active-set method did not terminate in %" PetscInt_FMT " iterations", it);
}

/* The work objects sized for one problem size m (the dense matrix, solution, bounds, linear term), and the TAO
   and SNES that use them: rebuilt when the size changes. */
static PetscErrorCode WorkDestroy(RollerContactLCP *cd)
{
  PetscFunctionBeginUser;
  PetscCall(TaoDestroy(&cd->tao));
  PetscCall(SNESDestroy(&cd->snes));
  PetscCall(MatDestroy(&cd->tG));
  PetscCall(VecDestroy(&cd->tx));
  PetscCall(VecDestroy(&cd->tlb));
  PetscCall(VecDestroy(&cd->tub));
  PetscCall(VecDestroy(&cd->td));
  cd->tao_m = 0;
  PetscFunctionReturn(0);
}

/* The work objects for size m, filled with G, d and the bounds (lo, up if set, else 0 and +inf). */
PetscErrorCode RollerContactLCPWork(RollerContactLCP *cd, PetscInt m)
{
  PetscScalar *a;

  PetscFunctionBeginUser;
  if (cd->tao_m != m) {
    PetscCall(WorkDestroy(cd));
    PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, m, m, NULL, &cd->tG));
    PetscCall(VecCreateSeq(PETSC_COMM_SELF, m, &cd->tx));
    PetscCall(VecDuplicate(cd->tx, &cd->tlb));
    PetscCall(VecDuplicate(cd->tx, &cd->tub));
    PetscCall(VecDuplicate(cd->tx, &cd->td));
    cd->tao_m = m;
  }
  PetscCall(MatDenseGetArrayWrite(cd->tG, &a));
  for (size_t k = 0; k < (size_t)m * m; ++k) a[k] = cd->G[k];
  PetscCall(MatDenseRestoreArrayWrite(cd->tG, &a));
  PetscCall(MatAssemblyBegin(cd->tG, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(cd->tG, MAT_FINAL_ASSEMBLY));
  PetscCall(VecGetArrayWrite(cd->td, &a));
  for (PetscInt k = 0; k < m; ++k) a[k] = cd->d[k];
  PetscCall(VecRestoreArrayWrite(cd->td, &a));
  if (cd->lo) {
    PetscCall(VecGetArrayWrite(cd->tlb, &a));
    for (PetscInt k = 0; k < m; ++k) a[k] = cd->lo[k];
    PetscCall(VecRestoreArrayWrite(cd->tlb, &a));
    PetscCall(VecGetArrayWrite(cd->tub, &a));
    for (PetscInt k = 0; k < m; ++k) a[k] = cd->up[k] >= PETSC_MAX_REAL ? PETSC_INFINITY : cd->up[k];
    PetscCall(VecRestoreArrayWrite(cd->tub, &a));
  } else {
    PetscCall(VecSet(cd->tlb, 0.0));
    PetscCall(VecSet(cd->tub, PETSC_INFINITY));
  }
  PetscFunctionReturn(0);
}

/* -contact_condensed_qp tao (and the friction's box QP): the same small problem with a TAO bound-constrained
   solver (prefix contact_condensed_, default gpcg, the TAO method for bound-constrained QPs; tron for the box QP), from lam = 0, to
   the absolute tolerance gatol of the gradient G lam + d (a gap); t is the step's time, for the error message. */
PetscErrorCode RollerContactLCPTao(RollerContactLCP *cd, PetscInt m, PetscReal gatol, PetscReal t, PetscReal lam[], PetscInt *its)
{
  const PetscScalar *x;
  TaoType            ttype;
  TaoConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(RollerContactLCPWork(cd, m));
  if (!cd->tao) {
    PetscCall(TaoCreate(PETSC_COMM_SELF, &cd->tao));
    PetscCall(TaoSetOptionsPrefix(cd->tao, "contact_condensed_"));
    PetscCall(TaoSetType(cd->tao, cd->lo ? TAOTRON : TAOGPCG)); /* the friction's box QP: gpcg stalls at round-off on it */
    PetscCall(TaoSetSolution(cd->tao, cd->tx));
    cd->tqp.H    = cd->tG; /* 1/2 lam^T G lam + d^T lam */
    cd->tqp.c    = cd->td;
    cd->tqp.sign = 1.0;
    PetscCall(TaoSetObjectiveAndGradient(cd->tao, NULL, RollerContactTaoQPObjective, &cd->tqp));
    PetscCall(TaoSetHessian(cd->tao, cd->tG, cd->tG, RollerContactTaoQPHessian, &cd->tqp));
    PetscCall(TaoSetVariableBounds(cd->tao, cd->tlb, cd->tub));
    PetscCall(TaoSetMaximumIterations(cd->tao, 10000));
    PetscCall(TaoSetFromOptions(cd->tao));
  }
  PetscCall(VecZeroEntries(cd->tx));
  PetscCall(TaoSetTolerances(cd->tao, gatol, 0.0, 0.0));
  PetscCall(TaoSolve(cd->tao));
  PetscCall(TaoGetConvergedReason(cd->tao, &reason));
  PetscCall(TaoGetType(cd->tao, &ttype));
  PetscCall(TaoGetIterationNumber(cd->tao, its));
  PetscCheck(reason > 0, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "Condensed contact QP at t = %g: TAO %s did not converge: %s", (double)t, ttype, TaoConvergedReasons[reason]);
  PetscCall(VecGetArrayRead(cd->tx, &x));
  for (PetscInt k = 0; k < m; ++k) lam[k] = cd->lo ? PetscMin(PetscMax(cd->lo[k], PetscRealPart(x[k])), cd->up[k]) : PetscMax(0.0, PetscRealPart(x[k]));
  PetscCall(VecRestoreArrayRead(cd->tx, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactLCPDestroy(RollerContactLCP *cd)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree4(cd->G, cd->Gff, cd->d, cd->lam));
  PetscCall(PetscFree5(cd->mu, cd->mu2, cd->w, cd->F, cd->act));
  PetscCall(WorkDestroy(cd));
  PetscFunctionReturn(0);
}
