/* The step solver: a direct factorization of A, computed once and reused by every step, and the defaults of
   every factorization Roller makes. */
#include "model/model.h"

/* The defaults of every factorization Roller makes (the step matrix, the stability check, SNES VI's inner
   solve): a direct solve, PETSc's own with nested dissection in serial (the fastest measured,
   docs/performance.md), MUMPS in parallel. Options may override them (KSPSetFromOptions follows). */
PetscErrorCode RollerDirectSolverDefaults(KSP ksp, PCType type)
{
  PC          pc;
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)ksp), &size));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, type));
  if (size > 1) PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  else PetscCall(PCFactorSetMatOrderingType(pc, MATORDERINGND));
  PetscFunctionReturn(0);
}

/* Cholesky of A (LU with the centred Coriolis term, A is then non-symmetric), made once; -ksp_type cg
   -pc_type gamg (the rigid-body near-null space is attached) or hypre for large meshes. */
PetscErrorCode RollerStepSolverSetUp(Roller ctx)
{
  MatNullSpace nsp;
  PetscBool    direct;

  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateRigidBody(ctx->mesh.dm, 0, &nsp));
  PetscCall(MatSetNearNullSpace(ctx->ops.A, nsp));
  PetscCall(MatNullSpaceDestroy(&nsp));
  PetscCall(KSPCreate(ctx->comm, &ctx->ops.ksp));
  PetscCall(KSPSetOperators(ctx->ops.ksp, ctx->ops.A, ctx->ops.A));
  PetscCall(RollerDirectSolverDefaults(ctx->ops.ksp, ctx->ops.Gyro ? PCLU : PCCHOLESKY));
  PetscCall(KSPSetTolerances(ctx->ops.ksp, 1e-12, 1e-50, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(KSPSetFromOptions(ctx->ops.ksp));
  /* an iterative solver starts from the extrapolation 2 xi^{k-1} - xi^{k-2} (step.c) */
  PetscCall(PetscObjectTypeCompare((PetscObject)ctx->ops.ksp, KSPPREONLY, &direct));
  PetscCall(KSPSetInitialGuessNonzero(ctx->ops.ksp, (PetscBool)!direct));
  PetscCall(KSPSetUp(ctx->ops.ksp));
  PetscFunctionReturn(0);
}
