/* The constant operators of the model (docs/model.md section 2): mass M, stiffness K, the Maxwell branches' deviatoric
   stiffness K_d (only with -rubber maxwell), the gyroscopic G (only for the centred Coriolis velocity), the loads of the rigid part of f,
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

PetscErrorCode RollerOperatorsSetUp(Roller ctx)
{
  PetscErrorCode (*position[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {RollerPosition};

  Mat T; /* massless contact nodes: M <- T^T M T (model/mass.c); NULL with the consistent mass */

  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, &ctx->ops.coordinates));
  PetscCall(DMProjectFunction(ctx->mesh.dm, 0.0, position, NULL, INSERT_VALUES, ctx->ops.coordinates));
  PetscCall(RollerMassTransfer(ctx, &T));
  PetscCall(RollerAssembleMatrix(ctx, "M", g0_mass, NULL, NULL, &ctx->ops.M));
  if (T) PetscCall(RollerMassReduce(T, 1.0, &ctx->ops.M));
  PetscCall(RollerAssembleMatrix(ctx, "K", NULL, NULL, g3_elastic, &ctx->ops.K));
  if (ctx->material.rubber == ROLLER_RUBBER_MAXWELL) { /* the branches' K_d, on K's pattern (the same DM and quadrature) */
    PetscCall(RollerAssembleMatrix(ctx, "K_d", NULL, NULL, g3_deviatoric, &ctx->ops.Kd));
    PetscCall(MatSetOption(ctx->ops.Kd, MAT_SPD, PETSC_TRUE));
  }
  if (ctx->disc.coriolis == ROLLER_CORIOLIS_CENTERED && !ctx->eig.on) {
    /* the centred Coriolis term's step matrix A - rho theta'/dt G (integrate/scheme_newmark.c): G on the pattern of
       the step matrix, K + M (T^T G T couples more nodes than G) */
    PetscCall(RollerAssembleMatrix(ctx, "G", g0_gyro, NULL, NULL, &ctx->ops.G));
    if (T) {
      Mat P;

      PetscCall(MatDuplicate(ctx->ops.K, MAT_COPY_VALUES, &P));
      PetscCall(MatAXPY(P, 1.0, ctx->ops.M, DIFFERENT_NONZERO_PATTERN));
      PetscCall(RollerMassReducePattern(T, P, &ctx->ops.G));
      PetscCall(MatDestroy(&P));
    }
  }
  PetscCall(RollerAssembleLoad(ctx, f0_euler, &ctx->ops.L_euler));
  PetscCall(RollerAssembleLoad(ctx, f0_centrifugal, &ctx->ops.L_centrifugal));
  if (T) { /* M_red x = T^T M x: the loads of M_red */
    PetscCall(RollerMassReduceLoad(T, ctx->ops.L_euler));
    PetscCall(RollerMassReduceLoad(T, ctx->ops.L_centrifugal));
  }
  PetscCall(MatDestroy(&T));
  {
    PetscScalar I0;

    PetscCall(VecDot(ctx->ops.coordinates, ctx->ops.L_centrifugal, &I0));
    ctx->ops.I0 = PetscRealPart(I0);
  }
  PetscFunctionReturn(0);
}
