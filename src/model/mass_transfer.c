/* The transfer T of the massless contact nodes (docs/contact.md "Massless contact nodes", docs/model.md section
   2): identity on every free node off Gamma_C; at a Gamma_C node b (label "outer": vertices, and P2 edge
   midpoints) (T u)_b = sum_i w_bi u_i, the same weights for both components, over the m nearest (m = 6 P1,
   12 P2) free nodes off Gamma_C among the nodes of the cells of b's 2-ring (its 3-ring, 4-ring if there are
   fewer), the weights reproducing the polynomials of the FE degree in the minimum-norm sense,
   w = P (P^T P)^{-1} e_1 in coordinates centred on b and scaled; if max |w| >= 5 the affine fit instead.
   The cells around Gamma_C are gathered on every rank first, so T does not depend on the partition. */
#include "model/mass_impl.h"

#define W_MAX 5.0 /* larger quadratic weights fall back to the affine fit */

/* Solve the n x n system G z = r (n <= 6) by elimination with partial pivoting; *ok false if G is singular */
static void SolveSmall(PetscInt n, const PetscReal G[], const PetscReal r[], PetscReal z[], PetscBool *ok)
{
  PetscReal a[36], b[6], gmax = 0;

  for (PetscInt i = 0; i < n * n; ++i) gmax = PetscMax(gmax, PetscAbsReal(G[i]));
  for (PetscInt i = 0; i < n * n; ++i) a[i] = G[i];
  for (PetscInt i = 0; i < n; ++i) b[i] = r[i];
  *ok = PETSC_TRUE;
  for (PetscInt k = 0; k < n; ++k) {
    PetscInt p = k;

    for (PetscInt i = k + 1; i < n; ++i)
      if (PetscAbsReal(a[i * n + k]) > PetscAbsReal(a[p * n + k])) p = i;
    if (PetscAbsReal(a[p * n + k]) < 1e-13 * gmax) {
      *ok = PETSC_FALSE;
      return;
    }
    for (PetscInt j = 0; j < n; ++j) {
      const PetscReal t = a[k * n + j];

      a[k * n + j] = a[p * n + j];
      a[p * n + j] = t;
    }
    {
      const PetscReal t = b[k];

      b[k] = b[p];
      b[p] = t;
    }
    for (PetscInt i = k + 1; i < n; ++i) {
      const PetscReal f = a[i * n + k] / a[k * n + k];

      for (PetscInt j = k; j < n; ++j) a[i * n + j] -= f * a[k * n + j];
      b[i] -= f * b[k];
    }
  }
  for (PetscInt k = n - 1; k >= 0; --k) {
    PetscReal s = b[k];

    for (PetscInt j = k + 1; j < n; ++j) s -= a[k * n + j] * z[j];
    z[k] = s / a[k * n + k];
  }
}

/* w = P (P^T P)^{-1} e_1 over the m nodes xi of the polynomials of degree 1 (1, x, y) or 2 (and x^2, xy, y^2) in
   coordinates centred on xb and scaled by the farthest node, with one refinement of P^T w = e_1 */
static void Weights(PetscInt m, const PetscReal xi[], const PetscReal xb[2], PetscInt degree, PetscReal w[], PetscBool *ok)
{
  const PetscInt np = degree == 1 ? 3 : 6;
  PetscReal      P[12 * 6], G[36], r[6], z[6], s = 0;

  for (PetscInt i = 0; i < m; ++i) s = PetscMax(s, PetscSqrtReal(PetscSqr(xi[2 * i] - xb[0]) + PetscSqr(xi[2 * i + 1] - xb[1])));
  for (PetscInt i = 0; i < m; ++i) {
    const PetscReal u = (xi[2 * i] - xb[0]) / s, v = (xi[2 * i + 1] - xb[1]) / s, p[6] = {1, u, v, u * u, u * v, v * v};

    for (PetscInt a = 0; a < np; ++a) P[i * np + a] = p[a];
  }
  for (PetscInt a = 0; a < np; ++a)
    for (PetscInt b = 0; b < np; ++b) {
      G[a * np + b] = 0;
      for (PetscInt i = 0; i < m; ++i) G[a * np + b] += P[i * np + a] * P[i * np + b];
    }
  for (PetscInt i = 0; i < m; ++i) w[i] = 0;
  for (PetscInt it = 0; it < 2; ++it) { /* solve, then refine on the residual of P^T w = e_1 */
    for (PetscInt a = 0; a < np; ++a) {
      r[a] = a == 0 ? 1.0 : 0.0;
      for (PetscInt i = 0; i < m; ++i) r[a] -= P[i * np + a] * w[i];
    }
    SolveSmall(np, G, r, z, ok);
    if (!*ok) return;
    for (PetscInt i = 0; i < m; ++i)
      for (PetscInt a = 0; a < np; ++a) w[i] += P[i * np + a] * z[a];
  }
}

typedef struct {
  PetscInt  gid;
  PetscReal x[2], d;
} Candidate;

static int CompareGid(const void *a, const void *b)
{
  const Candidate *p = (const Candidate *)a, *q = (const Candidate *)b;

  return (p->gid > q->gid) - (p->gid < q->gid);
}

/* nearest first; ties by position, so the choice does not depend on the order the ranks gathered the cells in */
static int CompareDistance(const void *a, const void *b)
{
  const Candidate *p = (const Candidate *)a, *q = (const Candidate *)b;

  if (p->d != q->d) return p->d < q->d ? -1 : 1;
  if (p->x[0] != q->x[0]) return p->x[0] < q->x[0] ? -1 : 1;
  return (p->x[1] > q->x[1]) - (p->x[1] < q->x[1]);
}

/* The layer's cells around each vertex (CSR over the sorted unique vertex numbers U) and around each node
   (the sorted pairs node, cell) */
typedef struct {
  PetscInt   nU, *U, *vstart, *vcells, npair, *pnode, *pcell, *mark, *cur;
  Candidate *cand;
} Adjacency;

static PetscErrorCode AdjacencyCreate(const RollerMassLayer *L, Adjacency *A)
{
  PetscInt *fill;

  PetscFunctionBeginUser;
  A->nU = 3 * L->ncell;
  PetscCall(PetscMalloc1(A->nU + 1, &A->U));
  PetscCall(PetscArraycpy(A->U, L->vert, A->nU));
  PetscCall(PetscSortRemoveDupsInt(&A->nU, A->U));
  PetscCall(PetscCalloc2(A->nU + 1, &A->vstart, 3 * L->ncell + 1, &A->vcells));
  PetscCall(PetscCalloc1(A->nU + 1, &fill));
  for (PetscInt c = 0; c < L->ncell; ++c)
    for (PetscInt k = 0; k < 3; ++k) {
      PetscInt loc;

      PetscCall(PetscFindInt(L->vert[3 * c + k], A->nU, A->U, &loc));
      A->vstart[loc + 1]++;
    }
  for (PetscInt v = 0; v < A->nU; ++v) A->vstart[v + 1] += A->vstart[v];
  for (PetscInt c = 0; c < L->ncell; ++c)
    for (PetscInt k = 0; k < 3; ++k) {
      PetscInt loc;

      PetscCall(PetscFindInt(L->vert[3 * c + k], A->nU, A->U, &loc));
      A->vcells[A->vstart[loc] + fill[loc]++] = c;
    }
  PetscCall(PetscMalloc4(L->nn * L->ncell + 1, &A->pnode, L->nn * L->ncell + 1, &A->pcell, L->ncell + 1, &A->mark, L->ncell + 1, &A->cur));
  PetscCall(PetscMalloc1(L->nn * L->ncell + 1, &A->cand));
  A->npair = 0;
  for (PetscInt c = 0; c < L->ncell; ++c) {
    A->mark[c] = -1;
    for (PetscInt k = 0; k < L->nn; ++k)
      if (L->node[L->nn * c + k] >= 0 && L->outer[L->nn * c + k]) {
        A->pnode[A->npair]   = L->node[L->nn * c + k];
        A->pcell[A->npair++] = c;
      }
  }
  PetscCall(PetscSortIntWithArray(A->npair, A->pnode, A->pcell));
  PetscCall(PetscFree(fill));
  PetscFunctionReturn(0);
}

static PetscErrorCode AdjacencyDestroy(Adjacency *A)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(A->U));
  PetscCall(PetscFree2(A->vstart, A->vcells));
  PetscCall(PetscFree4(A->pnode, A->pcell, A->mark, A->cur));
  PetscCall(PetscFree(A->cand));
  PetscFunctionReturn(0);
}

/* The m nearest free nodes off Gamma_C among the nodes of the cells of node b's 2-ring (or wider, up to ROLLER_MASS_RINGS)
   and their weights; ring: the ring used, fallback: the affine fit was used */
static PetscErrorCode NodeStencil(const RollerMassLayer *L, Adjacency *A, PetscInt b, PetscInt gb, const PetscReal xb[2], PetscInt degree, PetscInt m, PetscInt nb[], PetscReal w[], PetscInt *ring, PetscBool *fallback)
{
  PetscInt  ncur = 0, ncand = 0, first;
  PetscReal xi[24];
  PetscBool ok;

  PetscFunctionBeginUser;
  PetscCall(PetscFindInt(gb, A->npair, A->pnode, &first));
  PetscCheck(first >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Gamma_C node (dof %" PetscInt_FMT ") is in no cell of the layer", gb);
  while (first > 0 && A->pnode[first - 1] == gb) first--;
  for (PetscInt k = first; k < A->npair && A->pnode[k] == gb; ++k) {
    A->mark[A->pcell[k]] = b;
    A->cur[ncur++]       = A->pcell[k];
  }
  for (*ring = 1;; ++*ring) {
    if (*ring >= 2) {
      ncand = 0;
      for (PetscInt j = 0; j < ncur; ++j)
        for (PetscInt k = 0; k < L->nn; ++k) {
          const PetscInt e = L->nn * A->cur[j] + k;

          if (L->node[e] < 0 || L->outer[e]) continue;
          A->cand[ncand].gid  = L->node[e];
          A->cand[ncand].x[0] = L->x[2 * e];
          A->cand[ncand].x[1] = L->x[2 * e + 1];
          A->cand[ncand].d    = PetscSqrtReal(PetscSqr(L->x[2 * e] - xb[0]) + PetscSqr(L->x[2 * e + 1] - xb[1]));
          ncand++;
        }
      qsort(A->cand, (size_t)ncand, sizeof(Candidate), CompareGid);
      {
        PetscInt n = 0;

        for (PetscInt j = 0; j < ncand; ++j)
          if (!n || A->cand[j].gid != A->cand[n - 1].gid) A->cand[n++] = A->cand[j];
        ncand = n;
      }
      if (ncand >= m) break;
    }
    PetscCheck(*ring < ROLLER_MASS_RINGS, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "-contact_mass redistributed: only %" PetscInt_FMT " free nodes off Gamma_C within %d cell rings of the Gamma_C node at (%g, %g), %" PetscInt_FMT " needed (mesh too coarse?)", ncand, ROLLER_MASS_RINGS, (double)xb[0], (double)xb[1], m);
    for (PetscInt j = 0, n0 = ncur; j < n0; ++j)
      for (PetscInt k = 0; k < 3; ++k) {
        PetscInt v;

        PetscCall(PetscFindInt(L->vert[3 * A->cur[j] + k], A->nU, A->U, &v));
        for (PetscInt i = A->vstart[v]; i < A->vstart[v + 1]; ++i) {
          const PetscInt c = A->vcells[i];

          if (A->mark[c] == b) continue;
          A->mark[c]     = b;
          A->cur[ncur++] = c;
        }
      }
  }
  qsort(A->cand, (size_t)ncand, sizeof(Candidate), CompareDistance);
  for (PetscInt i = 0; i < m; ++i) {
    nb[i]         = A->cand[i].gid;
    xi[2 * i]     = A->cand[i].x[0];
    xi[2 * i + 1] = A->cand[i].x[1];
  }
  *fallback = PETSC_FALSE;
  Weights(m, xi, xb, degree, w, &ok);
  for (PetscInt i = 0; ok && i < m; ++i)
    if (PetscAbsReal(w[i]) >= W_MAX) ok = PETSC_FALSE;
  if (!ok && degree > 1) {
    *fallback = PETSC_TRUE;
    Weights(m, xi, xb, 1, w, &ok);
  }
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_PLIB, "-contact_mass redistributed: no affine fit from the %" PetscInt_FMT " nodes near the Gamma_C node at (%g, %g)", m, (double)xb[0], (double)xb[1]);
  PetscFunctionReturn(0);
}

/* T: free dofs to free dofs, rows owned with their node (MATAIJ); stencils of the owned Gamma_C nodes */
PetscErrorCode RollerMassTransferCreate(Roller ctx, Mat *T)
{
  const PetscInt     degree = ctx->disc.degree, m = degree == 1 ? 6 : 12;
  DM                 dm = ctx->mesh.dm;
  PetscSection       gsec;
  DMLabel            outer;
  RollerMassLayer    L = {0};
  Adjacency          A;
  const PetscScalar *x;
  PetscInt           pStart, eEnd, nloc, rstart, stats[3] = {0, 0, 0}, ring_max = 0, nb[12];
  PetscReal          w[12], wmax = 0;

  PetscFunctionBeginUser;
  PetscCall(RollerMassLayerCreate(ctx, &L));
  PetscCall(AdjacencyCreate(&L, &A));
  PetscCall(DMGetGlobalSection(dm, &gsec));
  PetscCall(DMGetLabel(dm, "outer", &outer));
  PetscCall(DMPlexGetChart(dm, &pStart, NULL));
  PetscCall(VecGetOwnershipRange(ctx->ops.coordinates, &rstart, NULL));
  PetscCall(VecGetArrayRead(ctx->ops.coordinates, &x));

  PetscCall(VecGetLocalSize(ctx->ops.coordinates, &nloc));
  PetscCall(MatCreate(ctx->comm, T));
  PetscCall(MatSetSizes(*T, nloc, nloc, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetType(*T, MATAIJ));
  PetscCall(MatSeqAIJSetPreallocation(*T, m, NULL));
  PetscCall(MatMPIAIJSetPreallocation(*T, m, NULL, m, NULL));
  PetscCall(DMPlexGetDepthStratum(dm, 1, NULL, &eEnd));
  for (PetscInt p = pStart; p < eEnd; ++p) { /* vertices and edges: the Lagrange nodes */
    PetscInt gdof, gcdof, goff, val;

    PetscCall(PetscSectionGetDof(gsec, p, &gdof));
    PetscCall(PetscSectionGetConstraintDof(gsec, p, &gcdof));
    PetscCall(PetscSectionGetOffset(gsec, p, &goff));
    if (gdof <= 0 || gdof == gcdof || goff < 0) continue; /* not owned here, Dirichlet, or no node */
    PetscCall(DMLabelGetValue(outer, p, &val));
    if (val != 1) {
      for (PetscInt c = 0; c < 2; ++c) PetscCall(MatSetValue(*T, goff + c, goff + c, 1.0, INSERT_VALUES));
      continue;
    }
    {
      PetscReal xb[2];
      PetscInt  ring;
      PetscBool fallback = PETSC_FALSE;

      xb[0] = PetscRealPart(x[goff - rstart]);
      xb[1] = PetscRealPart(x[goff - rstart + 1]);
      PetscCall(NodeStencil(&L, &A, p, goff, xb, degree, m, nb, w, &ring, &fallback));
      stats[0]++;
      stats[1] += fallback;
      stats[2] += ring > 2;
      ring_max = PetscMax(ring_max, ring);
      for (PetscInt i = 0; i < m; ++i) wmax = PetscMax(wmax, PetscAbsReal(w[i]));
      for (PetscInt c = 0; c < 2; ++c)
        for (PetscInt i = 0; i < m; ++i) PetscCall(MatSetValue(*T, goff + c, nb[i] + c, w[i], INSERT_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(*T, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*T, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscObjectSetName((PetscObject)*T, "T"));

  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, stats, 3, MPIU_INT, MPI_SUM, ctx->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &wmax, 1, MPIU_REAL, MPI_MAX, ctx->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &ring_max, 1, MPIU_INT, MPI_MAX, ctx->comm));
  PetscCall(PetscInfo(dm, "massless contact nodes: %" PetscInt_FMT " Gamma_C nodes, %" PetscInt_FMT " nearest of %" PetscInt_FMT " cells around Gamma_C, P%" PetscInt_FMT " fit; %" PetscInt_FMT " affine fallbacks (max |w| >= %g), %" PetscInt_FMT " beyond the 2-ring (up to ring %" PetscInt_FMT "); max |w| = %g\n", stats[0], m, L.ncell, degree, stats[1], (double)W_MAX, stats[2], ring_max, (double)wmax));
  PetscCall(VecRestoreArrayRead(ctx->ops.coordinates, &x));
  PetscCall(AdjacencyDestroy(&A));
  PetscCall(RollerMassLayerDestroy(&L));
  PetscFunctionReturn(0);
}
