/* The contact layer's face (docs/contact.md): the obstacle QP of a DMF step, only built when -obstacle is on.
   Its files and private header: contact_impl.h. */
#ifndef ROLLER_CONTACT_H
#define ROLLER_CONTACT_H

#include <roller_impl.h>
#include "model/model.h"

PETSC_INTERN PetscErrorCode RollerContactCreate(Roller, RollerContact *);
PETSC_INTERN PetscErrorCode RollerContactHelp(Roller); /* -help without -obstacle: the options block only */
PETSC_INTERN PetscErrorCode RollerContactSolve(Roller, RollerContact, PetscReal, Vec, Vec);
PETSC_INTERN PetscErrorCode RollerContactInfo(Roller, RollerContact, Vec, PetscReal, RollerStepInfo *);
PETSC_INTERN PetscErrorCode RollerContactFields(Roller, RollerContact, Vec, Vec, Vec); /* pressure, traction, state: P1 scalar Vecs on the mesh */
PETSC_INTERN PetscBool      RollerContactHasFriction(RollerContact);
/* Dense pieces the steady state of -modes (modes/steady*.c) shares with the step's contact solvers:
   contact_lemke.c: the LCP w = M z + q >= 0, z >= 0, z . w = 0 (M n x n column-major) by Lemke's method;
   *solved false on a secondary ray (no solution found);
   contact_lcp.c: y = G_FF^-1 r on an index set F of a column-major G (m, F, nf, spd: Cholesky else LU, scratch, r, y);
   contact_friction.c: mu(|v|) = mu + (mu_s - mu) exp(-|v| / v_c) (mu, mu_s, v_c, v; its derivative in |v|, or NULL). */
PETSC_INTERN PetscErrorCode RollerContactLemke(PetscInt, const PetscReal[], const PetscReal[], PetscReal[], PetscInt *, PetscBool *);
PETSC_INTERN PetscErrorCode RollerContactDenseSolve(const PetscReal[], PetscInt, const PetscInt[], PetscInt, PetscBool, PetscReal[], PetscReal[], PetscReal[]);
PETSC_INTERN PetscReal      RollerFrictionLaw(PetscReal, PetscReal, PetscReal, PetscReal, PetscReal *);
PETSC_INTERN PetscErrorCode RollerContactDestroy(RollerContact *);

/* The registry of the per-step QP solvers (-contact_solver NAME, contact_registry.c): a solver is made by
   its create function, which fills the ops and the data of the object it is given (like KSPRegister). */
typedef struct _n_RollerContactSolver *RollerContactSolver;

PETSC_INTERN PetscErrorCode RollerContactSolverRegister(const char[], PetscErrorCode (*)(RollerContactSolver));
PETSC_INTERN PetscErrorCode RollerContactSolversRegisterAll(void);

#endif
