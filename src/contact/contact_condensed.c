/* The default contact solver: the QP condensed onto the multipliers of the candidate nodes.

   With E the injection of the Gamma_C dofs and N = diag(n^k) at the candidates, the KKT conditions of the
   step QP (docs/model.md section 2) are  A xi = b + E N lambda,  lambda >= 0,  gap >= 0,  lambda . gap = 0, so
   xi = xi_f + A^{-1} E N lambda with the free solution xi_f = A^{-1} b, and gap(lambda) = d + G lambda with
   d = gap of xi_f and G = N^T S N, S = E^T A^{-1} E. Since A never changes, S (2 N_C x 2 N_C) is computed
   once with the step factorization; each step is one solve for xi_f, a small dense LCP in lambda (equivalently
   min 1/2 lambda^T G lambda + d^T lambda, lambda >= 0), and, only if some lambda > 0, one more solve for the
   correction. A step in which nothing touches costs what a free step costs. */
#include "contact_impl.h"

struct _n_RollerContactCondensed {
  PetscReal *S;                                /* 2 nc x 2 nc, column-major, the same on every rank */
  PetscReal *gf;                               /* nc: gap of the free solution */
  PetscReal *G, *Gff, *d, *lam, *mu, *mu2, *w; /* the small QP, sized for nc */
  PetscInt  *F;
  PetscBool *act;
  Vec        xf, f, corr;
  /* -contact_condensed_qp tao: a sequential TAO on the same small problem, rebuilt when its size changes */
  Tao      tao;
  Mat      tG;
  Vec      tx, tlb, tub, td;
  PetscInt tao_m;
};

/* S = E^T A^{-1} E: A^{-1} applied to the unit vectors of the Gamma_C dofs, in blocks of columns with
   KSPMatSolve on the one factorization; each column's Gamma_C entries are gathered on every rank. */
PetscErrorCode RollerContactCondensedCreate(Roller ctx, RollerContact c)
{
  RollerContactCondensed cd;
  const PetscInt         n = 2 * c->nc, nb = 64;
  PetscInt               nlocal, rstart, rend;
  PetscLogDouble         t0, t1;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&cd));
  c->condensed = cd;
  PetscCall(PetscTime(&t0));
  PetscCall(PetscMalloc1((size_t)n * n, &cd->S));
  PetscCall(PetscMalloc5(c->nc, &cd->gf, (size_t)c->nc * c->nc, &cd->G, (size_t)c->nc * c->nc, &cd->Gff, c->nc, &cd->d, c->nc, &cd->lam));
  PetscCall(PetscMalloc5(c->nc, &cd->mu, c->nc, &cd->mu2, c->nc, &cd->w, c->nc, &cd->F, c->nc, &cd->act));
  PetscCall(VecDuplicate(ctx->state.cur, &cd->xf));
  PetscCall(VecDuplicate(ctx->state.cur, &cd->f));
  PetscCall(VecDuplicate(ctx->state.cur, &cd->corr));
  PetscCall(VecGetLocalSize(ctx->state.cur, &nlocal));
  PetscCall(VecGetOwnershipRange(ctx->state.cur, &rstart, &rend));
  for (PetscInt j0 = 0; j0 < n; j0 += nb) {
    const PetscInt m = PetscMin(nb, n - j0);
    Mat            B, X;

    PetscCall(MatCreateDense(ctx->comm, nlocal, PETSC_DECIDE, PETSC_DETERMINE, m, NULL, &B));
    PetscCall(MatZeroEntries(B));
    for (PetscInt jj = 0; jj < m; ++jj) {
      const PetscInt j = j0 + jj, row = c->gidx[j / 2] + j % 2;

      if (row >= rstart && row < rend) PetscCall(MatSetValue(B, row, jj, 1.0, INSERT_VALUES));
    }
    PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatDuplicate(B, MAT_DO_NOT_COPY_VALUES, &X));
    PetscCall(KSPMatSolve(ctx->ops.ksp, B, X));
    for (PetscInt jj = 0; jj < m; ++jj) {
      Vec                col;
      const PetscScalar *r;

      PetscCall(MatDenseGetColumnVecRead(X, jj, &col));
      PetscCall(RollerContactGather(c, col, c->red));
      PetscCall(MatDenseRestoreColumnVecRead(X, jj, &col));
      PetscCall(VecGetArrayRead(c->red, &r));
      for (PetscInt i = 0; i < n; ++i) cd->S[i + (size_t)(j0 + jj) * n] = PetscRealPart(r[i]);
      PetscCall(VecRestoreArrayRead(c->red, &r));
    }
    PetscCall(MatDestroy(&B));
    PetscCall(MatDestroy(&X));
  }
  /* A is symmetric; remove the solver's round-off asymmetry so G is symmetric to the last bit */
  for (PetscInt j = 0; j < n; ++j)
    for (PetscInt i = 0; i < j; ++i) {
      const PetscReal s = 0.5 * (cd->S[i + (size_t)j * n] + cd->S[j + (size_t)i * n]);

      cd->S[i + (size_t)j * n] = cd->S[j + (size_t)i * n] = s;
    }
  PetscCall(PetscTime(&t1));
  PetscCall(PetscInfo(NULL, "Contact condensed: S = E^T A^-1 E of size %" PetscInt_FMT " in %g s\n", n, t1 - t0));
  PetscFunctionReturn(0);
}

/* n^T S_{ij} n: the normal-normal entry of S between nodes i and j. */
static inline PetscReal NormalEntry(const PetscReal *S, PetscInt n, const PetscReal nrm[2], PetscInt i, PetscInt j)
{
  const PetscReal *c0 = S + (size_t)(2 * j) * n, *c1 = S + (size_t)(2 * j + 1) * n;

  return nrm[0] * (nrm[0] * c0[2 * i] + nrm[1] * c1[2 * i]) + nrm[1] * (nrm[0] * c0[2 * i + 1] + nrm[1] * c1[2 * i + 1]);
}

/* lam_F = -G_FF^{-1} d_F on the free set F = {act}, lam = 0 elsewhere (dense Cholesky, LAPACK potrf). */
static PetscErrorCode SolveFreeSet(RollerContactCondensed cd, PetscInt m, const PetscBool act[], PetscReal lam[])
{
  PetscInt nf = 0;
  Mat      Gff;
  Vec      rhs, sol;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < m; ++a) {
    lam[a] = 0.0;
    if (act[a]) cd->F[nf++] = a;
  }
  if (!nf) PetscFunctionReturn(0);
  for (PetscInt q = 0; q < nf; ++q) {
    for (PetscInt p = 0; p < nf; ++p) cd->Gff[p + (size_t)q * nf] = cd->G[cd->F[p] + (size_t)cd->F[q] * m];
    cd->w[q] = -cd->d[cd->F[q]];
  }
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, nf, nf, cd->Gff, &Gff));
  PetscCall(MatSetOption(Gff, MAT_SPD, PETSC_TRUE));
  PetscCall(MatCholeskyFactor(Gff, NULL, NULL));
  PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, nf, cd->w, &rhs));
  PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, nf, cd->mu2, &sol));
  PetscCall(MatSolve(Gff, rhs, sol));
  PetscCall(VecDestroy(&rhs));
  PetscCall(VecDestroy(&sol));
  PetscCall(MatDestroy(&Gff));
  for (PetscInt q = 0; q < nf; ++q) lam[cd->F[q]] = cd->mu2[q];
  PetscFunctionReturn(0);
}

/* w = G lam + d */
static void Slack(RollerContactCondensed cd, PetscInt m, const PetscReal lam[], PetscReal w[])
{
  for (PetscInt a = 0; a < m; ++a) w[a] = cd->d[a];
  for (PetscInt b = 0; b < m; ++b)
    if (lam[b] != 0.0)
      for (PetscInt a = 0; a < m; ++a) w[a] += cd->G[a + (size_t)b * m] * lam[b];
}

/* The LCP  lam >= 0, w = G lam + d >= 0, lam . w = 0 with G symmetric positive definite.
   First the primal-dual active set method (Hintermueller, Ito, Kunisch 2003: a semismooth Newton method on
   min(lam, w) = 0), warm-started from the nodes on the obstacle at the previous level (c->on_obstacle): it
   finds the solution of a contact problem in a few iterations, each a dense Cholesky of the active block. PDAS is only guaranteed to terminate for
   M-matrices, so if it has not settled in m + 10 iterations the primal active-set method (Nocedal & Wright,
   Algorithm 16.3, on the bounds lam >= 0) takes over from lam = 0: monotone, finite. On return act marks
   lam > 0. */
static PetscErrorCode ActiveSetSolve(RollerContactCondensed cd, PetscInt m, PetscReal tol, PetscBool act[], PetscReal lam[], PetscInt *its)
{
  PetscInt it;

  PetscFunctionBeginUser;
  for (it = 1; it <= m + 10; ++it) {
    PetscInt changed = 0;

    PetscCall(SolveFreeSet(cd, m, act, lam));
    Slack(cd, m, lam, cd->w);
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

      Slack(cd, m, lam, cd->w);
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

static PetscErrorCode TaoObjectiveGradient(Tao tao, Vec x, PetscReal *f, Vec g, void *ptr)
{
  RollerContactCondensed cd = (RollerContactCondensed)ptr;
  PetscScalar            xgx, dx;

  PetscFunctionBeginUser;
  PetscCall(MatMult(cd->tG, x, g));
  PetscCall(VecDot(x, g, &xgx));
  PetscCall(VecDot(cd->td, x, &dx));
  *f = PetscRealPart(0.5 * xgx + dx);
  PetscCall(VecAXPY(g, 1.0, cd->td));
  PetscFunctionReturn(0);
}

static PetscErrorCode TaoHessian(Tao tao, Vec x, Mat H, Mat P, void *ptr)
{
  PetscFunctionBeginUser;
  PetscFunctionReturn(0); /* G is constant and already in H */
}

/* The TAO solver and its work objects, sized for one number of candidates. */
static PetscErrorCode TaoWorkDestroy(RollerContactCondensed cd)
{
  PetscFunctionBeginUser;
  PetscCall(TaoDestroy(&cd->tao));
  PetscCall(MatDestroy(&cd->tG));
  PetscCall(VecDestroy(&cd->tx));
  PetscCall(VecDestroy(&cd->tlb));
  PetscCall(VecDestroy(&cd->tub));
  PetscCall(VecDestroy(&cd->td));
  PetscFunctionReturn(0);
}

/* -contact_condensed_qp tao: the same small problem with a TAO bound-constrained solver (prefix
   contact_condensed_, default gpcg, the TAO method for bound-constrained QPs), from lam = 0. */
static PetscErrorCode TaoCondensedSolve(Roller ctx, RollerContact c, RollerContactCondensed cd, PetscInt m, PetscReal dmax, PetscReal lam[], PetscInt *its)
{
  PetscScalar       *a;
  const PetscScalar *x;
  TaoType            ttype;
  TaoConvergedReason reason;

  PetscFunctionBeginUser;
  if (cd->tao_m != m) {
    PetscCall(TaoWorkDestroy(cd));
    PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, m, m, NULL, &cd->tG));
    PetscCall(VecCreateSeq(PETSC_COMM_SELF, m, &cd->tx));
    PetscCall(VecDuplicate(cd->tx, &cd->tlb));
    PetscCall(VecDuplicate(cd->tx, &cd->tub));
    PetscCall(VecDuplicate(cd->tx, &cd->td));
    PetscCall(VecSet(cd->tlb, 0.0));
    PetscCall(VecSet(cd->tub, PETSC_INFINITY));
    PetscCall(TaoCreate(PETSC_COMM_SELF, &cd->tao));
    PetscCall(TaoSetOptionsPrefix(cd->tao, "contact_condensed_"));
    PetscCall(TaoSetType(cd->tao, TAOGPCG));
    PetscCall(TaoSetSolution(cd->tao, cd->tx));
    PetscCall(TaoSetObjectiveAndGradient(cd->tao, NULL, TaoObjectiveGradient, cd));
    PetscCall(TaoSetHessian(cd->tao, cd->tG, cd->tG, TaoHessian, cd));
    PetscCall(TaoSetVariableBounds(cd->tao, cd->tlb, cd->tub));
    PetscCall(TaoSetMaximumIterations(cd->tao, 10000));
    PetscCall(TaoSetFromOptions(cd->tao));
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
  PetscCall(VecZeroEntries(cd->tx));
  /* the gradient G lam + d is a gap (a length): converge it far below the gaps of the free solution */
  PetscCall(TaoSetTolerances(cd->tao, c->rtol * dmax, 0.0, 0.0));
  PetscCall(TaoSolve(cd->tao));
  PetscCall(TaoGetConvergedReason(cd->tao, &reason));
  PetscCall(TaoGetType(cd->tao, &ttype));
  PetscCall(TaoGetIterationNumber(cd->tao, its));
  PetscCheck(reason > 0, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "Condensed contact QP at t = %g: TAO %s did not converge: %s", (double)c->t, ttype, TaoConvergedReasons[reason]);
  PetscCall(VecGetArrayRead(cd->tx, &x));
  for (PetscInt k = 0; k < m; ++k) lam[k] = PetscMax(0.0, PetscRealPart(x[k]));
  PetscCall(VecRestoreArrayRead(cd->tx, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactCondensedSolve(Roller ctx, RollerContact c, Vec b, Vec xi, RollerContactResult *res)
{
  RollerContactCondensed cd  = c->condensed;
  const PetscInt         n   = 2 * c->nc;
  const PetscReal        tol = RollerContactGapTolerance(ctx);
  const PetscScalar     *u;
  KSPConvergedReason     reason;
  PetscBool              any = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCheck(cd, ctx->comm, PETSC_ERR_ORDER, "The condensed contact solver was not set up");
  PetscCall(KSPSolve(ctx->ops.ksp, b, cd->xf));
  PetscCall(KSPGetConvergedReason(ctx->ops.ksp, &reason));
  PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "The free solve of the contact step at t = %g diverged: %s", (double)c->t, KSPConvergedReasons[reason]);
  PetscCall(RollerContactGather(c, cd->xf, c->red));
  PetscCall(VecGetArrayRead(c->red, &u));
  for (PetscInt i = 0; i < c->nc; ++i) cd->gf[i] = PetscRealPart(u[2 * i]) * c->normal[0] + PetscRealPart(u[2 * i + 1]) * c->normal[1] - c->lower[i];
  PetscCall(VecRestoreArrayRead(c->red, &u));
  res->its = 0;
  for (;;) {
    const PetscInt m    = c->ncand;
    PetscReal      dmax = 0.0;
    PetscInt       its = 0, added = 0;

    for (PetscInt a = 0; a < m; ++a) {
      cd->d[a]   = cd->gf[c->cand[a]];
      cd->act[a] = c->on_obstacle[c->cand[a]];
      dmax       = PetscMax(dmax, PetscAbsReal(cd->d[a]));
      for (PetscInt b2 = 0; b2 <= a; ++b2) cd->G[a + (size_t)b2 * m] = cd->G[b2 + (size_t)a * m] = NormalEntry(cd->S, n, c->normal, c->cand[a], c->cand[b2]);
    }
    if (c->qp == CONTACT_QP_TAO && m > 0) PetscCall(TaoCondensedSolve(ctx, c, cd, m, dmax, cd->lam, &its));
    else if (m > 0) PetscCall(ActiveSetSolve(cd, m, 1e-13 * dmax, cd->act, cd->lam, &its));
    res->its += its;
    /* the gaps of every Gamma_C node at this lambda, before any further solve: add the penetrating ones */
    for (PetscInt i = 0; i < c->nc; ++i) {
      PetscReal gap = cd->gf[i];

      if (c->is_cand[i]) continue;
      for (PetscInt a = 0; a < m; ++a)
        if (cd->lam[a] > 0.0) gap += NormalEntry(cd->S, n, c->normal, i, c->cand[a]) * cd->lam[a];
      if (gap < -tol) {
        c->is_cand[i] = PETSC_TRUE;
        added++;
      }
    }
    if (!added) break;
    c->ncand = 0;
    for (PetscInt i = 0; i < c->nc; ++i)
      if (c->is_cand[i]) c->cand[c->ncand++] = i;
    c->resolves++;
  }
  PetscCall(PetscArrayzero(res->lambda, c->nc));
  for (PetscInt a = 0; a < c->ncand; ++a)
    if (cd->lam[a] > 0.0) {
      res->lambda[c->cand[a]] = cd->lam[a];
      any                     = PETSC_TRUE;
    }
  if (!any) {
    PetscCall(VecCopy(cd->xf, xi));
    PetscFunctionReturn(0);
  }
  PetscCall(RollerContactForce(c, res->lambda, cd->f));
  PetscCall(KSPSolve(ctx->ops.ksp, cd->f, cd->corr));
  PetscCall(KSPGetConvergedReason(ctx->ops.ksp, &reason));
  PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "The contact correction solve at t = %g diverged: %s", (double)c->t, KSPConvergedReasons[reason]);
  PetscCall(VecWAXPY(xi, 1.0, cd->xf, cd->corr));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactCondensedDestroy(RollerContact c)
{
  RollerContactCondensed cd = c->condensed;

  PetscFunctionBeginUser;
  if (!cd) PetscFunctionReturn(0);
  PetscCall(PetscFree(cd->S));
  PetscCall(PetscFree5(cd->gf, cd->G, cd->Gff, cd->d, cd->lam));
  PetscCall(PetscFree5(cd->mu, cd->mu2, cd->w, cd->F, cd->act));
  PetscCall(VecDestroy(&cd->xf));
  PetscCall(VecDestroy(&cd->f));
  PetscCall(VecDestroy(&cd->corr));
  PetscCall(TaoWorkDestroy(cd));
  PetscCall(PetscFree(cd));
  c->condensed = NULL;
  PetscFunctionReturn(0);
}
