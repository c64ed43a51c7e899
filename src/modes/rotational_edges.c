/* The edge terms of the rotational elastic form A_L (docs/squeal.md section 1.1): the part of the broken form's edge
   integrals that vanishes on smooth fields, subtracted to make A_L skew and consistent; in parallel the edges
   between two ranks' cells get the other rank's side through a star forest. */
#include "modes/rotational_impl.h"

enum {
  NQ    = 3, /* Gauss points per edge */
  MAXNB = 12 /* vector P2 */
};

/* One cell's side of an edge: the Gauss points x, the physical gradients g of its Nb basis functions there, the
   edge's normal (outer to this cell) and length element, the cell's global closure indices (negative: constrained). */
typedef struct {
  PetscReal x[NQ][2], g[NQ][MAXNB * 4], nrm[NQ][2], ds[NQ];
  PetscInt  idx[MAXNB];
} EdgeSide;

static PetscErrorCode EdgeSideCompute(DM dm, PetscFE fe, PetscFE cfe[2], PetscSection sec, PetscSection gsec, const PetscReal t[], PetscInt f, PetscInt cell, EdgeSide *es)
{
  const PetscReal ref[3][2] = {
    {-1, -1},
    {1,  -1},
    {-1, 1 }
  }; /* the reference triangle's vertices, in closure order */
  const PetscInt    *cone;
  PetscInt          *closure = NULL, ncl, nv = 0, loc[2] = {-1, -1}, Ncx, nidx, *idx, Nb;
  const PetscScalar *array;
  PetscScalar       *coords;
  PetscBool          isDG;
  PetscReal          p[(NQ + 1) * 2], xc[2];
  PetscTabulation    T, Tx;
  PetscFE            cf = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscFEGetDimension(fe, &Nb));
  PetscCall(DMPlexGetCone(dm, f, &cone));
  PetscCall(DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &ncl, &closure));
  for (PetscInt k = 0; k < ncl; ++k) {
    PetscInt depth;

    PetscCall(DMPlexGetPointDepth(dm, closure[2 * k], &depth));
    if (depth != 0) continue;
    if (closure[2 * k] == cone[0]) loc[0] = nv;
    if (closure[2 * k] == cone[1]) loc[1] = nv;
    ++nv;
  }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &ncl, &closure));
  PetscCheck(nv == 3 && loc[0] >= 0 && loc[1] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Edge %" PetscInt_FMT " not found in cell %" PetscInt_FMT, f, cell);
  for (PetscInt k = 0; k < NQ; ++k)
    for (PetscInt c = 0; c < 2; ++c) p[k * 2 + c] = ref[loc[0]][c] + t[k] * (ref[loc[1]][c] - ref[loc[0]][c]);
  p[NQ * 2] = p[NQ * 2 + 1] = -1.0 / 3.0; /* the centroid: the side of the normal */
  PetscCall(DMPlexGetCellCoordinates(dm, cell, &isDG, &Ncx, &array, &coords));
  PetscCall(RollerRotCoordinateElement(Ncx, cfe, &cf));
  PetscCall(PetscFECreateTabulation(fe, 1, NQ + 1, p, 1, &T));
  PetscCall(PetscFECreateTabulation(cf, 1, NQ + 1, p, 1, &Tx));
  for (PetscInt k = 0; k <= NQ; ++k) {
    PetscReal J[4], Ji[4], X2[8], det, tau[2];

    if (k == NQ) { /* orient the normals out of this cell */
      RollerRotGeometry(Tx, k, coords, xc, J, Ji, X2, &det);
      for (PetscInt q = 0; q < NQ; ++q)
        if (es->nrm[q][0] * (es->x[q][0] - xc[0]) + es->nrm[q][1] * (es->x[q][1] - xc[1]) < 0) es->nrm[q][0] = -es->nrm[q][0], es->nrm[q][1] = -es->nrm[q][1];
      continue;
    }
    RollerRotGeometry(Tx, k, coords, es->x[k], J, Ji, X2, &det);
    RollerRotDerivatives(T, k, Ji, X2, es->g[k], NULL);
    for (PetscInt c = 0; c < 2; ++c) tau[c] = J[c * 2 + 0] * (ref[loc[1]][0] - ref[loc[0]][0]) + J[c * 2 + 1] * (ref[loc[1]][1] - ref[loc[0]][1]); /* dx/dt */
    es->ds[k]     = PetscSqrtReal(tau[0] * tau[0] + tau[1] * tau[1]);
    es->nrm[k][0] = tau[1] / es->ds[k];
    es->nrm[k][1] = -tau[0] / es->ds[k];
  }
  PetscCall(PetscTabulationDestroy(&T));
  PetscCall(PetscTabulationDestroy(&Tx));
  PetscCall(DMPlexRestoreCellCoordinates(dm, cell, &isDG, &Ncx, &array, &coords));
  PetscCall(DMPlexGetClosureIndices(dm, sec, gsec, cell, PETSC_TRUE, &nidx, &idx, NULL, NULL));
  PetscCheck(nidx == Nb, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Cell %" PetscInt_FMT " has %" PetscInt_FMT " closure indices, expected %" PetscInt_FMT, cell, nidx, Nb);
  for (PetscInt k = 0; k < Nb; ++k) es->idx[k] = idx[k];
  PetscCall(DMPlexRestoreClosureIndices(dm, sec, gsec, cell, PETSC_TRUE, &nidx, &idx, NULL, NULL));
  PetscFunctionReturn(0);
}

/* The other side of the edges on the partition boundary (distributed without overlap, such an edge has one cell on
   each of two ranks): the owner (root) of each shared edge sends its side to the other rank (leaf), which assembles
   the edge; *skip[f - fStart]: an edge the other rank assembles; remote[f - fStart]: the index into *other of the
   other side of a leaf edge (-1: none). */
static PetscErrorCode RemoteSides(DM dm, PetscFE fe, PetscFE cfe[2], PetscSection sec, PetscSection gsec, const PetscReal t[], PetscInt fStart, PetscInt fEnd, PetscBool **skip, PetscInt **remote, EdgeSide **other)
{
  PetscSF            sf, esf;
  PetscInt           nroots, nleaves, pStart, pEnd, nr = 0, nl = 0, *rootidx, *leafidx;
  const PetscInt    *ilocal, *degree;
  const PetscSFNode *iremote;
  PetscSFNode       *eremote;
  PetscInt          *elocal;
  EdgeSide          *mine;
  MPI_Datatype       unit;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(fEnd - fStart, skip));
  PetscCall(PetscMalloc1(fEnd - fStart, remote));
  for (PetscInt f = fStart; f < fEnd; ++f) (*remote)[f - fStart] = -1;
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, &nroots, &nleaves, &ilocal, &iremote));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  *other = NULL;
  if (nroots < 0) PetscFunctionReturn(0); /* one rank */
  PetscCall(PetscSFComputeDegreeBegin(sf, &degree));
  PetscCall(PetscSFComputeDegreeEnd(sf, &degree));
  /* the roots: the shared edges this rank owns, numbered 0..nr-1, their sides computed */
  PetscCall(PetscMalloc2(pEnd - pStart, &rootidx, pEnd - pStart, &leafidx));
  for (PetscInt p = pStart; p < pEnd; ++p) rootidx[p - pStart] = leafidx[p - pStart] = -1;
  for (PetscInt f = fStart; f < fEnd; ++f)
    if (degree[f - pStart] > 0) {
      rootidx[f - pStart] = nr++;
      (*skip)[f - fStart] = PETSC_TRUE;
    }
  PetscCall(PetscMalloc1(nr, &mine));
  for (PetscInt f = fStart; f < fEnd; ++f) {
    const PetscInt *supp;
    PetscInt        ns;

    if (rootidx[f - pStart] < 0) continue;
    PetscCall(DMPlexGetSupportSize(dm, f, &ns));
    PetscCall(DMPlexGetSupport(dm, f, &supp));
    PetscCheck(ns == 1, PETSC_COMM_SELF, PETSC_ERR_PLIB, "A shared edge with %" PetscInt_FMT " local cells", ns);
    PetscCall(EdgeSideCompute(dm, fe, cfe, sec, gsec, t, f, supp[0], &mine[rootidx[f - pStart]]));
  }
  /* each leaf edge learns its root's number on the owner */
  PetscCall(PetscSFBcastBegin(sf, MPIU_INT, rootidx, leafidx, MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(sf, MPIU_INT, rootidx, leafidx, MPI_REPLACE));
  PetscCall(PetscMalloc2(nleaves, &elocal, nleaves, &eremote));
  for (PetscInt l = 0; l < nleaves; ++l) {
    const PetscInt p = ilocal ? ilocal[l] : l;

    if (p < fStart || p >= fEnd || leafidx[p - pStart] < 0) continue;
    (*remote)[p - fStart] = nl;
    elocal[nl]            = nl;
    eremote[nl].rank      = iremote[l].rank;
    eremote[nl].index     = leafidx[p - pStart];
    ++nl;
  }
  PetscCall(PetscSFCreate(PetscObjectComm((PetscObject)dm), &esf));
  PetscCall(PetscSFSetGraph(esf, nr, nl, elocal, PETSC_COPY_VALUES, eremote, PETSC_COPY_VALUES));
  PetscCall(PetscMalloc1(nl, other));
  PetscCallMPI(MPI_Type_contiguous((PetscMPIInt)sizeof(EdgeSide), MPI_BYTE, &unit));
  PetscCallMPI(MPI_Type_commit(&unit));
  PetscCall(PetscSFBcastBegin(esf, unit, mine, *other, MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(esf, unit, mine, *other, MPI_REPLACE));
  PetscCallMPI(MPI_Type_free(&unit));
  PetscCall(PetscSFDestroy(&esf));
  PetscCall(PetscFree2(elocal, eremote));
  PetscCall(PetscFree(mine));
  PetscCall(PetscFree2(rootidx, leafidx));
  PetscFunctionReturn(0);
}

/* The edge terms that make the broken form skew and keep it consistent (docs/squeal.md section 1.1): cellwise,
   sum_K int_K e . grad(sigma[grad u] : grad v) = sum_K int_dK (e . n) sigma[grad u] : grad v (div e = 0), so
     A + A^T = S + S^T + B,  S(u, v) = sum_interior F int_F (e . n) [sigma[grad u]] : {grad v},
                             B(u, v) = sum_boundary F int_F (e . n) sigma[grad u] : grad v
   ([.] the jump from the first supporting cell to the second, n the first cell's outer normal, {.} the average).
   S vanishes on a smooth u and B with e . n (0 on the circles), so A - S - B/2 is consistent and skew. Adds
   S + B/2 to the matrix; 3 Gauss points per edge, exact on straight cells. In parallel an edge between two ranks'
   cells is assembled by one of them with the other's side (RemoteSides). */
PetscErrorCode RollerRotEdgeTerms(Roller ctx, DM dm, PetscFE fe, PetscFE cfe[2], Mat S)
{
  PetscReal    t[NQ], wt[NQ];
  PetscSection sec, gsec;
  PetscInt     fStart, fEnd, Nb, *remote;
  PetscBool   *skip;
  EdgeSide    *other, side[2];
  PetscScalar *vals;
  PetscInt    *rows;

  PetscFunctionBeginUser;
  PetscCall(PetscDTGaussQuadrature(NQ, 0.0, 1.0, t, wt));
  PetscCall(DMGetLocalSection(dm, &sec));
  PetscCall(DMGetGlobalSection(dm, &gsec));
  PetscCall(PetscFEGetDimension(fe, &Nb));
  PetscCheck(Nb <= MAXNB, PETSC_COMM_SELF, PETSC_ERR_SUP, "%" PetscInt_FMT " basis functions: at most %d (vector P2)", Nb, (int)MAXNB);
  PetscCall(PetscMalloc2(4 * Nb * Nb, &vals, 2 * Nb, &rows));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  PetscCall(RemoteSides(dm, fe, cfe, sec, gsec, t, fStart, fEnd, &skip, &remote, &other));
  for (PetscInt f = fStart; f < fEnd; ++f) {
    const PetscInt *supp;
    PetscInt        ns, n = 0;

    if (skip[f - fStart]) continue;
    PetscCall(DMPlexGetSupportSize(dm, f, &ns));
    PetscCall(DMPlexGetSupport(dm, f, &supp));
    for (PetscInt s = 0; s < ns; ++s) PetscCall(EdgeSideCompute(dm, fe, cfe, sec, gsec, t, f, supp[s], &side[s]));
    if (remote[f - fStart] >= 0) side[ns++] = other[remote[f - fStart]];
    for (PetscInt s = 1; s < ns; ++s)
      for (PetscInt k = 0; k < NQ; ++k)
        PetscCheck(PetscAbsReal(side[s].x[k][0] - side[0].x[k][0]) + PetscAbsReal(side[s].x[k][1] - side[0].x[k][1]) < 1e-10 * (1.0 + ctx->mesh.r_outer), PETSC_COMM_SELF, PETSC_ERR_PLIB, "Edge %" PetscInt_FMT ": its cells disagree on a point", f);
    for (PetscInt s = 0; s < ns; ++s)
      for (PetscInt k = 0; k < Nb; ++k) rows[n++] = side[s].idx[k];
    /* interior: row (r, i), column (s, j): int (e . n) sgn_s sigma[grad phi_j^s] : grad phi_i^r / 2, sgn = +1, -1;
       boundary: the one cell, int (e . n) sigma[grad phi_j] : grad phi_i / 2 */
    PetscCall(PetscArrayzero(vals, n * n));
    for (PetscInt q = 0; q < NQ; ++q) {
      const PetscReal en = -side[0].x[q][1] * side[0].nrm[q][0] + side[0].x[q][0] * side[0].nrm[q][1], wq = 0.5 * wt[q] * side[0].ds[q] * en;

      for (PetscInt r = 0; r < ns; ++r)
        for (PetscInt i = 0; i < Nb; ++i)
          for (PetscInt s = 0; s < ns; ++s)
            for (PetscInt j = 0; j < Nb; ++j) vals[(r * Nb + i) * n + s * Nb + j] += (s == 0 ? wq : -wq) * RollerRotStressProduct(ctx, &side[s].g[q][j * 4], &side[r].g[q][i * 4]);
    }
    PetscCall(MatSetValues(S, n, rows, n, rows, vals, ADD_VALUES));
  }
  PetscCall(PetscFree(other));
  PetscCall(PetscFree2(skip, remote));
  PetscCall(PetscFree2(vals, rows));
  PetscFunctionReturn(0);
}
