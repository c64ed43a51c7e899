/* Anderson acceleration of the friction's fixed points (docs/friction.md section 3): the coefficients mu(v) of the
   velocity weakening about a Coulomb solve, and (lambda_N, mu) of the Tresca steps. With the weakening the map's
   gain approaches 1 where the slip speed is small against v_c (1 - 0.85 per pass was measured on the printer
   roller: 50 passes left a change of 1.5e-9), and damping it slows it further (the gain is positive: a larger mu
   gives less slip and a larger mu(v)). Anderson's method (Walker & Ni, SIAM J. Numer. Anal. 49 (2011) 1715,
   "Type II"): with f = g(x) - x and the differences dF, dG of the last `depth` iterates,
     gamma = argmin ||f_k - dF gamma||,   x_{k+1} = g(x_k) - dG gamma,
   the least-squares problem solved by its normal equations (a few unknowns; a relative Tikhonov shift 1e-12 of
   its diagonal drops columns that have become dependent). On a linear map it is GMRES, so a gain near 1 costs a
   few passes instead of hundreds. Safeguarded: an iterate whose residual ||f|| did not shrink restarts the history
   with the plain step x = g (the map is not smooth where a node changes between stick and slip, and a repeated
   iterate would make the history degenerate). */
#include "contact_impl.h"

PetscErrorCode RollerContactAndersonCreate(PetscInt n, PetscInt depth, RollerContactAnderson *aa)
{
  PetscFunctionBeginUser;
  aa->cap   = n;
  aa->depth = depth;
  aa->n = aa->k = aa->next = 0;
  aa->have                 = PETSC_FALSE;
  PetscCall(PetscMalloc4((size_t)n * depth, &aa->dF, (size_t)n * depth, &aa->dG, n, &aa->f, n, &aa->g));
  PetscFunctionReturn(0);
}

/* A new fixed point of n unknowns (n <= the capacity): no history. */
void RollerContactAndersonReset(RollerContactAnderson *aa, PetscInt n)
{
  aa->n = n;
  aa->k = aa->next = 0;
  aa->have         = PETSC_FALSE;
}

/* x (in) the iterate, g (in) its image; x (out) the next iterate. The first call after a reset returns g. */
PetscErrorCode RollerContactAndersonStep(RollerContactAnderson *aa, PetscReal x[], const PetscReal g[])
{
  const PetscInt n = aa->n;
  PetscReal      A[ROLLER_ANDERSON_MAX * ROLLER_ANDERSON_MAX], b[ROLLER_ANDERSON_MAX], gamma[ROLLER_ANDERSON_MAX] = {0};
  PetscInt       k;

  PetscFunctionBeginUser;
  PetscCheck(aa->depth <= ROLLER_ANDERSON_MAX, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Anderson depth %" PetscInt_FMT " > %d", aa->depth, ROLLER_ANDERSON_MAX);
  { /* the safeguard: an iterate that did not shrink ||f|| restarts the history with the plain step */
    PetscReal fn = 0.0;

    for (PetscInt i = 0; i < n; ++i) fn += (g[i] - x[i]) * (g[i] - x[i]);
    if (aa->have && aa->k && fn >= aa->fnorm) aa->have = PETSC_FALSE, aa->k = aa->next = 0;
    aa->fnorm = fn;
  }
  if (aa->have) { /* the differences to the previous pair, into the circular history */
    PetscReal *dF = aa->dF + (size_t)aa->next * n, *dG = aa->dG + (size_t)aa->next * n;

    for (PetscInt i = 0; i < n; ++i) {
      dF[i] = (g[i] - x[i]) - aa->f[i];
      dG[i] = g[i] - aa->g[i];
    }
    aa->next = (aa->next + 1) % aa->depth;
    aa->k    = PetscMin(aa->k + 1, aa->depth);
  }
  for (PetscInt i = 0; i < n; ++i) {
    aa->f[i] = g[i] - x[i];
    aa->g[i] = g[i];
  }
  aa->have = PETSC_TRUE;
  k        = aa->k;
  if (!k) {
    for (PetscInt i = 0; i < n; ++i) x[i] = g[i];
    PetscFunctionReturn(0);
  }
  for (PetscInt p = 0; p < k; ++p) {
    const PetscReal *Fp = aa->dF + (size_t)p * n;

    b[p] = 0.0;
    for (PetscInt i = 0; i < n; ++i) b[p] += Fp[i] * aa->f[i];
    for (PetscInt q = 0; q < k; ++q) {
      const PetscReal *Fq = aa->dF + (size_t)q * n;
      PetscReal        s  = 0.0;

      for (PetscInt i = 0; i < n; ++i) s += Fp[i] * Fq[i];
      A[p + q * k] = s;
    }
  }
  { /* Gaussian elimination with partial pivoting of the shifted normal equations */
    PetscReal tr = 0.0;

    for (PetscInt p = 0; p < k; ++p) tr = PetscMax(tr, A[p + p * k]);
    for (PetscInt p = 0; p < k; ++p) A[p + p * k] += 1e-12 * tr + 1e-300;
    for (PetscInt c = 0; c < k; ++c) {
      PetscInt piv = c;

      for (PetscInt r = c + 1; r < k; ++r)
        if (PetscAbsReal(A[r + c * k]) > PetscAbsReal(A[piv + c * k])) piv = r;
      if (piv != c) {
        for (PetscInt q = 0; q < k; ++q) {
          const PetscReal t = A[c + q * k];

          A[c + q * k]   = A[piv + q * k];
          A[piv + q * k] = t;
        }
        {
          const PetscReal t = b[c];

          b[c]   = b[piv];
          b[piv] = t;
        }
      }
      for (PetscInt r = c + 1; r < k; ++r) {
        const PetscReal l = A[r + c * k] / A[c + c * k];

        for (PetscInt q = c; q < k; ++q) A[r + q * k] -= l * A[c + q * k];
        b[r] -= l * b[c];
      }
    }
    for (PetscInt c = k - 1; c >= 0; --c) {
      PetscReal s = b[c];

      for (PetscInt q = c + 1; q < k; ++q) s -= A[c + q * k] * gamma[q];
      gamma[c] = s / A[c + c * k];
    }
  }
  for (PetscInt i = 0; i < n; ++i) {
    PetscReal s = g[i];

    for (PetscInt p = 0; p < k; ++p) s -= aa->dG[(size_t)p * n + i] * gamma[p];
    x[i] = s;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactAndersonDestroy(RollerContactAnderson *aa)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree4(aa->dF, aa->dG, aa->f, aa->g));
  PetscFunctionReturn(0);
}
