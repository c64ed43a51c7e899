/* The time integration layer (docs/model.md section 2):
     timestep.c     the time-stepping options, the number of steps, the -ts_monitor and progress lines
     initial.c      the initial state, -mms and its error report at the end
     initial_mode.c the initial state on a mode of -modes: co-rotating, or lab (squeal: about the steady state)
     step.c         one DMF step
     diagnostics.c  R, alpha, energy and the contact columns of a step
     checkpoint.c   checkpoint, restart, signals, -checkpoint_every
     monitor.c      the observers of the run (RollerMonitorSet, include/roller.h)
     driver.c       the time loop: step, diagnostics, observers, failures, signals */
#ifndef ROLLER_INTEGRATE_H
#define ROLLER_INTEGRATE_H

#include <roller_impl.h>
#include "verify/verify.h"
#include "contact/contact.h"
#include "io/io.h"

/* timestep.c */
PETSC_INTERN PetscErrorCode RollerTimeStepSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerTimeStepMonitorSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerStepCount(Roller, PetscInt *);

/* initial.c */
PETSC_INTERN PetscErrorCode RollerInitialSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerInitialState(Roller);
PETSC_INTERN PetscErrorCode RollerInitialMonitorSetUp(Roller);

/* step.c */
PETSC_INTERN PetscErrorCode RollerStep(Roller);

/* diagnostics.c */
PETSC_INTERN PetscErrorCode RollerComputeStepInfo(Roller);

/* checkpoint.c */
PETSC_INTERN PetscErrorCode RollerCheckpointSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerCheckpointMonitorSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerCheckpointWrite(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerCheckpointRead(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerCheckpointDiscretization(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerSignalsInstall(void);
PETSC_INTERN PetscErrorCode RollerSignalCaught(Roller, PetscInt *);

/* monitor.c (RollerMonitorSet and RollerMonitorCancel are public) */
PETSC_INTERN PetscErrorCode RollerMonitorRun(Roller, RollerMonitorEvent);

/* initial_mode.c: -initial_condition mode (docs/squeal.md section 4) */
PETSC_INTERN PetscErrorCode RollerInitialModeState(Roller);

/* driver.c: the time loop (RollerSolve without -modes) */
PETSC_INTERN PetscErrorCode RollerRun(Roller);

#endif
