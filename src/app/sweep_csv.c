/* The sweep's result: the eigenvalues each sub-communicator found (kept by its rank 0, ROLLER_SWEEP_ROW reals per
   eigenvalue) gathered to rank 0 of the sweep's communicator and written as one CSV, sorted by case, each case's
   eigenvalues in the order of -modes_csv (by frequency):
     case,<swept options>,re,im,frequency,growth_rate,order,wave,error
   written as F.part and renamed when complete, like every output (io/output_files.c). */
#include "app/sweep.h"
#include "io/io.h"
#include "modes/modes.h"

PetscErrorCode RollerSweepRowsAppend(RollerSweepRows *rows, PetscInt c, const RollerEigen *e)
{
  PetscFunctionBeginUser;
  if (rows->n + e->n > rows->max) {
    rows->max = PetscMax(2 * rows->max, rows->n + e->n);
    PetscCall(PetscRealloc(sizeof(PetscReal) * ROLLER_SWEEP_ROW * rows->max, &rows->rows));
  }
  for (PetscInt j = 0; j < e->n; ++j) {
    PetscReal *r = rows->rows + ROLLER_SWEEP_ROW * rows->n++;

    r[0] = (PetscReal)c;
    r[1] = e->re[j];
    r[2] = e->im[j];
    r[3] = (PetscReal)e->order[j];
    r[4] = (PetscReal)e->wave[j];
    r[5] = e->error[j];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepRowsDestroy(RollerSweepRows *rows)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(rows->rows));
  rows->n = rows->max = 0;
  PetscFunctionReturn(0);
}

/* Every process's rows to rank 0 (the ranks that are not the root of their sub-communicator hold none). */
static PetscErrorCode Gather(MPI_Comm comm, const RollerSweepRows *rows, PetscInt *n, PetscReal **all)
{
  PetscMPIInt rank, size, count, *counts = NULL, *displs = NULL;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMPIIntCast(ROLLER_SWEEP_ROW * rows->n, &count));
  if (!rank) PetscCall(PetscMalloc2(size, &counts, size + 1, &displs));
  PetscCallMPI(MPI_Gather(&count, 1, MPI_INT, counts, 1, MPI_INT, 0, comm));
  *n   = 0;
  *all = NULL;
  if (!rank) {
    displs[0] = 0;
    for (PetscMPIInt r = 0; r < size; ++r) PetscCall(PetscMPIIntCast((PetscInt)displs[r] + counts[r], &displs[r + 1]));
    *n = displs[size] / ROLLER_SWEEP_ROW;
    PetscCall(PetscMalloc1(displs[size] + 1, all));
  }
  PetscCallMPI(MPI_Gatherv(rows->rows, count, MPIU_REAL, *all, counts, displs, MPIU_REAL, 0, comm));
  PetscCall(PetscFree2(counts, displs));
  PetscFunctionReturn(0);
}

/* Rank 0: the cases in order. A case's rows are contiguous in the gathered array (one process appended them
   together), so each case is a start and a count. Returns the number of the run's cases that have no row. */
static PetscErrorCode WriteRows(const RollerSweepPlan *plan, PetscInt n, const PetscReal *all, const char part[], PetscInt *missing)
{
  PetscInt *start, *count;
  FILE     *fp;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(plan->ncases, &start, plan->ncases, &count));
  for (PetscInt c = 0; c < plan->ncases; ++c) start[c] = count[c] = 0;
  for (PetscInt r = 0; r < n; ++r) {
    const PetscInt c = (PetscInt)all[ROLLER_SWEEP_ROW * r];

    PetscCheck(c >= 0 && c < plan->ncases && (!count[c] || start[c] + count[c] == r), PETSC_COMM_SELF, PETSC_ERR_PLIB, "Sweep: case %" PetscInt_FMT " of row %" PetscInt_FMT " out of place", c, r);
    if (!count[c]++) start[c] = r;
  }
  PetscCall(PetscFOpen(PETSC_COMM_SELF, part, "w", &fp));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "case"));
  for (PetscInt q = 0; q < plan->nparams; ++q) PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, ",%s", plan->name[q]));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, ",re,im,frequency,growth_rate,order,wave,error\n"));
  *missing = 0;
  for (PetscInt c = plan->slice[0]; c < plan->ncases; c += plan->slice[1]) {
    PetscReal v[ROLLER_SWEEP_MAX_PARAMS];
    char      params[ROLLER_SWEEP_MAX_PARAMS * 32] = "", value[32];

    if (!count[c]) ++*missing;
    PetscCall(RollerSweepCaseValues(plan, c, v));
    for (PetscInt q = 0; q < plan->nparams; ++q) {
      PetscCall(RollerSweepFormatReal(value, sizeof(value), v[q]));
      PetscCall(PetscStrlcat(params, ",", sizeof(params)));
      PetscCall(PetscStrlcat(params, value, sizeof(params)));
    }
    for (PetscInt r = start[c]; r < start[c] + count[c]; ++r) {
      const PetscReal *x = all + ROLLER_SWEEP_ROW * r;

      PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "%" PetscInt_FMT "%s,%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%s,%.3e\n", c, params, (double)x[1], (double)x[2], (double)x[2], (double)x[1], (PetscInt)x[3], RollerWaves[(PetscInt)x[4]], (double)x[5]));
    }
  }
  PetscCall(PetscFClose(PETSC_COMM_SELF, fp));
  PetscCall(PetscFree2(start, count));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepWrite(MPI_Comm comm, const RollerSweepPlan *plan, const RollerSweepRows *rows)
{
  PetscInt    n = 0, missing = 0;
  PetscReal  *all;
  PetscMPIInt rank;
  char        part[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  PetscCall(RollerJoinPath(part, sizeof(part), plan->csv, ".part", "-sweep"));
  PetscCall(Gather(comm, rows, &n, &all));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) PetscCall(WriteRows(plan, n, all, part, &missing));
  PetscCall(PetscFree(all));
  PetscCallMPI(MPI_Bcast(&missing, 1, MPIU_INT, 0, comm));
  PetscCheck(!missing, comm, PETSC_ERR_PLIB, "-sweep %s: %" PetscInt_FMT " cases found no eigenvalue (left in %s)", plan->csv, missing, part);
  PetscCall(RollerRenameFile(comm, part, plan->csv));
  PetscFunctionReturn(0);
}
