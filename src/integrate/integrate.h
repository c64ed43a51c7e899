/* The time integration layer (docs/model.md section 2):
     timestep.c     the time-stepping options, the number of steps, the -ts_monitor and progress lines
     initial.c      the initial state, -mms and its error report at the end
     initial_mode.c the initial state on a mode of -modes: co-rotating, or lab (squeal: about the steady state)
     scheme*.c      the time schemes (-ts_scheme): registry, default and dt, dmf and trapezoidal (three-level),
                    composed (fourth order); scheme_impl.h
     diagnostics.c  R, alpha, energy and the contact columns of a step
     checkpoint*.c  checkpoint, restart (any number of ranks: checkpoint_order.c; refusals: checkpoint_identity.c),
                    signals, -checkpoint_every
     monitor.c      the observers of the run (RollerMonitorSet, include/roller.h)
     observers.c    the observers that write files: the CSV and the HDF5 fields (the writers are io's)
     observers_surface.c  -monitor_surface_csv: the lab-frame orders of the radial displacement of Gamma_C
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
PETSC_INTERN PetscErrorCode RollerSchemeChoose(Roller);                                    /* the scheme and the default dt (after the mesh is read) */
PETSC_INTERN PetscErrorCode RollerSchemeSetUp(Roller);                                     /* its step matrices (after M, K and the contact) */
PETSC_INTERN PetscErrorCode RollerSchemeKept(Roller, PetscInt *, Vec *[], const char *[]); /* the addresses of what it keeps beyond the levels */
PETSC_INTERN PetscErrorCode RollerSchemeStep(Roller);
PETSC_INTERN PetscErrorCode RollerSchemeEnergy(Roller, PetscReal *);
PETSC_INTERN PetscErrorCode RollerSchemeBalance(Roller, RollerStepInfo *);
#define ROLLER_SCHEME_KEPT (3 + 4 * ROLLER_MAX_BRANCHES) /* at most, the vectors a scheme keeps beyond the levels (checkpointed): M xi of three levels; z_i and K_d z_i of two levels per Maxwell branch */
PETSC_INTERN const char    *RollerSchemeName(Roller);
PETSC_INTERN PetscErrorCode RollerSchemePhase(Roller, PetscReal, PetscReal *); /* the run's scheme's phase error per step at x = w dt */
PETSC_INTERN PetscErrorCode RollerSchemesDestroy(Roller);

/* diagnostics.c: the works every step, the rest of a step's row when an observer asks (ctx->info) */
PETSC_INTERN PetscErrorCode RollerStepAccumulate(Roller);
PETSC_INTERN PetscErrorCode RollerStepInfoGet(Roller);

/* checkpoint.c (restarts on any number of ranks) */
PETSC_INTERN PetscErrorCode RollerCheckpointSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerCheckpointMonitorSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerCheckpointAddVec(Roller, const char[], Vec *, const char[], Vec); /* name, &v, where_name, where (NULL, NULL: the nodes) */
PETSC_INTERN PetscErrorCode RollerCheckpointAddReals(Roller, const char[], PetscInt, PetscReal[]);  /* the same on every rank */
PETSC_INTERN PetscErrorCode RollerCheckpointRegister(Roller);                                       /* the scheme's kept vectors and the hub's state (after the scheme's set-up) */
PETSC_INTERN PetscErrorCode RollerCheckpointWrite(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerCheckpointRead(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerCheckpointReadItems(Roller, const char *); /* after the scheme's set-up */
PETSC_INTERN PetscErrorCode RollerCheckpointDiscretization(Roller, const char *);
/* checkpoint_identity.c: what it was written for; a restart of another discretization refused by name */
PETSC_INTERN PetscErrorCode RollerCheckpointIdentityWrite(Roller, PetscViewer);
PETSC_INTERN PetscErrorCode RollerCheckpointIdentityCheck(Roller, PetscViewer, const char[]);
/* checkpoint_order.c: this run's points matched to the checkpoint's by position; a dataset read through the match */
PETSC_INTERN PetscErrorCode RollerCheckpointOrderCreate(Roller, PetscViewer, const char[], const char[], const char[], Vec, PetscInt *, PetscInt **); /* option, path, where_name, where */
PETSC_INTERN PetscErrorCode RollerCheckpointOrderLoad(PetscViewer, const char[], PetscInt, const PetscInt[], Vec);
PETSC_INTERN PetscErrorCode RollerSignalsInstall(void);
PETSC_INTERN PetscErrorCode RollerSignalCaught(Roller, PetscInt *);

/* monitor.c (RollerMonitorSet and RollerMonitorCancel are public) */
PETSC_INTERN PetscErrorCode RollerMonitorRun(Roller, RollerMonitorEvent);

/* observers.c */
PETSC_INTERN PetscErrorCode RollerOutputMonitorSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerSurfaceMonitorSetUp(Roller); /* observers_surface.c: -monitor_surface_csv */

/* initial_mode.c: -initial_condition mode (docs/squeal.md section 4) */
PETSC_INTERN PetscErrorCode RollerInitialModeState(Roller);

/* driver.c: the time loop (RollerSolve without -modes) */
PETSC_INTERN PetscErrorCode RollerRun(Roller);

#endif
