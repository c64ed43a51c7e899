/* PetscFE discretization (docs/model.md section 3) and the constant operators of the DMF step (docs/model.md section 2):
   mass M, stiffness K, A = rho/dt^2 M + K/2 (+ eta/(2 dt) M), factored once; the loads of the rigid part
   of f; the nodal positions; the boundary functionals behind R and alpha (docs/model.md section 4). */
#include "model/model.h"
#include "model/kernels.h"

static PetscErrorCode Zero(PetscInt dim, PetscReal time, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  for (PetscInt c = 0; c < Nc; ++c) u[c] = 0.0;
  return 0;
}

static PetscErrorCode AddDirichlet(Roller ctx, const char *name)
{
  DMLabel        label;
  const PetscInt one = 1;

  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(ctx->mesh.dm, name, &label));
  PetscCheck(label, ctx->comm, PETSC_ERR_ARG_WRONG, "The mesh has no label \"%s\"", name);
  PetscCall(DMAddBoundary(ctx->mesh.dm, DM_BC_ESSENTIAL, name, label, 1, &one, 0, 0, NULL, (void (*)(void))Zero, NULL, NULL, NULL));
  PetscFunctionReturn(0);
}

/* Lagrange P1 or P2 displacement; xi = 0 on Gamma_D (and on Gamma_C with -clamp_outer) removed from
   the global space, so every global vector and matrix lives on the free dofs. */
PetscErrorCode RollerDiscretizationSetUp(Roller ctx)
{
  PetscFE fe;

  PetscFunctionBeginUser;
  /* quadrature of order 2k integrates the mass matrix exactly on affine triangles */
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 2, 2, PETSC_TRUE, ctx->disc.degree, 2 * ctx->disc.degree, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, "displacement"));
  PetscCall(DMSetField(ctx->mesh.dm, 0, NULL, (PetscObject)fe));
  PetscCall(PetscFEDestroy(&fe));
  PetscCall(DMCreateDS(ctx->mesh.dm));
  PetscCall(AddDirichlet(ctx, "inner"));
  if (ctx->disc.clamp_outer) PetscCall(AddDirichlet(ctx, "outer"));
  PetscCall(RollerSetConstants(ctx, 0.0, 0.0, 0.0, 0.0));
  PetscFunctionReturn(0);
}

/* The DS constants (kernels.h): material, the time t of a load and theta there, the Jacobian weights. */
PetscErrorCode RollerSetConstants(Roller ctx, PetscReal t, PetscReal mass_weight, PetscReal stiffness_weight, PetscReal gyro_weight)
{
  PetscDS     ds;
  PetscScalar constants[ROLLER_NUM_CONSTANTS];
  PetscReal   td, tdd;

  PetscFunctionBeginUser;
  RollerTheta(ctx, t, NULL, &td, &tdd);
  constants[ROLLER_C_LAMBDA]           = ctx->material.lambda;
  constants[ROLLER_C_MU]               = ctx->material.mu;
  constants[ROLLER_C_RHO]              = ctx->material.density;
  constants[ROLLER_C_TIME]             = t;
  constants[ROLLER_C_THETA_DOT]        = td;
  constants[ROLLER_C_THETA_DDOT]       = tdd;
  constants[ROLLER_C_MMS]              = ctx->init.mms;
  constants[ROLLER_C_R_INNER]          = ctx->mesh.r_inner;
  constants[ROLLER_C_R_OUTER]          = ctx->mesh.r_outer;
  constants[ROLLER_C_MASS_WEIGHT]      = mass_weight;
  constants[ROLLER_C_STIFFNESS_WEIGHT] = stiffness_weight;
  constants[ROLLER_C_GYRO_WEIGHT]      = gyro_weight;
  constants[ROLLER_C_MMS_AMPLITUDE]    = ctx->init.amplitude;
  PetscCall(DMGetDS(ctx->mesh.dm, &ds));
  PetscCall(PetscDSSetConstants(ds, ROLLER_NUM_CONSTANTS, constants));
  PetscFunctionReturn(0);
}

/* weights (c_M, c_K, c_G) select M, K or G */
static PetscErrorCode AssembleMatrix(Roller ctx, const char *name, PetscReal cm, PetscReal ck, PetscReal cg, Mat *J)
{
  PetscDS ds;
  Vec     loc;

  PetscFunctionBeginUser;
  PetscCall(DMGetDS(ctx->mesh.dm, &ds));
  PetscCall(PetscDSSetJacobian(ds, 0, 0, g0_mass, NULL, NULL, g3_elastic));
  PetscCall(RollerSetConstants(ctx, 0.0, cm, ck, cg));
  PetscCall(DMCreateMatrix(ctx->mesh.dm, J));
  PetscCall(DMGetLocalVector(ctx->mesh.dm, &loc));
  PetscCall(VecZeroEntries(loc));
  PetscCall(DMPlexSNESComputeJacobianFEM(ctx->mesh.dm, loc, *J, *J, NULL));
  PetscCall(DMRestoreLocalVector(ctx->mesh.dm, &loc));
  PetscCall(PetscObjectSetName((PetscObject)*J, name));
  PetscFunctionReturn(0);
}

static PetscErrorCode AssembleLoad(Roller ctx, void (*f0)(ROLLER_KERNEL_ARGS, const PetscReal[], PetscInt, const PetscScalar[], PetscScalar[]), Vec *L)
{
  PetscDS ds;
  Vec     loc, locF;

  PetscFunctionBeginUser;
  PetscCall(DMGetDS(ctx->mesh.dm, &ds));
  PetscCall(PetscDSSetResidual(ds, 0, f0, NULL));
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, L));
  PetscCall(DMGetLocalVector(ctx->mesh.dm, &loc));
  PetscCall(DMGetLocalVector(ctx->mesh.dm, &locF));
  PetscCall(VecZeroEntries(loc));
  PetscCall(VecZeroEntries(locF));
  PetscCall(DMPlexSNESComputeResidualFEM(ctx->mesh.dm, loc, locF, NULL));
  PetscCall(DMLocalToGlobal(ctx->mesh.dm, locF, ADD_VALUES, *L));
  PetscCall(DMRestoreLocalVector(ctx->mesh.dm, &loc));
  PetscCall(DMRestoreLocalVector(ctx->mesh.dm, &locF));
  PetscFunctionReturn(0);
}

/* The step solver: a direct Cholesky factorization of A, computed once and reused by every step
   (PETSc's own with nested dissection in serial, MUMPS in parallel); -ksp_type cg -pc_type gamg (the
   rigid-body near-null space is attached) or hypre for large meshes. */
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

static PetscErrorCode StepSolverSetUp(Roller ctx)
{
  MatNullSpace nsp;

  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateRigidBody(ctx->mesh.dm, 0, &nsp));
  PetscCall(MatSetNearNullSpace(ctx->ops.A, nsp));
  PetscCall(MatNullSpaceDestroy(&nsp));
  PetscCall(KSPCreate(ctx->comm, &ctx->ops.ksp));
  PetscCall(KSPSetOperators(ctx->ops.ksp, ctx->ops.A, ctx->ops.A));
  PetscCall(RollerDirectSolverDefaults(ctx->ops.ksp, ctx->ops.Gyro ? PCLU : PCCHOLESKY));
  PetscCall(KSPSetTolerances(ctx->ops.ksp, 1e-12, 1e-50, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(KSPSetFromOptions(ctx->ops.ksp));
  {
    PetscBool direct;

    /* an iterative solver starts from the extrapolation 2 xi^{k-1} - xi^{k-2} (step.c) */
    PetscCall(PetscObjectTypeCompare((PetscObject)ctx->ops.ksp, KSPPREONLY, &direct));
    PetscCall(KSPSetInitialGuessNonzero(ctx->ops.ksp, (PetscBool)!direct));
  }
  PetscCall(KSPSetUp(ctx->ops.ksp));
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

  PetscFunctionBeginUser;
  PetscCall(AssembleMatrix(ctx, "M", 1.0, 0.0, 0.0, &ctx->ops.M));
  PetscCall(AssembleMatrix(ctx, "K", 0.0, 1.0, 0.0, &ctx->ops.K));
  PetscCall(MatDuplicate(ctx->ops.K, MAT_COPY_VALUES, &ctx->ops.A));
  if (!ctx->disc.static_solve) { /* -static: A = K, the step from rest is min 1/2 xi^T K xi over the admissible set */
    PetscCall(MatScale(ctx->ops.A, 0.5));
    PetscCall(MatAXPY(ctx->ops.A, shift, ctx->ops.M, SAME_NONZERO_PATTERN));
  }
  if (ctx->disc.coriolis == ROLLER_CORIOLIS_CENTERED) {
    /* A - rho theta'/dt G: no longer symmetric (G is skew), still positive definite */
    PetscCall(AssembleMatrix(ctx, "G", 0.0, 0.0, 1.0, &ctx->ops.Gyro));
    PetscCall(MatDuplicate(ctx->ops.A, MAT_COPY_VALUES, &ctx->ops.A0));
    PetscCall(RollerUpdateGyroscopic(ctx, 0.0));
  } else {
    PetscCall(MatSetOption(ctx->ops.A, MAT_SPD, PETSC_TRUE));
    PetscCall(MatSetOption(ctx->ops.A, MAT_SPD_ETERNAL, PETSC_TRUE));
  }
  PetscCall(PetscObjectSetName((PetscObject)ctx->ops.A, "A"));
  PetscCall(AssembleLoad(ctx, f0_euler, &ctx->ops.L_euler));
  PetscCall(AssembleLoad(ctx, f0_centrifugal, &ctx->ops.L_centrifugal));
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, &ctx->ops.coordinates));
  PetscCall(DMProjectFunction(ctx->mesh.dm, 0.0, position, NULL, INSERT_VALUES, ctx->ops.coordinates));
  PetscCall(StepSolverSetUp(ctx));
  PetscFunctionReturn(0);
}

/* w_R . xi = int_{Gamma_C} xi . x/|x| ds and w_alpha . xi = int_{Gamma_C} xi . x_perp/|x| ds, exact for the
   FE field on the discrete Gamma_C, and its length |Gamma_C|: 5-point Gauss on every outer edge, parametrized
   by the P2 map x(s) = x0 phi0 + x1 phi1 + xm phi2 (xm the geometry node of a curved edge, geometry.c, or the
   midpoint of a straight one), ds = |x'(s)|; basis functions of the edge's trace (P1: two vertices; P2: two
   vertices and the midpoint). */
PetscErrorCode RollerComputeBoundaryFunctionals(Roller ctx)
{
  static const PetscReal qx[5] = {0.046910077030668, 0.230765344947158, 0.5, 0.769234655052842, 0.953089922969332};
  static const PetscReal qw[5] = {0.118463442528095, 0.239314335249683, 0.284444444444444, 0.239314335249683, 0.118463442528095};
  DMLabel                label;
  IS                     is;
  PetscSection           section, csection;
  Vec                    wR, wA, clocal;
  const PetscScalar     *carr;
  PetscScalar           *r, *a;
  const PetscInt        *points;
  PetscInt               n, eStart, eEnd, pStart, pEnd, csStart, csEnd;
  PetscBool             *owned;
  PetscReal              length = 0.0;

  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(ctx->mesh.dm, "outer", &label));
  PetscCall(DMGetLocalSection(ctx->mesh.dm, &section));
  PetscCall(DMGetCoordinatesLocal(ctx->mesh.dm, &clocal));
  PetscCall(DMGetCoordinateSection(ctx->mesh.dm, &csection));
  PetscCall(PetscSectionGetChart(csection, &csStart, &csEnd));
  PetscCall(DMPlexGetHeightStratum(ctx->mesh.dm, 1, &eStart, &eEnd));
  PetscCall(DMPlexGetChart(ctx->mesh.dm, &pStart, &pEnd));
  PetscCall(RollerMeshOwnedMask(ctx->mesh.dm, &owned));
  PetscCall(DMGetLocalVector(ctx->mesh.dm, &wR));
  PetscCall(DMGetLocalVector(ctx->mesh.dm, &wA));
  PetscCall(VecZeroEntries(wR));
  PetscCall(VecZeroEntries(wA));
  PetscCall(VecGetArray(wR, &r));
  PetscCall(VecGetArray(wA, &a));
  PetscCall(VecGetArrayRead(clocal, &carr));
  PetscCall(DMLabelGetStratumIS(label, 1, &is));
  n = 0;
  if (is) PetscCall(ISGetLocalSize(is, &n));
  if (is) PetscCall(ISGetIndices(is, &points));
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt  e = points[i];
    const PetscInt *cone;
    PetscInt        off[3], ndof, coff[3], cdof;
    PetscReal       X[3][2]; /* x0, x1, xm */

    if (e < eStart || e >= eEnd) continue;
    if (!owned[e - pStart]) continue; /* its owner counts it */
    PetscCall(DMPlexGetCone(ctx->mesh.dm, e, &cone));
    PetscCall(PetscSectionGetOffset(csection, cone[0], &coff[0]));
    PetscCall(PetscSectionGetOffset(csection, cone[1], &coff[1]));
    cdof = 0; /* a P1 coordinate section has no chart beyond the vertices */
    if (e >= csStart && e < csEnd) PetscCall(PetscSectionGetDof(csection, e, &cdof));
    if (cdof) PetscCall(PetscSectionGetOffset(csection, e, &coff[2]));
    for (PetscInt d = 0; d < 2; ++d) {
      X[0][d] = PetscRealPart(carr[coff[0] + d]);
      X[1][d] = PetscRealPart(carr[coff[1] + d]);
      X[2][d] = cdof ? PetscRealPart(carr[coff[2] + d]) : 0.5 * (X[0][d] + X[1][d]);
    }
    PetscCall(PetscSectionGetOffset(section, cone[0], &off[0]));
    PetscCall(PetscSectionGetOffset(section, cone[1], &off[1]));
    PetscCall(PetscSectionGetOffset(section, e, &off[2]));
    PetscCall(PetscSectionGetDof(section, e, &ndof));
    for (PetscInt q = 0; q < 5; ++q) {
      const PetscReal s = qx[q], g[3] = {(1.0 - s) * (1.0 - 2.0 * s), s * (2.0 * s - 1.0), 4.0 * s * (1.0 - s)};
      const PetscReal dg[3] = {4.0 * s - 3.0, 4.0 * s - 1.0, 4.0 - 8.0 * s};
      PetscReal       x[2], dx[2], rad, ds, er[2], ep[2], phi[3];
      PetscInt        nb = 2;

      for (PetscInt d = 0; d < 2; ++d) {
        x[d]  = g[0] * X[0][d] + g[1] * X[1][d] + g[2] * X[2][d];
        dx[d] = dg[0] * X[0][d] + dg[1] * X[1][d] + dg[2] * X[2][d];
      }
      rad   = PetscSqrtReal(x[0] * x[0] + x[1] * x[1]);
      ds    = qw[q] * PetscSqrtReal(dx[0] * dx[0] + dx[1] * dx[1]);
      er[0] = x[0] / rad;
      er[1] = x[1] / rad;
      ep[0] = -er[1];
      ep[1] = er[0];
      length += ds;
      if (ndof == 0) {
        phi[0] = 1.0 - s;
        phi[1] = s;
      } else {
        for (PetscInt b = 0; b < 3; ++b) phi[b] = g[b];
        nb = 3;
      }
      for (PetscInt b = 0; b < nb; ++b)
        for (PetscInt c = 0; c < 2; ++c) {
          r[off[b] + c] += ds * phi[b] * er[c];
          a[off[b] + c] += ds * phi[b] * ep[c];
        }
    }
  }
  if (is) PetscCall(ISRestoreIndices(is, &points));
  PetscCall(ISDestroy(&is));
  PetscCall(PetscFree(owned));
  PetscCall(MPIU_Allreduce(&length, &ctx->mesh.boundary_length, 1, MPIU_REAL, MPI_SUM, ctx->comm));
  PetscCall(VecRestoreArrayRead(clocal, &carr));
  PetscCall(VecRestoreArray(wR, &r));
  PetscCall(VecRestoreArray(wA, &a));
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, &ctx->ops.w_R));
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, &ctx->ops.w_alpha));
  PetscCall(DMLocalToGlobal(ctx->mesh.dm, wR, ADD_VALUES, ctx->ops.w_R));
  PetscCall(DMLocalToGlobal(ctx->mesh.dm, wA, ADD_VALUES, ctx->ops.w_alpha));
  PetscCall(DMRestoreLocalVector(ctx->mesh.dm, &wR));
  PetscCall(DMRestoreLocalVector(ctx->mesh.dm, &wA));
  PetscFunctionReturn(0);
}
