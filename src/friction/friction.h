/* The friction layer (docs/friction.md): Coulomb's law between the roller and the sheet as pure functions of their
   data, below the contact layer, which calls them and which they never call.
     law.c      the friction coefficient mu(|v|) of the slip speed and its derivative: the exponential weakening or the
                monotone interpolant of -friction_table
     coulomb.c  Coulomb's law of one step on given dense data (the semismooth Newton method)
     dense.c    the small dense kernels of the friction and contact solves: the LU of their systems (LAPACK's, bit for
                bit, without the reference's overhead), the products d + G x
   The contact layer builds their data from the Gamma_C nodes (the slips, the condensed G and d; contact_friction*.c)
   and runs the fixed points and fallbacks about them; the steady state and the squeal linearization of -modes
   (modes/steady*.c, modes/squeal.c) take mu(v) and its slope from law.c. */
#ifndef ROLLER_FRICTION_H
#define ROLLER_FRICTION_H

#include <roller_impl.h>

/* law.c: the obstacle's mu(|v|) (its derivative in |v| into dmu, or NULL): the table's interpolant if it has one,
   else mu + (mu_s - mu) exp(-|v| / v_c); whether it varies with v at all; the least and the largest coefficient it
   takes (the interpolant stays between its points). The table's interpolant alone, and the table from the text of
   -friction_table (validated: one-line errors naming the entry) and its end. */
PETSC_INTERN PetscReal      RollerFrictionMu(const RollerObstacle *, PetscReal, PetscReal *);
PETSC_INTERN PetscBool      RollerFrictionVaries(const RollerObstacle *);
PETSC_INTERN void           RollerFrictionRange(const RollerObstacle *, PetscReal[2]);
PETSC_INTERN PetscReal      RollerFrictionTableMu(const RollerFrictionTable *, PetscReal, PetscReal *);
PETSC_INTERN PetscErrorCode RollerFrictionTableSetUp(MPI_Comm, const char[], RollerFrictionTable *);
PETSC_INTERN PetscErrorCode RollerFrictionTableDestroy(RollerFrictionTable *);

/* coulomb.c: Coulomb's law of m nodes on the data G (2m x 2m, column-major) and d (2m) of the box QP in
   x = (lambda_N, lambda_T), gap = (G x + d)_N, slip = (G x + d)_T, by the primal-dual active-set (semismooth Newton)
   method: law (mu(v) of the slip speed |slip|/two_dt inside the iteration; NULL: mu as given), mu (m: the
   coefficients, in/out), x (2m: the first iterate in, the solution out if *converged), at most maxit iterations
   (*its). */
PETSC_INTERN PetscErrorCode RollerFrictionCoulombNewton(PetscInt, const PetscReal[], const PetscReal[], const RollerObstacle *, PetscReal, PetscReal[], PetscReal[], PetscInt, PetscInt *, PetscBool *);

/* dense.c: LAPACK's dgetrf of an n x n column-major A (pivots 1-based; *info > 0: the first zero pivot), bit for bit, without
   its reference implementation's overhead on small systems (below its block size 64; LAPACK's own from there); w = d + G (alpha x)
   (G n x n, column-major; w may be d) over the nonzero entries of x, each entry's sum in the order of x's entries. */
PETSC_INTERN PetscErrorCode RollerDenseLUFactor(PetscBLASInt, PetscReal[], PetscBLASInt[], PetscBLASInt *);
PETSC_INTERN void           RollerDenseMultAdd(PetscInt, const PetscReal[], const PetscReal[], PetscReal, const PetscReal[], PetscReal[]);

#endif
