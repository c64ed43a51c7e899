/* The sweep's result: the rows of every case -- formatted by the root of the sub-communicator that solved it,
   complete CSV lines -- gathered to rank 0 of the sweep's communicator with those an earlier, killed run of the map
   journaled (sweep_journal.c), and written as one CSV sorted by case:
     -modes:    case,<swept options>,re,im,frequency,growth_rate,order,wave,error   (a row per eigenvalue, in the
                order of -modes_csv: by frequency)
     transient: case,<swept options>,window_start,window_end,contact_force,friction_force,stick_fraction,amplitude,
                growth_rate,frequency,wall_time,status                               (a row per case)
   written as F.part and renamed when complete, like every output (io/output_files.c). */
#include "sweep/sweep.h"
#include "io/io.h"
#include "modes/modes.h"

PetscErrorCode RollerSweepHeader(const RollerSweepPlan *plan, char buf[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(buf, "case", len));
  for (PetscInt q = 0; q < plan->nparams; ++q) {
    PetscCall(PetscStrlcat(buf, ",", len));
    PetscCall(PetscStrlcat(buf, plan->name[q], len));
  }
  PetscCall(PetscStrlcat(buf, plan->transient ? ",window_start,window_end,contact_force,friction_force,stick_fraction,amplitude,growth_rate,frequency,wall_time,status\n" : ",re,im,frequency,growth_rate,order,wave,error\n", len));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepRowsAdd(RollerSweepRows *rows, const char line[])
{
  size_t n;

  PetscFunctionBeginUser;
  PetscCall(PetscStrlen(line, &n));
  if (rows->len + n + 1 > rows->max) {
    rows->max = PetscMax(2 * rows->max, rows->len + n + 4096);
    PetscCall(PetscRealloc(rows->max, &rows->text));
  }
  PetscCall(PetscMemcpy(rows->text + rows->len, line, n + 1));
  rows->len += n;
  PetscFunctionReturn(0);
}

/* A modes case: a row per eigenvalue, frequency = im and growth_rate = re repeated for the reader */
PetscErrorCode RollerSweepRowsAddModes(RollerSweepRows *rows, const RollerSweepPlan *plan, PetscInt c, const RollerEigen *e)
{
  char params[ROLLER_SWEEP_MAX_PARAMS * 32], line[ROLLER_SWEEP_MAX_PARAMS * 32 + 256];

  PetscFunctionBeginUser;
  PetscCall(RollerSweepCaseParams(plan, c, params, sizeof(params)));
  for (PetscInt j = 0; j < e->n; ++j) {
    PetscCall(
      PetscSNPrintf(line, sizeof(line), "%" PetscInt_FMT "%s,%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%s,%.3e\n", c, params, (double)e->re[j], (double)e->im[j], (double)e->im[j], (double)e->re[j], e->order[j], RollerWaves[e->wave[j]], (double)e->error[j]));
    PetscCall(RollerSweepRowsAdd(rows, line));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepRowsDestroy(RollerSweepRows *rows)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(rows->text));
  rows->len = rows->max = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepRowsCase(const char *line, PetscInt *c)
{
  char *end;
  long  v = strtol(line, &end, 10);

  PetscFunctionBeginUser;
  *c = (end != line && *end == ',' && v >= 0) ? (PetscInt)v : -1;
  PetscFunctionReturn(0);
}

/* Every process's rows to rank 0 (the ranks that are not the root of their sub-communicator hold none) */
static PetscErrorCode Gather(MPI_Comm comm, const RollerSweepRows *rows, char **all, size_t *len)
{
  PetscMPIInt rank, size, count, *counts = NULL, *displs = NULL;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMPIIntCast((PetscInt)rows->len, &count));
  if (!rank) PetscCall(PetscMalloc2(size, &counts, size + 1, &displs));
  PetscCallMPI(MPI_Gather(&count, 1, MPI_INT, counts, 1, MPI_INT, 0, comm));
  *all = NULL;
  *len = 0;
  if (!rank) {
    displs[0] = 0;
    for (PetscMPIInt r = 0; r < size; ++r) PetscCall(PetscMPIIntCast((PetscInt)displs[r] + counts[r], &displs[r + 1]));
    *len = (size_t)displs[size];
    PetscCall(PetscMalloc1(*len + 1, all));
    (*all)[*len] = '\0';
  }
  PetscCallMPI(MPI_Gatherv(rows->text, count, MPI_CHAR, *all, counts, displs, MPI_CHAR, 0, comm));
  PetscCall(PetscFree2(counts, displs));
  PetscFunctionReturn(0);
}

/* Where each case's lines start in text (contiguous: one process added them together, and the journals' reader
   keeps one copy of each case) and how many bytes */
static PetscErrorCode IndexCases(const RollerSweepPlan *plan, const char *text, size_t len, size_t start[], size_t bytes[])
{
  PetscInt last = -1;

  PetscFunctionBeginUser;
  for (size_t i = 0; i < len;) {
    const char *eol = strchr(text + i, '\n');
    size_t      n   = eol ? (size_t)(eol - (text + i)) + 1 : len - i;
    PetscInt    c;

    PetscCall(RollerSweepRowsCase(text + i, &c));
    PetscCheck(c >= 0 && c < plan->ncases, PETSC_COMM_SELF, PETSC_ERR_PLIB, "-sweep %s: a row of no case of the map: %.60s", plan->csv, text + i);
    PetscCheck(!bytes[c] || (c == last && start[c] + bytes[c] == i), PETSC_COMM_SELF, PETSC_ERR_PLIB, "-sweep %s: the rows of case %" PetscInt_FMT " are not together", plan->csv, c);
    if (!bytes[c]) start[c] = i;
    bytes[c] += n;
    last = c;
    i += n;
  }
  PetscFunctionReturn(0);
}

/* Rank 0: the slice's cases in order, each from this run's rows or the journals'. Returns the cases without a
   row. */
static PetscErrorCode WriteRows(const RollerSweepPlan *plan, const char *old, size_t old_len, const char *now, size_t now_len, const char part[], PetscInt *missing)
{
  size_t *start[2], *bytes[2];
  FILE   *fp;
  char    header[ROLLER_SWEEP_MAX_PARAMS * 32 + 256];

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc4(plan->ncases, &start[0], plan->ncases, &bytes[0], plan->ncases, &start[1], plan->ncases, &bytes[1]));
  PetscCall(IndexCases(plan, old, old_len, start[0], bytes[0]));
  PetscCall(IndexCases(plan, now, now_len, start[1], bytes[1]));
  PetscCall(RollerSweepHeader(plan, header, sizeof(header)));
  PetscCall(PetscFOpen(PETSC_COMM_SELF, part, "w", &fp));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "%s", header));
  *missing = 0;
  for (PetscInt c = plan->slice[0]; c < plan->ncases; c += plan->slice[1]) {
    const PetscInt k = bytes[1][c] ? 1 : 0;

    if (!bytes[k][c]) ++*missing;
    else PetscCheck(fwrite((k ? now : old) + start[k][c], 1, bytes[k][c], fp) == bytes[k][c], PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-sweep: cannot write %s", part);
  }
  PetscCall(PetscFClose(PETSC_COMM_SELF, fp));
  PetscCall(PetscFree4(start[0], bytes[0], start[1], bytes[1]));
  PetscFunctionReturn(0);
}

/* The map's CSV from the journaled rows (old, rank 0's) and this run's (rows, each sub-communicator root's), renamed
   into place if no case is missing; else (a signal stopped the map) *complete is false and F.part stays. */
PetscErrorCode RollerSweepWrite(MPI_Comm comm, const RollerSweepPlan *plan, const RollerSweepRows *old, const RollerSweepRows *rows, PetscBool *complete)
{
  PetscInt    missing = 0;
  char       *all, part[PETSC_MAX_PATH_LEN];
  size_t      len = 0;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCall(RollerJoinPath(part, sizeof(part), plan->csv, ".part", "-sweep"));
  PetscCall(Gather(comm, rows, &all, &len));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) PetscCall(WriteRows(plan, old->text ? old->text : "", old->len, all ? all : "", len, part, &missing));
  PetscCall(PetscFree(all));
  PetscCallMPI(MPI_Bcast(&missing, 1, MPIU_INT, 0, comm));
  *complete = (PetscBool)!missing;
  if (!missing) PetscCall(RollerRenameFile(comm, part, plan->csv));
  PetscFunctionReturn(0);
}
