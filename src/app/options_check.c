/* Nothing passes silently (docs/options.md, "Unknown and unused options"): an option the run did not use is an
   error, with the closest known option suggested. The check runs twice: at the end of the set-up, before any
   output file is opened (every option but those of the solvers the run creates later, -pep_*, -ksp_*, ...), and
   at the end of the run (everything). An option that an options file (a YAML scene) sets and the run does not
   use, but that is a Roller option or a solver's, is reported on stderr, not refused: a contact scene runs with
   -obstacle false -modes unchanged. -options_left 0 turns the check off (PETSc's own option of that name). */
#include "integrate/integrate.h"
#include <ctype.h>
#include <roller_option_names.h> /* RollerOptionNames[]: every "-name" literal of src/, made by CMake */

/* The names that solver objects, created after the set-up, query, and PETSc's own run-time options. */
static const char *const Deferred[] = {"pep_",   "st_",    "eps_",    "bv_",      "ds_",    "rg_",  "fn_",     "ksp_",     "pc_",   "mat_", "snes_", "tao_", "log",
                                       "malloc", "memory", "objects", "options_", "viewer", "info", "history", "on_error", "petsc", "mpi",  "vec_",  NULL};

static PetscBool HasPrefix(const char name[], const char *const list[], PetscBool anywhere)
{
  for (PetscInt i = 0; list[i]; ++i) {
    const char *s = strstr(name, list[i]);

    if (s && (s == name || (anywhere && s[-1] == '_'))) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

/* Optimal string alignment distance (Levenshtein with transpositions), case-insensitive. */
static PetscInt Distance(const char a[], const char b[])
{
  PetscInt la = (PetscInt)strlen(a), lb = (PetscInt)strlen(b), d[64][64];

  if (la > 63 || lb > 63) return PETSC_MAX_INT;
  for (PetscInt i = 0; i <= la; ++i) d[i][0] = i;
  for (PetscInt j = 0; j <= lb; ++j) d[0][j] = j;
  for (PetscInt i = 1; i <= la; ++i)
    for (PetscInt j = 1; j <= lb; ++j) {
      PetscInt cost = tolower((unsigned char)a[i - 1]) != tolower((unsigned char)b[j - 1]);

      d[i][j] = PetscMin(PetscMin(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
      if (i > 1 && j > 1 && tolower((unsigned char)a[i - 1]) == tolower((unsigned char)b[j - 2]) && tolower((unsigned char)a[i - 2]) == tolower((unsigned char)b[j - 1])) d[i][j] = PetscMin(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[la][lb];
}

static PetscBool InList(const char name[], const char *const list[])
{
  for (PetscInt i = 0; list[i]; ++i)
    if (!strcasecmp(list[i] + 1, name)) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* The closest of Roller's option names, if close enough to be a typo. */
static const char *Suggest(const char name[])
{
  const char *best  = NULL;
  PetscInt    dbest = PetscMax(2, (PetscInt)strlen(name) / 3) + 1;

  for (PetscInt i = 0; RollerOptionNames[i]; ++i) {
    PetscInt d = Distance(name, RollerOptionNames[i] + 1);

    if (d < dbest) dbest = d, best = RollerOptionNames[i] + 1;
  }
  return best;
}

/* Was -name given on the command line (not by an options file or PETSC_OPTIONS)? */
static PetscErrorCode OnCommandLine(const char name[], PetscBool *given)
{
  int    argc;
  char **argv;

  PetscFunctionBeginUser;
  *given = PETSC_FALSE;
  PetscCall(PetscGetArgs(&argc, &argv));
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] == '-' && !strcasecmp(argv[i] + 1, name)) *given = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerOptionNameGivenOnCommandLine(const char name[], PetscBool *given)
{
  PetscFunctionBeginUser;
  PetscCall(OnCommandLine(name[0] == '-' ? name + 1 : name, given));
  PetscFunctionReturn(0);
}

/* Before any block reads them: a real or integer option of Roller's whose value is not a number, named (PETSc's own
   message names the value only). The ranges are the blocks' (RollerCheckOption). */
PetscErrorCode RollerOptionsCheckValues(MPI_Comm comm)
{
  PetscInt n;
  char   **names, **values;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i) {
    PetscBool   real = InList(names[i], RollerOptionReals), integer = InList(names[i], RollerOptionInts);
    const char *v   = values[i];
    char       *end = NULL;

    if (!real && !integer) continue;
    PetscCheck(v && v[0], comm, PETSC_ERR_USER_INPUT, "-%s: needs a value (%s)", names[i], real ? "a real number" : "an integer");
    if (!strncmp(v, "PETSC_", 6)) continue; /* PETSC_DEFAULT, PETSC_DECIDE: PETSc's */
    if (real) {
      (void)strtod(v, &end);
      PetscCheck(end != v && *end == 0, comm, PETSC_ERR_USER_INPUT, "-%s %s: not a number (a finite real number is allowed)", names[i], v);
    } else {
      long long x = strtoll(v, &end, 10);

      PetscCheck(end != v && *end == 0 && x >= PETSC_MIN_INT && x <= PETSC_MAX_INT, comm, PETSC_ERR_USER_INPUT, "-%s %s: not an integer (an integer of at most %d is allowed)", names[i], v, PETSC_MAX_INT);
    }
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerOptionsCheck(MPI_Comm comm, PetscBool final)
{
  PetscBool on = PETSC_TRUE, help;
  PetscInt  n, bad = 0;
  char    **names, **values, msg[1024] = "";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-options_left", &on, NULL));
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (!on || help) PetscFunctionReturn(0);
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i) {
    const char *name = names[i], *value = values[i] ? values[i] : "";
    PetscBool   cli, known = InList(name, RollerOptionNames), solver = HasPrefix(name, Deferred, PETSC_TRUE);
    char        line[512];

    if (!final && solver) continue; /* a solver's option: its object may be created after the set-up */
    PetscCall(OnCommandLine(name, &cli));
    if (!cli && (known || solver)) { /* a scene's option this run does not use: reported once, not refused */
      if (final == solver) PetscCall(PetscFPrintf(comm, PETSC_STDERR, "Warning: -%s %s, set by an options file, is not used by this run\n", name, value));
      continue;
    }
    if (known) PetscCall(PetscSNPrintf(line, sizeof(line), "-%s %s: not used by this run (it has no effect with the other options given)\n", name, value));
    else {
      const char *near = Suggest(name);

      if (near) PetscCall(PetscSNPrintf(line, sizeof(line), "-%s: unknown option; did you mean -%s?\n", name, near));
      else PetscCall(PetscSNPrintf(line, sizeof(line), "-%s: unknown option (roller -help lists them)\n", name));
    }
    PetscCall(PetscStrlcat(msg, line, sizeof(msg)));
    bad++;
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscCheck(!bad, comm, PETSC_ERR_USER_INPUT, "%s(-options_left 0 runs anyway)", msg);
  PetscFunctionReturn(0);
}
