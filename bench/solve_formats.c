/* bench/solve_formats.c: how fast can the step matrix be applied? Times MatSolve of Roller's step matrix A with
   PETSc's own factorizations in several storage formats, interleaved (min over rounds, robust to a shared
   machine), and MatMult in the same formats (docs/performance.md, "Where a step goes").

   Dump A from a run (the first step's solve) and time it:
     build/roller -degree 2 -mesh_h 0.0125 -ts_dt 0.002 -coriolis_velocity extrapolated -ts_max_steps 1 \
                  -ksp_view_mat binary:A.bin
     mpicc -O2 -o solve_formats bench/solve_formats.c -I$PETSC_DIR/include -L$PETSC_DIR/lib -lpetsc_real \
           -Wl,-rpath,$PETSC_DIR/lib          # Debian: PETSC_DIR=/usr/lib/petscdir/petsc3.18/x86_64-linux-gnu-real
     ./solve_formats -f A.bin [-n 50 -rounds 7]
   The node-wise nested-dissection permutation keeps the two displacement components of a node together, which
   is what the 2x2 block formats (BAIJ, SBAIJ with block size 2) need; the factor has the same fill as Roller's. */
#include <petscmat.h>

#define NV 8
int main(int argc, char **argv)
{
  Mat            A, Ap, S, B, N, F[NV], Aref[NV], Mm[3];
  Vec            b, x, bp, y;
  PetscViewer    v;
  char           file[PETSC_MAX_PATH_LEN];
  const char    *name[NV];
  PetscInt       n = 50, rounds = 7, m, nn, nv = 0, *dp;
  IS             rows, nodeperm, dofperm, cp;
  const PetscInt *np;
  PetscLogDouble t0, t1, best[NV], bestmm[3], ftime[NV];
  PetscBool      isperm[NV];
  MatFactorInfo  info;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-f", file, sizeof(file), NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-n", &n, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-rounds", &rounds, NULL));
  PetscCall(PetscViewerBinaryOpen(PETSC_COMM_WORLD, file, FILE_MODE_READ, &v));
  PetscCall(MatCreate(PETSC_COMM_WORLD, &A));
  PetscCall(MatSetType(A, MATSEQAIJ));
  PetscCall(MatLoad(A, v));
  PetscCall(PetscViewerDestroy(&v));
  PetscCall(MatSetOption(A, MAT_SPD, PETSC_TRUE));
  PetscCall(MatGetSize(A, &m, NULL));
  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(VecDuplicate(b, &y));
  PetscCall(VecDuplicate(b, &bp));
  PetscCall(VecSetRandom(b, NULL));
  PetscCall(MatFactorInfoInitialize(&info));
  /* node-wise ND permutation of A */
  nn = m / 2;
  PetscCall(ISCreateStride(PETSC_COMM_SELF, nn, 0, 2, &rows));
  PetscCall(MatCreateSubMatrix(A, rows, rows, MAT_INITIAL_MATRIX, &N));
  PetscCall(MatGetOrdering(N, MATORDERINGND, &nodeperm, &cp));
  PetscCall(ISDestroy(&cp));
  PetscCall(ISGetIndices(nodeperm, &np));
  PetscCall(PetscMalloc1(m, &dp));
  for (PetscInt i = 0; i < nn; ++i) { dp[2 * i] = 2 * np[i]; dp[2 * i + 1] = 2 * np[i] + 1; }
  PetscCall(ISRestoreIndices(nodeperm, &np));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, m, dp, PETSC_OWN_POINTER, &dofperm));
  PetscCall(MatPermute(A, dofperm, dofperm, &Ap));
  PetscCall(MatSetBlockSize(Ap, 2));
  PetscCall(MatSetOption(Ap, MAT_SPD, PETSC_TRUE));
  PetscCall(MatConvert(Ap, MATSEQSBAIJ, MAT_INITIAL_MATRIX, &S));
  PetscCall(MatConvert(Ap, MATSEQBAIJ, MAT_INITIAL_MATRIX, &B));
  Mm[0] = A; Mm[1] = B; Mm[2] = S;
  {
    struct { Mat M; MatFactorType ft; MatOrderingType ord; const char *nm; PetscBool perm; } var[] = {
      {A, MAT_FACTOR_CHOLESKY, MATORDERINGND, "AIJ Cholesky ND (Roller default)", PETSC_FALSE},
      {A, MAT_FACTOR_CHOLESKY, MATORDERINGAMD, "AIJ Cholesky AMD", PETSC_FALSE},
      {A, MAT_FACTOR_LU, MATORDERINGND, "AIJ LU ND", PETSC_FALSE},
      {S, MAT_FACTOR_CHOLESKY, MATORDERINGNATURAL, "SBAIJ bs=2 Cholesky, node ND", PETSC_TRUE},
      {B, MAT_FACTOR_LU, MATORDERINGNATURAL, "BAIJ bs=2 LU, node ND", PETSC_TRUE},
      {B, MAT_FACTOR_CHOLESKY, MATORDERINGNATURAL, "BAIJ bs=2 Cholesky, node ND", PETSC_TRUE},
    };
    for (size_t k = 0; k < sizeof(var) / sizeof(var[0]); ++k) {
      IS             rp, cq;
      PetscErrorCode ierr;

      PetscCall(PetscTime(&t0));
      ierr = MatGetFactor(var[k].M, MATSOLVERPETSC, var[k].ft, &F[nv]);
      if (ierr || !F[nv]) { PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%-36s not available\n", var[k].nm)); continue; }
      PetscCall(MatGetOrdering(var[k].M, var[k].ord, &rp, &cq));
      if (var[k].ft == MAT_FACTOR_CHOLESKY) {
        PetscCall(MatCholeskyFactorSymbolic(F[nv], var[k].M, rp, &info));
        PetscCall(MatCholeskyFactorNumeric(F[nv], var[k].M, &info));
      } else {
        PetscCall(MatLUFactorSymbolic(F[nv], var[k].M, rp, cq, &info));
        PetscCall(MatLUFactorNumeric(F[nv], var[k].M, &info));
      }
      PetscCall(PetscTime(&t1));
      PetscCall(ISDestroy(&rp));
      PetscCall(ISDestroy(&cq));
      ftime[nv] = t1 - t0; name[nv] = var[k].nm; isperm[nv] = var[k].perm; Aref[nv] = var[k].perm ? Ap : A; best[nv] = 1e30;
      nv++;
    }
  }
  PetscCall(VecCopy(b, bp));
  for (int k = 0; k < 3; ++k) bestmm[k] = 1e30;
  for (PetscInt r = 0; r < rounds; ++r) {
    for (PetscInt k = 0; k < nv; ++k) {
      PetscCall(MatSolve(F[k], isperm[k] ? bp : b, x));
      PetscCall(PetscTime(&t0));
      for (PetscInt i = 0; i < n; ++i) PetscCall(MatSolve(F[k], isperm[k] ? bp : b, x));
      PetscCall(PetscTime(&t1));
      best[k] = PetscMin(best[k], (t1 - t0) / n);
    }
    for (int k = 0; k < 3; ++k) {
      PetscCall(PetscTime(&t0));
      for (PetscInt i = 0; i < n; ++i) PetscCall(MatMult(Mm[k], b, y));
      PetscCall(PetscTime(&t1));
      bestmm[k] = PetscMin(bestmm[k], (t1 - t0) / n);
    }
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "n = %" PetscInt_FMT ", min over %" PetscInt_FMT " interleaved rounds of %" PetscInt_FMT " calls\n", m, rounds, n));
  for (PetscInt k = 0; k < nv; ++k) {
    MatInfo   fi;
    Vec       r;
    PetscReal rn, bn;

    PetscCall(MatSolve(F[k], isperm[k] ? bp : b, x));
    PetscCall(VecDuplicate(b, &r));
    PetscCall(MatMult(Aref[k], x, r));
    PetscCall(VecAXPY(r, -1.0, isperm[k] ? bp : b));
    PetscCall(VecNorm(r, NORM_2, &rn));
    PetscCall(VecNorm(b, NORM_2, &bn));
    PetscCall(VecDestroy(&r));
    PetscCall(MatGetInfo(F[k], MAT_LOCAL, &fi));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "| %s | %.3f | %.2f | %.0f | %.2f | %.1e |\n", name[k], 1e3 * best[k], best[0] / best[k], fi.nz_used, ftime[k], (double)(rn / bn)));
    PetscCall(MatDestroy(&F[k]));
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "| MatMult AIJ | %.3f | | | | |\n| MatMult BAIJ bs=2 | %.3f | | | | |\n| MatMult SBAIJ bs=2 | %.3f | | | | |\n", 1e3 * bestmm[0], 1e3 * bestmm[1], 1e3 * bestmm[2]));
  PetscCall(MatDestroy(&S)); PetscCall(MatDestroy(&B)); PetscCall(MatDestroy(&Ap)); PetscCall(MatDestroy(&N)); PetscCall(MatDestroy(&A));
  PetscCall(ISDestroy(&rows)); PetscCall(ISDestroy(&nodeperm)); PetscCall(ISDestroy(&dofperm));
  PetscCall(VecDestroy(&b)); PetscCall(VecDestroy(&bp)); PetscCall(VecDestroy(&x)); PetscCall(VecDestroy(&y));
  PetscCall(PetscFinalize());
  return 0;
}
