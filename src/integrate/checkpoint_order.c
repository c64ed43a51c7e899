/* A checkpoint restarts on any number of ranks. Its vectors are plain datasets in the global order of the run that
   wrote them, which depends on the partition (METIS on the cell graph of the same gmsh mesh, then PETSc's
   numbering of the distributed DM), next to the positions of their points ("nodes": (x, y) of every free
   displacement node, ops.coordinates, in the same order). A restart matches each of its own points to the
   checkpoint's point at the same position and reads every vector through that permutation.

   Why positions and not DMPlex's HDF5 views (DMPlexTopologyView, DMPlexSectionView, DMPlexGlobalVectorView and their
   loads): those reload the mesh from the file, and the run's DM would then have to be the loaded one, not the
   mesh it regenerates (gmsh, METIS, the curved P2 boundary, the labels), and the mesh set-up would have two
   paths. The mesh a restart regenerates from the same options is the same mesh, so its nodes are at the same
   positions to round-off (1e-16; a P2 edge node's position is evaluated by one of its two cells, which depends
   on the partition): matching them within 1e-9 of the largest coordinate, far below the smallest node
   distance (h/3), is exact, needs nothing from the DM, and is itself the last check that the mesh is the same:
   a point without exactly one partner is refused with its position. The file stays plain HDF5 (h5py reads
   it) and the format does not depend on PETSc's DMPlex storage version.

   The match is made on rank 0 from the gathered positions (2 reals per point; sorting by x, O(n log n)), then
   every rank gets the checkpoint index of each of its points. */
#include "integrate/integrate.h"
#include <petscviewerhdf5.h>

/* Rank 0: from[q] = the point of ck (n points, (x, y) interleaved) at the position of here's point q, or the first
   point of here that has no partner or more than one (*bad, -1: none) and how many it has. */
static PetscErrorCode MatchPoints(PetscInt n, const PetscScalar ck[], const PetscScalar here[], PetscInt from[], PetscInt *bad, PetscInt *partners)
{
  PetscReal *x, tol = 0;
  PetscInt  *perm;
  PetscBool *used;

  PetscFunctionBeginUser;
  *bad = -1;
  PetscCall(PetscMalloc3(n, &x, n, &perm, n, &used));
  for (PetscInt p = 0; p < n; ++p) {
    x[p]    = PetscRealPart(ck[2 * p]);
    perm[p] = p;
    used[p] = PETSC_FALSE;
    tol     = PetscMax(tol, PetscMax(PetscAbsScalar(ck[2 * p]), PetscAbsScalar(ck[2 * p + 1])));
  }
  tol *= 1e-9;
  PetscCall(PetscSortRealWithPermutation(n, x, perm)); /* x[perm[k]] ascending */
  for (PetscInt q = 0; q < n && *bad < 0; ++q) {
    const PetscReal xq = PetscRealPart(here[2 * q]), yq = PetscRealPart(here[2 * q + 1]);
    PetscInt        lo = 0, hi = n, count = 0;

    while (lo < hi) { /* the first k with x >= xq - tol */
      const PetscInt mid = (lo + hi) / 2;

      if (x[perm[mid]] < xq - tol) lo = mid + 1;
      else hi = mid;
    }
    for (PetscInt k = lo; k < n && x[perm[k]] <= xq + tol; ++k) {
      if (PetscAbsReal(PetscRealPart(ck[2 * perm[k] + 1]) - yq) > tol) continue;
      from[q] = perm[k];
      count++;
    }
    if (count == 1 && !used[from[q]]) used[from[q]] = PETSC_TRUE;
    else {
      *bad      = q;
      *partners = count;
    }
  }
  PetscCall(PetscFree3(x, perm, used));
  PetscFunctionReturn(0);
}

/* from[i]: the checkpoint's index of this rank's point i of where (2 entries per point), matched with the dataset
   where_name of the checkpoint (or of a -rom_input file: option names the file's option); refused in one line if a
   point has no partner. *npoints: this rank's points. */
PetscErrorCode RollerCheckpointOrderCreate(Roller ctx, PetscViewer viewer, const char option[], const char path[], const char where_name[], Vec where, PetscInt *npoints, PetscInt **from)
{
  Vec                ck, ck0, here0, map;
  VecScatter         to0;
  PetscInt           n, N, bad[2] = {-1, 0};
  PetscReal          at[2] = {0, 0};
  PetscMPIInt        rank;
  const PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  PetscCall(VecGetLocalSize(where, &n));
  PetscCall(VecGetSize(where, &N));
  PetscCheck(n % 2 == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Checkpoint positions %s: %" PetscInt_FMT " local entries, not (x, y) pairs", where_name, n);
  PetscCall(VecCreateMPI(ctx->comm, PETSC_DECIDE, N, &ck));
  PetscCall(PetscObjectSetName((PetscObject)ck, where_name));
  PetscCall(VecLoad(ck, viewer));
  PetscCall(VecScatterCreateToZero(ck, &to0, &ck0));
  PetscCall(VecScatterBegin(to0, ck, ck0, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(to0, ck, ck0, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterDestroy(&to0));
  PetscCall(VecScatterCreateToZero(where, &to0, &here0));
  PetscCall(VecScatterBegin(to0, where, here0, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(to0, where, here0, INSERT_VALUES, SCATTER_FORWARD));
  if (rank == 0) {
    const PetscScalar *c, *h;
    PetscScalar       *m;
    PetscInt          *f;

    PetscCall(PetscMalloc1(N / 2, &f));
    PetscCall(VecGetArrayRead(ck0, &c));
    PetscCall(VecGetArray(here0, &m));
    h = m;
    PetscCall(MatchPoints(N / 2, c, h, f, &bad[0], &bad[1]));
    if (bad[0] >= 0) {
      at[0] = PetscRealPart(h[2 * bad[0]]);
      at[1] = PetscRealPart(h[2 * bad[0] + 1]);
    } else
      for (PetscInt q = 0; q < N / 2; ++q) m[2 * q] = m[2 * q + 1] = (PetscScalar)f[q]; /* the map goes back in place of the positions */
    PetscCall(VecRestoreArray(here0, &m));
    PetscCall(VecRestoreArrayRead(ck0, &c));
    PetscCall(PetscFree(f));
  }
  PetscCallMPI(MPI_Bcast(bad, 2, MPIU_INT, 0, ctx->comm));
  PetscCallMPI(MPI_Bcast(at, 2, MPIU_REAL, 0, ctx->comm));
  PetscCheck(bad[0] < 0, ctx->comm, PETSC_ERR_ARG_INCOMP, "%s %s: refused, another mesh: this run's node at (%.17g, %.17g) has %" PetscInt_FMT " nodes of the file at its position (%s), not one", option, path, (double)at[0], (double)at[1], bad[1], where_name);
  PetscCall(VecDuplicate(where, &map));
  PetscCall(VecScatterBegin(to0, here0, map, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(to0, here0, map, INSERT_VALUES, SCATTER_REVERSE));
  *npoints = n / 2;
  PetscCall(PetscMalloc1(n / 2, from));
  PetscCall(VecGetArrayRead(map, &a));
  for (PetscInt i = 0; i < n / 2; ++i) (*from)[i] = (PetscInt)PetscRealPart(a[2 * i]);
  PetscCall(VecRestoreArrayRead(map, &a));
  PetscCall(VecDestroy(&map));
  PetscCall(VecScatterDestroy(&to0));
  PetscCall(VecDestroy(&here0));
  PetscCall(VecDestroy(&ck0));
  PetscCall(VecDestroy(&ck));
  PetscFunctionReturn(0);
}

/* The dataset name into v, whose local points have the checkpoint indices from[] (bs entries per point). */
PetscErrorCode RollerCheckpointOrderLoad(PetscViewer viewer, const char name[], PetscInt npoints, const PetscInt from[], Vec v)
{
  Vec        plain;
  IS         is;
  VecScatter sc;
  PetscInt   n, N, bs, *idx;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetSize(v, &N));
  bs = npoints ? n / npoints : 1;
  PetscCheck(bs * npoints == n, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Checkpoint dataset %s: %" PetscInt_FMT " local entries on %" PetscInt_FMT " points", name, n, npoints);
  PetscCall(VecCreateMPI(PetscObjectComm((PetscObject)v), PETSC_DECIDE, N, &plain));
  PetscCall(PetscObjectSetName((PetscObject)plain, name));
  PetscCall(VecLoad(plain, viewer));
  PetscCall(PetscMalloc1(n, &idx));
  for (PetscInt i = 0; i < npoints; ++i)
    for (PetscInt c = 0; c < bs; ++c) idx[i * bs + c] = from[i] * bs + c;
  PetscCall(ISCreateGeneral(PetscObjectComm((PetscObject)v), n, idx, PETSC_OWN_POINTER, &is));
  PetscCall(VecScatterCreate(plain, is, v, NULL, &sc));
  PetscCall(VecScatterBegin(sc, plain, v, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, plain, v, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(ISDestroy(&is));
  PetscCall(VecDestroy(&plain));
  PetscFunctionReturn(0);
}
