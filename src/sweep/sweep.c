/* -sweep F.csv (docs/squeal.md section 6): the plan of a map. The cases are the Cartesian product of the values given
   to a few scene options (-sweep_omega 0,0.1,0.2 -sweep_young_range 0.05,0.2,4 ...), numbered with the last swept
   option varying fastest, or the rows of a table (-sweep_cases, sweep_cases.c); with -modes each case is an eigenvalue problem, without it a transient reduced to one row
   over the last -sweep_window of its run (sweep_transient.c). The runs are sweep_run.c's. */
#include "sweep/sweep.h"
#include <ctype.h>

/* The scene options a sweep may vary: one row each (and nothing else to add for a new one: the case sets the option
   by name, the scene's own options block reads and validates it). */
static const char *const SweepParams[] = {"omega", "young", "friction", "obstacle_depth", "sheet_speed"};
#define NPARAMS ((PetscInt)(sizeof(SweepParams) / sizeof(SweepParams[0])))

/* The options of the sweep itself besides the swept lists */
static const char *const SweepOptions[] = {"-sweep_subcomms", "-sweep_slice", "-sweep_window", "-sweep_fit", "-sweep_cases", "-sweep_monitor_csv"};

const char *const RollerSweepFits[] = {"contact_force", "friction_force", "shaft_torque", "R", "alpha", "RollerSweepFit", "ROLLER_SWEEP_FIT_", NULL};

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
    for (PetscInt i = 0; i < (PetscInt)(sizeof(SweepOptions) / sizeof(SweepOptions[0])) && !known; ++i) PetscCall(PetscStrcmp(tok, SweepOptions[i], &known));
    for (PetscInt p = 0; p < NPARAMS && !known; ++p) {
      PetscCall(PetscSNPrintf(opt, sizeof(opt), "-sweep_%s", SweepParams[p]));
      PetscCall(PetscStrcmp(tok, opt, &known));
      if (!known) PetscCall(PetscStrlcat(opt, "_range", sizeof(opt)));
      if (!known) PetscCall(PetscStrcmp(tok, opt, &known));
    }
    PetscCheck(known, comm, PETSC_ERR_ARG_WRONG, "%s: not a sweep option; allowed: -sweep_<name> v1,v2,... or -sweep_<name>_range a,b,n for <name> one of %s (the table SweepParams in src/sweep/sweep.c), -sweep_cases F.csv, -sweep_monitor_csv F.csv, -sweep_subcomms k, -sweep_slice i,k, -sweep_window w, -sweep_fit column", tok, names);
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

/* qsort order of strings, the NULLs (items left out) last */
static int CompareStrings_Null(const void *a, const void *b)
{
  const char *x = *(const char *const *)a, *y = *(const char *const *)b;

  if (!x || !y) return (x == NULL) - (y == NULL);
  return strcmp(x, y);
}

/* What makes every case's scene besides its swept values: every option of the database but the sweep's own, the
   swept ones (which each case sets) and those that change no result (-quiet, -log_view, -options_left), as
   "-name value" items sorted and joined by spaces. A resumed map checks that its journals were written by the same
   scene (sweep_journal.c): a case already done is skipped only if it would come out the same. */
static PetscErrorCode SceneOptions(const RollerSweepPlan *plan, char **scene)
{
  static const char *const ignore[] = {"-quiet", "-log_view", "-options_left", "-help"};
  char                    *all, *tok, *save = NULL, **item;
  size_t                   len, n = 0, total = 1;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(NULL, &all));
  PetscCall(PetscStrlen(all, &len));
  PetscCall(PetscCalloc1(len / 2 + 2, &item));
  for (tok = strtok_r(all, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
    if (tok[0] == '-' && isalpha((unsigned char)tok[1])) item[n++] = tok; /* a name; else a value of the last name */
    else if (n) tok[-1] = '\x1f';                                         /* joined to it, marked apart from items */
  }
  for (size_t i = 0; i < n; ++i) {
    PetscBool skip, match;
    char     *name, *end;

    PetscCall(PetscStrallocpy(item[i], &name));
    if ((end = strchr(name, '\x1f'))) *end = '\0';
    PetscCall(PetscStrbeginswith(name, "-sweep", &skip));
    for (size_t k = 0; k < sizeof(ignore) / sizeof(ignore[0]) && !skip; ++k) PetscCall(PetscStrcasecmp(name, ignore[k], &skip));
    for (PetscInt q = 0; q < plan->nparams && !skip; ++q) {
      PetscCall(PetscStrcasecmp(name + 1, plan->name[q], &match));
      skip = match;
    }
    PetscCall(PetscFree(name));
    if (skip) item[i] = NULL;
    else {
      for (char *c = item[i]; *c; ++c)
        if (*c == '\x1f') *c = ' ';
      total += strlen(item[i]) + 1;
    }
  }
  qsort(item, n, sizeof(*item), CompareStrings_Null);
  PetscCall(PetscCalloc1(total, scene));
  for (size_t i = 0; i < n; ++i)
    if (item[i]) {
      if ((*scene)[0]) PetscCall(PetscStrlcat(*scene, " ", total));
      PetscCall(PetscStrlcat(*scene, item[i], total));
    }
  PetscCall(PetscFree(item));
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

/* The "Roller: sweep" options block (also listed by -help without -sweep); the lists are parsed and checked. */
PetscErrorCode RollerSweepSetFromOptions(MPI_Comm comm, RollerSweepPlan *plan)
{
  PetscMPIInt size;
  PetscInt    nslice = 2;
  PetscBool   slice_set, modes = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMemzero(plan, sizeof(*plan)));
  plan->nsub     = size;
  plan->slice[1] = 1;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-modes", &modes, NULL));
  plan->transient = (PetscBool)!modes;
  PetscOptionsBegin(comm, NULL, "Roller: sweep (docs/squeal.md section 6): -modes or a transient for every case of a product of scene option values or of a table (-sweep_cases), the cases spread over sub-communicators", NULL);
  PetscCall(PetscOptionsString("-sweep", "Run a map; F.csv gathers every case's rows. With -modes: case,<swept options>,re,im,frequency,growth_rate,order,wave,error; without: case,<swept options>,window_start,window_end,contact_force,friction_force,stick_fraction,amplitude,growth_rate,frequency,wall_time,status", NULL,
                               plan->csv, plan->csv, sizeof(plan->csv), NULL));
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
  PetscCall(PetscOptionsString("-sweep_cases", "F.csv: the cases as rows of a table, a header of scene option names (a first column case allowed) and one row of values per case (a Latin hypercube, any design); instead of the -sweep_<name> lists", NULL,
                               plan->cases_file, plan->cases_file, sizeof(plan->cases_file), NULL));
  PetscCall(PetscOptionsString("-sweep_monitor_csv", "F.csv: a transient map's case c writes its -monitor_csv series to F.case<c>.csv", NULL, plan->series, plan->series, sizeof(plan->series), NULL));
  PetscCall(PetscOptionsInt("-sweep_subcomms", "Sub-communicators, each solving its own cases (default: the number of ranks, one rank per case)", NULL, plan->nsub, &plan->nsub, NULL));
  PetscCall(PetscOptionsIntArray("-sweep_slice", "i,k: take only the cases c with c % k == i (one task of a job array; default 0,1: all)", NULL, plan->slice, &nslice, &slice_set));
  plan->window = 0.5;
  PetscCall(PetscOptionsReal("-sweep_window", "Transient map: the rows' means and fits are over the last w of each run's time, 0 < w <= 1", NULL, plan->window, &plan->window, NULL));
  plan->fit = ROLLER_SWEEP_FIT_CONTACT_FORCE;
  PetscCall(PetscOptionsEnum("-sweep_fit", "Transient map: the column whose growth rate and frequency are fitted over the window", "RollerSweepFit", RollerSweepFits, (PetscEnum)plan->fit, (PetscEnum *)&plan->fit, NULL));
  PetscOptionsEnd();
  for (PetscInt q = 0; q < plan->nparams; ++q) {
    PetscBool friction, table;

    PetscCall(PetscStrcmp(plan->name[q], "friction", &friction));
    PetscCall(PetscOptionsHasName(NULL, NULL, "-friction_table", &table));
    PetscCheck(!(friction && table), comm, PETSC_ERR_ARG_INCOMP, "-sweep_friction sweeps mu of the exponential law; -friction_table is the whole law mu(v): sweep without it");
  }
  RollerCheckOption(comm, "-sweep_window", plan->window, plan->window > 0 && plan->window <= 1, "in (0, 1] (the last fraction of each run's time)");
  PetscCheck(plan->nsub >= 1 && plan->nsub <= size, comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_subcomms %" PetscInt_FMT ": allowed 1 to the number of ranks, %d", plan->nsub, size);
  if (slice_set && !(nslice == 2 && plan->slice[1] >= 1 && plan->slice[0] >= 0 && plan->slice[0] < plan->slice[1])) {
    char given[64];

    PetscCall(PetscOptionsGetString(NULL, NULL, "-sweep_slice", given, sizeof(given), NULL));
    SETERRQ(comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_slice %s: allowed i,k with k >= 1 and 0 <= i < k (the cases c with c %% k == i)", given);
  }
  PetscCall(CheckUnknown(comm));
  { /* each case would stop at the limit with its own checkpoint: a sweep stops on SIGTERM and resumes from its journal */
    PetscBool wall;

    PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_max_wall", &wall));
    PetscCheck(!wall, comm, PETSC_ERR_ARG_INCOMP, "-ts_max_wall: not with -sweep (a sweep stops on SIGTERM and resumes from its journal, docs/squeal.md section 6)");
  }
  PetscCheck(!plan->series[0] || plan->transient, comm, PETSC_ERR_ARG_INCOMP, "-sweep_monitor_csv %s: a transient map's option (each case's series); a -modes map's rows are the eigenvalues", plan->series);
  if (plan->cases_file[0]) {
    PetscCheck(!plan->nparams, comm, PETSC_ERR_ARG_INCOMP, "-sweep_cases %s and -sweep_%s: give the cases as a table or as lists, not both", plan->cases_file, plan->name[0]);
    PetscCall(RollerSweepCasesRead(comm, plan->cases_file, plan));
  } else {
    plan->ncases = plan->nparams ? 1 : 0;
    for (PetscInt q = 0; q < plan->nparams; ++q) {
      PetscCheck(plan->ncases * plan->count[q] <= 10000000, comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep: more than 1e7 cases");
      plan->ncases *= plan->count[q];
    }
  }
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-quiet", &plan->quiet, NULL));
  PetscCall(SceneOptions(plan, &plan->scene));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepPlanDestroy(RollerSweepPlan *plan)
{
  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < plan->nparams; ++q) {
    PetscCall(PetscFree(plan->values[q]));
    PetscCall(PetscFree(plan->owned[q]));
  }
  PetscCall(PetscFree(plan->table));
  plan->nparams = 0;
  PetscCall(PetscFree(plan->scene));
  PetscFunctionReturn(0);
}

/* Case c's values as the CSV prints them: ",v1,v2,..." */
PetscErrorCode RollerSweepCaseParams(const RollerSweepPlan *plan, PetscInt c, char buf[], size_t len)
{
  PetscReal v[ROLLER_SWEEP_MAX_PARAMS];
  char      value[32];

  PetscFunctionBeginUser;
  PetscCall(RollerSweepCaseValues(plan, c, v));
  buf[0] = '\0';
  for (PetscInt q = 0; q < plan->nparams; ++q) {
    PetscCall(RollerSweepFormatReal(value, sizeof(value), v[q]));
    PetscCall(PetscStrlcat(buf, ",", len));
    PetscCall(PetscStrlcat(buf, value, len));
  }
  PetscFunctionReturn(0);
}

/* Case c's values: the table's row c, or the product's c-th (the last swept option varies fastest). */
PetscErrorCode RollerSweepCaseValues(const RollerSweepPlan *plan, PetscInt c, PetscReal v[])
{
  PetscFunctionBeginUser;
  if (plan->table) {
    PetscCall(PetscArraycpy(v, plan->table + c * ROLLER_SWEEP_MAX_PARAMS, plan->nparams));
    PetscFunctionReturn(0);
  }
  for (PetscInt q = plan->nparams - 1; q >= 0; --q) {
    v[q] = plan->values[q][c % plan->count[q]];
    c /= plan->count[q];
  }
  PetscFunctionReturn(0);
}
