/* The sweep (-sweep F.csv, docs/squeal.md section 6): many scenes, the Cartesian product of the values of a few scene
   options, each solved on a sub-communicator -- by -modes (an eigenvalue map) or, without -modes, as a transient (a
   map of per-case means and fits); the rows of every case gathered into one CSV.
     sweep.c            the "Roller: sweep" options, the cases and their values, the scene's fingerprint
     sweep_cases.c      -sweep_cases F.csv: the cases as the rows of a table (a Latin hypercube, any design)
     sweep_run.c        the sub-communicators and the runs, one Roller per case
     sweep_transient.c  a transient case's series (an observer of its run) reduced to one row: window means, fits
     sweep_csv.c        the rows of every case gathered to rank 0 and written, sorted by case
     sweep_journal.c    each sub-communicator's finished cases on disk as they end, read back by a resumed map */
#ifndef ROLLER_SWEEP_H
#define ROLLER_SWEEP_H

#include <roller_impl.h>

#define ROLLER_SWEEP_MAX_PARAMS 16

/* The columns a transient map may fit a growth rate and frequency to (-sweep_fit) */
typedef enum { ROLLER_SWEEP_FIT_CONTACT_FORCE, ROLLER_SWEEP_FIT_FRICTION_FORCE, ROLLER_SWEEP_FIT_SHAFT_TORQUE, ROLLER_SWEEP_FIT_R, ROLLER_SWEEP_FIT_ALPHA } RollerSweepFit;
PETSC_INTERN const char *const RollerSweepFits[];

/* What the sweep does: the swept scene options (names without the dash, in the table's order) and their values,
   the number of cases (the product of the counts), the slice i, k of them this run takes (c % k == i), the
   number of sub-communicators and the gathered CSV; a modes or a transient map, the transient's window (the last
   fraction of the run) and fitted column; the scene (every other option, sorted: a resumed map's must be the
   same). Case c varies the last swept option fastest; with -sweep_cases (cases_file) case c is the table's row c
   (table[c * ROLLER_SWEEP_MAX_PARAMS + q]) and the names are the table's (owned). A transient case writes its own
   monitor CSV when series (-sweep_monitor_csv) is given. */
typedef struct {
  PetscInt       nparams;
  const char    *name[ROLLER_SWEEP_MAX_PARAMS];
  char          *owned[ROLLER_SWEEP_MAX_PARAMS];
  PetscInt       count[ROLLER_SWEEP_MAX_PARAMS];
  PetscReal     *values[ROLLER_SWEEP_MAX_PARAMS], *table;
  PetscInt       ncases, slice[2], nsub;
  char           csv[PETSC_MAX_PATH_LEN], cases_file[PETSC_MAX_PATH_LEN], series[PETSC_MAX_PATH_LEN];
  PetscBool      quiet, transient;
  PetscReal      window;
  RollerSweepFit fit;
  char          *scene;
} RollerSweepPlan;

/* Complete CSV lines "c,<swept values>,...\n", the rows of whole cases, in the order they were added */
typedef struct {
  size_t len, max;
  char  *text;
} RollerSweepRows;

/* A transient case's series: every state's time and the columns the row needs (transient.c) */
typedef struct {
  PetscInt       n, max;
  PetscReal     *t, *contact, *friction, *stick, *fit; /* stick: the stick fraction, NaN without contact nodes */
  RollerSweepFit column;
} RollerSweepSeries;

/* sweep.c */
PETSC_INTERN PetscErrorCode RollerSweepSetFromOptions(MPI_Comm, RollerSweepPlan *);
PETSC_INTERN PetscErrorCode RollerSweepPlanDestroy(RollerSweepPlan *);
PETSC_INTERN PetscErrorCode RollerSweepCaseValues(const RollerSweepPlan *, PetscInt, PetscReal[]);
PETSC_INTERN PetscErrorCode RollerSweepCaseParams(const RollerSweepPlan *, PetscInt, char[], size_t); /* ",v1,v2" */
PETSC_INTERN PetscErrorCode RollerSweepFormatReal(char[], size_t, PetscReal);                         /* the shortest %g that reads back exactly */

/* sweep_cases.c */
PETSC_INTERN PetscErrorCode RollerSweepCasesRead(MPI_Comm, const char[], RollerSweepPlan *);
PETSC_INTERN PetscErrorCode RollerSweepCasesCheckUsed(MPI_Comm, const RollerSweepPlan *, const char[]);

/* sweep_transient.c */
PETSC_INTERN PetscErrorCode RollerSweepSeriesObserve(Roller, RollerSweepSeries *);
PETSC_INTERN PetscErrorCode RollerSweepSeriesDestroy(RollerSweepSeries *);
PETSC_INTERN PetscErrorCode RollerSweepFitGrowth(PetscInt, const PetscReal[], const PetscReal[], PetscReal *, PetscReal *, PetscReal *);
PETSC_INTERN PetscErrorCode RollerSweepTransientRow(const RollerSweepPlan *, const RollerSweepSeries *, PetscBool, char[], size_t, PetscReal *);

/* sweep_csv.c */
PETSC_INTERN PetscErrorCode RollerSweepHeader(const RollerSweepPlan *, char[], size_t);
PETSC_INTERN PetscErrorCode RollerSweepRowsAdd(RollerSweepRows *, const char[]);
PETSC_INTERN PetscErrorCode RollerSweepRowsAddModes(RollerSweepRows *, const RollerSweepPlan *, PetscInt, const RollerEigen *);
PETSC_INTERN PetscErrorCode RollerSweepRowsDestroy(RollerSweepRows *);
PETSC_INTERN PetscErrorCode RollerSweepRowsCase(const char *, PetscInt *); /* the case number a line starts with */
PETSC_INTERN PetscErrorCode RollerSweepWrite(MPI_Comm, const RollerSweepPlan *, const RollerSweepRows *, const RollerSweepRows *, PetscBool *);

/* sweep_journal.c */
typedef struct _n_RollerSweepJournal *RollerSweepJournal;
PETSC_INTERN PetscErrorCode           RollerSweepResume(MPI_Comm, const RollerSweepPlan *, RollerSweepRows *, PetscBool **);
PETSC_INTERN PetscErrorCode           RollerSweepJournalOpen(MPI_Comm, MPI_Comm, const RollerSweepPlan *, RollerSweepJournal *);
PETSC_INTERN PetscErrorCode           RollerSweepJournalAdd(RollerSweepJournal, PetscInt, const char[], size_t);
PETSC_INTERN PetscErrorCode           RollerSweepJournalClose(RollerSweepJournal *);
PETSC_INTERN PetscErrorCode           RollerSweepJournalsRemove(MPI_Comm, const RollerSweepPlan *);

#endif
