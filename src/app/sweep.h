/* The sweep (-sweep F.csv, docs/squeal.md section 6): many scenes, the Cartesian product of the values of a few scene
   options, each solved by -modes on a sub-communicator; the eigenvalues of every case gathered into one CSV.
     sweep.c      the "Roller: sweep" options, the cases, the sub-communicators and the runs
     sweep_csv.c  the eigenvalues of every case gathered to rank 0 and written, one row per eigenvalue */
#ifndef ROLLER_SWEEP_H
#define ROLLER_SWEEP_H

#include <roller_impl.h>

#define ROLLER_SWEEP_MAX_PARAMS 8

/* What the sweep does: the swept scene options (names without the dash, in the table's order) and their values,
   the number of cases (the product of the counts), the slice i, k of them this run takes (c % k == i), the
   number of sub-communicators and the gathered CSV. Case c varies the last swept option fastest. */
typedef struct {
  PetscInt    nparams;
  const char *name[ROLLER_SWEEP_MAX_PARAMS];
  PetscInt    count[ROLLER_SWEEP_MAX_PARAMS];
  PetscReal  *values[ROLLER_SWEEP_MAX_PARAMS];
  PetscInt    ncases, slice[2], nsub;
  char        csv[PETSC_MAX_PATH_LEN];
  PetscBool   quiet;
} RollerSweepPlan;

/* The eigenvalues a process found, ROLLER_SWEEP_ROW reals per eigenvalue: case, re, im, order, wave, error */
#define ROLLER_SWEEP_ROW 6
typedef struct {
  PetscInt   n, max; /* rows held, allocated */
  PetscReal *rows;
} RollerSweepRows;

/* sweep.c */
PETSC_INTERN PetscErrorCode RollerSweepSetFromOptions(MPI_Comm, RollerSweepPlan *);
PETSC_INTERN PetscErrorCode RollerSweepPlanDestroy(RollerSweepPlan *);
PETSC_INTERN PetscErrorCode RollerSweepCaseValues(const RollerSweepPlan *, PetscInt, PetscReal[]);
PETSC_INTERN PetscErrorCode RollerSweepFormatReal(char[], size_t, PetscReal); /* the shortest %g that reads back exactly */

/* sweep_csv.c */
PETSC_INTERN PetscErrorCode RollerSweepRowsAppend(RollerSweepRows *, PetscInt, const RollerEigen *);
PETSC_INTERN PetscErrorCode RollerSweepRowsDestroy(RollerSweepRows *);
PETSC_INTERN PetscErrorCode RollerSweepWrite(MPI_Comm, const RollerSweepPlan *, const RollerSweepRows *);

#endif
