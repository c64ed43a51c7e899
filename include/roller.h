/* Roller: a rubber roller as an elastic annulus in the co-rotating frame, pressed by a moving flat
   obstacle, advanced by the energy-conserving discrete Morse flow (DMF). See docs/model.md.
   This is the public face: create, configure from options, set up, solve, destroy; observers of the run. */
#ifndef ROLLER_H
#define ROLLER_H

#include <petscdmplex.h>
#include <petscksp.h>

typedef struct _n_Roller *Roller;

PETSC_EXTERN PetscErrorCode RollerCreate(MPI_Comm, Roller *);
PETSC_EXTERN PetscErrorCode RollerSetFromOptions(Roller);
PETSC_EXTERN PetscErrorCode RollerSetUp(Roller);
PETSC_EXTERN PetscErrorCode RollerSolve(Roller);
PETSC_EXTERN PetscErrorCode RollerDestroy(Roller *);

/* -sweep F.csv: the modes of every case of a product of scene option values, each case a Roller (create, set from
   options, set up, solve, destroy) on one of the communicator's sub-communicators; one gathered CSV. */
PETSC_EXTERN PetscErrorCode RollerSweep(MPI_Comm);
/* Unknown or unused options: an error (a typo suggested), before any output (final: PETSC_FALSE) and at the end
   (PETSC_TRUE); -options_left 0 turns it off (docs/options.md) */
PETSC_EXTERN PetscErrorCode RollerOptionsCheck(MPI_Comm, PetscBool);
PETSC_EXTERN PetscErrorCode RollerOptionsCheckValues(MPI_Comm);
/* Before PetscInitialize: 1 (after a line naming the file and the line) if a YAML options file does not parse */
PETSC_EXTERN int            RollerOptionsFilesParse(int, char **);
PETSC_EXTERN PetscErrorCode RollerOptionNameGivenOnCommandLine(const char[], PetscBool *);

/* Observers of the run (TSMonitorSet-style): RollerSolve calls every one, in the order they were set, at the
   state the run starts from (step 0, or the step a restart continues), after every step, and once at the
   successful end (where outputs are completed: files renamed into place). Set during set-up by each
   component (CSV, HDF5 fields, the -ts_monitor and progress lines, the periodic checkpoint, the MMS errors). */
typedef enum { ROLLER_MONITOR_INITIAL, ROLLER_MONITOR_STEP, ROLLER_MONITOR_FINAL } RollerMonitorEvent;
PETSC_EXTERN const char *const RollerMonitorEvents[];

PETSC_EXTERN PetscErrorCode RollerMonitorSet(Roller, PetscErrorCode (*)(Roller, RollerMonitorEvent, void *), void *, PetscErrorCode (*)(void **));
PETSC_EXTERN PetscErrorCode RollerMonitorCancel(Roller);

#endif
