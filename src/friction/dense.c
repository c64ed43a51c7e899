/* The small dense kernels of a step's contact and friction solves (coulomb.c, contact/contact_lcp.c: about 40
   unknowns, several times a step), the reference BLAS's arithmetic in the same order without its overhead.

   w = d + G (alpha x) (the slacks G x + d of Coulomb and the LCP, the reduced contact's residual r + R f_C/C): G's
   columns of the nonzero entries of x, times alpha x_b, added in their order, four a pass over w (each entry's sum in
   the order of one column at a time); w may be d.

   The LU factorization with partial pivoting of Coulomb's systems. Below LAPACK's block size (64) its dgetrf is the recursive dgetrf2
   (Toledo's algorithm: the left half of the columns factored, the row interchanges, a triangular solve and a matrix
   product to the right half, the right half factored), whose reference implementation spends more in its calls of
   dtrsm, dgemm and dlaswp on blocks of a few columns than in the arithmetic. This is that recursion with the three
   operations written out as the reference BLAS computes them, entry by entry in the same order (the pivot column
   scaled by the reciprocal of the pivot above the safe minimum), so the factors and the pivots are LAPACK's bit for
   bit (tests/unit/lu.c compares them); from the block size up it calls LAPACK. */
#include "friction/friction.h"
#include <float.h>
#include <petscblaslapack.h>

/* Rows k and piv[k]-1 (1-based pivots, as LAPACK's) interchanged for k in [k0, k1), in the columns [j0, j1). */
static void Swaps(PetscReal A[], PetscBLASInt lda, const PetscBLASInt piv[], PetscInt k0, PetscInt k1, PetscInt j0, PetscInt j1)
{
  for (PetscInt j = j0; j < j1; ++j)
    for (PetscInt k = k0; k < k1; ++k) {
      const PetscInt p = piv[k] - 1;

      if (p != k) {
        const PetscReal t = A[k + (size_t)j * lda];

        A[k + (size_t)j * lda] = A[p + (size_t)j * lda];
        A[p + (size_t)j * lda] = t;
      }
    }
}

/* dgetrf2 of the m x n block at A (leading dimension lda); *info the first zero pivot (1-based), else untouched. */
static void Factor(PetscInt m, PetscInt n, PetscReal A[], PetscBLASInt lda, PetscBLASInt piv[], PetscBLASInt *info)
{
  PetscInt     n1, n2, mn = PetscMin(m, n);
  PetscBLASInt sub = 0;

  if (m == 1) {
    piv[0] = 1;
    if (A[0] == 0.0 && !*info) *info = 1;
    return;
  }
  if (n == 1) { /* idamax (the first largest), the interchange, the scaling */
    PetscInt  p    = 0;
    PetscReal amax = PetscAbsReal(A[0]);

    for (PetscInt i = 1; i < m; ++i)
      if (PetscAbsReal(A[i]) > amax) {
        amax = PetscAbsReal(A[i]);
        p    = i;
      }
    piv[0] = (PetscBLASInt)(p + 1);
    if (A[p] == 0.0) {
      if (!*info) *info = 1;
      return;
    }
    if (p) {
      const PetscReal t = A[0];

      A[0] = A[p];
      A[p] = t;
    }
    if (PetscAbsReal(A[0]) >= DBL_MIN) {
      const PetscReal r = 1.0 / A[0];

      for (PetscInt i = 1; i < m; ++i) A[i] = r * A[i];
    } else
      for (PetscInt i = 1; i < m; ++i) A[i] = A[i] / A[0];
    return;
  }
  n1 = mn / 2;
  n2 = n - n1;
  Factor(m, n1, A, lda, piv, &sub);
  if (!*info && sub) *info = sub;
  Swaps(A, lda, piv, 0, n1, n1, n);
  for (PetscInt j = n1; j < n; ++j) { /* dtrsm (left, lower, unit): A12 = L11^-1 A12 */
    PetscReal *b = A + (size_t)j * lda;

    for (PetscInt k = 0; k < n1; ++k)
      if (b[k] != 0.0)
        for (PetscInt i = k + 1; i < n1; ++i) b[i] -= b[k] * A[i + (size_t)k * lda];
  }
  for (PetscInt j = n1; j < n; ++j) { /* dgemm: A22 -= A21 A12 */
    PetscReal *cj = A + (size_t)j * lda;

    for (PetscInt l = 0; l < n1; ++l) {
      const PetscReal  t  = -cj[l];
      const PetscReal *al = A + (size_t)l * lda;

      for (PetscInt i = n1; i < m; ++i) cj[i] += t * al[i];
    }
  }
  sub = 0;
  Factor(m - n1, n2, A + n1 + (size_t)n1 * lda, lda, piv + n1, &sub);
  if (!*info && sub) *info = sub + (PetscBLASInt)n1;
  for (PetscInt i = n1; i < mn; ++i) piv[i] += (PetscBLASInt)n1;
  Swaps(A, lda, piv, n1, mn, 0, n1);
}

PetscErrorCode RollerDenseLUFactor(PetscBLASInt n, PetscReal A[], PetscBLASInt piv[], PetscBLASInt *info)
{
  PetscFunctionBeginUser;
  *info = 0;
  if (n >= 64) PetscCallBLAS("LAPACKgetrf", LAPACKgetrf_(&n, &n, A, &n, piv, info));
  else if (n > 0) Factor(n, n, A, n, piv, info);
  PetscFunctionReturn(0);
}

void RollerDenseMultAdd(PetscInt n, const PetscReal G[], const PetscReal d[], PetscReal alpha, const PetscReal x[], PetscReal w[])
{
  PetscInt b = 0;

  for (PetscInt a = 0; a < n; ++a) w[a] = d[a];
  while (b < n) {
    const PetscReal *col[4];
    PetscReal        xb[4];
    PetscInt         nb = 0;

    for (; b < n && nb < 4; ++b)
      if (x[b] != 0.0) {
        col[nb]  = G + (size_t)b * n;
        xb[nb++] = alpha * x[b];
      }
    if (nb == 4)
      for (PetscInt a = 0; a < n; ++a) {
        PetscReal t = w[a];

        t += col[0][a] * xb[0];
        t += col[1][a] * xb[1];
        t += col[2][a] * xb[2];
        t += col[3][a] * xb[3];
        w[a] = t;
      }
    else
      for (PetscInt k = 0; k < nb; ++k)
        for (PetscInt a = 0; a < n; ++a) w[a] += col[k][a] * xb[k];
  }
}
