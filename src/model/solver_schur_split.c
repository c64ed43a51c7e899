/* The substructured Cholesky's split of a step matrix (solver_schur.c): the interface between the ranks and each
   rank's interior block, factored in nested-dissection order. */
#include "model/solver_schur.h"

/* The owner of the global row c (ranges of size + 1 entries). */
static PetscMPIInt Owner(PetscMPIInt size, const PetscInt ranges[], PetscInt c)
{
  PetscMPIInt lo = 0, hi = size - 1;

  while (lo < hi) {
    const PetscMPIInt mid = (lo + hi + 1) / 2;

    if (ranges[mid] <= c) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

/* The interface: for each pair of coupled ranks the smaller of their two sets of rows coupled to the other (the
   lower rank's on a tie), so that every coupling between two ranks has an interface row at one end; numbered rank
   by rank. gl[] all of them (global rows, sorted), on every rank; isg[] marks this rank's. */
PetscErrorCode RollerSchurInterface(Mat A, SchurCtx *sc, PetscInt **gl, PetscBool **isg)
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)A);
  Mat             Ad, Ao;
  const PetscInt *garray, *ranges;
  PetscInt        lo, hi, m, ng = 0, *mine, *cnt, *stamp;
  PetscMPIInt     rank, size, *counts, *displs, n;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(MatGetOwnershipRange(A, &lo, &hi));
  PetscCall(MatGetOwnershipRanges(A, &ranges));
  PetscCall(MatMPIAIJGetSeqAIJ(A, &Ad, &Ao, &garray));
  m = hi - lo;
  PetscCall(PetscCalloc1(m, isg));
  PetscCall(PetscMalloc1(m, &mine));
  PetscCall(PetscCalloc1((size_t)size * size, &cnt)); /* cnt[r * size + q]: rows of rank r coupled to rank q */
  PetscCall(PetscMalloc1(size, &stamp));
  for (PetscInt pass = 0; pass < 2; ++pass) {
    for (PetscMPIInt q = 0; q < size; ++q) stamp[q] = -1;
    for (PetscInt i = 0; i < m; ++i) {
      const PetscInt *cols;
      PetscInt        nc;

      PetscCall(MatGetRow(Ao, i, &nc, &cols, NULL));
      for (PetscInt k = 0; k < nc; ++k) {
        const PetscMPIInt q = Owner(size, ranges, garray[cols[k]]);

        if (stamp[q] == i) continue;
        stamp[q] = i;
        if (!pass) cnt[(size_t)rank * size + q]++;
        else if (cnt[(size_t)rank * size + q] < cnt[(size_t)q * size + rank] || (cnt[(size_t)rank * size + q] == cnt[(size_t)q * size + rank] && rank < q)) (*isg)[i] = PETSC_TRUE;
      }
      PetscCall(MatRestoreRow(Ao, i, &nc, &cols, NULL));
      if (pass && (*isg)[i]) mine[sc->nglocal++] = lo + i;
    }
    if (!pass) PetscCall(MPIU_Allreduce(MPI_IN_PLACE, cnt, (PetscMPIInt)(size * size), MPIU_INT, MPI_SUM, comm));
  }
  PetscCall(PetscFree(cnt));
  PetscCall(PetscFree(stamp));
  PetscCall(PetscMalloc2(size, &counts, size, &displs));
  PetscCall(PetscMPIIntCast(sc->nglocal, &n));
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts, 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; ++r) {
    displs[r] = (PetscMPIInt)ng;
    if (r == rank) sc->goff = ng;
    ng += counts[r];
  }
  sc->ng = ng;
  PetscCall(PetscMalloc1(ng + 1, gl));
  PetscCallMPI(MPI_Allgatherv(mine, n, MPIU_INT, *gl, counts, displs, MPIU_INT, comm));
  PetscCall(PetscMalloc1(sc->nglocal, &sc->grow));
  for (PetscInt q = 0; q < sc->nglocal; ++q) sc->grow[q] = mine[q] - lo;
  PetscCall(PetscFree2(counts, displs));
  PetscCall(PetscFree(mine));
  PetscFunctionReturn(0);
}

/* The interior block in nested-dissection order, factored; row[] maps the factor's unknowns to local rows. */
PetscErrorCode RollerSchurInteriorFactor(Mat A, SchurCtx *sc, const PetscBool isg[], PetscInt *nI, PetscInt **inv)
{
  Mat             Ad, Ao, AI, AP;
  const PetscInt *garray, *perm;
  PetscInt        lo, hi, m, n = 0, *loc, *nnz;
  IS              rp, cp, nat;
  MatFactorInfo   info;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(A, &lo, &hi));
  PetscCall(MatMPIAIJGetSeqAIJ(A, &Ad, &Ao, &garray));
  m = hi - lo;
  PetscCall(PetscMalloc2(m, &loc, m, &nnz));
  for (PetscInt i = 0; i < m; ++i) loc[i] = isg[i] ? -1 : n++;
  for (PetscInt pass = 0; pass < 2; ++pass) { /* the block in local order (for the ordering), then permuted */
    Mat B;

    for (PetscInt i = 0, k = 0; i < m; ++i) {
      const PetscInt *cols;
      PetscInt        nc, c = 0;

      if (loc[i] < 0) continue;
      PetscCall(MatGetRow(Ad, i, &nc, &cols, NULL));
      for (PetscInt j = 0; j < nc; ++j) c += loc[cols[j]] >= 0;
      PetscCall(MatRestoreRow(Ad, i, &nc, &cols, NULL));
      nnz[pass ? (*inv)[k] : k] = c;
      ++k;
    }
    PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, nnz, &B));
    for (PetscInt i = 0; i < m; ++i) {
      const PetscInt    *cols;
      const PetscScalar *vals;
      PetscInt           nc, r;

      if (loc[i] < 0) continue;
      r = pass ? (*inv)[loc[i]] : loc[i];
      PetscCall(MatGetRow(Ad, i, &nc, &cols, &vals));
      for (PetscInt j = 0; j < nc; ++j) {
        const PetscInt c = loc[cols[j]];

        if (c >= 0) PetscCall(MatSetValue(B, r, pass ? (*inv)[c] : c, vals[j], INSERT_VALUES));
      }
      PetscCall(MatRestoreRow(Ad, i, &nc, &cols, &vals));
    }
    PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
    if (pass) AP = B;
    else {
      AI = B;
      PetscCall(MatGetOrdering(AI, MATORDERINGND, &rp, &cp));
      PetscCall(ISGetIndices(rp, &perm)); /* perm[new] = old */
      PetscCall(PetscMalloc1(n, inv));
      PetscCall(PetscMalloc1(n, &sc->row));
      for (PetscInt p = 0; p < n; ++p) (*inv)[perm[p]] = p;
      for (PetscInt i = 0; i < m; ++i)
        if (loc[i] >= 0) sc->row[(*inv)[loc[i]]] = i;
      PetscCall(ISRestoreIndices(rp, &perm));
      PetscCall(ISDestroy(&rp));
      PetscCall(ISDestroy(&cp));
    }
  }
  /* inv[] was for the interior's local numbering; callers need it for local rows */
  {
    PetscInt *byrow;

    PetscCall(PetscMalloc1(m, &byrow));
    for (PetscInt i = 0; i < m; ++i) byrow[i] = loc[i] >= 0 ? (*inv)[loc[i]] : -1;
    PetscCall(PetscFree(*inv));
    *inv = byrow;
  }
  PetscCall(MatDestroy(&AI));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, n, 0, 1, &nat));
  PetscCall(MatGetFactor(AP, MATSOLVERPETSC, MAT_FACTOR_CHOLESKY, &sc->F));
  PetscCall(MatFactorInfoInitialize(&info));
  info.fill = 6.0;
  PetscCall(MatCholeskyFactorSymbolic(sc->F, AP, nat, &info));
  PetscCall(MatCholeskyFactorNumeric(sc->F, AP, &info));
  PetscCall(ISDestroy(&nat));
  PetscCall(MatDestroy(&AP));
  PetscCall(PetscFree2(loc, nnz));
  *nI = n;
  PetscFunctionReturn(0);
}
