static const char help[] = "Unit test: the LU factorization of Coulomb's small systems (friction/dense.c) is LAPACK's dgetrf bit for bit\n"
                           "(factors, pivots, the first zero pivot) on random systems of 1 to 100 unknowns, with zero entries,\n"
                           "entries over seven decades, diagonally dominant and not, singular ones, and the systems' solves\n"
                           "reach round-off.\n";

#include "friction/friction.h"
#include <petscblaslapack.h>
#include <string.h>

int main(int argc, char **argv)
{
  PetscRandom r;
  PetscInt    checked = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &r));
  PetscCall(PetscRandomSetFromOptions(r));
  for (PetscInt trial = 0; trial < 1200; ++trial) {
    const PetscBLASInt n = (PetscBLASInt)(1 + trial % 100);
    PetscReal         *A, *B, *C, *x;
    PetscBLASInt      *p, *q, info_a = 0, info_b = 0, one = 1, info;

    PetscCall(PetscMalloc4((size_t)n * n, &A, (size_t)n * n, &B, (size_t)n * n, &C, n, &x));
    PetscCall(PetscMalloc2(n, &p, n, &q));
    for (PetscInt k = 0; k < (PetscInt)n * n; ++k) {
      PetscReal u, z, e;

      PetscCall(PetscRandomGetValueReal(r, &u));
      PetscCall(PetscRandomGetValueReal(r, &z));
      PetscCall(PetscRandomGetValueReal(r, &e));
      A[k] = z < 0.2 ? 0.0 : (u - 0.5) * PetscPowReal(10.0, PetscFloorReal(7 * e) - 3);
    }
    if (trial % 3 == 0)
      for (PetscInt k = 0; k < n; ++k) A[k + (size_t)k * n] += 5.0; /* Coulomb's systems: dominant gap rows */
    if (trial % 17 == 5 && n > 2)
      for (PetscInt k = 0; k < n; ++k) A[k + (size_t)(n - 1) * n] = A[k]; /* two equal columns: singular */
    for (PetscInt k = 0; k < n; ++k) x[k] = 1.0 + k;
    PetscCall(PetscArraycpy(B, A, (size_t)n * n));
    PetscCall(PetscArraycpy(C, A, (size_t)n * n));
    PetscCallBLAS("LAPACKgetrf", LAPACKgetrf_(&n, &n, A, &n, p, &info_a));
    PetscCall(RollerDenseLUFactor(n, B, q, &info_b));
    PetscCheck(info_a == info_b, PETSC_COMM_SELF, PETSC_ERR_PLIB, "n = %d (trial %" PetscInt_FMT "): LAPACK's info %d, dense.c's %d", (int)n, trial, (int)info_a, (int)info_b);
    for (PetscInt k = 0; k < n; ++k) PetscCheck(p[k] == q[k], PETSC_COMM_SELF, PETSC_ERR_PLIB, "n = %d (trial %" PetscInt_FMT "): pivot %" PetscInt_FMT " LAPACK's %d, dense.c's %d", (int)n, trial, k, (int)p[k], (int)q[k]);
    for (PetscInt k = 0; k < (PetscInt)n * n; ++k)
      PetscCheck(memcmp(&A[k], &B[k], sizeof(PetscReal)) == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "n = %d (trial %" PetscInt_FMT "): factor entry %" PetscInt_FMT " LAPACK's %.17g, dense.c's %.17g", (int)n, trial, k, (double)A[k], (double)B[k]);
    if (!info_b) { /* the solve through the factors: the residual of C x = b against |C| |x| */
      PetscReal res = 0.0, scale = 0.0;

      PetscCallBLAS("LAPACKgetrs", LAPACKgetrs_("N", &n, &one, B, &n, q, x, &n, &info));
      PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "getrs info %d", (int)info);
      for (PetscInt i = 0; i < n; ++i) {
        PetscReal ri = -(1.0 + i), si = 0.0;

        for (PetscInt j = 0; j < n; ++j) {
          ri += C[i + (size_t)j * n] * x[j];
          si += PetscAbsReal(C[i + (size_t)j * n] * x[j]);
        }
        res   = PetscMax(res, PetscAbsReal(ri));
        scale = PetscMax(scale, si);
      }
      if (res <= 1e-9 * scale) checked++; /* (a random matrix may be nearly singular: counted, not failed) */
    }
    PetscCall(PetscFree4(A, B, C, x));
    PetscCall(PetscFree2(p, q));
  }
  PetscCheck(checked > 1000, PETSC_COMM_SELF, PETSC_ERR_PLIB, "only %" PetscInt_FMT " of the systems solved to round-off", checked);
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "dense.c: LAPACK's factors and pivots bit for bit on 1200 systems (%" PetscInt_FMT " solved to round-off)\n", checked));
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(PetscFinalize());
  return 0;
}
