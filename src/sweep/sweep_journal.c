/* A map that resumes (docs/squeal.md section 6.5): the root of each sub-communicator appends every case it finishes
   to its journal F.journal.<rank> at once -- the case's CSV lines and "# end <case> <lines>", one write, flushed --
   so a map killed at any moment (SIGKILL, a node lost, a time limit) keeps every case it finished. Run again with
   the same command, rank 0 reads the journals before any case: the cases whose block is complete, whose scene
   (every option but the sweep's own, line 1) and whose swept values are this map's, are done and skipped; their
   lines go into the final CSV as if computed now. Those lines are first consolidated into F.journal.resumed
   (written under another name and renamed) and only then are the journals read removed, so a map killed again
   loses nothing. A map that completes removes its journals. */
#include "sweep/sweep.h"
#include "io/io.h"
#include <dirent.h>
#include <errno.h>

struct _n_RollerSweepJournal {
  FILE *fp; /* the sub-communicator's root only */
  char  path[PETSC_MAX_PATH_LEN];
};

static PetscErrorCode WriteHead(FILE *fp, const RollerSweepPlan *plan)
{
  char header[ROLLER_SWEEP_MAX_PARAMS * 32 + 256];

  PetscFunctionBeginUser;
  PetscCall(RollerSweepHeader(plan, header, sizeof(header)));
  PetscCheck(fprintf(fp, "# roller -sweep journal; scene: %s\n%s", plan->scene, header) > 0 && fflush(fp) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-sweep %s: cannot write its journal: %s", plan->csv, strerror(errno));
  PetscFunctionReturn(0);
}

/* A block: the case's lines and its end line, one fwrite and a flush */
static PetscErrorCode WriteBlock(FILE *fp, const char path[], PetscInt c, const char text[], size_t len)
{
  char    *block, end[64];
  PetscInt lines = 0;
  size_t   n;

  PetscFunctionBeginUser;
  for (size_t i = 0; i < len; ++i) lines += text[i] == '\n';
  PetscCall(PetscSNPrintf(end, sizeof(end), "# end %" PetscInt_FMT " %" PetscInt_FMT "\n", c, lines));
  PetscCall(PetscStrlen(end, &n));
  PetscCall(PetscMalloc1(len + n, &block));
  PetscCall(PetscMemcpy(block, text, len));
  PetscCall(PetscMemcpy(block + len, end, n));
  PetscCheck(fwrite(block, 1, len + n, fp) == len + n && fflush(fp) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", path, strerror(errno));
  PetscCall(PetscFree(block));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepJournalOpen(MPI_Comm comm, MPI_Comm sub, const RollerSweepPlan *plan, RollerSweepJournal *journal)
{
  PetscMPIInt rank, sub_rank;
  char        suffix[32];

  PetscFunctionBeginUser;
  PetscCall(PetscNew(journal));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_rank(sub, &sub_rank));
  if (sub_rank) PetscFunctionReturn(0);
  PetscCall(PetscSNPrintf(suffix, sizeof(suffix), ".journal.%d", rank));
  PetscCall(RollerJoinPath((*journal)->path, sizeof((*journal)->path), plan->csv, suffix, "-sweep"));
  (*journal)->fp = fopen((*journal)->path, "w");
  PetscCheck((*journal)->fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-sweep %s: cannot write its journal %s: %s", plan->csv, (*journal)->path, strerror(errno));
  PetscCall(WriteHead((*journal)->fp, plan));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepJournalAdd(RollerSweepJournal journal, PetscInt c, const char text[], size_t len)
{
  PetscFunctionBeginUser;
  if (journal->fp) PetscCall(WriteBlock(journal->fp, journal->path, c, text, len));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepJournalClose(RollerSweepJournal *journal)
{
  PetscFunctionBeginUser;
  if (!*journal) PetscFunctionReturn(0);
  if ((*journal)->fp) PetscCheck(fclose((*journal)->fp) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot close %s: %s", (*journal)->path, strerror(errno));
  PetscCall(PetscFree(*journal));
  PetscFunctionReturn(0);
}

static int CompareNames(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The journals of the map F (F.journal.*), sorted by name, as paths */
static PetscErrorCode ListJournals(const RollerSweepPlan *plan, PetscInt *n, char ***paths)
{
  char           dir[PETSC_MAX_PATH_LEN], prefix[PETSC_MAX_PATH_LEN];
  const char    *slash = strrchr(plan->csv, '/'), *base = slash ? slash + 1 : plan->csv;
  DIR           *d;
  struct dirent *e;
  PetscInt       max = 0;

  PetscFunctionBeginUser;
  *n     = 0;
  *paths = NULL;
  PetscCall(PetscStrncpy(dir, slash ? plan->csv : ".", slash ? (size_t)(slash - plan->csv) + 1 : sizeof(dir)));
  if (slash && !dir[0]) PetscCall(PetscStrncpy(dir, "/", sizeof(dir)));
  PetscCall(RollerJoinPath(prefix, sizeof(prefix), base, ".journal.", "-sweep"));
  if (!(d = opendir(dir))) PetscFunctionReturn(0);
  while ((e = readdir(d))) {
    PetscBool match;

    PetscCall(PetscStrbeginswith(e->d_name, prefix, &match));
    if (!match) continue;
    if (*n == max) {
      max = PetscMax(8, 2 * max);
      PetscCall(PetscRealloc(sizeof(char *) * max, paths));
    }
    PetscCall(PetscMalloc1(PETSC_MAX_PATH_LEN, &(*paths)[*n]));
    PetscCall(PetscSNPrintf((*paths)[(*n)++], PETSC_MAX_PATH_LEN, "%s/%s", dir, e->d_name));
  }
  closedir(d);
  if (*n) qsort(*paths, (size_t)*n, sizeof(char *), CompareNames);
  PetscFunctionReturn(0);
}

/* One journal's complete blocks into rows, marking their cases done (a case already done: its copy skipped) */
static PetscErrorCode ReadJournal(const RollerSweepPlan *plan, const char path[], RollerSweepRows *rows, PetscBool done[])
{
  FILE           *fp   = fopen(path, "r");
  char           *line = NULL, header[ROLLER_SWEEP_MAX_PARAMS * 32 + 256], params[ROLLER_SWEEP_MAX_PARAMS * 32];
  size_t          cap  = 0;
  ssize_t         len;
  PetscInt        lineno = 0;
  RollerSweepRows block  = {0, 0, NULL};

  PetscFunctionBeginUser;
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-sweep %s: cannot read the journal %s: %s", plan->csv, path, strerror(errno));
  PetscCall(RollerSweepHeader(plan, header, sizeof(header)));
  while ((len = getline(&line, &cap, fp)) > 0) {
    PetscInt c, end_c, end_n, lines = 0;

    if (line[len - 1] != '\n') break; /* the last line, cut by the kill */
    if (++lineno == 1) {
      const char *scene = strstr(line, "; scene: ");

      line[len - 1] = '\0';
      PetscCheck(scene && !strcmp(scene + 9, plan->scene), PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "-sweep %s: the journal %s of an earlier run has another scene (its options \"%s\", this run's \"%s\"): remove it to start the map anew, or run it with the same options",
                 plan->csv, path, scene ? scene + 9 : line, plan->scene);
      continue;
    }
    if (lineno == 2) {
      PetscCheck(!strcmp(line, header), PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "-sweep %s: the journal %s has the columns %.*s, this map %s: remove it to start the map anew", plan->csv, path, (int)(len - 1), line, header);
      continue;
    }
    if (sscanf(line, "# end %" PetscInt_FMT " %" PetscInt_FMT, &end_c, &end_n) != 2) {
      PetscCall(RollerSweepRowsAdd(&block, line));
      continue;
    }
    for (size_t i = 0; i < block.len; i = (size_t)(strchr(block.text + i, '\n') - block.text) + 1, ++lines) {
      char expect[ROLLER_SWEEP_MAX_PARAMS * 32 + 32];

      PetscCall(RollerSweepRowsCase(block.text + i, &c));
      PetscCheck(c == end_c && c < plan->ncases, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep %s: the journal %s has a block of case %" PetscInt_FMT " with a row of case %" PetscInt_FMT " (a map of %" PetscInt_FMT " cases): remove it to start the map anew",
                 plan->csv, path, end_c, c, plan->ncases);
      PetscCall(RollerSweepCaseParams(plan, c, params, sizeof(params)));
      PetscCall(PetscSNPrintf(expect, sizeof(expect), "%" PetscInt_FMT "%s,", c, params));
      PetscCheck(!strncmp(block.text + i, expect, strlen(expect)), PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "-sweep %s: in the journal %s case %" PetscInt_FMT " is \"%.*s\", in this map \"%s\" (other swept values): remove it to start the map anew",
                 plan->csv, path, c, (int)strlen(expect), block.text + i, expect);
    }
    PetscCheck(lines == end_n, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-sweep %s: the journal %s has %" PetscInt_FMT " rows for case %" PetscInt_FMT ", its end line says %" PetscInt_FMT, plan->csv, path, lines, end_c, end_n);
    if (end_c >= 0 && end_c < plan->ncases && !done[end_c]) {
      done[end_c] = PETSC_TRUE;
      if (block.len) PetscCall(RollerSweepRowsAdd(rows, block.text));
    }
    block.len = 0;
    if (block.text) block.text[0] = '\0';
  }
  free(line);
  fclose(fp);
  PetscCall(RollerSweepRowsDestroy(&block));
  PetscFunctionReturn(0);
}

/* Rank 0 keeps the read cases in F.journal.resumed (through a temporary name) before removing what it read */
static PetscErrorCode Consolidate(const RollerSweepPlan *plan, const RollerSweepRows *rows, PetscInt n, char **paths)
{
  char  tmp[PETSC_MAX_PATH_LEN], resumed[PETSC_MAX_PATH_LEN];
  FILE *fp;

  PetscFunctionBeginUser;
  PetscCall(RollerJoinPath(tmp, sizeof(tmp), plan->csv, ".resume.tmp", "-sweep"));
  PetscCall(RollerJoinPath(resumed, sizeof(resumed), plan->csv, ".journal.resumed", "-sweep"));
  fp = fopen(tmp, "w");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-sweep %s: cannot write %s: %s", plan->csv, tmp, strerror(errno));
  PetscCall(WriteHead(fp, plan));
  for (size_t i = 0; i < rows->len;) { /* case by case: each block's lines are together */
    PetscInt c, d;
    size_t   j = i;

    PetscCall(RollerSweepRowsCase(rows->text + i, &c));
    do {
      j = (size_t)(strchr(rows->text + j, '\n') - rows->text) + 1;
      if (j < rows->len) PetscCall(RollerSweepRowsCase(rows->text + j, &d));
    } while (j < rows->len && d == c);
    PetscCall(WriteBlock(fp, tmp, c, rows->text + i, j - i));
    i = j;
  }
  PetscCheck(fclose(fp) == 0 && rename(tmp, resumed) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-sweep %s: cannot write %s: %s", plan->csv, resumed, strerror(errno));
  for (PetscInt i = 0; i < n; ++i) {
    PetscBool same;

    PetscCall(PetscStrcmp(paths[i] + strlen(paths[i]) - strlen(".journal.resumed"), ".journal.resumed", &same));
    if (!same) PetscCheck(remove(paths[i]) == 0 || errno == ENOENT, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-sweep %s: cannot remove %s: %s", plan->csv, paths[i], strerror(errno));
  }
  PetscFunctionReturn(0);
}

/* Before the cases: done[c] for the cases the journals of an earlier run of this map have (on every rank), their
   rows (rank 0). An error on rank 0 (a journal of another scene) is every rank's. */
PetscErrorCode RollerSweepResume(MPI_Comm comm, const RollerSweepPlan *plan, RollerSweepRows *rows, PetscBool **done)
{
  PetscMPIInt    rank;
  PetscErrorCode ierr = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscCalloc1(plan->ncases, done));
  if (!rank) {
    PetscInt n;
    char   **paths;

    PetscCall(ListJournals(plan, &n, &paths));
    for (PetscInt i = 0; i < n && !ierr; ++i) ierr = ReadJournal(plan, paths[i], rows, *done);
    if (!ierr && n) ierr = Consolidate(plan, rows, n, paths);
    for (PetscInt i = 0; i < n; ++i) PetscCall(PetscFree(paths[i]));
    PetscCall(PetscFree(paths));
  }
  PetscCallMPI(MPI_Bcast(&ierr, 1, MPI_INT, 0, comm));
  PetscCheck(!ierr, comm, PETSC_ERR_ARG_INCOMP, "-sweep %s: the journals of an earlier run cannot be resumed (the message above)", plan->csv);
  PetscCallMPI(MPI_Bcast(*done, (PetscMPIInt)plan->ncases, MPIU_BOOL, 0, comm));
  PetscFunctionReturn(0);
}

/* The complete map: its journals go */
PetscErrorCode RollerSweepJournalsRemove(MPI_Comm comm, const RollerSweepPlan *plan)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    PetscInt n;
    char   **paths;

    PetscCall(ListJournals(plan, &n, &paths));
    for (PetscInt i = 0; i < n; ++i) {
      PetscCheck(remove(paths[i]) == 0 || errno == ENOENT, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-sweep %s: cannot remove %s: %s", plan->csv, paths[i], strerror(errno));
      PetscCall(PetscFree(paths[i]));
    }
    PetscCall(PetscFree(paths));
  }
  PetscCallMPI(MPI_Barrier(comm));
  PetscFunctionReturn(0);
}
