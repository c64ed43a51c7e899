static const char help[] = "Unit test: the massless contact nodes M_red = T^T M T (model/mass.c, -contact_mass redistributed)\n"
                           "on the coarse annulus with the obstacle, P1 or P2, 1 or 2 ranks: (a) the kinetic energy of\n"
                           "every affine velocity is that of the consistent mass M: u^T M_red v = u^T M v for u, v in {1, x + 0.3, R x}\n"
                           "(x the nodal positions, R the rotation by -pi/2) to 1e-12 relative; (b) the rigid loads are those of M_red:\n"
                           "L_red - M_red u = L - M u (u = x, R x; nonzero only next to Gamma_D, from the clamped nodes' positions);\n"
                           "(c) every row and column of a Gamma_C dof of M_red, and the loads there, are exactly zero, every other\n"
                           "diagonal is positive; (d) A = rho/dt^2 M_red + K/2 is positive definite: a symmetric indefinite (MUMPS)\n"
                           "factorization of it has no negative and no zero pivot.\n";

#include "model/model.h"
#include "unit.h"
#include "model/kernels.h"

static PetscErrorCode Form(Mat M, Vec u, Vec v, Vec work, PetscReal *value)
{
  PetscScalar s;

  PetscFunctionBeginUser;
  PetscCall(MatMult(M, v, work));
  PetscCall(VecDot(u, work, &s));
  *value = PetscRealPart(s);
  PetscFunctionReturn(0);
}

/* (a) u^T M_red v against u^T M v for the affine fields; (b) the loads */
static PetscErrorCode CheckAffine(Roller ctx, Mat M)
{
  Vec         one, x, Rx, w;
  Vec         f[3];
  const char *name[3] = {"1", "x + 0.3", "R x"};
  PetscReal   a, b, mi, mj, err;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(ctx->ops.coordinates, &one));
  PetscCall(VecDuplicate(one, &Rx));
  PetscCall(VecDuplicate(one, &w));
  PetscCall(VecDuplicate(one, &x));
  PetscCall(VecSet(one, 1.0));
  PetscCall(RollerApplyRotate90(ctx, ctx->ops.coordinates, Rx));
  PetscCall(VecWAXPY(x, 0.3, one, ctx->ops.coordinates)); /* off the centre of mass, so x^T M 1 != 0 */
  f[0] = one;
  f[1] = x;
  f[2] = Rx;
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j <= i; ++j) {
      PetscCall(Form(M, f[i], f[j], w, &a));
      PetscCall(Form(ctx->ops.M, f[i], f[j], w, &b));
      PetscCall(Form(M, f[i], f[i], w, &mi));
      PetscCall(Form(M, f[j], f[j], w, &mj));
      err = PetscAbsReal(b - a) / PetscSqrtReal(mi * mj); /* relative to the bound |u^T M v| <= |u|_M |v|_M */
      PetscCheck(err <= 1e-12, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "P%" PetscInt_FMT " (a) (%s)^T M_red (%s) = %.16g differs from the consistent %.16g by %.2e relative > 1e-12", ctx->disc.degree, name[i], name[j], (double)b, (double)a, (double)err);
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "P%" PetscInt_FMT " (a) (%s)^T M_red (%s) = %.15g, consistent %.15g: relative difference %.1e\n", ctx->disc.degree, name[i], name[j], (double)b, (double)a, (double)err));
    }
  for (PetscInt k = 0; k < 2; ++k) { /* L_red - M_red u = T^T (L - M u) = L - M u (u = x or R x): L - M u is the load of
                                        the Dirichlet nodes' u, zero at Gamma_C */
    Vec       L = k ? ctx->ops.L_euler : ctx->ops.L_centrifugal, u = k ? Rx : ctx->ops.coordinates, Lc, d;
    PetscReal nl;

    PetscCall(RollerAssembleLoad(ctx, k ? f0_euler : f0_centrifugal, &Lc));
    PetscCall(VecDuplicate(Lc, &d));
    PetscCall(VecNorm(Lc, NORM_INFINITY, &nl));
    PetscCall(MatMult(M, u, w));
    PetscCall(VecWAXPY(d, -1.0, w, Lc)); /* L - M u */
    PetscCall(MatMult(ctx->ops.M, u, w));
    PetscCall(VecAXPY(d, 1.0, w));  /* + M_red u */
    PetscCall(VecAXPY(d, -1.0, L)); /* - L_red */
    PetscCall(VecNorm(d, NORM_INFINITY, &err));
    err /= nl;
    PetscCheck(err <= 1e-12, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "P%" PetscInt_FMT " (b) %s - M_red %s differs from the consistent L - M %s by %.2e relative > 1e-12", ctx->disc.degree, k ? "L_euler" : "L_centrifugal", k ? "R x" : "x", k ? "R x" : "x", (double)err);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "P%" PetscInt_FMT " (b) %s - M_red %s = the consistent L - M %s to %.1e relative\n", ctx->disc.degree, k ? "L_euler" : "L_centrifugal", k ? "R x" : "x", k ? "R x" : "x", (double)err));
    PetscCall(VecDestroy(&Lc));
    PetscCall(VecDestroy(&d));
  }
  PetscCall(VecDestroy(&one));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&Rx));
  PetscCall(VecDestroy(&w));
  PetscFunctionReturn(0);
}

/* (c) the rows of the owned Gamma_C dofs are empty or zero; M_red g = 0 for g = 1 on Gamma_C, 0 elsewhere (the
   columns); every other owned row has a positive diagonal */
static PetscErrorCode CheckZeroRows(Roller ctx)
{
  PetscSection gsec;
  DMLabel      outer;
  PetscInt     pStart, pEnd, counts[2] = {0, 0}, bad = 0;
  PetscReal    colmax;
  Vec          g, y;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(ctx->mesh.dm, &gsec));
  PetscCall(DMGetLabel(ctx->mesh.dm, "outer", &outer));
  PetscCall(PetscSectionGetChart(gsec, &pStart, &pEnd));
  PetscCall(VecDuplicate(ctx->ops.coordinates, &g));
  PetscCall(VecDuplicate(g, &y));
  PetscCall(VecZeroEntries(g));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt gdof, gcdof, goff, val;

    PetscCall(PetscSectionGetDof(gsec, p, &gdof));
    PetscCall(PetscSectionGetConstraintDof(gsec, p, &gcdof));
    PetscCall(PetscSectionGetOffset(gsec, p, &goff));
    if (gdof <= 0 || gdof == gcdof || goff < 0) continue;
    PetscCall(DMLabelGetValue(outer, p, &val));
    for (PetscInt c = 0; c < gdof - gcdof; ++c) {
      const PetscInt     row = goff + c;
      const PetscInt    *cols;
      const PetscScalar *vals;
      PetscInt           ncols;
      PetscReal          diag = 0, rowmax = 0;

      PetscCall(MatGetRow(ctx->ops.M, row, &ncols, &cols, &vals));
      for (PetscInt k = 0; k < ncols; ++k) {
        rowmax = PetscMax(rowmax, PetscAbsScalar(vals[k]));
        if (cols[k] == row) diag = PetscRealPart(vals[k]);
      }
      PetscCall(MatRestoreRow(ctx->ops.M, row, &ncols, &cols, &vals));
      if (val == 1) {
        PetscCall(VecSetValue(g, row, 1.0, INSERT_VALUES));
        counts[0]++;
        if (rowmax != 0) bad++;
      } else {
        counts[1]++;
        if (!(diag > 0)) bad++;
      }
    }
  }
  PetscCall(VecAssemblyBegin(g));
  PetscCall(VecAssemblyEnd(g));
  PetscCall(MatMult(ctx->ops.M, g, y));
  PetscCall(VecNorm(y, NORM_INFINITY, &colmax));
  for (PetscInt k = 0; k < 2; ++k) {
    PetscReal lmax;

    PetscCall(VecPointwiseMult(y, g, k ? ctx->ops.L_euler : ctx->ops.L_centrifugal));
    PetscCall(VecNorm(y, NORM_INFINITY, &lmax));
    if (lmax != 0) bad++;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCheck(counts[0] > 0 && !bad && colmax == 0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "P%" PetscInt_FMT " (c) %" PetscInt_FMT " rows or loads wrong (a non-zero Gamma_C row or load, or a non-positive other diagonal) of %" PetscInt_FMT " Gamma_C and %" PetscInt_FMT " other dofs; max |M_red g| over the Gamma_C columns %g",
             ctx->disc.degree, bad, counts[0], counts[1], (double)colmax);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "P%" PetscInt_FMT " (c) the %" PetscInt_FMT " Gamma_C rows and columns of M_red and entries of the loads are exactly zero, the other %" PetscInt_FMT " diagonals positive\n", ctx->disc.degree, counts[0], counts[1]));
  PetscCall(VecDestroy(&g));
  PetscCall(VecDestroy(&y));
  PetscFunctionReturn(0);
}

/* (d) the inertia of the step matrix A = rho/dt^2 M_red + K/2 (the DMF's; every scheme's is c_M M_red + c_K K with
   c_M, c_K > 0) from a symmetric-indefinite MUMPS factorization: all pivots positive */
static PetscErrorCode CheckDefinite(Roller ctx)
{
  Mat                B, F;
  MatFactorInfo      info;
  IS                 rperm, cperm;
  PetscInt           nneg, nzero, npos, n;
  RollerStepOperator op;

  PetscFunctionBeginUser;
  PetscCall(RollerStepOperatorCreate(ctx, ctx->material.density / (ctx->ts.dt * ctx->ts.dt), 0.5, 0.0, NULL, 0.0, 0, &op));
  PetscCall(MatDuplicate(op.A, MAT_COPY_VALUES, &B));
  PetscCall(RollerStepOperatorDestroy(&op));
  PetscCall(MatSetOption(B, MAT_SPD, PETSC_FALSE)); /* MUMPS's general symmetric mode, which reports the inertia */
  PetscCall(MatSetOption(B, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatGetFactor(B, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &F));
  PetscCall(MatMumpsSetIcntl(F, 13, 1)); /* the inertia in parallel: no ScaLAPACK root */
  PetscCall(MatMumpsSetIcntl(F, 24, 1)); /* null pivots detected, counted as zero */
  PetscCall(MatGetOrdering(B, MATORDERINGNATURAL, &rperm, &cperm));
  PetscCall(MatFactorInfoInitialize(&info));
  PetscCall(MatCholeskyFactorSymbolic(F, B, rperm, &info));
  PetscCall(MatCholeskyFactorNumeric(F, B, &info));
  PetscCall(MatGetInertia(F, &nneg, &nzero, &npos));
  PetscCall(MatGetSize(B, &n, NULL));
  PetscCheck(nneg == 0 && nzero == 0 && npos == n, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "P%" PetscInt_FMT " (d) A is not positive definite: inertia (negative, zero, positive) = (%" PetscInt_FMT ", %" PetscInt_FMT ", %" PetscInt_FMT ") of %" PetscInt_FMT,
             ctx->disc.degree, nneg, nzero, npos, n);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "P%" PetscInt_FMT " (d) A = rho/dt^2 M_red + K/2: %" PetscInt_FMT " positive pivots of %" PetscInt_FMT "\n", ctx->disc.degree, npos, n));
  PetscCall(ISDestroy(&rperm));
  PetscCall(ISDestroy(&cperm));
  PetscCall(MatDestroy(&F));
  PetscCall(MatDestroy(&B));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  Roller            ctx;
  Mat               M;
  const char *const scene[][2] = {
    {"-mesh_h",       "0.1"          },
    {"-ts_dt",        "0.01"         },
    {"-omega",        "0"            },
    {"-obstacle",     NULL           },
    {"-contact_mass", "redistributed"},
    {"-ts_max_time",  "1"            }
  };

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(RollerUnitSetUp(scene, ROLLER_UNIT_COUNT(scene), &ctx));
  PetscCall(RollerAssembleMatrix(ctx, "M", g0_mass, NULL, NULL, &M));
  PetscCall(CheckAffine(ctx, M));
  PetscCall(CheckZeroRows(ctx));
  PetscCall(CheckDefinite(ctx));
  PetscCall(MatDestroy(&M));
  PetscCall(RollerDestroy(&ctx));
  PetscCall(PetscFinalize());
  return 0;
}
