static const char help[] = "Unit test: the elasticity and mass kernels on the library's annulus (-degree 1, or 2 with the curved boundary):\n"
                           "(a) a linear displacement has the exact constant stress (RollerStress and f_stress_norm with the constants of\n"
                           "ctx->mesh.dm's DS); (b) a rigid motion stores no energy, u^T K u = 0; (c) the patch test: K u of a linear u\n"
                           "vanishes at every interior dof; (d) 1^T M 1 is twice the area of the discrete (curved) annulus; and ctx->ops.K,\n"
                           "ctx->ops.M are the free-dof blocks of the same forms.\n";

#include "model/model.h"
#include "unit.h"
#include "model/kernels.h"

/* u = B x + c */
typedef struct {
  PetscReal B[4], c[2];
} Affine;

static PetscErrorCode AffineField(PetscInt dim, PetscReal time, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  const Affine *A = (const Affine *)ctx;

  u[0] = A->B[0] * x[0] + A->B[1] * x[1] + A->c[0];
  u[1] = A->B[2] * x[0] + A->B[3] * x[1] + A->c[1];
  return 0;
}

/* the stress tensor through the library's RollerStress, with the constants of the input DS */
static void f_stress(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[])
{
  RollerStress(PetscRealPart(constants[ROLLER_C_LAMBDA]), PetscRealPart(constants[ROLLER_C_MU]), u_x, f);
}

/* A DM with ctx->mesh.dm's space and no Dirichlet boundary, and the form of one Jacobian kernel on it. */
static PetscErrorCode FullForm(Roller ctx, PetscPointJac g0, PetscPointJac g3, DM *dm, Mat *J)
{
  PetscObject fe;
  PetscDS     ds;
  Vec         loc;

  PetscFunctionBeginUser;
  PetscCall(DMClone(ctx->mesh.dm, dm));
  PetscCall(DMGetField(ctx->mesh.dm, 0, NULL, &fe));
  PetscCall(DMSetField(*dm, 0, NULL, fe));
  PetscCall(DMCreateDS(*dm));
  PetscCall(DMGetDS(*dm, &ds));
  PetscCall(PetscDSSetJacobian(ds, 0, 0, g0, NULL, NULL, g3));
  if (g3) PetscCall(RollerMaterialSetConstants(ctx, ds));
  PetscCall(DMCreateMatrix(*dm, J));
  PetscCall(DMGetLocalVector(*dm, &loc));
  PetscCall(VecZeroEntries(loc));
  PetscCall(DMPlexSNESComputeJacobianFEM(*dm, loc, *J, *J, NULL));
  PetscCall(DMRestoreLocalVector(*dm, &loc));
  PetscFunctionReturn(0);
}

/* (a) the stress of u = B x + c at every vertex, against sigma = lambda tr(eps) I + 2 mu eps. */
static PetscErrorCode CheckStress(Roller ctx, const Affine *A)
{
  RollerPointFunc kernels[2][1]                                                                       = {{f_stress}, {f_stress_norm}};
  const PetscInt  nc[2]                                                                               = {4, 1};
  PetscErrorCode (*field[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {AffineField};
  void           *fctx[1]                                                                             = {(void *)A};
  const PetscReal lambda = ctx->material.lambda, mu = ctx->material.mu, div = A->B[0] + A->B[3];
  PetscReal       sigma[4], norm;
  Vec             ul;

  PetscFunctionBeginUser;
  sigma[0] = lambda * div + 2 * mu * A->B[0];
  sigma[1] = mu * (A->B[1] + A->B[2]);
  sigma[2] = sigma[1];
  sigma[3] = lambda * div + 2 * mu * A->B[3];
  norm     = PetscSqrtReal(sigma[0] * sigma[0] + sigma[1] * sigma[1] + sigma[2] * sigma[2] + sigma[3] * sigma[3]);
  PetscCall(DMGetLocalVector(ctx->mesh.dm, &ul));
  PetscCall(DMProjectFunctionLocal(ctx->mesh.dm, 0.0, field, fctx, INSERT_ALL_VALUES, ul));
  for (PetscInt k = 0; k < 2; ++k) {
    DM                 dm;
    PetscFE            fe;
    Vec                X;
    const PetscScalar *x;
    PetscInt           n;
    PetscReal          err = 0;

    PetscCall(DMClone(ctx->mesh.dm, &dm));
    PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 2, nc[k], PETSC_TRUE, 1, PETSC_DETERMINE, &fe));
    PetscCall(DMSetField(dm, 0, NULL, (PetscObject)fe));
    PetscCall(PetscFEDestroy(&fe));
    PetscCall(DMCreateDS(dm));
    PetscCall(DMGetLocalVector(dm, &X));
    /* DMProjectFieldLocal hands the kernel the constants of the input DS: ctx->mesh.dm's */
    PetscCall(DMProjectFieldLocal(dm, 0.0, ul, kernels[k], INSERT_VALUES, X));
    PetscCall(VecGetLocalSize(X, &n));
    PetscCall(VecGetArrayRead(X, &x));
    for (PetscInt i = 0; i < n; ++i) err = PetscMax(err, PetscAbsReal(PetscRealPart(x[i]) - (k ? norm : sigma[i % 4])));
    PetscCall(VecRestoreArrayRead(X, &x));
    PetscCall(DMRestoreLocalVector(dm, &X));
    PetscCall(DMDestroy(&dm));
    PetscCheck(n > 0 && err <= 1e-12 * norm, PETSC_COMM_SELF, PETSC_ERR_PLIB, "P%" PetscInt_FMT " (a) linear u: %s at %" PetscInt_FMT " vertex values differs from the exact %g by %g (relative %g > 1e-12)", ctx->disc.degree, k ? "|sigma|" : "sigma", n, (double)norm, (double)err, (double)(err / norm));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "P%" PetscInt_FMT " (a) %s of a linear u exact at every vertex to %.1e relative\n", ctx->disc.degree, k ? "|sigma|" : "sigma", (double)(err / norm)));
  }
  PetscCall(DMRestoreLocalVector(ctx->mesh.dm, &ul));
  PetscFunctionReturn(0);
}

/* y = R J P v: J (on the BC-free dm) applied to the free-dof vector v of ctx->mesh.dm extended by zero, restricted
   to the free dofs: ctx->ops.K v and ctx->ops.M v if they are the free blocks of J. */
static PetscErrorCode FreeBlockMult(Roller ctx, DM dm, Mat J, Vec v, Vec y)
{
  Vec l, g, Jg;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(ctx->mesh.dm, &l));
  PetscCall(DMGetGlobalVector(dm, &g));
  PetscCall(DMGetGlobalVector(dm, &Jg));
  PetscCall(VecZeroEntries(l));
  PetscCall(DMGlobalToLocal(ctx->mesh.dm, v, INSERT_VALUES, l));
  PetscCall(DMLocalToGlobal(dm, l, INSERT_VALUES, g));
  PetscCall(MatMult(J, g, Jg));
  PetscCall(DMGlobalToLocal(dm, Jg, INSERT_VALUES, l));
  PetscCall(DMLocalToGlobal(ctx->mesh.dm, l, INSERT_VALUES, y));
  PetscCall(DMRestoreGlobalVector(dm, &Jg));
  PetscCall(DMRestoreGlobalVector(dm, &g));
  PetscCall(DMRestoreLocalVector(ctx->mesh.dm, &l));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckFreeBlock(Roller ctx, DM dm, Mat J, Mat op, const char *name)
{
  Vec         v, y, z;
  PetscRandom rnd;
  PetscReal   nz, nd;

  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(op, &v, &y));
  PetscCall(VecDuplicate(y, &z));
  PetscCall(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
  PetscCall(VecSetRandom(v, rnd));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(MatMult(op, v, y));
  PetscCall(FreeBlockMult(ctx, dm, J, v, z));
  PetscCall(VecNorm(y, NORM_INFINITY, &nz));
  PetscCall(VecAXPY(z, -1.0, y));
  PetscCall(VecNorm(z, NORM_INFINITY, &nd));
  PetscCheck(nz > 0 && nd <= 1e-13 * nz, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "P%" PetscInt_FMT ": ctx->ops.%s v differs from the free block of the form by %g (|%s v| = %g)", ctx->disc.degree, name, (double)nd, name, (double)nz);
  PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&z));
  PetscFunctionReturn(0);
}

/* (b) rigid motion, (c) patch test, on the stiffness without Dirichlet boundary. */
static PetscErrorCode CheckStiffness(Roller ctx, DM dm, Mat K, const Affine *linear)
{
  const Affine rigid = {
    {0.0,  -0.7, 0.7, 0.0},
    {0.3, -0.2    }
  };
  PetscErrorCode (*field[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {AffineField};
  void              *fctx[1];
  Vec                u, Ku, Kul;
  PetscScalar        uKu;
  PetscReal          Knorm, unorm, interior = 0, boundary = 0;
  PetscSection       section;
  DMLabel            inner, outer;
  PetscInt           pStart, pEnd, ninterior = 0;
  const PetscScalar *r;

  PetscFunctionBeginUser;
  PetscCall(MatNorm(K, NORM_INFINITY, &Knorm));
  PetscCall(DMCreateGlobalVector(dm, &u));
  PetscCall(VecDuplicate(u, &Ku));
  fctx[0] = (void *)&rigid;
  PetscCall(DMProjectFunction(dm, 0.0, field, fctx, INSERT_VALUES, u));
  PetscCall(MatMult(K, u, Ku));
  PetscCall(VecDot(u, Ku, &uKu));
  PetscCall(VecNorm(u, NORM_2, &unorm));
  PetscCheck(PetscAbsScalar(uKu) <= 1e-13 * Knorm * unorm * unorm, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "P%" PetscInt_FMT " (b) rigid motion: u^T K u = %g, relative to ||K|| ||u||^2 = %g: %g > 1e-13", ctx->disc.degree, (double)PetscRealPart(uKu), (double)(Knorm * unorm * unorm), (double)(PetscAbsScalar(uKu) / (Knorm * unorm * unorm)));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "P%" PetscInt_FMT " (b) rigid motion: u^T K u / (||K|| ||u||^2) = %.1e\n", ctx->disc.degree, (double)(PetscAbsScalar(uKu) / (Knorm * unorm * unorm))));

  fctx[0] = (void *)linear;
  PetscCall(DMProjectFunction(dm, 0.0, field, fctx, INSERT_VALUES, u));
  PetscCall(VecNorm(u, NORM_INFINITY, &unorm));
  PetscCall(MatMult(K, u, Ku));
  PetscCall(DMGetLocalVector(dm, &Kul));
  PetscCall(DMGlobalToLocal(dm, Ku, INSERT_VALUES, Kul));
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(DMGetLabel(dm, "inner", &inner));
  PetscCall(DMGetLabel(dm, "outer", &outer));
  PetscCall(PetscSectionGetChart(section, &pStart, &pEnd));
  PetscCall(VecGetArrayRead(Kul, &r));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt dof, off, vi, vo;

    PetscCall(PetscSectionGetDof(section, p, &dof));
    PetscCall(PetscSectionGetOffset(section, p, &off));
    PetscCall(DMLabelGetValue(inner, p, &vi));
    PetscCall(DMLabelGetValue(outer, p, &vo));
    for (PetscInt d = 0; d < dof; ++d) {
      if (vi == 1 || vo == 1) boundary = PetscMax(boundary, PetscAbsScalar(r[off + d]));
      else {
        interior = PetscMax(interior, PetscAbsScalar(r[off + d]));
        ++ninterior;
      }
    }
  }
  PetscCall(VecRestoreArrayRead(Kul, &r));
  PetscCall(DMRestoreLocalVector(dm, &Kul));
  PetscCheck(ninterior > 0 && interior <= 1e-13 * Knorm * unorm, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "P%" PetscInt_FMT " (c) patch test: max |K u| over %" PetscInt_FMT " interior dofs is %g, relative to ||K|| ||u|| = %g: %g > 1e-13", ctx->disc.degree, ninterior, (double)interior, (double)(Knorm * unorm), (double)(interior / (Knorm * unorm)));
  /* the check above is not vacuous: the linear field does load the boundary (a traction sigma n) */
  PetscCheck(boundary > 1e-6 * Knorm * unorm, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "P%" PetscInt_FMT " (c) patch test: max |K u| on the boundary is %g, relative %g: the linear field should load it", ctx->disc.degree, (double)boundary, (double)(boundary / (Knorm * unorm)));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "P%" PetscInt_FMT " (c) patch test: max |K u| / (||K|| ||u||) %.1e at %" PetscInt_FMT " interior dofs, %.1e on the boundary\n", ctx->disc.degree, (double)(interior / (Knorm * unorm)), ninterior, (double)(boundary / (Knorm * unorm))));
  PetscCall(VecDestroy(&u));
  PetscCall(VecDestroy(&Ku));
  PetscFunctionReturn(0);
}

/* The area of the discrete annulus: its straight-sided triangles (ctx->mesh.dm_view), and with the curved
   geometry, for every edge of Gamma_C (Gamma_D) the parabolic segment between the chord and the P2 edge, whose
   middle node lies at distance delta = r - |chord midpoint| from the chord: (2/3) |chord| delta added (removed). */
static PetscErrorCode DiscreteArea(Roller ctx, PetscReal *area)
{
  DM        dm = ctx->mesh.dm_view;
  PetscInt  cStart, cEnd;
  PetscReal a = 0;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscReal vol;

    PetscCall(DMPlexComputeCellGeometryFVM(dm, c, &vol, NULL, NULL));
    a += vol;
  }
  if (ctx->mesh.curved) {
    const char     *names[2] = {"outer", "inner"};
    const PetscReal r[2] = {ctx->mesh.r_outer, ctx->mesh.r_inner}, sign[2] = {1.0, -1.0};
    PetscInt        eStart, eEnd;

    PetscCall(DMPlexGetHeightStratum(dm, 1, &eStart, &eEnd));
    for (PetscInt b = 0; b < 2; ++b) {
      DMLabel         label;
      IS              is;
      const PetscInt *pts;
      PetscInt        n;

      PetscCall(DMGetLabel(dm, names[b], &label));
      PetscCall(DMLabelGetStratumIS(label, 1, &is));
      PetscCall(ISGetLocalSize(is, &n));
      PetscCall(ISGetIndices(is, &pts));
      for (PetscInt i = 0; i < n; ++i) {
        PetscReal len, m[2];

        if (pts[i] < eStart || pts[i] >= eEnd) continue;
        PetscCall(DMPlexComputeCellGeometryFVM(dm, pts[i], &len, m, NULL));
        a += sign[b] * 2.0 / 3.0 * len * (r[b] - PetscSqrtReal(m[0] * m[0] + m[1] * m[1]));
      }
      PetscCall(ISRestoreIndices(is, &pts));
      PetscCall(ISDestroy(&is));
    }
  }
  *area = a;
  PetscFunctionReturn(0);
}

/* (d) 1^T M 1 = 2 |Omega_h| (two components). */
static PetscErrorCode CheckMass(Roller ctx, DM dm, Mat M)
{
  Vec         one, Mone;
  PetscScalar m;
  PetscReal   area;

  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(M, &one, &Mone));
  PetscCall(VecSet(one, 1.0));
  PetscCall(MatMult(M, one, Mone));
  PetscCall(VecDot(one, Mone, &m));
  PetscCall(DiscreteArea(ctx, &area));
  PetscCheck(PetscAbsReal(PetscRealPart(m) / 2 - area) <= 1e-13 * area, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "P%" PetscInt_FMT " (d) 1^T M 1 / 2 = %.16g, the discrete area %.16g: relative difference %g > 1e-13", ctx->disc.degree, (double)(PetscRealPart(m) / 2), (double)area, (double)(PetscAbsReal(PetscRealPart(m) / 2 - area) / area));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "P%" PetscInt_FMT " (d) 1^T M 1 / 2 = %.15g = the discrete area to %.1e (pi (r_o^2 - r_i^2) = %.15g)\n", ctx->disc.degree, (double)(PetscRealPart(m) / 2), (double)(PetscAbsReal(PetscRealPart(m) / 2 - area) / area),
                        (double)(PETSC_PI * (PetscSqr(ctx->mesh.r_outer) - PetscSqr(ctx->mesh.r_inner)))));
  PetscCall(VecDestroy(&one));
  PetscCall(VecDestroy(&Mone));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  const Affine linear = {
    {0.3,   -0.45, 0.2, 0.15},
    {0.01, -0.02     }
  };
  Roller ctx;
  DM     dmK, dmM;
  Mat    K, M;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(RollerUnitAnnulus(&ctx)); /* one Roller per process: RollerCreate registers the log stages */
  PetscCall(CheckStress(ctx, &linear));
  PetscCall(FullForm(ctx, NULL, g3_elastic, &dmK, &K));
  PetscCall(FullForm(ctx, g0_mass, NULL, &dmM, &M));
  PetscCall(CheckStiffness(ctx, dmK, K, &linear));
  PetscCall(CheckMass(ctx, dmM, M));
  PetscCall(CheckFreeBlock(ctx, dmK, K, ctx->ops.K, "K"));
  PetscCall(CheckFreeBlock(ctx, dmM, M, ctx->ops.M, "M"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "P%" PetscInt_FMT ": ctx->ops.K and ctx->ops.M are the free-dof blocks of the forms\n", ctx->disc.degree));
  PetscCall(MatDestroy(&K));
  PetscCall(MatDestroy(&M));
  PetscCall(DMDestroy(&dmK));
  PetscCall(DMDestroy(&dmM));
  PetscCall(RollerDestroy(&ctx));
  PetscCall(PetscFinalize());
  return 0;
}
