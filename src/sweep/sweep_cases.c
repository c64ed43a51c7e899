/* -sweep_cases F.csv (docs/squeal.md section 6.6): a map whose cases are the rows of a table instead of a product of
   lists: a Latin hypercube, a design of experiments, any set of points. The header names scene options (without the
   dash; a first column "case" is allowed and must count 0, 1, ...); each row gives one case's values. Every column
   must be an option the case's run reads (checked on the first case a run solves: sweep_run.c), so a misspelt
   column is an error, not a silently unvaried scene. */
#include "sweep/sweep.h"
#include <ctype.h>
#include <errno.h>

#define LINE_MAX_CHARS 4096

/* Read the next line of fp into buf without its end of line; PETSC_FALSE at the end of the file. An over-long line
   is an error naming the file and the line. */
static PetscErrorCode ReadLine(FILE *fp, const char path[], PetscInt lineno, char buf[], size_t len, PetscBool *got)
{
  size_t n;

  PetscFunctionBeginUser;
  *got = (PetscBool)(fgets(buf, (int)len, fp) != NULL);
  if (!*got) PetscFunctionReturn(0);
  n = strlen(buf);
  PetscCheck(n + 1 < len || buf[n - 1] == '\n', PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: line %" PetscInt_FMT " is longer than %d characters", path, lineno, (int)len - 2);
  while (n && (buf[n - 1] == '\n' || buf[n - 1] == '\r' || buf[n - 1] == ' ')) buf[--n] = '\0';
  PetscFunctionReturn(0);
}

/* The header's names: option names as PETSc spells them (letters, digits, underscores), none of the sweep's own. */
static PetscErrorCode ParseHeader(const char path[], char line[], RollerSweepPlan *plan, PetscBool *numbered)
{
  char *item, *next;

  PetscFunctionBeginUser;
  *numbered = PETSC_FALSE;
  for (item = line; item; item = next) {
    PetscBool ok = PETSC_TRUE, sweep;

    next = strchr(item, ',');
    if (next) *next++ = '\0';
    while (*item == ' ') ++item;
    if (item == line && !strcmp(item, "case")) {
      *numbered = PETSC_TRUE;
      continue;
    }
    if (item[0] == '-') ++item; /* "-friction" reads as "friction" */
    for (const char *c = item; *c; ++c) ok = (PetscBool)(ok && (isalnum((unsigned char)*c) || *c == '_'));
    PetscCall(PetscStrbeginswith(item, "sweep", &sweep));
    PetscCheck(ok && item[0] && isalpha((unsigned char)item[0]) && !sweep && strlen(item) <= 40, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: header column \"%s\" is not a scene option's name; allowed: names such as friction, nip_force (letters, digits, _, at most 40; not a -sweep option)", path, item);
    PetscCheck(plan->nparams < ROLLER_SWEEP_MAX_PARAMS, PETSC_COMM_SELF, PETSC_ERR_SUP, "-sweep_cases %s: more than %d columns", path, ROLLER_SWEEP_MAX_PARAMS);
    for (PetscInt q = 0; q < plan->nparams; ++q) PetscCheck(strcmp(plan->name[q], item), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: column %s twice in the header", path, item);
    PetscCall(PetscStrallocpy(item, &plan->owned[plan->nparams]));
    plan->name[plan->nparams] = plan->owned[plan->nparams];
    plan->nparams++;
  }
  PetscCheck(plan->nparams, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: the header names no option; allowed: a first line such as case,friction,nip_force", path);
  PetscFunctionReturn(0);
}

/* One row: (case number,) then one finite value per column. */
static PetscErrorCode ParseRow(const char path[], PetscInt lineno, char line[], PetscBool numbered, PetscInt c, PetscInt nparams, PetscReal row[])
{
  char    *item, *next;
  PetscInt k = numbered ? -1 : 0;

  PetscFunctionBeginUser;
  for (item = line; item; item = next, ++k) {
    char  *end;
    double x;

    next = strchr(item, ',');
    if (next) *next++ = '\0';
    PetscCheck(k < nparams, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: line %" PetscInt_FMT " has more values than the header's %" PetscInt_FMT " columns", path, lineno, nparams + (numbered ? 1 : 0));
    x = strtod(item, &end);
    while (*end == ' ') ++end;
    PetscCheck(end != item && *end == '\0' && !PetscIsInfOrNanReal((PetscReal)x), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: line %" PetscInt_FMT ": \"%s\" is not a finite number", path, lineno, item);
    if (k < 0) PetscCheck(x == (double)c, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: line %" PetscInt_FMT " is case %s; allowed: the cases numbered 0, 1, 2, ... in order (this line: %" PetscInt_FMT ")", path, lineno, item, c);
    else row[k] = (PetscReal)x;
  }
  PetscCheck(k == nparams, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: line %" PetscInt_FMT " has %" PetscInt_FMT " values; the header has %" PetscInt_FMT " options", path, lineno, k, nparams);
  PetscFunctionReturn(0);
}

/* Rank 0 reads the table; the names and values go to every rank. Empty lines and lines starting with # are skipped. */
static PetscErrorCode ReadTable(const char path[], RollerSweepPlan *plan)
{
  FILE     *fp = fopen(path, "r");
  char      line[LINE_MAX_CHARS];
  PetscBool got, numbered = PETSC_FALSE, header = PETSC_FALSE;
  PetscInt  lineno = 0, max = 64;

  PetscFunctionBeginUser;
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-sweep_cases %s: cannot read it: %s", path, strerror(errno));
  PetscCall(PetscMalloc1(max * ROLLER_SWEEP_MAX_PARAMS, &plan->table));
  for (;;) {
    PetscCall(ReadLine(fp, path, ++lineno, line, sizeof(line), &got));
    if (!got) break;
    if (!line[0] || line[0] == '#') continue;
    if (!header) {
      PetscCall(ParseHeader(path, line, plan, &numbered));
      header = PETSC_TRUE;
      continue;
    }
    if (plan->ncases == max) {
      PetscReal *grown;

      PetscCheck(max <= 5000000, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_cases %s: more than 1e7 cases", path);
      PetscCall(PetscMalloc1(2 * max * ROLLER_SWEEP_MAX_PARAMS, &grown));
      PetscCall(PetscArraycpy(grown, plan->table, max * ROLLER_SWEEP_MAX_PARAMS));
      PetscCall(PetscFree(plan->table));
      plan->table = grown;
      max *= 2;
    }
    PetscCall(ParseRow(path, lineno, line, numbered, plan->ncases, plan->nparams, plan->table + plan->ncases * ROLLER_SWEEP_MAX_PARAMS));
    plan->ncases++;
  }
  fclose(fp);
  PetscCheck(header, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: empty; allowed: a header of option names, then one row of values per case", path);
  PetscCheck(plan->ncases, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: a header and no case", path);
  PetscFunctionReturn(0);
}

/* The table on rank 0, broadcast: its size, the names (one string "a,b,c"), the values. An error on rank 0 ends the
   run there with its message; the others learn it from the broadcast size. */
PetscErrorCode RollerSweepCasesRead(MPI_Comm comm, const char path[], RollerSweepPlan *plan)
{
  PetscMPIInt    rank;
  PetscErrorCode ierr                  = 0;
  PetscInt       sizes[2]              = {0, 0};
  char           names[LINE_MAX_CHARS] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    ierr = ReadTable(path, plan);
    if (!ierr) {
      sizes[0] = plan->nparams;
      sizes[1] = plan->ncases;
      for (PetscInt q = 0; q < plan->nparams; ++q) {
        PetscCall(PetscStrlcat(names, q ? "," : "", sizeof(names)));
        PetscCall(PetscStrlcat(names, plan->name[q], sizeof(names)));
      }
    }
  }
  PetscCallMPI(MPI_Bcast(sizes, 2, MPIU_INT, 0, comm));
  PetscCheck(sizes[1] > 0, comm, PETSC_ERR_FILE_UNEXPECTED, "-sweep_cases %s: not a table of cases (the message above)", path);
  PetscCallMPI(MPI_Bcast(names, sizeof(names), MPI_CHAR, 0, comm));
  if (rank) {
    char *item = names, *next;

    plan->nparams = sizes[0];
    plan->ncases  = sizes[1];
    for (PetscInt q = 0; q < plan->nparams; ++q, item = next) {
      next = strchr(item, ',');
      if (next) *next++ = '\0';
      PetscCall(PetscStrallocpy(item, &plan->owned[q]));
      plan->name[q] = plan->owned[q];
    }
    PetscCall(PetscMalloc1(plan->ncases * ROLLER_SWEEP_MAX_PARAMS, &plan->table));
  }
  PetscCallMPI(MPI_Bcast(plan->table, (PetscMPIInt)(plan->ncases * ROLLER_SWEEP_MAX_PARAMS), MPIU_REAL, 0, comm));
  PetscFunctionReturn(0);
}

/* After the first case's set-up: every column was read by the run (PetscOptionsUsed), else the column is no option
   of this scene. */
PetscErrorCode RollerSweepCasesCheckUsed(MPI_Comm comm, const RollerSweepPlan *plan, const char path[])
{
  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < plan->nparams; ++q) {
    PetscBool used;

    PetscCall(PetscOptionsUsed(NULL, plan->name[q], &used)); /* the database keeps names without the dash */
    PetscCheck(used, comm, PETSC_ERR_USER_INPUT, "-sweep_cases %s: column %s is not an option this scene's run reads (misspelt, or of a part the scene leaves off); allowed: the options of roller -help with this scene", path, plan->name[q]);
  }
  PetscFunctionReturn(0);
}
