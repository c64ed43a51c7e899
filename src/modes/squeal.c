/* The linearization about the steady sliding state (docs/squeal.md section 3), the complex eigenvalue analysis of
   the brake industry: a perturbation keeps the active contact nodes a (normal force N_a > 0) on the flat sheet
   (du_a,y = 0, the sheet is rigid), its normal force perturbation dN_a is the reaction of row a,y, and Coulomb's
   sliding force -s mu(v) N along e1 perturbs as

     dT_a = -s mu_a dN_a - N_a mu'_a dv_a,   dv_a = (lambda + theta' d_phi) du_a,x   (the slip speed's change)

   so that, with Q(lambda) = lambda^2 M + lambda C + K the lab-frame operator of the free annulus:
     row a,x  +=  s mu_a row a,y          (friction follows the normal force: a non-symmetric stiffness,
                                             mass and gyroscopic coupling: mode coupling, flutter)
     C(a,x; a,x) += N_a mu'_a,  K(a,x; .) += N_a mu'_a theta' d_phi   (velocity weakening mu' < 0: negative damping)
     rows and columns a,y removed.
   The same three operations on M, C and K give the reduced quadratic eigenproblem on the kept dofs. */
#include "modes/modes.h"

PetscErrorCode RollerSquealOperators(Roller ctx, const RollerSteady *st, Mat M, Mat C, Mat K, Mat *Mr, Mat *Cr, Mat *Kr, IS *kept)
{
  const PetscReal tol  = 1e-12;
  PetscReal       nmax = 0;
  Mat             R, RM, RC, RK;
  PetscInt        lo, hi, m, nk = 0, *idx;
  PetscBool      *drop;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < st->n; ++j) nmax = PetscMax(nmax, st->normal[j]);
  PetscCall(MatGetOwnershipRange(M, &lo, &hi));
  m = hi - lo;
  /* R = I + sum_a s mu_a e_{a,x} e_{a,y}^T: the friction rows */
  PetscCall(MatCreateAIJ(ctx->comm, m, m, PETSC_DETERMINE, PETSC_DETERMINE, 2, NULL, 1, NULL, &R));
  for (PetscInt i = lo; i < hi; ++i) PetscCall(MatSetValue(R, i, i, 1.0, INSERT_VALUES));
  PetscCall(PetscCalloc1(m, &drop));
  for (PetscInt j = 0; j < st->n; ++j) {
    const PetscInt a = st->dof[j];

    if (st->normal[j] <= tol * nmax || a < lo || a >= hi) continue;
    if (st->tangent[j] != 0) PetscCall(MatSetValue(R, a, a + 1, -st->tangent[j] / st->normal[j], INSERT_VALUES)); /* s mu_a */
    drop[a + 1 - lo] = PETSC_TRUE;
  }
  PetscCall(MatAssemblyBegin(R, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(R, MAT_FINAL_ASSEMBLY));
  PetscCall(MatMatMult(R, M, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &RM));
  PetscCall(MatMatMult(R, C, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &RC));
  PetscCall(MatMatMult(R, K, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &RK));
  /* velocity weakening on the rows a,x */
  PetscCall(MatSetOption(RC, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(MatSetOption(RK, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  for (PetscInt j = 0; j < st->n; ++j) {
    const PetscInt a = st->dof[j];
    PetscInt       nb[3], cols[3];
    PetscReal      c[3], vals[3];

    if (st->normal[j] <= tol * nmax || a < lo || a >= hi || st->dmu[j] == 0) continue;
    PetscCall(MatSetValue(RC, a, a, st->normal[j] * st->dmu[j], ADD_VALUES));
    PetscCall(RollerSteadyAngularDerivative(st, ctx->rotation.omega, j, nb, c));
    for (PetscInt k = 0; k < 3; ++k) {
      cols[k] = st->dof[nb[k]];
      vals[k] = st->normal[j] * st->dmu[j] * ctx->rotation.omega * c[k];
    }
    PetscCall(MatSetValues(RK, 1, &a, 3, cols, vals, ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(RC, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(RC, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyBegin(RK, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(RK, MAT_FINAL_ASSEMBLY));
  /* the kept dofs: all but the active nodes' normal ones */
  PetscCall(PetscMalloc1(m, &idx));
  for (PetscInt i = 0; i < m; ++i)
    if (!drop[i]) idx[nk++] = lo + i;
  PetscCall(ISCreateGeneral(ctx->comm, nk, idx, PETSC_OWN_POINTER, kept));
  PetscCall(MatCreateSubMatrix(RM, *kept, *kept, MAT_INITIAL_MATRIX, Mr));
  PetscCall(MatCreateSubMatrix(RC, *kept, *kept, MAT_INITIAL_MATRIX, Cr));
  PetscCall(MatCreateSubMatrix(RK, *kept, *kept, MAT_INITIAL_MATRIX, Kr));
  PetscCall(PetscFree(drop));
  PetscCall(MatDestroy(&R));
  PetscCall(MatDestroy(&RM));
  PetscCall(MatDestroy(&RC));
  PetscCall(MatDestroy(&RK));
  PetscFunctionReturn(0);
}
