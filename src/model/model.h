/* The model layer (docs/model.md sections 1-3, 6.2):
     forcing.c         theta(t), the obstacle height g(t), R(-pi/2)
     discretization.c  PetscFE spaces, Dirichlet boundary, the operators M, K, A, the loads, the factorization
     accuracy.c        the default dt and h from -ts_phase_error
     kernels.h         pointwise FE kernels */
#ifndef ROLLER_MODEL_H
#define ROLLER_MODEL_H

#include <roller_impl.h>
#include "mesh/mesh.h"

PETSC_INTERN PetscErrorCode RollerLameFromYoung(PetscReal, PetscReal, PetscReal *, PetscReal *);

/* discretization.c */
PETSC_INTERN PetscErrorCode RollerDiscretizationSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerDirectSolverDefaults(KSP, PCType); /* preonly + factorization: ND serial, MUMPS parallel */
PETSC_INTERN PetscErrorCode RollerSetConstants(Roller, PetscReal, PetscReal, PetscReal, PetscReal);
PETSC_INTERN PetscErrorCode RollerUpdateGyroscopic(Roller, PetscReal);
PETSC_INTERN PetscErrorCode RollerOperatorsSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerComputeBoundaryFunctionals(Roller);

/* forcing.c: theta and its derivatives, the obstacle height, R(-pi/2) */
PETSC_INTERN void           RollerTheta(Roller, PetscReal, PetscReal *, PetscReal *, PetscReal *);
PETSC_INTERN PetscReal      RollerObstacleHeight(Roller, PetscReal);
PETSC_INTERN PetscErrorCode RollerApplyRotate90(Vec, Vec);

/* accuracy.c: the default -mesh_h and -ts_dt from the accuracy target -ts_phase_error */
PETSC_INTERN PetscErrorCode RollerModeFrequencies(Roller, PetscReal *, PetscReal *);
PETSC_INTERN PetscErrorCode RollerChooseMeshSize(Roller);
PETSC_INTERN PetscErrorCode RollerChooseTimeStep(Roller);

#endif
