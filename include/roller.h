/* Roller: a rubber roller as an elastic annulus in the co-rotating frame, pressed by a moving flat
   obstacle, advanced by the energy-conserving discrete Morse flow (DMF). See docs/model.md.
   This is the public face: create, configure from options, set up, solve, destroy. */
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

#endif
