/* The constant operators of the DMF step (docs/model.md section 2): mass M, stiffness K, the gyroscopic G,
   A = rho/dt^2 M + (1/2 + tau/(2 dt)) K (+ eta/(2 dt) M) (- rho theta'/dt G), the loads of the rigid part of f,
   the nodal positions; with -contact_mass redistributed M, G and the loads are T^T M T, T^T G T, T^T L
   (mass.c). Each bilinear form and load is assembled on a DM of its own (RollerOperatorDMCreate), whose
   PetscDS holds exactly its kernel and the constants that kernel reads, set once: no assembly changes what
   another computes. */
#include "model/model.h"
#include "model/kernels.h"

/* The bilinear form of Jacobian kernels g0, g1, g3 (any may be NULL) on its own DM; constants: the material's. */
PetscErrorCode RollerAssembleMatrix(Roller ctx, const char *name, PetscPointJac g0, PetscPointJac g1, PetscPointJac g3, Mat *J)
{
  DM      dm;
  PetscDS ds;
  Vec     loc;

  PetscFunctionBeginUser;
  PetscCall(RollerOperatorDMCreate(ctx, NULL, &dm));
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(PetscDSSetJacobian(ds, 0, 0, g0, g1, NULL, g3));
  if (g3) PetscCall(RollerMaterialSetConstants(ctx, ds));
  PetscCall(DMCreateMatrix(dm, J));
  PetscCall(DMGetLocalVector(dm, &loc));
  PetscCall(VecZeroEntries(loc));
  PetscCall(DMPlexSNESComputeJacobianFEM(dm, loc, *J, *J, NULL));
  PetscCall(DMRestoreLocalVector(dm, &loc));
  PetscCall(PetscObjectSetName((PetscObject)*J, name));
  PetscCall(DMDestroy(&dm)); /* the matrix keeps it */
  PetscFunctionReturn(0);
}

/* b += (f, v) for every free test function v: the load of the residual kernel f0 that the operator's DM
   (RollerOperatorDMCreate) holds, with the constants it set there. The one load assembly of Roller: the
   rigid-body loads here, the manufactured body force (verify/mms.c). */
PetscErrorCode RollerAddLoad(DM dm, Vec b)
{
  Vec loc, locF;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm, &loc));
  PetscCall(DMGetLocalVector(dm, &locF));
  PetscCall(VecZeroEntries(loc));
  PetscCall(VecZeroEntries(locF));
  PetscCall(DMPlexSNESComputeResidualFEM(dm, loc, locF, NULL));
  PetscCall(DMLocalToGlobal(dm, locF, ADD_VALUES, b));
  PetscCall(DMRestoreLocalVector(dm, &loc));
  PetscCall(DMRestoreLocalVector(dm, &locF));
  PetscFunctionReturn(0);
}

/* L = (f0, v), a load without constants, on its own DM. */
PetscErrorCode RollerAssembleLoad(Roller ctx, RollerPointFunc f0, Vec *L)
{
  DM      dm;
  PetscDS ds;

  PetscFunctionBeginUser;
  PetscCall(RollerOperatorDMCreate(ctx, NULL, &dm));
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(PetscDSSetResidual(ds, 0, f0, NULL));
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, L));
  PetscCall(RollerAddLoad(dm, *L));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

/* The implicit centred Coriolis term: A = A0 - rho theta'(t_{k-1})/dt G. With a constant theta' (no
   perturbation) this happens once; with theta_a != 0 every step, and the factorization is redone. */
PetscErrorCode RollerUpdateGyroscopic(Roller ctx, PetscReal t1)
{
  PetscReal td;

  PetscFunctionBeginUser;
  if (!ctx->ops.Gyro || (ctx->ops.ksp && ctx->rotation.a * ctx->rotation.b == 0)) PetscFunctionReturn(0);
  RollerTheta(ctx, t1, NULL, &td, NULL);
  PetscCall(MatCopy(ctx->ops.A0, ctx->ops.A, SAME_NONZERO_PATTERN));
  PetscCall(MatAXPY(ctx->ops.A, -ctx->material.density * td / ctx->ts.dt, ctx->ops.Gyro, SAME_NONZERO_PATTERN));
  if (ctx->ops.ksp) PetscCall(KSPSetOperators(ctx->ops.ksp, ctx->ops.A, ctx->ops.A));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerOperatorsSetUp(Roller ctx)
{
  PetscErrorCode (*position[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {RollerPosition};

  const PetscReal shift = ctx->material.density / (ctx->ts.dt * ctx->ts.dt) + ctx->disc.damping / (2.0 * ctx->ts.dt);
  Mat             T; /* massless contact nodes: M <- T^T M T (model/mass.c); NULL with the consistent mass */

  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, &ctx->ops.coordinates));
  PetscCall(DMProjectFunction(ctx->mesh.dm, 0.0, position, NULL, INSERT_VALUES, ctx->ops.coordinates));
  PetscCall(RollerMassTransfer(ctx, &T));
  PetscCall(RollerAssembleMatrix(ctx, "M", g0_mass, NULL, NULL, &ctx->ops.M));
  if (T) PetscCall(RollerMassReduce(T, 1.0, &ctx->ops.M));
  PetscCall(RollerAssembleMatrix(ctx, "K", NULL, NULL, g3_elastic, &ctx->ops.K));
  PetscCall(MatDuplicate(ctx->ops.K, MAT_COPY_VALUES, &ctx->ops.A));
  if (!ctx->disc.static_solve) { /* -static: A = K, the step from rest is min 1/2 xi^T K xi over the admissible set */
    /* Kelvin-Voigt: tau K (xi^k - xi^{k-2})/(2 dt), centred on t_{k-1} like the mass damping (docs/model.md section 2) */
    PetscCall(MatScale(ctx->ops.A, 0.5 + ctx->material.viscosity / (2.0 * ctx->ts.dt)));
    PetscCall(MatAXPY(ctx->ops.A, shift, ctx->ops.M, T ? DIFFERENT_NONZERO_PATTERN : SAME_NONZERO_PATTERN)); /* T^T M T couples more nodes than K */
  }
  if (ctx->disc.coriolis == ROLLER_CORIOLIS_CENTERED) {
    /* A - rho theta'/dt G: no longer symmetric (G is skew), still positive definite */
    PetscCall(RollerAssembleMatrix(ctx, "G", g0_gyro, NULL, NULL, &ctx->ops.Gyro));
    if (T) PetscCall(RollerMassReducePattern(T, ctx->ops.A, &ctx->ops.Gyro)); /* T^T G T, on A's pattern */
    PetscCall(MatDuplicate(ctx->ops.A, MAT_COPY_VALUES, &ctx->ops.A0));
    PetscCall(RollerUpdateGyroscopic(ctx, 0.0));
  } else {
    PetscCall(MatSetOption(ctx->ops.A, MAT_SPD, PETSC_TRUE));
    PetscCall(MatSetOption(ctx->ops.A, MAT_SPD_ETERNAL, PETSC_TRUE));
  }
  PetscCall(PetscObjectSetName((PetscObject)ctx->ops.A, "A"));
  PetscCall(RollerAssembleLoad(ctx, f0_euler, &ctx->ops.L_euler));
  PetscCall(RollerAssembleLoad(ctx, f0_centrifugal, &ctx->ops.L_centrifugal));
  if (T) { /* M_red x = T^T M x: the loads of M_red */
    PetscCall(RollerMassReduceLoad(T, ctx->ops.L_euler));
    PetscCall(RollerMassReduceLoad(T, ctx->ops.L_centrifugal));
  }
  PetscCall(MatDestroy(&T));
  if (!ctx->eig.on) PetscCall(RollerStepSolverSetUp(ctx)); /* -modes factors its own shifted operator */
  PetscFunctionReturn(0);
}
