/* The monitor CSV (docs/model.md section 6.1): one row per step, %.17g so that it round-trips; written as
   F.part and renamed at the end; a restart continues the rows of the run it restarts. Rank 0 writes. */
#include "output.h"

/* A restart continues the CSV of the run it restarts: the rows up to its step are copied from the
   earlier file (complete, or .part if that run was killed) into the new .part, so that an interrupted and
   restarted run ends with the same rows as an uninterrupted one. Rank 0 reads and writes. */
static PetscErrorCode CsvResume(Roller ctx, RollerOutput out)
{
  PetscMPIInt rank;
  char        line[4096];
  FILE       *src;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  if (rank) PetscFunctionReturn(0);
  src = fopen(out->csv_old, "r");
  if (!src) {
    PetscCall(PetscInfo(NULL, "-restart: no earlier %s to continue; the CSV starts after step %" PetscInt_FMT "\n", out->csv_path, ctx->state.step));
    PetscFunctionReturn(0);
  }
  PetscCheck(fgets(line, sizeof(line), src), PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "-monitor_csv %s: empty file, cannot continue it after -restart", out->csv_path);
  while (fgets(line, sizeof(line), src)) {
    if (atol(line) > (long)ctx->state.step) break;
    PetscCheck(fputs(line, out->csv) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", out->csv_part, strerror(errno));
  }
  fclose(src);
  PetscCheck(remove(out->csv_old) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot remove %s: %s", out->csv_old, strerror(errno));
  PetscFunctionReturn(0);
}

/* Before a restart truncates the CSV: keep the earlier run's rows (complete file, or .part if it was killed). */
static PetscErrorCode CsvKeepOld(MPI_Comm comm, RollerOutput out)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0 && (rename(out->csv_path, out->csv_old) == 0 || rename(out->csv_part, out->csv_old) == 0)) PetscCall(PetscInfo(NULL, "-restart: continuing %s\n", out->csv_path));
  PetscCallMPI(MPI_Barrier(comm));
  PetscFunctionReturn(0);
}

/* -monitor_csv F: F.part opened with the header (after keeping the rows a restart continues). */
PetscErrorCode RollerCsvOpen(Roller ctx, RollerOutput out)
{
  PetscFunctionBeginUser;
  PetscCall(RollerJoinPath(out->csv_part, sizeof(out->csv_part), out->csv_path, ".part", "-monitor_csv"));
  PetscCall(RollerJoinPath(out->csv_old, sizeof(out->csv_old), out->csv_path, ".old", "-monitor_csv"));
  if (ctx->ck.restart[0]) PetscCall(CsvKeepOld(ctx->comm, out));
  PetscCall(RollerRemoveStale(ctx->comm, out->csv_path));
  PetscCall(PetscFOpen(ctx->comm, out->csv_part, "w", &out->csv));
  PetscCall(PetscFPrintf(ctx->comm, out->csv, "step,t,R,alpha,energy,contact_nodes,contact_force,gap_min,qp_iterations,kkt_residual,theta\n"));
  if (ctx->ck.restart[0]) PetscCall(CsvResume(ctx, out));
  PetscFunctionReturn(0);
}

/* The row of the current step, flushed: a killed run keeps every row it printed. */
PetscErrorCode RollerCsvRow(Roller ctx, RollerOutput out)
{
  const RollerStepInfo *info = &ctx->info;
  PetscReal             theta;

  PetscFunctionBeginUser;
  RollerTheta(ctx, ctx->state.time, &theta, NULL, NULL);
  PetscCall(PetscFPrintf(ctx->comm, out->csv, "%" PetscInt_FMT ",%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%.17g,%.17g,%" PetscInt_FMT ",%.17g,%.17g\n", ctx->state.step, (double)ctx->state.time, (double)info->R, (double)info->alpha, (double)info->energy,
                         info->contact_nodes, (double)info->contact_force, (double)info->gap_min, info->qp_iterations, (double)info->kkt_residual, (double)theta));
  if (out->csv) PetscCheck(fflush(out->csv) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", out->csv_part, strerror(errno));
  PetscFunctionReturn(0);
}

/* The successful end: F.part becomes F. */
PetscErrorCode RollerCsvClose(Roller ctx, RollerOutput out)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFClose(ctx->comm, out->csv));
  PetscCall(RollerRenameFile(ctx->comm, out->csv_part, out->csv_path));
  PetscFunctionReturn(0);
}
