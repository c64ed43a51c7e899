/* -contact_solver condensed, the default: the QP condensed onto the multipliers of the candidate nodes.

   With E the injection of the Gamma_C dofs and N = diag(n^k) at the candidates, the KKT conditions of the
   step QP (docs/model.md section 2) are  A xi = b + E N lambda,  lambda >= 0,  gap >= 0,  lambda . gap = 0, so
   xi = xi_f + A^{-1} E N lambda with the free solution xi_f = A^{-1} b, and gap(lambda) = d + G lambda with
   d = gap of xi_f and G = N^T S N, S = E^T A^{-1} E. Since A never changes, S (2 N_C x 2 N_C) is computed
   once with the step factorization; each step is one solve for xi_f, a small dense LCP in lambda
   (contact_lcp.c), and, only if some lambda > 0, one more solve for the correction. A step in which nothing
   touches costs what a free step costs. */
#include "contact_impl.h"

typedef enum { CONTACT_QP_ACTIVESET, CONTACT_QP_TAO } CondensedQPType;
static const char *const CondensedQPTypes[] = {"activeset", "tao", "CondensedQPType", "CONTACT_QP_", NULL};

typedef struct {
  CondensedQPType  qp;
  PetscReal       *S;  /* 2 nc x 2 nc, column-major, the same on every rank */
  PetscReal       *gf; /* nc: gap of the free solution */
  RollerContactLCP lcp;
  Vec              xf, f, corr;
} Condensed;

static PetscErrorCode CondensedSetFromOptions(RollerContactSolver s, PetscOptionItems *PetscOptionsObject)
{
  Condensed *cd = (Condensed *)s->data;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsEnum("-contact_condensed_qp", "Solver of the condensed multiplier QP: activeset (exact) or tao (type -contact_condensed_tao_type)", NULL, CondensedQPTypes, (PetscEnum)cd->qp, (PetscEnum *)&cd->qp, NULL));
  PetscFunctionReturn(0);
}

/* S = E^T A^{-1} E: A^{-1} applied to the unit vectors of the Gamma_C dofs, in blocks of columns with
   KSPMatSolve on the one factorization; each column's Gamma_C entries are gathered on every rank. */
static PetscErrorCode CondensedSetUp(RollerContactSolver s, Roller ctx, RollerContact c)
{
  Condensed     *cd = (Condensed *)s->data;
  const PetscInt n = 2 * c->nodes.nc, nb = 64;
  PetscInt       nlocal, rstart, rend;
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t0));
  PetscCall(PetscMalloc2((size_t)n * n, &cd->S, c->nodes.nc, &cd->gf));
  PetscCall(RollerContactLCPCreate(c->nodes.nc, &cd->lcp));
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
      const PetscInt j = j0 + jj, row = c->nodes.gidx[j / 2] + j % 2;

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
      PetscCall(RollerContactGather(c, col, c->nodes.red));
      PetscCall(MatDenseRestoreColumnVecRead(X, jj, &col));
      PetscCall(VecGetArrayRead(c->nodes.red, &r));
      for (PetscInt i = 0; i < n; ++i) cd->S[i + (size_t)(j0 + jj) * n] = PetscRealPart(r[i]);
      PetscCall(VecRestoreArrayRead(c->nodes.red, &r));
    }
    PetscCall(MatDestroy(&B));
    PetscCall(MatDestroy(&X));
  }
  /* A is symmetric; remove the solver's round-off asymmetry so G is symmetric to the last bit */
  for (PetscInt j = 0; j < n; ++j)
    for (PetscInt i = 0; i < j; ++i) {
      const PetscReal sij = 0.5 * (cd->S[i + (size_t)j * n] + cd->S[j + (size_t)i * n]);

      cd->S[i + (size_t)j * n] = cd->S[j + (size_t)i * n] = sij;
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

/* xi_f = A^{-1} b and its gaps at the step's bounds. */
static PetscErrorCode FreeSolution(Roller ctx, RollerContact c, Condensed *cd, Vec b)
{
  const PetscScalar *u;
  KSPConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(KSPSolve(ctx->ops.ksp, b, cd->xf));
  PetscCall(KSPGetConvergedReason(ctx->ops.ksp, &reason));
  PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "The free solve of the contact step at t = %g diverged: %s", (double)c->step.t, KSPConvergedReasons[reason]);
  PetscCall(RollerContactGather(c, cd->xf, c->nodes.red));
  PetscCall(VecGetArrayRead(c->nodes.red, &u));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) cd->gf[i] = PetscRealPart(u[2 * i]) * c->step.normal[0] + PetscRealPart(u[2 * i + 1]) * c->step.normal[1] - c->step.lower[i];
  PetscCall(VecRestoreArrayRead(c->nodes.red, &u));
  PetscFunctionReturn(0);
}

/* The LCP on the candidate set, warm-started (active set) from the nodes on the obstacle at the previous
   level; then xi = xi_f + A^{-1} E N lambda. */
static PetscErrorCode CondensedSolve(RollerContactSolver s, Roller ctx, RollerContact c, Vec b, Vec xi, RollerContactResult *res)
{
  Condensed         *cd  = (Condensed *)s->data;
  RollerContactLCP  *lcp = &cd->lcp;
  const PetscInt     n = 2 * c->nodes.nc, m = c->step.ncand, *cand = c->step.cand;
  PetscReal          dmax = 0.0;
  PetscBool          any  = PETSC_FALSE;
  KSPConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(FreeSolution(ctx, c, cd, b));
  for (PetscInt a = 0; a < m; ++a) {
    lcp->d[a]   = cd->gf[cand[a]];
    lcp->act[a] = c->step.on_obstacle[cand[a]];
    dmax        = PetscMax(dmax, PetscAbsReal(lcp->d[a]));
    for (PetscInt b2 = 0; b2 <= a; ++b2) lcp->G[a + (size_t)b2 * m] = lcp->G[b2 + (size_t)a * m] = NormalEntry(cd->S, n, c->step.normal, cand[a], cand[b2]);
  }
  res->its = 0;
  /* TAO: the gradient G lam + d is a gap (a length): converge it far below the gaps of the free solution */
  if (cd->qp == CONTACT_QP_TAO && m > 0) PetscCall(RollerContactLCPTao(lcp, m, c->opt.rtol * dmax, c->step.t, lcp->lam, &res->its));
  else if (m > 0) PetscCall(RollerContactLCPActiveSet(lcp, m, 1e-13 * dmax, lcp->act, lcp->lam, &res->its));
  PetscCall(PetscArrayzero(res->lambda, c->nodes.nc));
  for (PetscInt a = 0; a < m; ++a)
    if (lcp->lam[a] > 0.0) {
      res->lambda[cand[a]] = lcp->lam[a];
      any                  = PETSC_TRUE;
    }
  /* with friction: the Coulomb multipliers from these (contact_friction.c; c->nodes.red still holds xi_f) */
  if (c->friction) PetscCall(RollerContactFrictionSolve(ctx, c, cd->S, lcp, res));
  if (!any) {
    PetscCall(VecCopy(cd->xf, xi));
    PetscFunctionReturn(0);
  }
  PetscCall(RollerContactForce(c, res->lambda, c->friction ? res->lambda_t : NULL, cd->f));
  PetscCall(KSPSolve(ctx->ops.ksp, cd->f, cd->corr));
  PetscCall(KSPGetConvergedReason(ctx->ops.ksp, &reason));
  PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "The contact correction solve at t = %g diverged: %s", (double)c->step.t, KSPConvergedReasons[reason]);
  PetscCall(VecWAXPY(xi, 1.0, cd->xf, cd->corr));
  PetscFunctionReturn(0);
}

static PetscErrorCode CondensedDestroy(RollerContactSolver s)
{
  Condensed *cd = (Condensed *)s->data;

  PetscFunctionBeginUser;
  if (s->setupcalled) {
    PetscCall(PetscFree2(cd->S, cd->gf));
    PetscCall(RollerContactLCPDestroy(&cd->lcp));
    PetscCall(VecDestroy(&cd->xf));
    PetscCall(VecDestroy(&cd->f));
    PetscCall(VecDestroy(&cd->corr));
  }
  PetscFunctionReturn(0);
}

static const RollerContactSolverOps ops = {.setfromoptions = CondensedSetFromOptions, .setup = CondensedSetUp, .solve = CondensedSolve, .destroy = CondensedDestroy};

PetscErrorCode RollerContactSolverCreate_Condensed(RollerContactSolver s)
{
  Condensed *cd;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&cd));
  cd->qp  = CONTACT_QP_ACTIVESET;
  s->data = cd;
  *s->ops = ops;
  PetscFunctionReturn(0);
}
