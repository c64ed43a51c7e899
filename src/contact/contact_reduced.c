/* Contact on the reduced model (-rom, docs/model.md "The reduced model", docs/performance.md "Reduced-order
   transient"): the displacement is xi = V q, so the Gamma_C dofs are u_C = Phi q with Phi = E^T V the Gamma_C rows
   of the basis, and the contact force E N lambda (+ the friction's) enters the reduced equations as Phi^T of it. The
   step QP is the full model's with E replaced by Phi (a Galerkin projection): the condensed S = Phi A_r^{-1} Phi^T,
   the same LCP and Coulomb solves on the same nodes, and the scheme's energy identity holds for the reduced model.
   Within a step only the window's nodes are gathered (the obstacle can reach no other): 2 nwin nq products, not
   2 nc nq. */
#include "contact_impl.h"

/* PETSc 3.18 exports PetscObjectStateGet (documented with PetscObjectState in petscsystypes.h; a Vec's state grows
   with every write) but its installed headers do not declare it. */
PETSC_EXTERN PetscErrorCode PetscObjectStateGet(PetscObject, PetscObjectState *);

/* -rom's contact is the condensed solver's (before the basis is made: a refusal costs no eigensolve). */
PetscErrorCode RollerContactCheckReduced(Roller ctx, RollerContact c)
{
  PetscBool condensed;

  PetscFunctionBeginUser;
  PetscCall(PetscStrcmp(c->opt.solver, "condensed", &condensed));
  PetscCheck(condensed && !c->opt.check, ctx->comm, PETSC_ERR_ARG_INCOMP, "-rom takes -contact_solver condensed (the reduced model's S = Phi A_r^-1 Phi^T), not %s%s", c->opt.solver, c->opt.check ? " or -contact_check" : "");
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactSetBasis(Roller ctx, RollerContact c, Mat V, Vec q)
{
  const PetscInt n = 2 * c->nodes.nc;
  PetscInt       nq;
  PetscReal     *phi;

  PetscFunctionBeginUser;
  PetscCall(RollerContactCheckReduced(ctx, c));
  PetscCall(MatGetSize(V, NULL, &nq));
  PetscCall(PetscMalloc2((size_t)n * nq, &phi, c->nodes.nc, &c->nodes.win));
  for (PetscInt j = 0; j < nq; ++j) { /* column j of V gathered at Gamma_C: column j of Phi */
    Vec                v;
    const PetscScalar *r;

    PetscCall(MatDenseGetColumnVecRead(V, j, &v));
    PetscCall(VecScatterBegin(c->nodes.scatter, v, c->nodes.red, INSERT_VALUES, SCATTER_FORWARD)); /* the nodal gather */
    PetscCall(VecScatterEnd(c->nodes.scatter, v, c->nodes.red, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(MatDenseRestoreColumnVecRead(V, j, &v));
    PetscCall(VecGetArrayRead(c->nodes.red, &r));
    for (PetscInt i = 0; i < n; ++i) phi[(size_t)i * nq + j] = PetscRealPart(r[i]);
    PetscCall(VecRestoreArrayRead(c->nodes.red, &r));
  }
  PetscCall(VecScatterCreateToAll(q, &c->nodes.gather.qscatter, &c->nodes.gather.qall));
  for (Vec *v = &c->acc.b; v; v = v == &c->acc.b ? &c->acc.force : v == &c->acc.force ? &c->acc.work : NULL) { /* the step's vectors in the reduced layout */
    PetscCall(VecDestroy(v));
    PetscCall(VecDuplicate(q, v));
  }
  c->nodes.nq       = nq;
  c->nodes.phi      = phi; /* from here the gathers and forces are the reduced model's */
  c->nodes.nwin     = c->nodes.nc;
  c->nodes.windowed = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactReducedDestroy(RollerContact c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(c->nodes.phi, c->nodes.win));
  PetscCall(RollerContactResidualDestroy(c));
  for (PetscInt k = 0; k < ROLLER_GATHER_CACHE; ++k) PetscCall(PetscFree(c->nodes.gather.val[k]));
  PetscCall(VecScatterDestroy(&c->nodes.gather.qscatter));
  PetscCall(VecDestroy(&c->nodes.gather.qall));
  PetscFunctionReturn(0);
}

/* The step's window (after RollerContactSetTime): the nodes whose undeformed gap x_n . n^k - g^k is at most 4 times
   the obstacle's depth plus -contact_margin. Outside it a node would need a displacement toward the obstacle of 3
   depths to touch; the nodes in contact move by about one. */
void RollerContactReducedWindow(Roller ctx, RollerContact c)
{
  const PetscReal reach = 4.0 * (ctx->obstacle.depth + PetscMax(c->opt.margin, 0.0));

  c->nodes.nwin = 0;
  for (PetscInt i = 0; i < c->nodes.nc; ++i)
    if (-c->step.lower[i] <= reach) c->nodes.win[c->nodes.nwin++] = i;
  c->nodes.windowed = PETSC_TRUE;
  c->nodes.gather.wstamp++; /* the cached gathers were of another window */
}

/* u = Phi q at the window's nodes (all nodes outside a step): four nodes' eight rows a pass over q, each row's sum in
   the order of q's entries (the same sums as one row at a time, with eight independent chains instead of two). */
static void GatherRows(RollerContact c, const PetscScalar qa[], PetscScalar u[])
{
  const PetscInt nq = c->nodes.nq, nw = c->nodes.nwin, blk = 4;

  for (PetscInt k0 = 0; k0 < nw; k0 += blk) {
    const PetscInt   nb = PetscMin(blk, nw - k0);
    const PetscReal *p[2 * 4];
    PetscReal        s[2 * 4] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};

    for (PetscInt b = 0; b < blk; ++b) { /* a short block repeats its last node (computed, not stored) */
      const PetscInt k = k0 + PetscMin(b, nb - 1), i = c->nodes.windowed ? c->nodes.win[k] : k;

      p[2 * b]     = c->nodes.phi + (size_t)(2 * i) * nq;
      p[2 * b + 1] = p[2 * b] + nq;
    }
    for (PetscInt j = 0; j < nq; ++j) {
      const PetscReal qj = PetscRealPart(qa[j]);

      s[0] += p[0][j] * qj;
      s[1] += p[1][j] * qj;
      s[2] += p[2][j] * qj;
      s[3] += p[3][j] * qj;
      s[4] += p[4][j] * qj;
      s[5] += p[5][j] * qj;
      s[6] += p[6][j] * qj;
      s[7] += p[7][j] * qj;
    }
    for (PetscInt b = 0; b < nb; ++b) {
      const PetscInt k = k0 + b, i = c->nodes.windowed ? c->nodes.win[k] : k;

      u[2 * i]     = s[2 * b];
      u[2 * i + 1] = s[2 * b + 1];
    }
  }
}

/* red = Phi q at the window's nodes (all nodes outside a step), 0 at the others; a gather of the same Vec, unchanged,
   within the same window is the cached one's copy. */
PetscErrorCode RollerContactReducedGather(RollerContact c, Vec q, Vec red)
{
  RollerContactGatherCache *gc = &c->nodes.gather;
  const PetscScalar        *qa;
  PetscScalar              *u;
  PetscObjectId             id;
  PetscObjectState          state;
  PetscInt                  slot;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetId((PetscObject)q, &id));
  PetscCall(PetscObjectStateGet((PetscObject)q, &state));
  for (slot = 0; slot < ROLLER_GATHER_CACHE; ++slot)
    if (gc->id[slot] == id && gc->state[slot] == state && gc->stamp[slot] == gc->wstamp && gc->val[slot]) break;
  if (slot < ROLLER_GATHER_CACHE) { /* a hit */
    const PetscReal *g = gc->val[slot];

    PetscCall(VecGetArray(red, &u));
    if (c->nodes.windowed) PetscCall(PetscArrayzero(u, 2 * c->nodes.nc));
    for (PetscInt k = 0; k < c->nodes.nwin; ++k) {
      const PetscInt i = c->nodes.windowed ? c->nodes.win[k] : k;

      u[2 * i]     = g[2 * i];
      u[2 * i + 1] = g[2 * i + 1];
    }
    PetscCall(VecRestoreArray(red, &u));
    PetscCall(RollerContactReducedAddResidual(c, q, red));
    PetscFunctionReturn(0);
  }
  PetscCall(VecScatterBegin(c->nodes.gather.qscatter, q, c->nodes.gather.qall, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(c->nodes.gather.qscatter, q, c->nodes.gather.qall, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(c->nodes.gather.qall, &qa));
  PetscCall(VecGetArray(red, &u));
  if (c->nodes.windowed) PetscCall(PetscArrayzero(u, 2 * c->nodes.nc));
  GatherRows(c, qa, u);
  slot     = gc->next; /* kept for the next reads of this level in this window (round robin) */
  gc->next = (gc->next + 1) % ROLLER_GATHER_CACHE;
  if (!gc->val[slot]) PetscCall(PetscMalloc1(2 * c->nodes.nc, &gc->val[slot]));
  for (PetscInt k = 0; k < c->nodes.nwin; ++k) {
    const PetscInt i = c->nodes.windowed ? c->nodes.win[k] : k;

    gc->val[slot][2 * i]     = PetscRealPart(u[2 * i]);
    gc->val[slot][2 * i + 1] = PetscRealPart(u[2 * i + 1]);
  }
  gc->id[slot]    = id;
  gc->state[slot] = state;
  gc->stamp[slot] = gc->wstamp;
  PetscCall(VecRestoreArray(red, &u));
  PetscCall(VecRestoreArrayRead(c->nodes.gather.qall, &qa));
  PetscCall(RollerContactReducedAddResidual(c, q, red)); /* -rom_residual: + R f_C of the level */
  PetscFunctionReturn(0);
}

/* f = Phi^T (N lambda + T lambda_t): the reduced force of the nodal multipliers, each rank its own entries. */
PetscErrorCode RollerContactReducedForce(RollerContact c, const PetscReal lambda[], const PetscReal lambda_t[], Vec f)
{
  const PetscInt nq = c->nodes.nq;
  PetscScalar   *fa;
  PetscInt       rstart, rend;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(f));
  PetscCall(VecGetOwnershipRange(f, &rstart, &rend));
  PetscCall(VecGetArray(f, &fa));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscReal  lt = lambda_t ? lambda_t[i] : 0.0;
    const PetscReal  fx = lambda[i] * c->step.normal[0] + lt * c->step.tangent[0], fy = lambda[i] * c->step.normal[1] + lt * c->step.tangent[1];
    const PetscReal *p0 = c->nodes.phi + (size_t)(2 * i) * nq, *p1 = p0 + nq;

    if (fx == 0.0 && fy == 0.0) continue;
    for (PetscInt j = rstart; j < PetscMin(rend, nq); ++j) fa[j - rstart] += p0[j] * fx + p1[j] * fy;
  }
  PetscCall(VecRestoreArray(f, &fa));
  PetscFunctionReturn(0);
}

/* out (2 nc x mb, column-major) = Phi X for the mb solved columns of X (reduced layout): every Gamma_C row, one
   BLAS product. */
PetscErrorCode RollerContactReducedColumns(RollerContact c, Mat X, PetscInt mb, PetscReal out[])
{
  const PetscInt nq = c->nodes.nq, n = 2 * c->nodes.nc;
  PetscReal     *x;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1((size_t)nq * mb, &x));
  for (PetscInt jj = 0; jj < mb; ++jj) {
    Vec                v;
    const PetscScalar *a;

    PetscCall(MatDenseGetColumnVecRead(X, jj, &v));
    PetscCall(VecScatterBegin(c->nodes.gather.qscatter, v, c->nodes.gather.qall, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(c->nodes.gather.qscatter, v, c->nodes.gather.qall, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(MatDenseRestoreColumnVecRead(X, jj, &v));
    PetscCall(VecGetArrayRead(c->nodes.gather.qall, &a));
    for (PetscInt j = 0; j < nq; ++j) x[j + (size_t)jj * nq] = PetscRealPart(a[j]);
    PetscCall(VecRestoreArrayRead(c->nodes.gather.qall, &a));
  }
  { /* phi row-major (n x nq) is column-major nq x n: out = P^T x, P that matrix (PETSc's dense product, BLAS gemm) */
    Mat                P, Xs, O;
    const PetscScalar *o;

    PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, nq, n, c->nodes.phi, &P));
    PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, nq, mb, x, &Xs));
    PetscCall(MatTransposeMatMult(P, Xs, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &O));
    PetscCall(MatDenseGetArrayRead(O, &o));
    for (size_t k = 0; k < (size_t)n * mb; ++k) out[k] = PetscRealPart(o[k]);
    PetscCall(MatDenseRestoreArrayRead(O, &o));
    PetscCall(MatDestroy(&O));
    PetscCall(MatDestroy(&Xs));
    PetscCall(MatDestroy(&P));
  }
  PetscCall(PetscFree(x));
  PetscFunctionReturn(0);
}
