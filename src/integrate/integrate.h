/* The time integration layer (docs/model.md section 2):
     timestep.c     the time-stepping options, the number of steps, the -ts_monitor and progress lines
     initial.c      the initial state, -mms and its error report at the end
     initial_mode.c the initial state on a mode of -modes: co-rotating, or lab (squeal: about the steady state)
     scheme*.c      the time schemes (-ts_scheme): registry, default and dt, dmf and trapezoidal (three-level),
                    composed (fourth order); scheme_impl.h
     diagnostics.c  R, alpha, energy and the contact columns of a step
     checkpoint.c   checkpoint, restart, signals, -checkpoint_every
     monitor.c      the observers of the run (RollerMonitorSet, include/roller.h)
     observers.c    the observers that write files: the CSV and the HDF5 fields (the writers are io's)
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

/* scheme.c: the time scheme of the run (docs/model.md section 2.1) */
PETSC_INTERN PetscErrorCode RollerSchemeRegister(const char[], PetscErrorCode (*)(RollerScheme));
PETSC_INTERN PetscErrorCode RollerSchemesRegisterAll(void);
PETSC_INTERN PetscErrorCode RollerSchemeSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerSchemeChoose(Roller); /* the scheme and the default dt (after the mesh is read) */
PETSC_INTERN PetscErrorCode RollerSchemeSetUp(Roller);  /* its step matrices (after M, K and the contact) */
PETSC_INTERN PetscErrorCode RollerSchemeStep(Roller);
PETSC_INTERN PetscErrorCode RollerSchemeEnergy(Roller, PetscReal *);
PETSC_INTERN PetscErrorCode RollerSchemeBalance(Roller, RollerStepInfo *);
#define ROLLER_SCHEME_KEPT 8
PETSC_INTERN PetscErrorCode RollerSchemeKept(Roller, PetscInt *, Vec[], const char *[]); /* at most ROLLER_SCHEME_KEPT */
PETSC_INTERN const char    *RollerSchemeName(Roller);
PETSC_INTERN PetscErrorCode RollerSchemePhase(Roller, PetscReal, PetscReal *); /* the run's scheme's phase error per step at x = w dt */
PETSC_INTERN PetscErrorCode RollerSchemesDestroy(Roller);

/* diagnostics.c: the works every step, the rest of a step's row when an observer asks (ctx->info) */
PETSC_INTERN PetscErrorCode RollerStepAccumulate(Roller);
PETSC_INTERN PetscErrorCode RollerStepInfoGet(Roller);

/* checkpoint.c */
PETSC_INTERN PetscErrorCode RollerCheckpointSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerCheckpointMonitorSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerCheckpointWrite(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerCheckpointRead(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerCheckpointReadKept(Roller, const char *); /* after the scheme's set-up */
PETSC_INTERN PetscErrorCode RollerCheckpointDiscretization(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerSignalsInstall(void);
PETSC_INTERN PetscErrorCode RollerSignalCaught(Roller, PetscInt *);

/* monitor.c (RollerMonitorSet and RollerMonitorCancel are public) */
PETSC_INTERN PetscErrorCode RollerMonitorRun(Roller, RollerMonitorEvent);

/* observers.c */
PETSC_INTERN PetscErrorCode RollerOutputMonitorSetUp(Roller);

/* initial_mode.c: -initial_condition mode (docs/squeal.md section 4) */
PETSC_INTERN PetscErrorCode RollerInitialModeState(Roller);

/* driver.c: the time loop (RollerSolve without -modes) */
PETSC_INTERN PetscErrorCode RollerRun(Roller);

#endif
