/* The step solvers: a step matrix A = c_M M + c_K K (+ c_D K_d) of a time scheme (RollerStepOperator), assembled and
   factored once and reused by every step, and the defaults of every factorization Roller makes. */
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

/* The parallel layout of a step matrix's direct solve (docs/performance.md "Several ranks"):
   - a symmetric positive definite matrix by substructuring (-solver_schur, model/solver_schur.c): each rank factors
     its interior, the interface's dense Schur complement on every rank; a solve is each rank's share of the
     substitutions and one reduction of the interface's size (2 ranks: the rolling and feed scenes 2.2-2.4x faster
     than one rank, 221k unknowns 1.9x);
   - otherwise (the centred Coriolis term's LU, or -solver_schur false) up to -solver_redundant_max unknowns every rank
     factors the whole matrix (PCREDUNDANT, the serial factorization with nested dissection; the contact
     condensation's columns split over the ranks, contact_condensed.c), larger ones MUMPS, whose distributed
     triangular solves cost more than a serial solve on these sizes. */
static PetscErrorCode StepSolverLayout(Roller ctx, RollerStepOperator *op, PCType type)
{
  PetscMPIInt size, gsize;
  PetscInt    N;
  PC          pc, ipc;
  KSP         inner;
  PetscBool   schur, redundant;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCall(MatGetSize(op->A, &N, NULL));
  schur     = (PetscBool)(size > 1 && ctx->disc.schur && !op->G);
  redundant = (PetscBool)(size > 1 && !schur && N <= ctx->disc.redundant_max);
  if (ctx->ts.view && op->id == 0 && size > 1)
    PetscCall(PetscPrintf(ctx->comm, "roller: step solver on %d ranks, %" PetscInt_FMT " unknowns: %s\n", size, N,
                          schur       ? (size <= ctx->disc.schur_ranks ? "substructured Cholesky (each rank factors its interior, the interface's dense Schur complement on every rank; -solver_schur)" : "substructured Cholesky on groups of at most -solver_schur_ranks ranks, each group a copy of the matrix (PCREDUNDANT): the dense interface of all the ranks would cost more than it saves")
                          : redundant ? "the whole matrix factored on every rank (PCREDUNDANT, serial nested dissection; the contact condensation's columns split over the ranks; at most -solver_redundant_max unknowns)"
                                      : "MUMPS, the factorization distributed (more than -solver_redundant_max unknowns)"));
  PetscCall(KSPGetPC(op->ksp, &pc));
  if (schur && size <= ctx->disc.schur_ranks) PetscCall(RollerSchurPCSet(pc));
  if (!redundant && !(schur && size > ctx->disc.schur_ranks)) PetscFunctionReturn(0);
  /* a copy of the matrix on every rank (redundant) or on every group of at most -solver_schur_ranks ranks */
  PetscCall(PCSetType(pc, PCREDUNDANT));
  PetscCall(PCRedundantSetNumber(pc, redundant ? size : (size + ctx->disc.schur_ranks - 1) / ctx->disc.schur_ranks));
  PetscCall(PCRedundantGetKSP(pc, &inner));
  PetscCall(KSPSetType(inner, KSPPREONLY));
  PetscCall(KSPGetPC(inner, &ipc));
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)inner), &gsize));
  if (redundant || gsize == 1) { /* a group of one rank (more groups than ranks / -solver_schur_ranks) factors alone */
    PetscCall(PCSetType(ipc, type));
    PetscCall(PCFactorSetMatOrderingType(ipc, MATORDERINGND));
  } else PetscCall(RollerSchurPCSet(ipc));
  PetscFunctionReturn(0);
}

/* Cholesky of A (LU with the centred Coriolis term: A is then non-symmetric), made once; -ksp_type cg
   -pc_type gamg (the rigid-body near-null space is attached) or hypre for large meshes. Every operator reads the
   same options (its KSP has no prefix), so that -ksp_type and -pc_factor_* act on all of a scheme's matrices. */
static PetscErrorCode StepSolverSetUp(Roller ctx, RollerStepOperator *op)
{
  MatNullSpace nsp;
  PetscBool    direct;

  PetscFunctionBeginUser;
  if (ctx->ops.reduced) { /* -rom: a diagonal A on the reduced coordinates (src/rom), exact by Jacobi; with the Maxwell
                              branches' dense K_d,r a direct factorization of the small dense A */
    PC pc;

    PetscCall(KSPCreate(ctx->comm, &op->ksp));
    PetscCall(KSPSetOperators(op->ksp, op->A, op->A));
    PetscCall(KSPSetType(op->ksp, KSPPREONLY));
    PetscCall(KSPGetPC(op->ksp, &pc));
    if (op->c_D != 0) PetscCall(RollerDirectSolverDefaults(op->ksp, op->G ? PCLU : PCCHOLESKY));
    else PetscCall(PCSetType(pc, PCJACOBI));
    PetscCall(KSPSetUp(op->ksp));
    PetscFunctionReturn(0);
  }
  PetscCall(DMPlexCreateRigidBody(ctx->mesh.dm, 0, &nsp));
  PetscCall(MatSetNearNullSpace(op->A, nsp));
  PetscCall(MatNullSpaceDestroy(&nsp));
  PetscCall(KSPCreate(ctx->comm, &op->ksp));
  PetscCall(KSPSetOperators(op->ksp, op->A, op->A));
  PetscCall(RollerDirectSolverDefaults(op->ksp, op->G ? PCLU : PCCHOLESKY));
  PetscCall(StepSolverLayout(ctx, op, op->G ? PCLU : PCCHOLESKY));
  PetscCall(KSPSetTolerances(op->ksp, 1e-12, 1e-50, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(KSPSetFromOptions(op->ksp));
  /* an iterative solver starts from the scheme's prediction of the new level */
  PetscCall(PetscObjectTypeCompare((PetscObject)op->ksp, KSPPREONLY, &direct));
  PetscCall(KSPSetInitialGuessNonzero(op->ksp, (PetscBool)!direct));
  PetscCall(KSPSetUp(op->ksp));
  PetscFunctionReturn(0);
}

/* -rom: the reduced model's passive unknowns (its residual forces at Gamma_C, src/rom) have no mass and no stiffness
   in the scheme's operators; a unit diagonal there makes the step's solve copy them from the right-hand side. */
static PetscErrorCode UnitPassiveDiagonal(Mat A)
{
  Vec          d;
  PetscScalar *a;
  PetscInt     n;

  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(A, &d, NULL));
  PetscCall(MatGetDiagonal(A, d));
  PetscCall(VecGetLocalSize(d, &n));
  PetscCall(VecGetArray(d, &a));
  for (PetscInt i = 0; i < n; ++i)
    if (a[i] == 0.0) a[i] = 1.0;
  PetscCall(VecRestoreArray(d, &a));
  PetscCall(MatDiagonalSet(A, d, INSERT_VALUES));
  PetscCall(VecDestroy(&d));
  PetscFunctionReturn(0);
}

/*
  RollerStepOperatorCreate - A = c_M M + c_K K + c_D K_d (M, K, K_d of ctx->ops; c_D != 0 only with the Maxwell
  branches, whose K_d has K's pattern, or with -rom contains the diagonal K_r's), factored: the matrix of a step (or a stage) of a time scheme. With G (the
  gyroscopic matrix of the centred Coriolis term, or NULL), A = A0 - c_G G, A0 = c_M M + c_K K + c_D K_d:
  non-symmetric, factored by LU (RollerStepOperatorUpdateGyroscopic changes c_G).
*/
PetscErrorCode RollerStepOperatorCreate(Roller ctx, PetscReal c_M, PetscReal c_K, PetscReal c_D, Mat G, PetscReal c_G, PetscInt id, RollerStepOperator *op)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(op, sizeof(*op)));
  op->c_M = c_M;
  op->c_K = c_K;
  op->c_D = c_D;
  op->id  = id;
  PetscCheck(c_D == 0 || ctx->ops.Kd, ctx->comm, PETSC_ERR_PLIB, "A step matrix with the Maxwell branches needs K_d (-rubber maxwell)");
  if (c_D != 0 && ctx->ops.reduced) { /* -rom: K_r diagonal, inside the dense pattern of K_d,r */
    PetscCall(MatDuplicate(ctx->ops.Kd, MAT_COPY_VALUES, &op->A));
    PetscCall(MatScale(op->A, c_D));
    PetscCall(MatAXPY(op->A, c_K, ctx->ops.K, SUBSET_NONZERO_PATTERN));
  } else {
    PetscCall(MatDuplicate(ctx->ops.K, MAT_COPY_VALUES, &op->A));
    PetscCall(MatScale(op->A, c_K));
    if (c_D != 0) PetscCall(MatAXPY(op->A, c_D, ctx->ops.Kd, SAME_NONZERO_PATTERN));
  }
  if (c_M != 0) PetscCall(MatAXPY(op->A, c_M, ctx->ops.M, UNKNOWN_NONZERO_PATTERN)); /* T^T M T (massless contact nodes) couples more nodes than K */
  if (G) {
    PetscCall(PetscObjectReference((PetscObject)G));
    op->G = G;
    PetscCall(MatDuplicate(op->A, MAT_COPY_VALUES, &op->A0));
    PetscCall(MatAXPY(op->A, -c_G, op->G, SAME_NONZERO_PATTERN));
  } else {
    PetscCall(MatSetOption(op->A, MAT_SPD, PETSC_TRUE));
    PetscCall(MatSetOption(op->A, MAT_SPD_ETERNAL, PETSC_TRUE));
  }
  if (ctx->ops.reduced) PetscCall(UnitPassiveDiagonal(op->A));
  PetscCall(PetscObjectSetName((PetscObject)op->A, "A"));
  PetscCall(StepSolverSetUp(ctx, op));
  PetscFunctionReturn(0);
}

/* The centred Coriolis term: A = A0 - c_G G, re-factored (with a constant theta' only once: the scheme calls this
   only when c_G changes). */
PetscErrorCode RollerStepOperatorUpdateGyroscopic(RollerStepOperator *op, PetscReal c_G)
{
  PetscFunctionBeginUser;
  PetscCall(MatCopy(op->A0, op->A, SAME_NONZERO_PATTERN));
  PetscCall(MatAXPY(op->A, -c_G, op->G, SAME_NONZERO_PATTERN));
  PetscCall(KSPSetOperators(op->ksp, op->A, op->A));
  PetscFunctionReturn(0);
}

/* x = A^{-1} b, checked: a direct solve fails only on a zero pivot, an iterative one may diverge. With the hub's
   border (-axle), the eliminated system's x = A_eff^{-1} b = A^{-1} b + Y W Y^T b (Woodbury, model/axle.h). */
PetscErrorCode RollerStepOperatorSolve(Roller ctx, const RollerStepOperator *op, Vec b, Vec x, PetscReal t)
{
  KSPConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(KSPSolve(op->ksp, b, x));
  PetscCall(KSPGetConvergedReason(op->ksp, &reason));
  PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "The step solve at t = %g diverged: %s", (double)t, KSPConvergedReasons[reason]);
  if (op->border) {
    PetscScalar yb[3];
    PetscReal   c[3], w[3];

    PetscCall(VecMDot(b, 3, op->border->Y, yb));
    for (PetscInt i = 0; i < 3; ++i) c[i] = PetscRealPart(yb[i]);
    RollerMat3Vec(op->border->W, c, w);
    for (PetscInt i = 0; i < 3; ++i) yb[i] = w[i];
    PetscCall(VecMAXPY(x, 3, yb, op->border->Y));
  }
  PetscFunctionReturn(0);
}

/* The hub's border of a step matrix (-axle): C = c_M C_M + c_K C_K + c_D C_D (the step matrix's own coefficients on
   the couplings), Y = A^{-1} C (three solves, once) and C^T Y. Its W follows the step (RollerStepOperatorUpdateBorder). */
PetscErrorCode RollerStepOperatorSetBorder(Roller ctx, RollerStepOperator *op)
{
  struct _n_RollerBorder *bd;
  const RollerHub        *hub = ctx->axle.hub;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&bd));
  for (PetscInt j = 0; j < 3; ++j) {
    PetscCall(VecDuplicate(hub->c.CM[j], &bd->C[j]));
    PetscCall(VecAXPBYPCZ(bd->C[j], op->c_M, op->c_K, 0.0, hub->c.CM[j], hub->c.CK[j]));
    if (op->c_D != 0) PetscCall(VecAXPY(bd->C[j], op->c_D, hub->c.CD[j])); /* the Maxwell branches' instantaneous stiffness */
    PetscCall(VecDuplicate(hub->c.CM[j], &bd->Y[j]));
    PetscCall(VecZeroEntries(bd->Y[j]));
    PetscCall(RollerStepOperatorSolve(ctx, op, bd->C[j], bd->Y[j], 0.0)); /* op->border not set yet: A^{-1} C */
  }
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) {
      PetscScalar d;

      PetscCall(VecDot(bd->C[i], bd->Y[j], &d));
      bd->CtY[3 * i + j] = PetscRealPart(d);
    }
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < i; ++j) bd->CtY[3 * i + j] = bd->CtY[3 * j + i] = 0.5 * (bd->CtY[3 * i + j] + bd->CtY[3 * j + i]);
  op->border = bd;
  PetscFunctionReturn(0);
}

/* The step's W = Z (Z^T (D_A - C^T Y) Z)^{-1} Z^T at t (the constraint's Z of the new level). */
PetscErrorCode RollerStepOperatorUpdateBorder(Roller ctx, RollerStepOperator *op, PetscReal t, const PetscReal DA[9])
{
  PetscReal Sigma[9];

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < 9; ++i) Sigma[i] = DA[i] - op->border->CtY[i];
  RollerAxleProject(ctx, t, Sigma, op->border->W);
  PetscFunctionReturn(0);
}

PetscErrorCode RollerBorderDestroy(struct _n_RollerBorder **bd)
{
  PetscFunctionBeginUser;
  if (!*bd) PetscFunctionReturn(0);
  for (PetscInt j = 0; j < 3; ++j) {
    PetscCall(VecDestroy(&(*bd)->C[j]));
    PetscCall(VecDestroy(&(*bd)->Y[j]));
  }
  PetscCall(PetscFree(*bd));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerStepOperatorDestroy(RollerStepOperator *op)
{
  PetscFunctionBeginUser;
  PetscCall(RollerBorderDestroy(&op->border));
  PetscCall(KSPDestroy(&op->ksp));
  PetscCall(MatDestroy(&op->A));
  PetscCall(MatDestroy(&op->A0));
  PetscCall(MatDestroy(&op->G));
  PetscFunctionReturn(0);
}
