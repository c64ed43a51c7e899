/* The time integration layer (docs/model.md section 2):
     step.c         the initial state and one DMF step
     diagnostics.c  R, alpha, energy and the contact columns of a step
     checkpoint.c   checkpoint, restart, signals
     driver.c       the time loop, its observers, the progress line */
#ifndef ROLLER_INTEGRATE_H
#define ROLLER_INTEGRATE_H

#include <roller_impl.h>
#include "verify/verify.h"
#include "contact/contact.h"
#include "io/io.h"

/* step.c */
PETSC_INTERN PetscErrorCode RollerInitialState(Roller);
PETSC_INTERN PetscErrorCode RollerStep(Roller);

/* diagnostics.c */
PETSC_INTERN PetscErrorCode RollerComputeStepInfo(Roller);

/* checkpoint.c */
PETSC_INTERN PetscErrorCode RollerCheckpointWrite(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerCheckpointRead(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerCheckpointDiscretization(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerSignalsInstall(void);
PETSC_INTERN PetscErrorCode RollerSignalCaught(Roller, PetscInt *);

#endif
