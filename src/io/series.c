/* The per-step diagnostics (docs/model.md section 6 columns) kept in memory while fields go to HDF5, and written at
   the successful end as /diagnostics/<column>, one dataset per column of length steps: the HDF5 file
   then carries the same time series as the CSV. Rank 0 holds the rows. */
#include "io/io.h"
#include <petscviewerhdf5.h>

#define NCOL 8
static const char *const columns[NCOL] = {"step", "t", "R", "alpha", "energy", "contact_nodes", "contact_force", "gap_min"};

struct _n_RollerSeries {
  PetscInt   n, size;
  PetscReal *rows; /* n x NCOL */
};

PetscErrorCode RollerSeriesAppend(Roller ctx, RollerSeries *series)
{
  RollerSeries s = *series;
  PetscReal   *r;

  PetscFunctionBeginUser;
  if (!s) {
    PetscCall(PetscNew(&s));
    *series = s;
  }
  if (s->n == s->size) {
    PetscReal *rows;

    s->size = PetscMax(2 * s->size, 1024);
    PetscCall(PetscMalloc1(s->size * NCOL, &rows));
    if (s->n) PetscCall(PetscArraycpy(rows, s->rows, s->n * NCOL));
    PetscCall(PetscFree(s->rows));
    s->rows = rows;
  }
  r    = s->rows + s->n++ * NCOL;
  r[0] = ctx->state.step;
  r[1] = ctx->state.time;
  r[2] = ctx->info.R;
  r[3] = ctx->info.alpha;
  r[4] = ctx->info.energy;
  r[5] = ctx->info.contact_nodes;
  r[6] = ctx->info.contact_force;
  r[7] = ctx->info.gap_min;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSeriesWrite(Roller ctx, RollerSeries s, PetscViewer h5)
{
  PetscMPIInt rank;
  PetscInt    n = s ? s->n : 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  PetscCall(PetscViewerHDF5PushGroup(h5, "/diagnostics"));
  for (PetscInt c = 0; c < NCOL; ++c) {
    Vec          v;
    PetscScalar *a;

    PetscCall(VecCreateMPI(ctx->comm, rank ? 0 : n, PETSC_DETERMINE, &v));
    PetscCall(PetscObjectSetName((PetscObject)v, columns[c]));
    PetscCall(VecGetArrayWrite(v, &a));
    for (PetscInt i = 0; i < (rank ? 0 : n); ++i) a[i] = s->rows[i * NCOL + c];
    PetscCall(VecRestoreArrayWrite(v, &a));
    PetscCall(VecView(v, h5));
    PetscCall(VecDestroy(&v));
  }
  PetscCall(PetscViewerHDF5PopGroup(h5));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSeriesDestroy(RollerSeries *series)
{
  PetscFunctionBeginUser;
  if (!*series) PetscFunctionReturn(0);
  PetscCall(PetscFree((*series)->rows));
  PetscCall(PetscFree(*series));
  PetscFunctionReturn(0);
}
