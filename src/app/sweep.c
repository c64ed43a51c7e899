/* -sweep F.csv (docs/squeal.md section 6): a stability map in one run. The cases are the Cartesian product of the values
   given to a few scene options (-sweep_omega 0,0.1,0.2 -sweep_young_range 0.05,0.2,4 ...); MPI_COMM_WORLD is split
   into -sweep_subcomms sub-communicators and the j-th case of the run goes to sub-communicator j % k, which solves it
   as a separate `roller -modes` would: the case's values are set in this process's options database, a Roller is
   created on the sub-communicator, set from the options, set up and solved, and its eigenvalues (ctx->eig) are kept.
   Whatever the scene (free annulus, obstacle and friction) the case is the scene of the other options on the command
   line, so the sweep needs no change when -modes learns a new scene. The eigenvalues of all cases are gathered to
   rank 0 and written as one CSV (sweep_csv.c). */
#include "app/sweep.h"
#include "io/io.h"

/* The scene options a sweep may vary: one row each (and nothing else to add for a new one: the case sets the option
   by name, the scene's own options block reads and validates it). */
static const char *const SweepParams[] = {"omega", "young", "friction", "obstacle_depth", "sheet_speed"};
#define NPARAMS ((PetscInt)(sizeof(SweepParams) / sizeof(SweepParams[0])))

/* The outputs of a single run, which would collide between the cases: the sweep's CSV has every eigenvalue. */
static const char *const CaseOutputs[] = {"-modes_csv", "-modes_output", "-monitor_csv", "-output", "-checkpoint"};
#define NOUTPUTS ((PetscInt)(sizeof(CaseOutputs) / sizeof(CaseOutputs[0])))

PetscErrorCode RollerSweepFormatReal(char buf[], size_t len, PetscReal v)
{
  PetscFunctionBeginUser;
  for (int digits = 15; digits <= 17; ++digits) {
    PetscCall(PetscSNPrintf(buf, len, "%.*g", digits, (double)v));
    if (strtod(buf, NULL) == (double)v) break;
  }
  PetscFunctionReturn(0);
}

/* "a,b,c" -> reals; every item must be a finite number (the whole item), else an error naming the option, the value
   and what is allowed. */
static PetscErrorCode ParseReals(MPI_Comm comm, const char opt[], const char str[], const char allowed[], PetscInt *n, PetscReal **v)
{
  char  *copy, *item, *next;
  size_t len;

  PetscFunctionBeginUser;
  PetscCall(PetscStrlen(str, &len));
  PetscCheck(len > 0, comm, PETSC_ERR_ARG_WRONG, "%s needs a value; allowed: %s", opt, allowed);
  PetscCall(PetscStrallocpy(str, &copy));
  PetscCall(PetscMalloc1(len / 2 + 1, v)); /* at most one item per two characters, "a,b" */
  *n = 0;
  for (item = copy; item; item = next) {
    char  *end;
    double x;

    next = strchr(item, ',');
    if (next) *next++ = '\0';
    while (*item == ' ') ++item;
    x = strtod(item, &end);
    while (*end == ' ') ++end;
    PetscCheck(end != item && *end == '\0' && !PetscIsInfOrNanReal((PetscReal)x), comm, PETSC_ERR_ARG_WRONG, "%s %s: \"%s\" is not a finite number; allowed: %s", opt, str, item, allowed);
    (*v)[(*n)++] = (PetscReal)x;
  }
  PetscCall(PetscFree(copy));
  PetscFunctionReturn(0);
}

/* -sweep_<name> v1,v2,... or -sweep_<name>_range a,b,n (n values from a to b); not both. */
static PetscErrorCode ParseParam(MPI_Comm comm, const char name[], const char list[], const char range[], PetscInt *n, PetscReal **v)
{
  char opt[64], allowed[256];

  PetscFunctionBeginUser;
  *n = 0;
  PetscCheck(!(list[0] && range[0]), comm, PETSC_ERR_ARG_INCOMP, "-sweep_%s %s and -sweep_%s_range %s: give one of them", name, list, name, range);
  if (list[0]) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-sweep_%s", name));
    PetscCall(PetscSNPrintf(allowed, sizeof(allowed), "a comma-separated list of reals v1,v2,... (or -sweep_%s_range a,b,n)", name));
    PetscCall(ParseReals(comm, opt, list, allowed, n, v));
  } else if (range[0]) {
    PetscReal *abn;
    PetscInt   three;

    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-sweep_%s_range", name));
    PetscCall(PetscSNPrintf(allowed, sizeof(allowed), "a,b,n: n >= 1 values of -%s linearly spaced from a to b", name));
    PetscCall(ParseReals(comm, opt, range, allowed, &three, &abn));
    PetscCheck(three == 3, comm, PETSC_ERR_ARG_WRONG, "%s %s: %" PetscInt_FMT " values; allowed: %s", opt, range, three, allowed);
    PetscCheck(abn[2] >= 1 && abn[2] <= 1e6 && abn[2] == PetscFloorReal(abn[2]), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s %s: n = %g is not an integer in [1, 1e6]; allowed: %s", opt, range, (double)abn[2], allowed);
    *n = (PetscInt)abn[2];
    PetscCall(PetscMalloc1(*n, v));
    for (PetscInt i = 0; i < *n; ++i) (*v)[i] = *n == 1 ? abn[0] : abn[0] + (abn[1] - abn[0]) * i / (*n - 1);
    if (*n > 1) (*v)[*n - 1] = abn[1]; /* b exactly */
    PetscCall(PetscFree(abn));
  }
  PetscFunctionReturn(0);
}

/* A -sweep_* option that is not one of ours (a misspelt or unsupported parameter) is an error, not a silent
   single-value sweep. */
static PetscErrorCode CheckUnknown(MPI_Comm comm)
{
  char *all, *tok, *save = NULL, names[256] = "";

  PetscFunctionBeginUser;
  for (PetscInt p = 0; p < NPARAMS; ++p) {
    PetscCall(PetscStrlcat(names, p ? ", " : "", sizeof(names)));
    PetscCall(PetscStrlcat(names, SweepParams[p], sizeof(names)));
  }
  PetscCall(PetscOptionsGetAll(NULL, &all));
  for (tok = strtok_r(all, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
    PetscBool known = PETSC_FALSE, match;
    char      opt[64];

    PetscCall(PetscStrbeginswith(tok, "-sweep_", &match));
    if (!match) continue;
    PetscCall(PetscStrcmp(tok, "-sweep_subcomms", &known));
    if (!known) PetscCall(PetscStrcmp(tok, "-sweep_slice", &known));
    for (PetscInt p = 0; p < NPARAMS && !known; ++p) {
      PetscCall(PetscSNPrintf(opt, sizeof(opt), "-sweep_%s", SweepParams[p]));
      PetscCall(PetscStrcmp(tok, opt, &known));
      if (!known) PetscCall(PetscStrlcat(opt, "_range", sizeof(opt)));
      if (!known) PetscCall(PetscStrcmp(tok, opt, &known));
    }
    PetscCheck(known, comm, PETSC_ERR_ARG_WRONG, "%s: not a sweep option; allowed: -sweep_<name> v1,v2,... or -sweep_<name>_range a,b,n for <name> one of %s (the table SweepParams in src/app/sweep.c), -sweep_subcomms k, -sweep_slice i,k", tok, names);
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

/* The "Roller: sweep" options block (also listed by -help without -sweep); the lists are parsed and checked. */
PetscErrorCode RollerSweepSetFromOptions(MPI_Comm comm, RollerSweepPlan *plan)
{
  PetscMPIInt size;
  PetscInt    nslice = 2;
  PetscBool   slice_set;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMemzero(plan, sizeof(*plan)));
  plan->nsub     = size;
  plan->slice[1] = 1;
  PetscOptionsBegin(comm, NULL, "Roller: sweep (docs/squeal.md section 6): -modes for every case of a product of scene option values, the cases spread over sub-communicators", NULL);
  PetscCall(PetscOptionsString("-sweep", "Run a sweep of -modes; F.csv gathers every case's eigenvalues: case,<swept options>,re,im,frequency,growth_rate,order,wave,error", NULL, plan->csv, plan->csv, sizeof(plan->csv), NULL));
  for (PetscInt p = 0; p < NPARAMS; ++p) {
    char opt[64], help[128], list[PETSC_MAX_PATH_LEN] = "", range[PETSC_MAX_PATH_LEN] = "";

    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-sweep_%s", SweepParams[p]));
    PetscCall(PetscSNPrintf(help, sizeof(help), "Values v1,v2,... of -%s, one case each (times the other lists)", SweepParams[p]));
    PetscCall(PetscOptionsString(opt, help, NULL, list, list, sizeof(list), NULL));
    PetscCall(PetscStrlcat(opt, "_range", sizeof(opt)));
    PetscCall(PetscSNPrintf(help, sizeof(help), "a,b,n: n values of -%s linearly spaced from a to b", SweepParams[p]));
    PetscCall(PetscOptionsString(opt, help, NULL, range, range, sizeof(range), NULL));
    if (list[0] || range[0]) {
      const PetscInt q = plan->nparams++;

      PetscCheck(q < ROLLER_SWEEP_MAX_PARAMS, comm, PETSC_ERR_SUP, "At most %d swept options", ROLLER_SWEEP_MAX_PARAMS);
      plan->name[q] = SweepParams[p];
      PetscCall(ParseParam(comm, SweepParams[p], list, range, &plan->count[q], &plan->values[q]));
    }
  }
  PetscCall(PetscOptionsInt("-sweep_subcomms", "Sub-communicators, each solving its own cases (default: the number of ranks, one rank per case)", NULL, plan->nsub, &plan->nsub, NULL));
  PetscCall(PetscOptionsIntArray("-sweep_slice", "i,k: take only the cases c with c % k == i (one task of a job array; default 0,1: all)", NULL, plan->slice, &nslice, &slice_set));
  PetscOptionsEnd();
  PetscCheck(plan->nsub >= 1 && plan->nsub <= size, comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_subcomms %" PetscInt_FMT ": allowed 1 to the number of ranks, %d", plan->nsub, size);
  if (slice_set && !(nslice == 2 && plan->slice[1] >= 1 && plan->slice[0] >= 0 && plan->slice[0] < plan->slice[1])) {
    char given[64];

    PetscCall(PetscOptionsGetString(NULL, NULL, "-sweep_slice", given, sizeof(given), NULL));
    SETERRQ(comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_slice %s: allowed i,k with k >= 1 and 0 <= i < k (the cases c with c %% k == i)", given);
  }
  PetscCall(CheckUnknown(comm));
  plan->ncases = plan->nparams ? 1 : 0;
  for (PetscInt q = 0; q < plan->nparams; ++q) {
    PetscCheck(plan->ncases * plan->count[q] <= 10000000, comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep: more than 1e7 cases");
    plan->ncases *= plan->count[q];
  }
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-quiet", &plan->quiet, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepPlanDestroy(RollerSweepPlan *plan)
{
  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < plan->nparams; ++q) PetscCall(PetscFree(plan->values[q]));
  plan->nparams = 0;
  PetscFunctionReturn(0);
}

/* Case c's values: the last swept option varies fastest. */
PetscErrorCode RollerSweepCaseValues(const RollerSweepPlan *plan, PetscInt c, PetscReal v[])
{
  PetscFunctionBeginUser;
  for (PetscInt q = plan->nparams - 1; q >= 0; --q) {
    v[q] = plan->values[q][c % plan->count[q]];
    c /= plan->count[q];
  }
  PetscFunctionReturn(0);
}

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

/* One case on the sub-communicator: exactly a `roller -modes` run with the case's values on the command line. */
static PetscErrorCode SolveCase(MPI_Comm sub, const RollerSweepPlan *plan, PetscInt c, RollerSweepRows *rows, PetscInt *n, PetscReal *growth)
{
  PetscReal   v[ROLLER_SWEEP_MAX_PARAMS];
  SavedOption saved[ROLLER_SWEEP_MAX_PARAMS];
  Roller      roller;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCall(RollerSweepCaseValues(plan, c, v));
  for (PetscInt q = 0; q < plan->nparams; ++q) {
    char opt[64], value[32];

    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s", plan->name[q]));
    PetscCall(RollerSweepFormatReal(value, sizeof(value), v[q]));
    PetscCall(OptionPush(opt, PETSC_TRUE, value, &saved[q]));
  }
  PetscCall(RollerCreate(sub, &roller));
  PetscCall(RollerSetFromOptions(roller));
  PetscCall(RollerSetUp(roller));
  PetscCall(RollerSolve(roller));
  PetscCallMPI(MPI_Comm_rank(sub, &rank));
  if (!rank) PetscCall(RollerSweepRowsAppend(rows, c, &roller->eig));
  *n      = roller->eig.n;
  *growth = PETSC_MIN_REAL;
  for (PetscInt j = 0; j < roller->eig.n; ++j) *growth = PetscMax(*growth, roller->eig.re[j]);
  PetscCall(RollerDestroy(&roller));
  for (PetscInt q = plan->nparams - 1; q >= 0; --q) PetscCall(OptionPop(&saved[q]));
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

/* This sub-communicator's cases: the j-th case of the run's slice if j % k is its colour. A failed case names
   itself before the error goes up (Open MPI then ends the other ranks). */
static PetscErrorCode SolveCases(MPI_Comm sub, PetscMPIInt color, const RollerSweepPlan *plan, RollerSweepRows *rows)
{
  PetscFunctionBeginUser;
  for (PetscInt c = plan->slice[0], j = 0; c < plan->ncases; c += plan->slice[1], ++j) {
    char           label[256];
    PetscInt       n      = 0;
    PetscReal      growth = 0;
    PetscLogDouble t0     = MPI_Wtime();
    PetscErrorCode ierr;

    if (j % plan->nsub != color) continue;
    PetscCall(CaseLabel(plan, c, label, sizeof(label)));
    ierr = SolveCase(sub, plan, c, rows, &n, &growth);
    if (ierr) PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDERR, "sweep: case %" PetscInt_FMT "/%" PetscInt_FMT " (%s) on subcomm %d failed\n", c, plan->ncases, label, color));
    PetscCall(ierr);
    if (!plan->quiet) PetscCall(PetscPrintf(sub, "sweep: case %" PetscInt_FMT "/%" PetscInt_FMT " (%s) on subcomm %d: %" PetscInt_FMT " eigenvalues, max growth %.3g, %.2f s\n", c, plan->ncases, label, color, n, (double)growth, MPI_Wtime() - t0));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweep(MPI_Comm comm)
{
  RollerSweepPlan plan;
  RollerSweepRows rows = {0, 0, NULL};
  PetscSubcomm    psub;
  SavedOption     saved[NOUTPUTS + 1];
  PetscBool       modes = PETSC_FALSE;
  PetscLogDouble  t0    = MPI_Wtime();
  char            part[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  PetscCall(RollerSweepSetFromOptions(comm, &plan));
  PetscCheck(plan.csv[0], comm, PETSC_ERR_ARG_WRONG, "-sweep needs the name of its CSV, -sweep F.csv");
  PetscCheck(plan.nparams, comm, PETSC_ERR_ARG_WRONG, "-sweep %s: nothing to sweep; give -sweep_<name> v1,v2,... or -sweep_<name>_range a,b,n for <name> one of omega, young, friction, obstacle_depth, sheet_speed", plan.csv);
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-modes", &modes, NULL));
  PetscCheck(modes, comm, PETSC_ERR_ARG_WRONG, "-sweep %s maps the eigenvalues of every case: give -modes too", plan.csv);
  PetscCall(RollerJoinPath(part, sizeof(part), plan.csv, ".part", "-sweep"));
  PetscCall(RollerRemoveStale(comm, plan.csv));
  PetscCall(RollerCheckWritable(comm, "-sweep", part)); /* before hours of cases, not after */

  PetscCall(PetscSubcommCreate(comm, &psub));
  PetscCall(PetscSubcommSetNumber(psub, plan.nsub));
  PetscCall(PetscSubcommSetType(psub, PETSC_SUBCOMM_CONTIGUOUS));
  for (PetscInt i = 0; i < NOUTPUTS; ++i) {
    PetscCall(OptionPush(CaseOutputs[i], PETSC_FALSE, NULL, &saved[i]));
    if (saved[i].had) PetscCall(PetscPrintf(comm, "sweep: %s %s is not written by the cases (the sweep's CSV %s has every eigenvalue)\n", CaseOutputs[i], saved[i].value, plan.csv));
  }
  PetscCall(OptionPush("-quiet", PETSC_TRUE, NULL, &saved[NOUTPUTS])); /* the progress lines instead of each case's table */
  PetscCall(SolveCases(PetscSubcommChild(psub), psub->color, &plan, &rows));
  for (PetscInt i = NOUTPUTS; i >= 0; --i) PetscCall(OptionPop(&saved[i]));

  PetscCall(RollerSweepWrite(comm, &plan, &rows));
  if (!plan.quiet)
    PetscCall(PetscPrintf(comm, "sweep: %" PetscInt_FMT " cases (slice %" PetscInt_FMT ",%" PetscInt_FMT ") on %" PetscInt_FMT " subcomms -> %s, %.2f s\n", (plan.ncases - plan.slice[0] + plan.slice[1] - 1) / plan.slice[1], plan.slice[0], plan.slice[1],
                          plan.nsub, plan.csv, MPI_Wtime() - t0));
  PetscCall(PetscSubcommDestroy(&psub));
  PetscCall(RollerSweepRowsDestroy(&rows));
  PetscCall(RollerSweepPlanDestroy(&plan));
  PetscFunctionReturn(0);
}
