/* -contact_solver condensed, the default: the QP condensed onto the multipliers of the candidate nodes.

   With E the injection of the Gamma_C dofs and N = diag(n^k) at the candidates, the KKT conditions of the
   step QP (docs/model.md section 2) are  A xi = b + E N lambda,  lambda >= 0,  gap >= 0,  lambda . gap = 0, so
   xi = xi_f + A^{-1} E N lambda with the free solution xi_f = A^{-1} b, and gap(lambda) = d + G lambda with
   d = gap of xi_f and G = N^T S N, S = E^T A^{-1} E. Since A never changes, S (2 N_C x 2 N_C) is computed
   once with the step factorization (per step matrix of the scheme; the columns of a node when it can first be
   touched); each step is one solve for xi_f, a small dense LCP in lambda
   (contact_lcp.c), and, only if some lambda > 0, one more solve for the correction. A step in which nothing
   touches costs what a free step costs. */
#include "contact_impl.h"

typedef enum { CONTACT_QP_ACTIVESET, CONTACT_QP_TAO } CondensedQPType;
static const char *const CondensedQPTypes[] = {"activeset", "tao", "CondensedQPType", "CONTACT_QP_", NULL};

#define CONDENSED_MAX_OPERATORS 4 /* a scheme has one step matrix or a fixed few */

/* S = E^T A^{-1} E of one step matrix, 2 nc x 2 nc column-major, the same on every rank; the two columns of node j
   are computed when j first becomes a candidate (have[j]), and S is kept symmetric on the nodes computed so far. */
typedef struct {
  PetscReal *S;
  PetscBool *have;
  PetscInt   nhave;
  PetscReal *Yg; /* -axle: the Gamma_C rows of the operator's border Y (S_eff = S + Yg W Yg^T, contact_impl.h) */
} CondensedS;

typedef struct {
  CondensedQPType  qp;
  CondensedS       s[CONDENSED_MAX_OPERATORS]; /* by RollerStepOperator id */
  PetscReal       *gf;                         /* nc: gap of the free solution */
  PetscInt        *need;                       /* nc: scratch, the nodes whose columns a step needs */
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

static PetscErrorCode CondensedSetUp(RollerContactSolver s, Roller ctx, RollerContact c)
{
  Condensed *cd = (Condensed *)s->data;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(c->nodes.nc, &cd->gf, c->nodes.nc, &cd->need));
  PetscCall(RollerContactLCPCreate(c->nodes.nc, &cd->lcp));
  PetscCall(VecDuplicate(ctx->state.cur, &cd->xf));
  PetscCall(VecDuplicate(ctx->state.cur, &cd->f));
  PetscCall(VecDuplicate(ctx->state.cur, &cd->corr));
  PetscFunctionReturn(0);
}

/* With a factorization held whole on every rank (PCREDUNDANT, model/solver.c): the columns j = 0..2m of the nodes
   need[] split over the ranks (j mod size), each solved by the rank's own serial factor (KSPMatSolve on its copy,
   which has the global numbering), their Gamma_C rows summed onto every rank (the others' columns are zero). */
static PetscErrorCode CondensedColumnsSplit(Roller ctx, RollerContact c, PC pc, CondensedS *cs, const PetscInt need[], PetscInt m)
{
  const PetscInt n = 2 * c->nodes.nc, nb = 64;
  PetscMPIInt    rank, size;
  PetscInt       N, mine = 0;
  KSP            inner;
  Mat            B, X;
  PetscReal     *buf;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCall(PCRedundantGetKSP(pc, &inner));
  PetscCall(VecGetSize(ctx->state.cur, &N));
  for (PetscInt j = rank; j < 2 * m; j += size) ++mine;
  PetscCall(PetscCalloc1((size_t)n * 2 * m, &buf));
  for (PetscInt k0 = 0; k0 < mine; k0 += nb) { /* this rank's columns j = rank + size k, in blocks of nb */
    const PetscInt     mb = PetscMin(nb, mine - k0);
    const PetscScalar *x;
    PetscInt           lda;

    PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, N, mb, NULL, &B));
    PetscCall(MatZeroEntries(B));
    for (PetscInt kk = 0; kk < mb; ++kk) {
      const PetscInt j = rank + size * (k0 + kk);

      PetscCall(MatSetValue(B, c->nodes.gidx[need[j / 2]] + j % 2, kk, 1.0, INSERT_VALUES));
    }
    PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatDuplicate(B, MAT_DO_NOT_COPY_VALUES, &X));
    PetscCall(KSPMatSolve(inner, B, X));
    PetscCall(MatDenseGetLDA(X, &lda));
    PetscCall(MatDenseGetArrayRead(X, &x));
    for (PetscInt kk = 0; kk < mb; ++kk) {
      const PetscInt j = rank + size * (k0 + kk);

      for (PetscInt i = 0; i < n; ++i) buf[i + (size_t)j * n] = PetscRealPart(x[c->nodes.gidx[i / 2] + i % 2 + (size_t)kk * lda]);
    }
    PetscCall(MatDenseRestoreArrayRead(X, &x));
    PetscCall(MatDestroy(&B));
    PetscCall(MatDestroy(&X));
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, buf, (PetscMPIInt)(n * 2 * m), MPIU_REAL, MPIU_SUM, ctx->comm));
  for (PetscInt j = 0; j < 2 * m; ++j) PetscCall(PetscArraycpy(cs->S + (size_t)(2 * need[j / 2] + j % 2) * n, buf + (size_t)j * n, n));
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(0);
}

/* The columns of the nodes need[0..m) of S = E^T A^{-1} E: A^{-1} applied to the unit vectors of their Gamma_C
   dofs, in blocks of columns with KSPMatSolve on the operator's factorization, each column's Gamma_C entries
   gathered on every rank (or split over the ranks with a factorization held whole on each); then S symmetrized between the new columns and all computed ones (A is symmetric: the
   solver's round-off asymmetry is removed, so that G is symmetric to the last bit). */
static PetscErrorCode CondensedColumns(Roller ctx, RollerContact c, const RollerStepOperator *op, CondensedS *cs, const PetscInt need[], PetscInt m)
{
  const PetscInt n = 2 * c->nodes.nc, nb = 64;
  PetscInt       nlocal, rstart, rend;
  PetscLogDouble t0, t1;
  PC             pc;
  PetscBool      redundant;

  PetscFunctionBeginUser;
  if (m == 0) PetscFunctionReturn(0);
  PetscCall(PetscTime(&t0));
  PetscCall(VecGetLocalSize(ctx->state.cur, &nlocal));
  PetscCall(VecGetOwnershipRange(ctx->state.cur, &rstart, &rend));
  PetscCall(KSPGetPC(op->ksp, &pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCREDUNDANT, &redundant));
  if (redundant) { /* the columns split over the ranks only when each holds the whole factor (not groups of ranks) */
    KSP         inner;
    PetscMPIInt gsize;

    PetscCall(PCRedundantGetKSP(pc, &inner));
    PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)inner), &gsize));
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &gsize, 1, MPI_INT, MPI_MAX, ctx->comm)); /* the same path on every rank */
    redundant = (PetscBool)(gsize == 1);
  }
  if (c->nodes.phi) redundant = PETSC_FALSE; /* -rom: the reduced columns below */
  if (redundant) PetscCall(CondensedColumnsSplit(ctx, c, pc, cs, need, m));
  for (PetscInt j0 = 0; !redundant && j0 < 2 * m; j0 += nb) {
    const PetscInt mb = PetscMin(nb, 2 * m - j0);
    Mat            B, X;

    PetscCall(MatCreateDense(ctx->comm, nlocal, PETSC_DECIDE, PETSC_DETERMINE, mb, NULL, &B));
    PetscCall(MatZeroEntries(B));
    for (PetscInt jj = 0; jj < mb; ++jj) {
      const PetscInt j = j0 + jj, row = c->nodes.gidx[need[j / 2]] + j % 2;

      if (c->nodes.phi) { /* -rom: the column E e_j of the reduced model is Phi^T e_j, the row j of Phi */
        const PetscReal *p = c->nodes.phi + (size_t)(2 * need[j / 2] + j % 2) * c->nodes.nq;

        for (PetscInt i = rstart; i < PetscMin(rend, c->nodes.nq); ++i) PetscCall(MatSetValue(B, i, jj, p[i], INSERT_VALUES));
      } else if (row >= rstart && row < rend) PetscCall(MatSetValue(B, row, jj, 1.0, INSERT_VALUES));
    }
    PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatDuplicate(B, MAT_DO_NOT_COPY_VALUES, &X));
    PetscCall(KSPMatSolve(op->ksp, B, X));
    if (c->nodes.phi) { /* -rom: S's columns Phi X, every Gamma_C row (the window only bounds a step's gathers) */
      PetscReal *out;

      PetscCall(PetscMalloc1((size_t)n * mb, &out));
      PetscCall(RollerContactReducedColumns(c, X, mb, out));
      for (PetscInt jj = 0; jj < mb; ++jj) {
        const PetscInt col = 2 * need[(j0 + jj) / 2] + (j0 + jj) % 2;

        PetscCall(PetscArraycpy(cs->S + (size_t)col * n, out + (size_t)jj * n, n));
        RollerContactReducedAddFlexibility(c, col, cs->S + (size_t)col * n); /* -rom_residual: S + R */
      }
      PetscCall(PetscFree(out));
    }
    for (PetscInt jj = 0; !c->nodes.phi && jj < mb; ++jj) {
      const PetscInt     j = j0 + jj, col = 2 * need[j / 2] + j % 2;
      Vec                v;
      const PetscScalar *r;

      PetscCall(MatDenseGetColumnVecRead(X, jj, &v));
      PetscCall(RollerContactGather(c, v, c->nodes.red));
      PetscCall(MatDenseRestoreColumnVecRead(X, jj, &v));
      PetscCall(VecGetArrayRead(c->nodes.red, &r));
      for (PetscInt i = 0; i < n; ++i) cs->S[i + (size_t)col * n] = PetscRealPart(r[i]);
      PetscCall(VecRestoreArrayRead(c->nodes.red, &r));
    }
    PetscCall(MatDestroy(&B));
    PetscCall(MatDestroy(&X));
  }
  for (PetscInt a = 0; a < m; ++a) cs->have[need[a]] = PETSC_TRUE;
  cs->nhave += m;
  for (PetscInt a = 0; a < m; ++a)
    for (PetscInt jd = 0; jd < 2; ++jd) {
      const PetscInt j = 2 * need[a] + jd;

      for (PetscInt i = 0; i < n; ++i) {
        PetscReal sij;

        if (!cs->have[i / 2] || i == j) continue;
        sij                      = 0.5 * (cs->S[i + (size_t)j * n] + cs->S[j + (size_t)i * n]);
        cs->S[i + (size_t)j * n] = cs->S[j + (size_t)i * n] = sij;
      }
    }
  PetscCall(PetscTime(&t1));
  PetscCall(PetscInfo(NULL, "Contact condensed: %" PetscInt_FMT " columns of S = E^T A^-1 E (operator %" PetscInt_FMT ", %" PetscInt_FMT " of %" PetscInt_FMT " nodes now) in %g s\n", 2 * m, op->id, cs->nhave, c->nodes.nc, t1 - t0));
  PetscFunctionReturn(0);
}

/* The S of the operator, allocated at its first use. */
static PetscErrorCode CondensedGetS(RollerContact c, Condensed *cd, const RollerStepOperator *op, CondensedS **cs)
{
  const PetscInt n = 2 * c->nodes.nc;

  PetscFunctionBeginUser;
  PetscCheck(op->id >= 0 && op->id < CONDENSED_MAX_OPERATORS, c->comm, PETSC_ERR_SUP, "The condensed contact solver keeps at most %d step matrices (operator %" PetscInt_FMT ")", CONDENSED_MAX_OPERATORS, op->id);
  *cs = &cd->s[op->id];
  if (!(*cs)->S) PetscCall(PetscCalloc2((size_t)n * n, &(*cs)->S, c->nodes.nc, &(*cs)->have));
  PetscFunctionReturn(0);
}

/* For the operator of a scheme, in the set-up stage: the columns the run surely needs, those of the nodes within
   reach of the obstacle's final depth (all of Gamma_C when the roller turns: the patch travels around it); the
   others when they first become candidates. */
static PetscErrorCode CondensedPrepare(RollerContactSolver s, Roller ctx, RollerContact c, const RollerStepOperator *op)
{
  Condensed      *cd = (Condensed *)s->data;
  CondensedS     *cs;
  PetscInt        m     = 0;
  const PetscReal depth = ctx->obstacle.depth + c->opt.margin;

  PetscFunctionBeginUser;
  PetscCall(CondensedGetS(c, cd, op, &cs));
  if (op->border && !cs->Yg) { /* the hub's rows of S_eff (-axle) */
    const PetscInt     n = 2 * c->nodes.nc;
    const PetscScalar *y;

    PetscCall(PetscMalloc1(3 * n, &cs->Yg));
    for (PetscInt k = 0; k < 3; ++k) {
      PetscCall(RollerContactGather(c, op->border->Y[k], c->nodes.red));
      PetscCall(VecGetArrayRead(c->nodes.red, &y));
      for (PetscInt i = 0; i < n; ++i) cs->Yg[k * n + i] = PetscRealPart(y[i]);
      PetscCall(VecRestoreArrayRead(c->nodes.red, &y));
    }
  }
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscBool turns = (PetscBool)(ctx->rotation.omega != 0 || ctx->rotation.a != 0 || ctx->axle.on); /* -axle: the hub moves down by a depth not known before */

    /* at rest the obstacle's line stays at height g = depth - r_C along e2: the nodes with x_2 <= -r_C + depth */
    if (!cs->have[i] && (turns || c->nodes.xc[2 * i + 1] <= -ctx->mesh.r_outer + depth)) cd->need[m++] = i;
  }
  PetscCall(CondensedColumns(ctx, c, op, cs, cd->need, m));
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

  PetscFunctionBeginUser;
  PetscCall(RollerStepOperatorSolve(ctx, c->step.op, b, cd->xf, c->step.t));
  PetscCall(RollerContactGather(c, cd->xf, c->nodes.red));
  PetscCall(RollerContactResidualAddHistory(c, c->nodes.red)); /* -rom_residual with the branches: R h/C */
  PetscCall(VecGetArrayRead(c->nodes.red, &u));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) cd->gf[i] = PetscRealPart(u[2 * i]) * c->step.normal[0] + PetscRealPart(u[2 * i + 1]) * c->step.normal[1] - c->step.lower[i];
  PetscCall(VecRestoreArrayRead(c->nodes.red, &u));
  PetscFunctionReturn(0);
}

/* The LCP on the candidate set, warm-started (active set) from the nodes on the obstacle at the previous
   level; then xi = xi_f + A^{-1} E N lambda. */
static PetscErrorCode CondensedSolve(RollerContactSolver s, Roller ctx, RollerContact c, Vec b, Vec xi, RollerContactResult *res)
{
  Condensed        *cd  = (Condensed *)s->data;
  RollerContactLCP *lcp = &cd->lcp;
  const PetscInt    n = 2 * c->nodes.nc, m = c->step.ncand, *cand = c->step.cand;
  PetscReal         dmax = 0.0;
  PetscBool         any  = PETSC_FALSE;
  CondensedS       *cs;
  PetscInt          nneed = 0;
  PetscReal        *yn;

  PetscFunctionBeginUser;
  PetscCall(CondensedGetS(c, cd, c->step.op, &cs));
  c->step.Yg = cs->Yg;
  for (PetscInt a = 0; a < m; ++a)
    if (!cs->have[cand[a]]) cd->need[nneed++] = cand[a];
  PetscCall(CondensedColumns(ctx, c, c->step.op, cs, cd->need, nneed));
  PetscCall(FreeSolution(ctx, c, cd, b));
  PetscCall(PetscMalloc1(3 * m, &yn)); /* the hub's rows of the candidates along the normal (-axle) */
  for (PetscInt a = 0; a < m; ++a) RollerContactBorderRow(&c->step, c->step.normal, cand[a], n, yn + 3 * a);
  for (PetscInt a = 0; a < m; ++a) {
    lcp->d[a]   = cd->gf[cand[a]];
    lcp->act[a] = c->step.on_obstacle[cand[a]];
    dmax        = PetscMax(dmax, PetscAbsReal(lcp->d[a]));
    for (PetscInt b2 = 0; b2 <= a; ++b2) lcp->G[a + (size_t)b2 * m] = lcp->G[b2 + (size_t)a * m] = NormalEntry(cs->S, n, c->step.normal, cand[a], cand[b2]) + RollerContactBorderPair(&c->step, yn + 3 * a, yn + 3 * b2);
  }
  PetscCall(PetscFree(yn));
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
  if (c->friction) PetscCall(RollerContactFrictionSolve(ctx, c, cs->S, lcp, res));
  if (!any) {
    PetscCall(VecCopy(cd->xf, xi));
    PetscFunctionReturn(0);
  }
  PetscCall(RollerContactForce(c, res->lambda, c->friction ? res->lambda_t : NULL, cd->f));
  PetscCall(RollerStepOperatorSolve(ctx, c->step.op, cd->f, cd->corr, c->step.t));
  PetscCall(VecWAXPY(xi, 1.0, cd->xf, cd->corr));
  PetscFunctionReturn(0);
}

static PetscErrorCode CondensedDestroy(RollerContactSolver s)
{
  Condensed *cd = (Condensed *)s->data;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < CONDENSED_MAX_OPERATORS; ++k) {
    PetscCall(PetscFree2(cd->s[k].S, cd->s[k].have));
    PetscCall(PetscFree(cd->s[k].Yg));
  }
  if (s->setupcalled) {
    PetscCall(PetscFree2(cd->gf, cd->need));
    PetscCall(RollerContactLCPDestroy(&cd->lcp));
    PetscCall(VecDestroy(&cd->xf));
    PetscCall(VecDestroy(&cd->f));
    PetscCall(VecDestroy(&cd->corr));
  }
  PetscFunctionReturn(0);
}

static const RollerContactSolverOps ops = {.setfromoptions = CondensedSetFromOptions, .setup = CondensedSetUp, .prepare = CondensedPrepare, .solve = CondensedSolve, .destroy = CondensedDestroy};

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
