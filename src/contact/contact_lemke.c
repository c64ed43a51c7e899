/* Lemke's complementary pivoting method for the LCP  w = M z + q >= 0, z >= 0, z . w = 0  (Cottle, Pang & Stone,
   The Linear Complementarity Problem, section 4.4), on a dense tableau with the covering vector e = 1. Coulomb
   friction in 2-D is such an LCP (contact_friction.c), and Lemke's method processes it (Stewart & Trinkle
   1996): the fallback when the fixed point of Tresca steps does not converge. It ends on a solution or on a
   secondary ray (*solved false). */
#include "contact_impl.h"

/* Pivot the tableau T (n rows, nc columns, row-major) and right-hand side on (r, col). */
static void Pivot(PetscReal *T, PetscReal *rhs, PetscInt n, PetscInt nc, PetscInt r, PetscInt col)
{
  const PetscReal piv = T[(size_t)r * nc + col];

  for (PetscInt j = 0; j < nc; ++j) T[(size_t)r * nc + j] /= piv;
  rhs[r] /= piv;
  for (PetscInt i = 0; i < n; ++i) {
    const PetscReal f = T[(size_t)i * nc + col];

    if (i == r || f == 0.0) continue;
    for (PetscInt j = 0; j < nc; ++j) T[(size_t)i * nc + j] -= f * T[(size_t)r * nc + j];
    rhs[i] -= f * rhs[r];
  }
}

/* The leaving row of the entering column: the least ratio rhs_i / T_i,enter over T_i,enter > eps; among ties the
   artificial variable (the method ends), else the lexicographic minimum of the rows of B^{-1} (the w columns)
   over T_i,enter, which rules out cycling on the degenerate problems friction gives (zero gaps, zero rows of q).
   -1: no such row (a ray). */
static PetscInt MinimumRatio(const PetscReal *T, const PetscReal *rhs, const PetscInt *basis, PetscInt n, PetscInt nc, PetscInt enter, PetscReal eps, PetscInt art)
{
  PetscReal rmin = PETSC_MAX_REAL;
  PetscInt  best = -1;

  for (PetscInt i = 0; i < n; ++i)
    if (T[(size_t)i * nc + enter] > eps) rmin = PetscMin(rmin, rhs[i] / T[(size_t)i * nc + enter]);
  if (rmin == PETSC_MAX_REAL) return -1;
  for (PetscInt i = 0; i < n; ++i) {
    const PetscReal a = T[(size_t)i * nc + enter];

    if (a <= eps || rhs[i] / a > rmin + 1e-13 * PetscMax(1.0, PetscAbsReal(rmin))) continue;
    if (basis[i] == art) return i;
    if (best < 0) {
      best = i;
      continue;
    }
    for (PetscInt j = 0; j < n; ++j) { /* lexicographic comparison of row i with row best */
      const PetscReal x = T[(size_t)i * nc + j] / a, y = T[(size_t)best * nc + j] / T[(size_t)best * nc + enter], tol = 1e-13 * PetscMax(1.0, PetscMax(PetscAbsReal(x), PetscAbsReal(y)));

      if (x < y - tol) best = i;
      if (x < y - tol || x > y + tol) break;
    }
  }
  return best;
}

/* Columns: w_0..w_{n-1}, z_0..z_{n-1}, z0 (the artificial variable); the tableau is [I, -M, -e | q]. */
PetscErrorCode RollerContactLemke(PetscInt n, const PetscReal M[], const PetscReal q[], PetscReal z[], PetscInt *pivots, PetscBool *solved)
{
  const PetscInt nc = 2 * n + 1, art = 2 * n, maxpiv = 50 * n + 100;
  PetscReal     *T, *rhs, qmin = 0.0, scale = 0.0;
  PetscInt      *basis, r = -1, enter;

  PetscFunctionBeginUser;
  *pivots = 0;
  *solved = PETSC_TRUE;
  for (PetscInt i = 0; i < n; ++i) z[i] = 0.0;
  for (PetscInt i = 0; i < n; ++i)
    if (q[i] < qmin) {
      qmin = q[i];
      r    = i;
    }
  if (r < 0) PetscFunctionReturn(0); /* q >= 0: z = 0 */
  PetscCall(PetscCalloc3((size_t)n * nc, &T, n, &rhs, n, &basis));
  for (PetscInt i = 0; i < n; ++i) {
    T[(size_t)i * nc + i] = 1.0;
    for (PetscInt j = 0; j < n; ++j) {
      T[(size_t)i * nc + n + j] = -M[i + (size_t)j * n];
      scale                     = PetscMax(scale, PetscAbsReal(M[i + (size_t)j * n]));
    }
    T[(size_t)i * nc + art] = -1.0;
    rhs[i]                  = q[i];
    basis[i]                = i;
  }
  Pivot(T, rhs, n, nc, r, art);
  enter    = n + r; /* the complement of w_r, which left */
  basis[r] = art;
  for (*pivots = 1; *pivots < maxpiv; ++*pivots) {
    const PetscReal eps = 1e-12 * PetscMax(1.0, scale);
    PetscInt        leave;

    r = MinimumRatio(T, rhs, basis, n, nc, enter, eps, art);
    if (r < 0) { /* a secondary ray */
      *solved = PETSC_FALSE;
      break;
    }
    leave = basis[r];
    Pivot(T, rhs, n, nc, r, enter);
    basis[r] = enter;
    if (leave == art) {
      for (PetscInt i = 0; i < n; ++i)
        if (basis[i] >= n && basis[i] < art) z[basis[i] - n] = PetscMax(0.0, rhs[i]);
      break;
    }
    enter = leave < n ? leave + n : leave - n;
  }
  if (*pivots >= maxpiv) *solved = PETSC_FALSE;
  PetscCall(PetscFree3(T, rhs, basis));
  PetscFunctionReturn(0);
}
