/* Private to scheme_newmark*.c: the three-level schemes' data (scheme_newmark.c: the step, set-up and registration;
   scheme_newmark_energy.c: the energy of a level, the balance of a step, the vectors a checkpoint keeps). */
#ifndef ROLLER_SCHEME_NEWMARK_H
#define ROLLER_SCHEME_NEWMARK_H

#include "scheme_impl.h"

typedef struct {
  PetscReal           beta;
  RollerStepOperator *op;
  Vec                 Mprev, Mprev2, Mv; /* M xi^{k-1}, M xi^{k-2} (state.Mcur = M xi^k); scratch */
  RollerMaxwell       mx;                /* the Maxwell branches (scheme_maxwell.c), or NULL */
  PetscReal           kinetic;           /* (xi^k - xi^{k-1}) . M (xi^k - xi^{k-1}) of step kinetic_step (made when asked) */
  PetscInt            kinetic_step;
} Newmark;

PETSC_INTERN PetscErrorCode RollerNewmarkEnergy(RollerScheme, Roller, PetscReal *);
PETSC_INTERN PetscErrorCode RollerNewmarkBalance(RollerScheme, Roller, RollerStepInfo *);
PETSC_INTERN PetscErrorCode RollerNewmarkKept(RollerScheme, Roller, PetscInt *, Vec *[], const char *[]);

#endif
