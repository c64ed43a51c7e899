static const char help[] = "Unit test: the 2-DOF mode-coupling (flutter) model of friction of Hoffmann, Fischer, Allgaier and Gaul (2002)\n"
                           "through the roller's quadratic-eigenproblem path (modes/pep.c: SLEPc PEP, TOAR, shift-and-invert). A point\n"
                           "mass m (x tangential, y normal) on two springs k1, k2 at angles alpha1, alpha2 and a contact spring k3 on a\n"
                           "belt sliding in +x: the friction mu N, N = -k3 y, makes K non-symmetric. Checks (docs/squeal.md section 5):\n"
                           "(a) undamped, mu below, at and above mu_c: every eigenvalue equals the closed-form root of the biquadratic\n"
                           "to 1e-10 relative (1e-7 at mu_c, where the pair is defective: rounding moves it by sqrt(eps));\n"
                           "(b) below mu_c every |re| < 1e-10 |lambda|; above, exactly one kept pair has re > 0, the closed-form growth rate\n"
                           "to 1e-10 relative; (c) mu_c by bisection on the PEP's largest real part equals the closed form\n"
                           "mu_c = ((k11 - k22)^2 + 4 k12^2) / (-4 k3 k12) to 1e-8; (d) with viscous damping C = diag(c1, c2) the\n"
                           "eigenvalues are roots of the quartic det(lambda^2 M + lambda C + K) (1e-12 relative to the sum of its terms)\n"
                           "and the critical mu found by bisection equals the Routh-Hurwitz closed form to 1e-8: above mu_c for proportional\n"
                           "damping (c1 = c2), below it for non-proportional damping, even as c1 -> 0 (the destabilization paradox).\n";

#include <slepcsys.h>
#include "modes/modes.h"

/* The model (SI-free, the values of docs/squeal.md section 5): the springs' unit vectors e_i = (cos alpha_i,
   sin alpha_i) point from the mass to their anchors above the belt; the stiffer spring upstream (alpha1 = 150 deg). */
typedef struct {
  PetscReal m, k1, k2, k3, alpha1, alpha2;
  PetscReal k11, k12, k22; /* k22 includes the contact spring k3 */
} Hoffmann;

static void HoffmannSetUp(Hoffmann *h)
{
  h->m      = 1.0;
  h->k1     = 2.0;
  h->k2     = 1.0;
  h->k3     = 1.0;
  h->alpha1 = 5 * PETSC_PI / 6;
  h->alpha2 = PETSC_PI / 6;
  h->k11    = h->k1 * PetscSqr(PetscCosReal(h->alpha1)) + h->k2 * PetscSqr(PetscCosReal(h->alpha2));
  h->k12    = h->k1 * PetscSinReal(h->alpha1) * PetscCosReal(h->alpha1) + h->k2 * PetscSinReal(h->alpha2) * PetscCosReal(h->alpha2);
  h->k22    = h->k1 * PetscSqr(PetscSinReal(h->alpha1)) + h->k2 * PetscSqr(PetscSinReal(h->alpha2)) + h->k3;
}

/* K(mu) = [k11, k12 + mu k3; k12, k22]: the friction force on the mass, mu N = -mu k3 y along +x, moved to the left. */
static void HoffmannK(const Hoffmann *h, PetscReal mu, PetscReal K[4])
{
  K[0] = h->k11;
  K[1] = h->k12 + mu * h->k3;
  K[2] = h->k12;
  K[3] = h->k22;
}

/* The undamped critical mu: the discriminant (k11 - k22)^2 + 4 k12 (k12 + mu k3) of the biquadratic in lambda^2 vanishes. */
static PetscReal HoffmannMuCritical(const Hoffmann *h)
{
  return (PetscSqr(h->k11 - h->k22) + 4 * PetscSqr(h->k12)) / (-4 * h->k3 * h->k12);
}

/* The quartic det(lambda^2 M + lambda C + K) = a[4] lambda^4 + ... + a[0], M = m I, C = diag(c1, c2). */
static void HoffmannQuartic(const Hoffmann *h, PetscReal mu, PetscReal c1, PetscReal c2, PetscReal a[5])
{
  PetscReal K[4];

  HoffmannK(h, mu, K);
  a[4] = h->m * h->m;
  a[3] = h->m * (c1 + c2);
  a[2] = h->m * (K[0] + K[3]) + c1 * c2;
  a[1] = c1 * K[3] + c2 * K[0];
  a[0] = K[0] * K[3] - K[1] * K[2];
}

/* The damped critical mu: the Hurwitz determinant a3 a2 a1 - a4 a1^2 - a3^2 a0 of the quartic vanishes; only a0 = det K
   depends on mu, linearly (a0 = k11 k22 - k12^2 - mu k3 k12). */
static PetscReal HoffmannMuCriticalDamped(const Hoffmann *h, PetscReal c1, PetscReal c2)
{
  PetscReal a[5], a0;

  HoffmannQuartic(h, 0.0, c1, c2, a);
  a0 = a[1] * (a[3] * a[2] - a[4] * a[1]) / PetscSqr(a[3]);
  return (h->k11 * h->k22 - h->k12 * h->k12 - a0) / (h->k3 * h->k12);
}

/* The closed-form roots with im >= 0 of the undamped m^2 lambda^4 + m tr(K) lambda^2 + det K = 0: i omega_{1,2},
   omega^2 = (tr K -+ sqrt(D)) / 2m for D >= 0; -sigma + i omega and sigma + i omega for D < 0 (flutter), with
   sigma^2 = (2 sqrt(det K) - tr K) / 4m, omega^2 = (2 sqrt(det K) + tr K) / 4m. */
static void HoffmannRoots(const Hoffmann *h, PetscReal mu, PetscReal re[2], PetscReal im[2])
{
  PetscReal K[4], tr, det, D;

  HoffmannK(h, mu, K);
  tr  = K[0] + K[3];
  det = K[0] * K[3] - K[1] * K[2];
  D   = PetscSqr(K[0] - K[3]) + 4 * K[1] * K[2];
  if (D >= 0) {
    re[0] = re[1] = 0;
    im[0]         = PetscSqrtReal((tr - PetscSqrtReal(D)) / (2 * h->m));
    im[1]         = PetscSqrtReal((tr + PetscSqrtReal(D)) / (2 * h->m));
  } else {
    re[1] = PetscSqrtReal((2 * PetscSqrtReal(det) - tr) / (4 * h->m));
    re[0] = -re[1];
    im[0] = im[1] = PetscSqrtReal((2 * PetscSqrtReal(det) + tr) / (4 * h->m));
  }
}

static PetscErrorCode Mat2x2(const PetscReal a[4], Mat *A)
{
  const PetscInt idx[2] = {0, 1};
  PetscScalar    v[4];

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < 4; ++i) v[i] = a[i];
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, 2, 2, 2, NULL, A));
  PetscCall(MatSetValues(*A, 2, idx, 2, idx, v, INSERT_VALUES)); /* all four, zeros too: one nonzero pattern for M, C, K */
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* The kept eigenvalues (im >= 0) of (lambda^2 M + lambda C + K(mu)) x = 0 through RollerPEP; n of them, at most 4. */
static PetscErrorCode Solve(const Hoffmann *h, PetscReal mu, PetscReal c1, PetscReal c2, PetscInt *n, PetscReal re[4], PetscReal im[4])
{
  PetscReal m[4] = {h->m, 0, 0, h->m}, c[4] = {c1, 0, 0, c2}, k[4];
  Mat       M, C, K;
  RollerPEP pep;

  PetscFunctionBeginUser;
  HoffmannK(h, mu, k);
  PetscCall(Mat2x2(m, &M));
  PetscCall(Mat2x2(c, &C));
  PetscCall(Mat2x2(k, &K));
  PetscCall(RollerPEPCreate(PETSC_COMM_SELF, M, C, K, 4, PETSC_FALSE, NULL, &pep));
  PetscCall(RollerPEPSolve(pep, n));
  PetscCheck(*n <= 4, PETSC_COMM_SELF, PETSC_ERR_PLIB, "mu = %g: %" PetscInt_FMT " kept eigenvalues of a 2-DOF problem", (double)mu, *n);
  for (PetscInt i = 0; i < *n; ++i) PetscCall(RollerPEPGetPair(pep, i, &re[i], &im[i], NULL, NULL));
  PetscCall(RollerPEPDestroy(&pep));
  PetscCall(MatDestroy(&M));
  PetscCall(MatDestroy(&C));
  PetscCall(MatDestroy(&K));
  PetscFunctionReturn(0);
}

/* The largest real part among the PEP's eigenvalues; every eigenvalue of the 2-DOF problem must have converged. */
static PetscErrorCode MaxReal(const Hoffmann *h, PetscReal mu, PetscReal c1, PetscReal c2, PetscReal *remax)
{
  PetscInt  n;
  PetscReal re[4], im[4];

  PetscFunctionBeginUser;
  PetscCall(Solve(h, mu, c1, c2, &n, re, im));
  PetscCheck(n == 2, PETSC_COMM_SELF, PETSC_ERR_PLIB, "mu = %g, c = (%g, %g): %" PetscInt_FMT " kept eigenvalues, expected 2 (two complex pairs)", (double)mu, (double)c1, (double)c2, n);
  *remax = PetscMax(re[0], re[1]);
  PetscFunctionReturn(0);
}

/* (c), (d): the mu in [lo, hi] where the largest real part first exceeds threshold, by bisection to 1e-11. */
static PetscErrorCode Bisect(const Hoffmann *h, PetscReal c1, PetscReal c2, PetscReal lo, PetscReal hi, PetscReal threshold, PetscReal *mu)
{
  PetscReal r;

  PetscFunctionBeginUser;
  PetscCall(MaxReal(h, lo, c1, c2, &r));
  PetscCheck(r <= threshold, PETSC_COMM_SELF, PETSC_ERR_PLIB, "c = (%g, %g): unstable (re %g) at the bracket's lower end mu = %g", (double)c1, (double)c2, (double)r, (double)lo);
  PetscCall(MaxReal(h, hi, c1, c2, &r));
  PetscCheck(r > threshold, PETSC_COMM_SELF, PETSC_ERR_PLIB, "c = (%g, %g): stable (re %g) at the bracket's upper end mu = %g", (double)c1, (double)c2, (double)r, (double)hi);
  while (hi - lo > 1e-11) {
    const PetscReal mid = 0.5 * (lo + hi);

    PetscCall(MaxReal(h, mid, c1, c2, &r));
    if (r > threshold) hi = mid;
    else lo = mid;
  }
  *mu = 0.5 * (lo + hi);
  PetscFunctionReturn(0);
}

/* (a), (b) at one mu of the undamped model */
static PetscErrorCode CheckUndamped(const Hoffmann *h, PetscReal mu, PetscReal tol)
{
  const PetscReal muc = HoffmannMuCritical(h);
  PetscInt        n, unstable = 0;
  PetscReal       re[4], im[4], xre[2], xim[2];
  PetscBool       used[2] = {PETSC_FALSE, PETSC_FALSE};

  PetscFunctionBeginUser;
  PetscCall(Solve(h, mu, 0.0, 0.0, &n, re, im));
  HoffmannRoots(h, mu, xre, xim);
  PetscCheck(n == 2, PETSC_COMM_SELF, PETSC_ERR_PLIB, "mu = %.12g: %" PetscInt_FMT " kept eigenvalues, expected 2", (double)mu, n);
  for (PetscInt i = 0; i < n; ++i) {
    const PetscReal a    = PetscSqrtReal(re[i] * re[i] + im[i] * im[i]);
    PetscInt        best = -1;
    PetscReal       dist = PETSC_MAX_REAL;

    for (PetscInt j = 0; j < 2; ++j) { /* the nearest closed-form root not matched yet: the kept pairs of a flutter share im */
      const PetscReal d = PetscSqrtReal(PetscSqr(re[i] - xre[j]) + PetscSqr(im[i] - xim[j]));

      if (!used[j] && d < dist) {
        dist = d;
        best = j;
      }
    }
    used[best] = PETSC_TRUE;
    PetscCheck(dist <= tol * a, PETSC_COMM_SELF, PETSC_ERR_PLIB, "(a) mu = %.12g: PEP eigenvalue %.15g + %.15gi differs from the closed form %.15g + %.15gi by %.2e relative > %.0e", (double)mu, (double)re[i], (double)im[i], (double)xre[best], (double)xim[best], (double)(dist / a), (double)tol);
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "(a) mu = %.12f: lambda = %+.3e + %.12fi, closed form %+.3e + %.12fi, relative difference %.1e\n", (double)mu, (double)re[i], (double)im[i], (double)xre[best], (double)xim[best], (double)(dist / a)));
    if (mu < muc) PetscCheck(PetscAbsReal(re[i]) < 1e-10 * a, PETSC_COMM_SELF, PETSC_ERR_PLIB, "(b) mu = %.12g < mu_c: re = %.3e, not 0 to 1e-10 |lambda|", (double)mu, (double)re[i]);
    if (re[i] > tol * a) { /* at mu_c the defective pair splits by O(sqrt(eps)): growing only beyond tol */
      ++unstable;
      PetscCheck(PetscAbsReal(re[i] - xre[1]) <= 1e-10 * xre[1], PETSC_COMM_SELF, PETSC_ERR_PLIB, "(b) mu = %.12g: growth rate %.15g, closed form %.15g: %.2e relative > 1e-10", (double)mu, (double)re[i], (double)xre[1], (double)(PetscAbsReal(re[i] - xre[1]) / xre[1]));
    }
  }
  if (mu > muc) {
    PetscCheck(unstable == 1, PETSC_COMM_SELF, PETSC_ERR_PLIB, "(b) mu = %.12g > mu_c: %" PetscInt_FMT " kept eigenvalues with re > 0, expected 1", (double)mu, unstable);
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "(b) mu = %.12f: one growing pair, growth rate %.15f (closed form %.15f)\n", (double)mu, (double)PetscMax(re[0], re[1]), (double)xre[1]));
  } else PetscCheck(unstable == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "(b) mu = %.12g <= mu_c: %" PetscInt_FMT " growing eigenvalues", (double)mu, unstable);
  PetscFunctionReturn(0);
}

/* (d) the PEP's eigenvalues are roots of the damped quartic: |p(lambda)| <= 1e-12 sum_k |a_k| |lambda|^k */
static PetscErrorCode CheckQuartic(const Hoffmann *h, PetscReal mu, PetscReal c1, PetscReal c2)
{
  PetscInt  n;
  PetscReal re[4], im[4], a[5];

  PetscFunctionBeginUser;
  PetscCall(Solve(h, mu, c1, c2, &n, re, im));
  PetscCheck(n == 2, PETSC_COMM_SELF, PETSC_ERR_PLIB, "(d) mu = %g, c = (%g, %g): %" PetscInt_FMT " kept eigenvalues, expected 2", (double)mu, (double)c1, (double)c2, n);
  HoffmannQuartic(h, mu, c1, c2, a);
  for (PetscInt i = 0; i < n; ++i) {
    PetscReal pr = 0, pi = 0, scale = 0, zr = 1, zi = 0, t, r;

    for (PetscInt k = 0; k <= 4; ++k) { /* sum a_k z^k, z^k by repeated products */
      pr += a[k] * zr;
      pi += a[k] * zi;
      scale += PetscAbsReal(a[k]) * PetscSqrtReal(zr * zr + zi * zi);
      t  = zr * re[i] - zi * im[i];
      zi = zr * im[i] + zi * re[i];
      zr = t;
    }
    r = PetscSqrtReal(pr * pr + pi * pi) / scale;
    PetscCheck(r <= 1e-12, PETSC_COMM_SELF, PETSC_ERR_PLIB, "(d) mu = %g, c = (%g, %g): PEP eigenvalue %.15g + %.15gi leaves the quartic at %.2e relative > 1e-12", (double)mu, (double)c1, (double)c2, (double)re[i], (double)im[i], (double)r);
  }
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  Hoffmann        h;
  PetscReal       muc, mu;
  const PetscReal below[] = {0.0, 0.3, 0.5}, above[] = {0.6, 0.7, 1.0};
  const PetscReal damping[][2] = {
    {0.05, 0.05}, /* proportional (C = 0.05 M): stabilizes, mu_d > mu_c */
    {0.1,  0.02}, /* non-proportional: destabilizes, mu_d < mu_c */
    {0.1,  0.0 }, /* tangential only: mu_d = sqrt(3)/4 whatever c1 */
    {1e-3, 0.0 }  /* ... however small: the destabilization paradox */
  };
  PetscReal mud[4];

  PetscCall(SlepcInitialize(&argc, &argv, NULL, help));
  HoffmannSetUp(&h);
  muc = HoffmannMuCritical(&h);
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "Hoffmann model: m %g, k1 %g, k2 %g, k3 %g, alpha1 %g deg, alpha2 %g deg: k11 %.15g, k12 %.15g, k22 %.15g; mu_c = %.15g (1/sqrt(3) = %.15g)\n", (double)h.m, (double)h.k1, (double)h.k2, (double)h.k3, (double)(h.alpha1 * 180 / PETSC_PI), (double)(h.alpha2 * 180 / PETSC_PI),
                        (double)h.k11, (double)h.k12, (double)h.k22, (double)muc, (double)(1 / PetscSqrtReal(3.0))));
  PetscCheck(PetscAbsReal(muc - 1 / PetscSqrtReal(3.0)) < 1e-14, PETSC_COMM_SELF, PETSC_ERR_PLIB, "mu_c = %.17g, expected 1/sqrt(3) for these values", (double)muc);
  /* (a), (b) */
  for (size_t i = 0; i < sizeof(below) / sizeof(below[0]); ++i) PetscCall(CheckUndamped(&h, below[i], 1e-10));
  PetscCall(CheckUndamped(&h, muc, 1e-7)); /* the defective double pair: O(sqrt(eps)) */
  for (size_t i = 0; i < sizeof(above) / sizeof(above[0]); ++i) PetscCall(CheckUndamped(&h, above[i], 1e-10));
  /* (c) the growth rate ~ sqrt(mu - mu_c) exceeds 1e-7 within 1e-12 of mu_c, and below mu_c rounding leaves |re| far under it */
  PetscCall(Bisect(&h, 0.0, 0.0, 0.3, 1.0, 1e-7, &mu));
  PetscCheck(PetscAbsReal(mu - muc) <= 1e-8, PETSC_COMM_SELF, PETSC_ERR_PLIB, "(c) mu_c by bisection on the PEP %.15g, closed form %.15g: %.2e > 1e-8", (double)mu, (double)muc, (double)PetscAbsReal(mu - muc));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "(c) mu_c: PEP bisection %.15f, closed form %.15f, difference %.1e\n", (double)mu, (double)muc, (double)PetscAbsReal(mu - muc)));
  /* (d) */
  for (PetscInt d = 0; d < 4; ++d) {
    const PetscReal c1 = damping[d][0], c2 = damping[d][1], exact = HoffmannMuCriticalDamped(&h, c1, c2);

    PetscCall(CheckQuartic(&h, 0.3, c1, c2));
    PetscCall(CheckQuartic(&h, exact, c1, c2));
    PetscCall(CheckQuartic(&h, 1.0, c1, c2));
    PetscCall(Bisect(&h, c1, c2, 0.3, 1.0, 0.0, &mud[d]));
    PetscCheck(PetscAbsReal(mud[d] - exact) <= 1e-8, PETSC_COMM_SELF, PETSC_ERR_PLIB, "(d) c = (%g, %g): critical mu by bisection on the PEP %.15g, Routh-Hurwitz %.15g: %.2e > 1e-8", (double)c1, (double)c2, (double)mud[d], (double)exact, (double)PetscAbsReal(mud[d] - exact));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "(d) c1 = %g, c2 = %g: critical mu: PEP bisection %.15f, Routh-Hurwitz %.15f, difference %.1e\n", (double)c1, (double)c2, (double)mud[d], (double)exact, (double)PetscAbsReal(mud[d] - exact)));
  }
  PetscCheck(mud[0] > muc && mud[1] < muc, PETSC_COMM_SELF, PETSC_ERR_PLIB, "(d) proportional damping should raise mu_c (%g), non-proportional lower it (%g); mu_c %g", (double)mud[0], (double)mud[1], (double)muc);
  for (PetscInt d = 2; d < 4; ++d) PetscCheck(PetscAbsReal(mud[d] - PetscSqrtReal(3.0) / 4) <= 1e-8, PETSC_COMM_SELF, PETSC_ERR_PLIB, "(d) c = (%g, 0): critical mu %.15g, expected sqrt(3)/4", (double)damping[d][0], (double)mud[d]);
  PetscCall(SlepcFinalize());
  return 0;
}
