/* The linearized free annulus as a quadratic eigenproblem (lambda^2 M + lambda C + K) x = 0 (docs/squeal.md
   section 1), on the free dofs of the time step's operators:
     co-rotating frame:  M = rho M0,  C = -2 theta' rho G + tau K0 + eta M0,  K = K0 - theta'^2 rho M0
       (G = (R(-pi/2) u, v) skew: the Coriolis term moved to the left; -theta'^2 rho M0 the centrifugal softening)
     lab (Eulerian) frame: M = rho M0,  C = 2 theta' rho D,  K = K0 - theta'^2 rho P
       (D = (d_phi u, v) skew, P = (d_phi u, d_phi v): the material derivative d/dt + theta' d_phi squared)
   M0 is the step's mass (with -contact_mass redistributed, T^T M T), K0 its stiffness. */
#include "modes/modes.h"
#include "model/kernels.h"

PetscErrorCode RollerModeOperators(Roller ctx, Mat *M, Mat *C, Mat *K)
{
  const PetscReal rho = ctx->material.density, w = ctx->rotation.omega;

  PetscFunctionBeginUser;
  PetscCall(MatDuplicate(ctx->ops.M, MAT_COPY_VALUES, M));
  PetscCall(MatScale(*M, rho));
  PetscCall(MatDuplicate(ctx->ops.K, MAT_COPY_VALUES, K));
  if (ctx->eig.frame == ROLLER_FRAME_ROTATING) {
    Mat G;

    PetscCall(RollerAssembleMatrix(ctx, "G", g0_gyro, NULL, NULL, &G));
    PetscCall(MatDuplicate(ctx->ops.K, MAT_COPY_VALUES, C));
    PetscCall(MatScale(*C, ctx->material.viscosity)); /* Kelvin-Voigt: sigma = C:(eps + tau eps_t) */
    PetscCall(MatAXPY(*C, -2.0 * w * rho, G, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatAXPY(*C, ctx->disc.damping, ctx->ops.M, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatAXPY(*K, -w * w * rho, ctx->ops.M, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatDestroy(&G));
  } else {
    Mat P;

    PetscCall(RollerAssembleMatrix(ctx, "D", NULL, g1_convective, NULL, C));
    PetscCall(MatScale(*C, 2.0 * w * rho));
    PetscCall(RollerAssembleMatrix(ctx, "P", NULL, NULL, g3_convective, &P));
    PetscCall(MatAXPY(*K, -w * w * rho, P, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatDestroy(&P));
  }
  PetscFunctionReturn(0);
}
