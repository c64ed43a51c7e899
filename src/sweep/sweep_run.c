/* -sweep F.csv (docs/squeal.md section 6): a map in one run. MPI_COMM_WORLD is split into -sweep_subcomms
   sub-communicators and the j-th case of the run goes to sub-communicator j % k, which solves it as a separate run
   would: the case's values are set in this process's options database, a Roller is created on the sub-communicator,
   set from the options, set up and solved. With -modes its eigenvalues (ctx->eig) are the case's rows; without,
   the transient's series, recorded by an observer of the run, is reduced to one row (sweep_transient.c). Whatever
   the scene, the case is the scene of the other options on the command line, so the sweep needs no change when the
   solvers learn a new one. Each finished case goes to its sub-communicator's journal at once (sweep_journal.c), so
   that a killed map, run again with the same command, skips what it had done; at the end the rows of all cases are
   gathered to rank 0 and written as one CSV (sweep_csv.c). */
#include "sweep/sweep.h"
#include "integrate/integrate.h"
#include "io/io.h"

/* The outputs of a single run, which would collide between the cases: the sweep's CSV has the results. A transient
   case's checkpoint (written only if a step fails or a signal stops it) gets the case's own name instead. */
static const char *const CaseOutputs[] = {"-modes_csv", "-modes_output", "-monitor_csv", "-output", "-checkpoint", "-checkpoint_every", "-restart"};
#define NOUTPUTS ((PetscInt)(sizeof(CaseOutputs) / sizeof(CaseOutputs[0])))

/* An option of this process's database set (to value, NULL for a flag) or removed (set false) for the cases, and
   put back after. */
typedef struct {
  char      name[64], value[PETSC_MAX_PATH_LEN];
  PetscBool had;
} SavedOption;

static PetscErrorCode OptionPush(const char name[], PetscBool set, const char value[], SavedOption *s)
{
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(s->name, name, sizeof(s->name)));
  PetscCall(PetscOptionsGetString(NULL, NULL, name, s->value, sizeof(s->value), &s->had));
  if (set) PetscCall(PetscOptionsSetValue(NULL, name, value));
  else PetscCall(PetscOptionsClearValue(NULL, name));
  PetscFunctionReturn(0);
}

static PetscErrorCode OptionPop(const SavedOption *s)
{
  PetscFunctionBeginUser;
  if (s->had) PetscCall(PetscOptionsSetValue(NULL, s->name, s->value[0] ? s->value : NULL));
  else PetscCall(PetscOptionsClearValue(NULL, s->name));
  PetscFunctionReturn(0);
}

/* What a case reports on its progress line and whether a signal stopped it */
typedef struct {
  PetscInt  n;      /* eigenvalues (-modes) or states (transient) */
  PetscReal growth; /* the largest Re(lambda), or the fitted growth rate */
  PetscBool failed, stopped;
} CaseOutcome;

/* Case c's own monitor CSV (-sweep_monitor_csv F.csv): F.case<c>.csv (the case number before a .csv ending, else
   after the name). */
static PetscErrorCode CaseSeriesPath(const RollerSweepPlan *plan, PetscInt c, char path[], size_t len)
{
  char   stem[PETSC_MAX_PATH_LEN], suffix[48];
  size_t n;

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(stem, plan->series, sizeof(stem)));
  PetscCall(PetscStrlen(stem, &n));
  if (n > 4 && !strcmp(stem + n - 4, ".csv")) stem[n - 4] = '\0';
  PetscCall(PetscSNPrintf(suffix, sizeof(suffix), ".case%" PetscInt_FMT ".csv", c));
  PetscCall(RollerJoinPath(path, len, stem, suffix, "-sweep_monitor_csv"));
  PetscFunctionReturn(0);
}

/* A transient case: the run with an observer recording its series. The set-up's errors (a value out of range, a
   rotation beyond the stability limit) end the map like any bad input; an error of the run itself (a step or the
   contact solver failing) is the case's status, "failed", and the map goes on. A signal (SIGTERM before a batch
   system's time limit) stops the case unfinished: it is not recorded, and the map stops taking cases. */
static PetscErrorCode SolveTransient(Roller roller, const RollerSweepPlan *plan, PetscLogDouble t0, char row[], size_t len, CaseOutcome *out)
{
  RollerSweepSeries series = {0};
  PetscErrorCode    ierr;
  PetscInt          sig;
  char              wall[32];

  PetscFunctionBeginUser;
  series.column = plan->fit;
  PetscCall(RollerSweepSeriesObserve(roller, &series));
  ierr = RollerSolve(roller);
  if (ierr) PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDERR, "sweep: the run failed (error %d above); its row says status failed and the map goes on\n", (int)ierr));
  PetscCall(RollerSignalCaught(roller, &sig));
  out->failed  = (PetscBool)(ierr != 0);
  out->stopped = (PetscBool)(sig != 0 && !ierr);
  PetscCall(RollerSweepTransientRow(plan, &series, out->failed, row, len, &out->growth));
  PetscCall(PetscSNPrintf(wall, sizeof(wall), ",%.3f,%s\n", MPI_Wtime() - t0, out->failed ? "failed" : "ok"));
  PetscCall(PetscStrlcat(row, wall, len));
  out->n = series.n;
  PetscCall(RollerSweepSeriesDestroy(&series));
  PetscFunctionReturn(0);
}

/* One case on the sub-communicator: exactly a `roller [-modes]` run with the case's values on the command line; its
   rows go to the sub-communicator's root (rows) and journal. */
static PetscErrorCode SolveCase(MPI_Comm sub, const RollerSweepPlan *plan, PetscInt c, RollerSweepRows *rows, RollerSweepJournal journal, CaseOutcome *out)
{
  PetscReal      v[ROLLER_SWEEP_MAX_PARAMS];
  SavedOption    saved[ROLLER_SWEEP_MAX_PARAMS + 2];
  PetscInt       nsaved = 0;
  char           ck[PETSC_MAX_PATH_LEN];
  Roller         roller;
  PetscMPIInt    rank;
  PetscLogDouble t0 = MPI_Wtime();
  size_t         before;

  PetscFunctionBeginUser;
  PetscCall(RollerSweepCaseValues(plan, c, v));
  for (PetscInt q = 0; q < plan->nparams; ++q) {
    char opt[64], value[32];

    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s", plan->name[q]));
    PetscCall(RollerSweepFormatReal(value, sizeof(value), v[q]));
    PetscCall(OptionPush(opt, PETSC_TRUE, value, &saved[nsaved++]));
  }
  if (plan->transient) {
    char suffix[32];

    PetscCall(PetscSNPrintf(suffix, sizeof(suffix), ".case%" PetscInt_FMT ".h5", c));
    PetscCall(RollerJoinPath(ck, sizeof(ck), plan->csv, suffix, "-sweep"));
    PetscCall(OptionPush("-checkpoint", PETSC_TRUE, ck, &saved[nsaved++]));
  }
  if (plan->series[0]) {
    char series[PETSC_MAX_PATH_LEN];

    PetscCall(CaseSeriesPath(plan, c, series, sizeof(series)));
    PetscCall(OptionPush("-monitor_csv", PETSC_TRUE, series, &saved[nsaved++]));
  }
  PetscCall(RollerCreate(sub, &roller));
  PetscCall(RollerSetFromOptions(roller));
  PetscCall(RollerSetUp(roller));
  if (plan->table) PetscCall(RollerSweepCasesCheckUsed(sub, plan, plan->cases_file));
  PetscCallMPI(MPI_Comm_rank(sub, &rank));
  before = rows->len;
  PetscCall(PetscMemzero(out, sizeof(*out)));
  if (plan->transient) {
    char row[1024], params[ROLLER_SWEEP_MAX_PARAMS * 32], line[1600];

    PetscCall(SolveTransient(roller, plan, t0, row, sizeof(row), out));
    PetscCall(RollerSweepCaseParams(plan, c, params, sizeof(params)));
    PetscCall(PetscSNPrintf(line, sizeof(line), "%" PetscInt_FMT "%s%s", c, params, row));
    if (!rank && !out->stopped) PetscCall(RollerSweepRowsAdd(rows, line));
  } else {
    PetscCall(RollerSolve(roller));
    if (!rank) PetscCall(RollerSweepRowsAddModes(rows, plan, c, &roller->eig));
    out->n      = roller->eig.n;
    out->growth = PETSC_MIN_REAL;
    for (PetscInt j = 0; j < roller->eig.n; ++j) out->growth = PetscMax(out->growth, roller->eig.re[j]);
  }
  if (journal && rows->len > before) PetscCall(RollerSweepJournalAdd(journal, c, rows->text + before, rows->len - before));
  PetscCall(RollerDestroy(&roller));
  if (out->stopped) PetscCall(RollerRemoveStale(sub, ck)); /* the map reruns the case whole: its checkpoint is of no use */
  while (nsaved) PetscCall(OptionPop(&saved[--nsaved]));
  PetscFunctionReturn(0);
}

static PetscErrorCode CaseLabel(const RollerSweepPlan *plan, PetscInt c, char buf[], size_t len)
{
  PetscReal v[ROLLER_SWEEP_MAX_PARAMS];
  char      item[96], value[32];

  PetscFunctionBeginUser;
  PetscCall(RollerSweepCaseValues(plan, c, v));
  buf[0] = '\0';
  for (PetscInt q = 0; q < plan->nparams; ++q) {
    PetscCall(RollerSweepFormatReal(value, sizeof(value), v[q]));
    PetscCall(PetscSNPrintf(item, sizeof(item), "%s%s %s", q ? ", " : "", plan->name[q], value));
    PetscCall(PetscStrlcat(buf, item, len));
  }
  PetscFunctionReturn(0);
}

/* This sub-communicator's cases: the j-th case of the run's slice if j % k is its colour, unless done (an earlier,
   killed run journaled it). A case whose set-up fails names itself before the error goes up (Open MPI then ends the
   other ranks). A signal stops the loop (*stopped). */
static PetscErrorCode SolveCases(MPI_Comm sub, PetscMPIInt color, const RollerSweepPlan *plan, const PetscBool done[], RollerSweepRows *rows, RollerSweepJournal journal, PetscBool *stopped)
{
  PetscFunctionBeginUser;
  *stopped = PETSC_FALSE;
  for (PetscInt c = plan->slice[0], j = 0; c < plan->ncases && !*stopped; c += plan->slice[1]) {
    char           label[512];
    CaseOutcome    out = {0};
    PetscLogDouble t0  = MPI_Wtime();
    PetscErrorCode ierr;

    if (done[c]) continue;
    if (j++ % plan->nsub != color) continue;
    PetscCall(CaseLabel(plan, c, label, sizeof(label)));
    ierr = SolveCase(sub, plan, c, rows, journal, &out);
    if (ierr) PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDERR, "sweep: case %" PetscInt_FMT "/%" PetscInt_FMT " (%s) on subcomm %d failed\n", c, plan->ncases, label, color));
    PetscCall(ierr);
    *stopped = out.stopped;
    if (!plan->quiet && out.stopped) PetscCall(PetscPrintf(sub, "sweep: case %" PetscInt_FMT "/%" PetscInt_FMT " (%s) on subcomm %d stopped by a signal: not recorded\n", c, plan->ncases, label, color));
    else if (!plan->quiet && plan->transient)
      PetscCall(PetscPrintf(sub, "sweep: case %" PetscInt_FMT "/%" PetscInt_FMT " (%s) on subcomm %d: %" PetscInt_FMT " states, growth rate %.3g, %s, %.2f s\n", c, plan->ncases, label, color, out.n, (double)out.growth, out.failed ? "failed" : "ok", MPI_Wtime() - t0));
    else if (!plan->quiet)
      PetscCall(PetscPrintf(sub, "sweep: case %" PetscInt_FMT "/%" PetscInt_FMT " (%s) on subcomm %d: %" PetscInt_FMT " eigenvalues, max growth %.3g, %.2f s\n", c, plan->ncases, label, color, out.n, (double)out.growth, MPI_Wtime() - t0));
  }
  PetscFunctionReturn(0);
}

/* A sub-communicator done with its cases waits for the others without spinning (a blocking collective of Open MPI
   polls at full speed): the cores go to the cases still running, and the map's CPU time is its cases'. */
static PetscErrorCode WaitIdle(MPI_Comm comm)
{
  MPI_Request req;
  int         done = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Ibarrier(comm, &req));
  PetscCallMPI(MPI_Test(&req, &done, MPI_STATUS_IGNORE));
  while (!done) {
    PetscCall(PetscSleep(0.01));
    PetscCallMPI(MPI_Test(&req, &done, MPI_STATUS_IGNORE));
  }
  PetscFunctionReturn(0);
}

/* The options' use as rank 0's: a rank whose sub-communicator solved no case (fewer cases than sub-communicators) used
   none of the scene's options, and main's check (RollerOptionsCheck) would refuse them there alone: the map written,
   that rank's exit an error. Every option rank 0 used (not in its list of those left) is marked used on every rank, so
   that each rank's list of unused options is at most rank 0's. */
static PetscErrorCode ShareOptionsUse(MPI_Comm comm)
{
  PetscMPIInt rank;
  PetscInt    n, len = 0;
  char      **names, **values, *left = NULL;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  if (!rank) {
    for (PetscInt i = 0; i < n; ++i) {
      size_t l;

      PetscCall(PetscStrlen(names[i], &l));
      len += (PetscInt)l + 2;
    }
  }
  PetscCallMPI(MPI_Bcast(&len, 1, MPIU_INT, 0, comm));
  PetscCall(PetscCalloc1(len + 2, &left));
  if (!rank) { /* " name1 name2 ... ": each name between blanks */
    left[0] = ' ';
    for (PetscInt i = 0; i < n; ++i) {
      PetscCall(PetscStrlcat(left, names[i], len + 2));
      PetscCall(PetscStrlcat(left, " ", len + 2));
    }
  }
  PetscCallMPI(MPI_Bcast(left, (PetscMPIInt)(len + 2), MPI_CHAR, 0, comm));
  for (PetscInt i = 0; rank && i < n; ++i) {
    char      item[256], option[256];
    char     *found;
    PetscBool has;

    PetscCall(PetscSNPrintf(item, sizeof(item), " %s ", names[i]));
    PetscCall(PetscStrstr(left, item, &found));
    if (found) continue; /* unused on rank 0 too: the check names it */
    PetscCall(PetscSNPrintf(option, sizeof(option), "-%s", names[i]));
    PetscCall(PetscOptionsHasName(NULL, NULL, option, &has)); /* a query marks it used */
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscCall(PetscFree(left));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweep(MPI_Comm comm)
{
  RollerSweepPlan    plan;
  RollerSweepRows    rows = {0, 0, NULL}, resumed = {0, 0, NULL};
  RollerSweepJournal journal = NULL;
  PetscSubcomm       psub;
  SavedOption        saved[NOUTPUTS + 1];
  PetscBool         *done, stopped, any_stopped, complete;
  PetscLogDouble     t0    = MPI_Wtime();
  PetscInt           ndone = 0, nrun;
  char               part[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  PetscCall(RollerSweepSetFromOptions(comm, &plan));
  PetscCheck(plan.csv[0], comm, PETSC_ERR_ARG_WRONG, "-sweep needs the name of its CSV, -sweep F.csv");
  PetscCheck(plan.nparams, comm, PETSC_ERR_ARG_WRONG, "-sweep %s: nothing to sweep; give -sweep_cases F.csv (a table of cases), or -sweep_<name> v1,v2,... or -sweep_<name>_range a,b,n for <name> one of omega, young, friction, obstacle_depth, sheet_speed",
             plan.csv);
  PetscCall(RollerJoinPath(part, sizeof(part), plan.csv, ".part", "-sweep"));
  PetscCall(RollerRemoveStale(comm, plan.csv));
  PetscCall(RollerCheckWritable(comm, "-sweep", part)); /* before hours of cases, not after */
  PetscCall(RollerSweepResume(comm, &plan, &resumed, &done));
  for (PetscInt c = plan.slice[0]; c < plan.ncases; c += plan.slice[1]) ndone += done[c];
  nrun = (plan.ncases - plan.slice[0] + plan.slice[1] - 1) / plan.slice[1];
  if (ndone && !plan.quiet) PetscCall(PetscPrintf(comm, "sweep: %" PetscInt_FMT " of the %" PetscInt_FMT " cases done by an earlier run of this map (its journals %s.journal.*): skipped\n", ndone, nrun, plan.csv));

  PetscCall(PetscSubcommCreate(comm, &psub));
  PetscCall(PetscSubcommSetNumber(psub, plan.nsub));
  PetscCall(PetscSubcommSetType(psub, PETSC_SUBCOMM_CONTIGUOUS));
  for (PetscInt i = 0; i < NOUTPUTS; ++i) {
    PetscCall(OptionPush(CaseOutputs[i], PETSC_FALSE, NULL, &saved[i]));
    if (saved[i].had) PetscCall(PetscPrintf(comm, "sweep: %s %s is not written by the cases (the sweep's CSV %s has the results)\n", CaseOutputs[i], saved[i].value, plan.csv));
  }
  PetscCall(OptionPush("-quiet", PETSC_TRUE, NULL, &saved[NOUTPUTS])); /* the progress lines instead of each case's table */
  PetscCall(RollerSweepJournalOpen(comm, PetscSubcommChild(psub), &plan, &journal));
  PetscCall(SolveCases(PetscSubcommChild(psub), psub->color, &plan, done, &rows, journal, &stopped));
  PetscCall(RollerSweepJournalClose(&journal));
  for (PetscInt i = NOUTPUTS; i >= 0; --i) PetscCall(OptionPop(&saved[i]));

  PetscCall(WaitIdle(comm));
  PetscCall(MPIU_Allreduce(&stopped, &any_stopped, 1, MPIU_BOOL, MPI_LOR, comm));
  PetscCall(RollerSweepWrite(comm, &plan, &resumed, &rows, &complete));
  PetscCheck(complete || any_stopped, comm, PETSC_ERR_PLIB, "-sweep %s: cases without a row (left in %s)", plan.csv, part);
  if (complete) PetscCall(RollerSweepJournalsRemove(comm, &plan));
  else PetscCall(RollerRemoveStale(comm, part)); /* the journals have what was done */
  if (!complete) PetscCall(PetscPrintf(comm, "sweep: stopped by a signal; the finished cases are in the journals %s.journal.*: the same command continues the map\n", plan.csv));
  if (!plan.quiet && complete)
    PetscCall(
      PetscPrintf(comm, "sweep: %" PetscInt_FMT " cases (slice %" PetscInt_FMT ",%" PetscInt_FMT "; %" PetscInt_FMT " from the journals) on %" PetscInt_FMT " subcomms -> %s, %.2f s\n", nrun, plan.slice[0], plan.slice[1], ndone, plan.nsub, plan.csv, MPI_Wtime() - t0));
  PetscCall(ShareOptionsUse(comm));
  PetscCall(PetscFree(done));
  PetscCall(PetscSubcommDestroy(&psub));
  PetscCall(RollerSweepRowsDestroy(&rows));
  PetscCall(RollerSweepRowsDestroy(&resumed));
  PetscCall(RollerSweepPlanDestroy(&plan));
  PetscFunctionReturn(0);
}
