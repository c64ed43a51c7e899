/* The friction layer (docs/friction.md): Coulomb's law between the roller and the sheet as pure functions of their
   data, below the contact layer, which calls them and which they never call.
     law.c      the friction coefficient mu(|v|) of the slip speed and its derivative
     coulomb.c  Coulomb's law of one step on given dense data (the semismooth Newton method)
   The contact layer builds their data from the Gamma_C nodes (the slips, the condensed G and d; contact_friction*.c)
   and runs the fixed points and fallbacks about them; the steady state and the squeal linearization of -modes
   (modes/steady*.c, modes/squeal.c) take mu(v) and its slope from law.c. */
#ifndef ROLLER_FRICTION_H
#define ROLLER_FRICTION_H

#include <roller_impl.h>

/* law.c: mu(|v|) = mu + (mu_s - mu) exp(-|v| / v_c) (mu, mu_s, v_c, v; its derivative in |v|, or NULL) */
PETSC_INTERN PetscReal RollerFrictionLaw(PetscReal, PetscReal, PetscReal, PetscReal, PetscReal *);

/* coulomb.c: Coulomb's law of m nodes on the data G (2m x 2m, column-major) and d (2m) of the box QP in
   x = (lambda_N, lambda_T), gap = (G x + d)_N, slip = (G x + d)_T, by the primal-dual active-set (semismooth Newton)
   method: law (mu, mu_s, v_c, 2 dt: mu(v) inside the iteration when v_c > 0, or NULL), mu (m: the coefficients,
   in/out), x (2m: the first iterate in, the solution out if *converged), at most maxit iterations (*its). */
PETSC_INTERN PetscErrorCode RollerFrictionCoulombNewton(PetscInt, const PetscReal[], const PetscReal[], const PetscReal[], PetscReal[], PetscReal[], PetscInt, PetscInt *, PetscBool *);

#endif
