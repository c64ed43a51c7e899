/* The monitor CSV (docs/model.md section 6.1): one row per step, %.17g so that it round-trips; written as
   F.part and renamed at the successful end; a restart continues the rows of the run it restarts. Rank 0
   writes. -monitor_csv F makes the driver call it (integrate/observers.c). */
#include "output.h"

struct _n_RollerCsv {
  MPI_Comm  comm;
  char      path[PETSC_MAX_PATH_LEN], part[PETSC_MAX_PATH_LEN], old[PETSC_MAX_PATH_LEN];
  FILE     *fp;   /* rank 0 only */
  PetscBool open; /* until RollerCsvClose */
};

/* A restart continues the CSV of the run it restarts: the rows up to its step are copied from the
   earlier file (complete, or .part if that run was killed) into the new .part, so that an interrupted and
   restarted run ends with the same rows as an uninterrupted one. Rank 0 reads and writes. */
static PetscErrorCode CsvResume(RollerCsv csv, PetscInt step)
{
  PetscMPIInt rank;
  char        line[4096];
  FILE       *src;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(csv->comm, &rank));
  if (rank) PetscFunctionReturn(0);
  src = fopen(csv->old, "r");
  if (!src) {
    PetscCall(PetscInfo(NULL, "-restart: no earlier %s to continue; the CSV starts after step %" PetscInt_FMT "\n", csv->path, step));
    PetscFunctionReturn(0);
  }
  PetscCheck(fgets(line, sizeof(line), src), PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "-monitor_csv %s: empty file, cannot continue it after -restart", csv->path);
  while (fgets(line, sizeof(line), src)) {
    if (atol(line) > (long)step) break;
    PetscCheck(fputs(line, csv->fp) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", csv->part, strerror(errno));
  }
  fclose(src);
  PetscCheck(remove(csv->old) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot remove %s: %s", csv->old, strerror(errno));
  PetscFunctionReturn(0);
}

/* Before a restart truncates the CSV: keep the earlier run's rows (complete file, or .part if it was killed). */
static PetscErrorCode CsvKeepOld(RollerCsv csv)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(csv->comm, &rank));
  if (rank == 0 && (rename(csv->path, csv->old) == 0 || rename(csv->part, csv->old) == 0)) PetscCall(PetscInfo(NULL, "-restart: continuing %s\n", csv->path));
  PetscCallMPI(MPI_Barrier(csv->comm));
  PetscFunctionReturn(0);
}

/* -monitor_csv path: path.part opened with the header; a restart from step resume (>= 0) first copies the earlier
   run's rows up to that step (resume < 0: a new run). */
PetscErrorCode RollerCsvOpen(MPI_Comm comm, const char path[], PetscInt resume, RollerCsv *csv_out)
{
  RollerCsv csv;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&csv));
  *csv_out  = csv;
  csv->comm = comm;
  PetscCall(PetscStrncpy(csv->path, path, sizeof(csv->path)));
  PetscCall(RollerJoinPath(csv->part, sizeof(csv->part), path, ".part", "-monitor_csv"));
  PetscCall(RollerJoinPath(csv->old, sizeof(csv->old), path, ".old", "-monitor_csv"));
  if (resume >= 0) PetscCall(CsvKeepOld(csv));
  PetscCall(RollerRemoveStale(comm, csv->path));
  PetscCall(PetscFOpen(comm, csv->part, "w", &csv->fp));
  csv->open = PETSC_TRUE;
  PetscCall(PetscFPrintf(comm, csv->fp, "step,t,R,alpha,energy,contact_nodes,contact_force,gap_min,qp_iterations,kkt_residual,theta,load_work,obstacle_work,contact_dissipation,damping_dissipation,viscous_dissipation,contact_flips,contact_reversals,friction_force,shaft_torque,stick_nodes,slip_nodes,friction_work,shaft_work,sheet_work,friction_residual,coulomb_iterations,coulomb_fallback,axle_y,hub_rate,drive_torque,sheet_speed\n"));
  if (resume >= 0) PetscCall(CsvResume(csv, resume));
  PetscFunctionReturn(0);
}

/* The row of one step, formatted whole and written by one fwrite and flushed: a killed run keeps every row it
   printed, and a reader of F.part never meets half a row (tests/hard_crash.py). */
PetscErrorCode RollerCsvRow(RollerCsv csv, PetscInt step, PetscReal t, const RollerStepInfo *info, PetscReal theta)
{
  char row[2048];
  int  n, m;

  PetscFunctionBeginUser;
  PetscCheck(csv->open, csv->comm, PETSC_ERR_ARG_WRONGSTATE, "-monitor_csv %s: a row after the file was closed", csv->path);
  if (!csv->fp) PetscFunctionReturn(0); /* rank 0 writes */
  n = snprintf(row, sizeof(row), "%" PetscInt_FMT ",%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%.17g,%.17g,%" PetscInt_FMT ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%" PetscInt_FMT ",", step, (double)t, (double)info->R,
               (double)info->alpha, (double)info->energy, info->contact_nodes, (double)info->contact_force, (double)info->gap_min, info->qp_iterations, (double)info->kkt_residual, (double)theta, (double)info->load_work, (double)info->obstacle_work,
               (double)info->contact_dissipation, (double)info->damping_dissipation, (double)info->viscous_dissipation, info->contact_flips, info->contact_reversals);
  PetscCheck(n > 0 && n < (int)sizeof(row), PETSC_COMM_SELF, PETSC_ERR_PLIB, "CSV row too long");
  m = snprintf(row + n, sizeof(row) - n, "%.17g,%.17g,%" PetscInt_FMT ",%" PetscInt_FMT ",%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%" PetscInt_FMT ",%.17g,%.17g,%.17g,%.17g\n", (double)info->friction.force, (double)info->friction.torque,
               info->friction.stick, info->friction.slip, (double)info->friction.work, (double)info->friction.shaft_work, (double)info->friction.sheet_work, (double)info->friction.residual, info->friction.iterations, info->friction.fallback,
               (double)info->axle.y, (double)info->axle.hub_rate, (double)info->axle.drive_torque, (double)info->axle.sheet_speed);
  PetscCheck(m > 0 && n + m < (int)sizeof(row), PETSC_COMM_SELF, PETSC_ERR_PLIB, "CSV row too long");
  PetscCheck(fflush(csv->fp) == 0 && fwrite(row, 1, (size_t)(n + m), csv->fp) == (size_t)(n + m) && fflush(csv->fp) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", csv->part, strerror(errno));
  PetscFunctionReturn(0);
}

/* The successful end: F.part becomes F. */
PetscErrorCode RollerCsvClose(RollerCsv csv)
{
  PetscFunctionBeginUser;
  if (!csv->open) PetscFunctionReturn(0);
  PetscCall(PetscFClose(csv->comm, csv->fp));
  csv->fp   = NULL;
  csv->open = PETSC_FALSE;
  PetscCall(RollerRenameFile(csv->comm, csv->part, csv->path));
  PetscFunctionReturn(0);
}

/* Frees the writer; a file not closed by RollerCsvClose (a run that did not end) stays F.part. */
PetscErrorCode RollerCsvDestroy(RollerCsv *csv)
{
  PetscFunctionBeginUser;
  if (!*csv) PetscFunctionReturn(0);
  if ((*csv)->open) PetscCall(PetscFClose((*csv)->comm, (*csv)->fp));
  PetscCall(PetscFree(*csv));
  PetscFunctionReturn(0);
}
