/* The verification layer (docs/validation.md):
     mms.c        manufactured solutions: exact field, body load, L2/H1 errors
     stability.c  the centrifugal-softening limit of the rotation */
#ifndef ROLLER_VERIFY_H
#define ROLLER_VERIFY_H

#include <roller_impl.h>
#include "model/model.h"

PETSC_INTERN PetscErrorCode RollerAddMMSLoad(Roller, PetscReal, Vec);
PETSC_INTERN PetscErrorCode RollerMMSExact(Roller, PetscReal, Vec);
PETSC_INTERN PetscErrorCode RollerMMSVelocity(Roller, PetscReal, Vec);
PETSC_INTERN PetscErrorCode RollerComputeErrors(Roller, PetscReal, PetscReal *, PetscReal *);
PETSC_INTERN PetscErrorCode RollerCheckRotation(Roller);

#endif
