/* The cells around Gamma_C for the massless contact nodes (mass_transfer.c): the cells within
   ROLLER_MASS_RINGS rings of Gamma_C's vertices, each with its vertices and its Lagrange nodes (first global
   dof, Gamma_C flag, position), gathered ring by ring on every rank, so every rank holds the same layer,
   whatever the partition, with the off-process neighbours of its Gamma_C nodes. */
#include "model/mass_impl.h"

/* What a rank knows of its points: sections, Gamma_C label, global point numbers, positions (local Vec) */
typedef struct {
  DM                 dm;
  PetscSection       lsec, gsec;
  DMLabel            outer;
  IS                 pnum_is;
  const PetscInt    *pnum;
  Vec                xloc;
  const PetscScalar *x;
  PetscInt           pStart;
} Points;

static PetscInt Decode(PetscInt g)
{
  return g < 0 ? -(g + 1) : g;
}

/* The cell's 3 global vertex numbers and its nodes (first global dof or -1, Gamma_C flag, position) */
static PetscErrorCode CellRecord(Points *P, PetscInt cell, PetscInt nn, PetscInt vert[], PetscInt node[], PetscInt outer[], PetscReal x[])
{
  PetscInt *closure = NULL, nclosure, nv = 0, nd = 0;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetTransitiveClosure(P->dm, cell, PETSC_TRUE, &nclosure, &closure));
  for (PetscInt k = 0; k < nclosure; ++k) {
    const PetscInt p = closure[2 * k];
    PetscInt       depth, dof, cdof, off, val;

    PetscCall(DMPlexGetPointDepth(P->dm, p, &depth));
    if (depth == 0) vert[nv++] = Decode(P->pnum[p - P->pStart]);
    PetscCall(PetscSectionGetDof(P->lsec, p, &dof));
    if (depth > 1 || dof == 0) continue;
    PetscCheck(dof == 2 && nd < nn, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Cell %" PetscInt_FMT ": point %" PetscInt_FMT " has %" PetscInt_FMT " dofs (node %" PetscInt_FMT " of %" PetscInt_FMT ")", cell, p, dof, nd, nn);
    PetscCall(PetscSectionGetConstraintDof(P->lsec, p, &cdof));
    PetscCall(PetscSectionGetOffset(P->lsec, p, &off));
    x[2 * nd]     = PetscRealPart(P->x[off]);
    x[2 * nd + 1] = PetscRealPart(P->x[off + 1]);
    node[nd]      = -1;
    if (!cdof) {
      PetscCall(PetscSectionGetOffset(P->gsec, p, &off));
      node[nd] = Decode(off);
    }
    PetscCall(DMLabelGetValue(P->outer, p, &val));
    outer[nd++] = val == 1;
  }
  PetscCheck(nv == 3 && nd == nn, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Cell %" PetscInt_FMT " has %" PetscInt_FMT " vertices and %" PetscInt_FMT " nodes, expected 3 and %" PetscInt_FMT, cell, nv, nd, nn);
  PetscCall(DMPlexRestoreTransitiveClosure(P->dm, cell, PETSC_TRUE, &nclosure, &closure));
  PetscFunctionReturn(0);
}

/* Every rank's array of n items of size bs gathered, in rank order, on every rank */
static PetscErrorCode AllGather(MPI_Comm comm, PetscInt n, PetscInt bs, MPI_Datatype type, size_t size, const void *mine, PetscInt *N, void **all)
{
  PetscMPIInt nr, *counts, *displs, cnt;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &nr));
  PetscCall(PetscMalloc2(nr, &counts, nr, &displs));
  PetscCall(PetscMPIIntCast(n * bs, &cnt));
  PetscCallMPI(MPI_Allgather(&cnt, 1, MPI_INT, counts, 1, MPI_INT, comm));
  *N = 0;
  for (PetscMPIInt r = 0; r < nr; ++r) {
    PetscCall(PetscMPIIntCast(*N, &displs[r]));
    *N += counts[r];
  }
  PetscCall(PetscMalloc(size * (*N > 0 ? *N : 1), all));
  PetscCallMPI(MPI_Allgatherv(mine, cnt, type, *all, counts, displs, type, comm));
  *N /= bs;
  PetscCall(PetscFree2(counts, displs));
  PetscFunctionReturn(0);
}

/* The layer of the (owned, so each once) cells with a vertex in the sorted S, gathered on every rank */
static PetscErrorCode LayerGather(Points *P, MPI_Comm comm, PetscInt nS, const PetscInt S[], RollerMassLayer *L)
{
  PetscInt   cStart, cEnd, n = 0, nn = L->nn, N, *vert, *node, *outer;
  PetscReal *x;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(P->dm, 0, &cStart, &cEnd));
  PetscCall(PetscMalloc4(3 * (cEnd - cStart) + 1, &vert, nn * (cEnd - cStart) + 1, &node, nn * (cEnd - cStart) + 1, &outer, 2 * nn * (cEnd - cStart) + 1, &x));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscBool touch = PETSC_FALSE;

    if (P->pnum[c - P->pStart] < 0) continue;
    PetscCall(CellRecord(P, c, nn, &vert[3 * n], &node[nn * n], &outer[nn * n], &x[2 * nn * n]));
    for (PetscInt k = 0; k < 3; ++k) {
      PetscInt loc;

      PetscCall(PetscFindInt(vert[3 * n + k], nS, S, &loc));
      if (loc >= 0) touch = PETSC_TRUE;
    }
    if (touch) n++;
  }
  PetscCall(PetscFree(L->vert));
  PetscCall(PetscFree(L->node));
  PetscCall(PetscFree(L->outer));
  PetscCall(PetscFree(L->x));
  PetscCall(AllGather(comm, n, 3, MPIU_INT, sizeof(PetscInt), vert, &L->ncell, (void **)&L->vert));
  PetscCall(AllGather(comm, n, nn, MPIU_INT, sizeof(PetscInt), node, &N, (void **)&L->node));
  PetscCall(AllGather(comm, n, nn, MPIU_INT, sizeof(PetscInt), outer, &N, (void **)&L->outer));
  PetscCall(AllGather(comm, n, 2 * nn, MPIU_REAL, sizeof(PetscReal), x, &N, (void **)&L->x));
  PetscCall(PetscFree4(vert, node, outer, x));
  PetscFunctionReturn(0);
}

/* The cells within ROLLER_MASS_RINGS rings of Gamma_C's vertices */
static PetscErrorCode LayerFill(Points *P, MPI_Comm comm, RollerMassLayer *L)
{
  PetscInt  vStart, vEnd, n = 0, nS, *mine, *S;
  PetscBool on;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(P->dm, 0, &vStart, &vEnd));
  PetscCall(PetscMalloc1(vEnd - vStart + 1, &mine));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt val;

    PetscCall(DMLabelGetValue(P->outer, v, &val));
    if (val == 1 && P->pnum[v - P->pStart] >= 0) mine[n++] = P->pnum[v - P->pStart];
  }
  PetscCall(AllGather(comm, n, 1, MPIU_INT, sizeof(PetscInt), mine, &nS, (void **)&S));
  PetscCall(PetscFree(mine));
  on = (PetscBool)(nS > 0);
  PetscCheck(on, comm, PETSC_ERR_ARG_WRONG, "-contact_mass redistributed: Gamma_C (label \"outer\") has no vertices");
  for (PetscInt r = 0; r < ROLLER_MASS_RINGS; ++r) {
    PetscCall(PetscSortInt(nS, S));
    PetscCall(LayerGather(P, comm, nS, S, L));
    PetscCall(PetscFree(S));
    nS = 3 * L->ncell;
    PetscCall(PetscMalloc1(nS, &S));
    PetscCall(PetscArraycpy(S, L->vert, nS));
    PetscCall(PetscSortRemoveDupsInt(&nS, S));
  }
  PetscCall(PetscFree(S));
  PetscFunctionReturn(0);
}

/* The layer of ctx->mesh.dm around Gamma_C (label "outer"), positions from ctx->ops.coordinates */
PetscErrorCode RollerMassLayerCreate(Roller ctx, RollerMassLayer *L)
{
  Points   P;
  PetscInt pEnd;

  PetscFunctionBeginUser;
  L->nn = ctx->disc.degree == 1 ? 3 : 6;
  P.dm  = ctx->mesh.dm;
  PetscCall(DMGetLocalSection(P.dm, &P.lsec));
  PetscCall(DMGetGlobalSection(P.dm, &P.gsec));
  PetscCall(DMGetLabel(P.dm, "outer", &P.outer));
  PetscCheck(P.outer, ctx->comm, PETSC_ERR_ARG_WRONG, "The mesh has no label \"outer\" (Gamma_C)");
  PetscCall(DMPlexCreatePointNumbering(P.dm, &P.pnum_is));
  PetscCall(ISGetIndices(P.pnum_is, &P.pnum));
  PetscCall(DMPlexGetChart(P.dm, &P.pStart, &pEnd));
  PetscCall(DMGetLocalVector(P.dm, &P.xloc));
  PetscCall(DMGlobalToLocal(P.dm, ctx->ops.coordinates, INSERT_VALUES, P.xloc));
  PetscCall(VecGetArrayRead(P.xloc, &P.x));
  PetscCall(LayerFill(&P, ctx->comm, L));
  PetscCall(VecRestoreArrayRead(P.xloc, &P.x));
  PetscCall(DMRestoreLocalVector(P.dm, &P.xloc));
  PetscCall(ISRestoreIndices(P.pnum_is, &P.pnum));
  PetscCall(ISDestroy(&P.pnum_is));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerMassLayerDestroy(RollerMassLayer *L)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(L->vert));
  PetscCall(PetscFree(L->node));
  PetscCall(PetscFree(L->outer));
  PetscCall(PetscFree(L->x));
  PetscFunctionReturn(0);
}
