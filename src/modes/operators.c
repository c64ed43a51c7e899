/* The linearized free annulus as a quadratic eigenproblem (lambda^2 M + lambda C + K) x = 0 (docs/squeal.md
   section 1), on the free dofs of the time step's operators:
     co-rotating frame:  M = rho M0,  C = -2 theta' rho G + tau K0 + eta M0,  K = K0 - theta'^2 rho M0
       (G = (R(-pi/2) u, v) skew: the Coriolis term moved to the left; -theta'^2 rho M0 the centrifugal softening)
     lab (Eulerian) frame: M = rho M0,  C = 2 theta' rho D + tau K0 + eta M0,
                           K = K0 - theta'^2 rho P + theta' tau A_L + theta' eta B_L
       (D = (d_phi u, v) skew, P = (d_phi u, d_phi v): the material derivative d/dt + theta' d_phi squared;
        the damping acts on the objective rate u_t + theta' L u, L u = d_phi u - J u, the rate seen in the
        co-rotating frame: A_L = a(L u, v), B_L = (L u, v), their skew parts (rotational.c, section 1.1))
   tau is -viscosity (Kelvin-Voigt, sigma = C:(eps + tau eps_t)), eta -damping. M0 is the step's mass (with
   -contact_mass redistributed, T^T M T), K0 its stiffness. */
#include "modes/modes.h"
#include "model/kernels.h"

/* The lab frame's damping of the objective rate: C += tau K0 + eta M0, K += theta' (tau A_L + eta B_L). */
static PetscErrorCode AddLabDamping(Roller ctx, Mat C, Mat K)
{
  const PetscReal tau = ctx->material.viscosity, eta = ctx->disc.damping, w = ctx->rotation.omega;
  PetscReal       broken = 0, da = 0, db = 0;

  PetscFunctionBeginUser;
  PetscCall(MatAXPY(C, tau, ctx->ops.K, DIFFERENT_NONZERO_PATTERN));
  PetscCall(MatAXPY(C, eta, ctx->ops.M, DIFFERENT_NONZERO_PATTERN));
  if (w != 0 && tau != 0) {
    Mat A;

    PetscCall(RollerAssembleRotationalElastic(ctx, &A, &broken));
    PetscCall(RollerSkewPart(A, &da));
    PetscCall(MatAXPY(K, w * tau, A, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatDestroy(&A));
  }
  if (w != 0 && eta != 0) {
    Mat B;

    PetscCall(RollerAssembleRotationalMass(ctx, &B));
    PetscCall(RollerSkewPart(B, &db));
    PetscCall(MatAXPY(K, w * eta, B, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatDestroy(&B));
  }
  ctx->eig.skew_defect[0] = w != 0 && tau != 0 ? da : -1.0;
  ctx->eig.skew_defect[1] = w != 0 && eta != 0 ? db : -1.0;
  if (!ctx->ts.quiet)
    PetscCall(PetscPrintf(ctx->comm, "roller: lab-frame damping (tau %g, eta %g): skewness defect ||A + A^T||/||A|| of A_L %.3e (its cell terms alone %.3e), of B_L %.3e; their skew parts used\n", (double)tau, (double)eta, (double)da, (double)broken, (double)db));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerModeOperators(Roller ctx, Mat *M, Mat *C, Mat *K)
{
  const PetscReal rho = ctx->material.density, w = ctx->rotation.omega;

  PetscFunctionBeginUser;
  PetscCall(MatDuplicate(ctx->ops.M, MAT_COPY_VALUES, M));
  PetscCall(MatScale(*M, rho));
  PetscCall(MatDuplicate(ctx->ops.K, MAT_COPY_VALUES, K));
  PetscCheck(!ctx->ops.reduced || ctx->eig.frame == ROLLER_FRAME_ROTATING, ctx->comm, PETSC_ERR_SUP, "-rom reduces the co-rotating frame's operators: -modes_frame lab is the full model's");
  if (ctx->ops.reduced) { /* -rom (src/rom): the scheme's Coriolis force 2 rho theta' R(-pi/2) M v is ops.R90 on M v = v */
    PetscCall(MatDuplicate(ctx->ops.K, MAT_COPY_VALUES, C));
    PetscCall(MatScale(*C, ctx->material.viscosity));
    PetscCall(MatAXPY(*C, -2.0 * w * rho, ctx->ops.R90, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatAXPY(*C, ctx->disc.damping, ctx->ops.M, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatAXPY(*K, -w * w * rho, ctx->ops.M, DIFFERENT_NONZERO_PATTERN));
  } else if (ctx->eig.frame == ROLLER_FRAME_ROTATING) {
    Mat G;

    PetscCall(RollerAssembleMatrix(ctx, "G", g0_gyro, NULL, NULL, &G));
    PetscCall(MatDuplicate(ctx->ops.K, MAT_COPY_VALUES, C));
    PetscCall(MatScale(*C, ctx->material.viscosity)); /* Kelvin-Voigt: sigma = C:(eps + tau eps_t) */
    PetscCall(MatAXPY(*C, -2.0 * w * rho, G, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatAXPY(*C, ctx->disc.damping, ctx->ops.M, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatAXPY(*K, -w * w * rho, ctx->ops.M, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatDestroy(&G));
  } else {
    const PetscReal tau = ctx->material.viscosity, eta = ctx->disc.damping;
    Mat             P;

    PetscCall(RollerAssembleMatrix(ctx, "D", NULL, g1_convective, NULL, C));
    PetscCall(MatScale(*C, 2.0 * w * rho));
    PetscCall(RollerAssembleMatrix(ctx, "P", NULL, NULL, g3_convective, &P));
    PetscCall(MatAXPY(*K, -w * w * rho, P, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatDestroy(&P));
    if (tau != 0 || eta != 0) PetscCall(AddLabDamping(ctx, *C, *K));
  }
  PetscFunctionReturn(0);
}
