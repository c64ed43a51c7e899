static const char help[] = "Unit test: the measured friction curve of -friction_table (friction/law.c): its monotone cubic interpolant\n"
                           "is exact at the points, monotone and within its two points on every interval (no overshoot on a\n"
                           "table that rises and then falls: slope 0 at the peak), has a continuous derivative equal to central\n"
                           "differences, is constant beyond the ends and even in v; sampled from the exponential law it\n"
                           "reproduces it to the bound the docs give; bad tables are refused.\n";

#include "friction/friction.h"

/* Dense samples of every interval of tab: the interpolant stays between the interval's points (to round-off) and is
   monotone from one to the other; its derivative matches central differences; the largest |mu - mu_near| where the
   interval is flat. */
static PetscErrorCode CheckShape(const char name[], const RollerFrictionTable *tab)
{
  const PetscInt  N   = 400;
  const PetscReal eps = 1e-14 * tab->mu[0];
  PetscReal       dd = 0.0, dscale = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < tab->n; ++i) {
    PetscReal dmu, mu = RollerFrictionTableMu(tab, tab->v[i], &dmu);

    PetscCheck(mu == tab->mu[i], PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: mu(v_%" PetscInt_FMT " = %g) = %.17g, not the point's %.17g", name, i + 1, (double)tab->v[i], (double)mu, (double)tab->mu[i]);
    dscale = PetscMax(dscale, PetscAbsReal(tab->s[i]));
  }
  for (PetscInt i = 0; i + 1 < tab->n; ++i) {
    const PetscReal lo = PetscMin(tab->mu[i], tab->mu[i + 1]), hi = PetscMax(tab->mu[i], tab->mu[i + 1]), dir = tab->mu[i + 1] - tab->mu[i], h = tab->v[i + 1] - tab->v[i];
    PetscReal       prev = tab->mu[i];

    for (PetscInt k = 1; k <= N; ++k) {
      const PetscReal v = tab->v[i] + h * k / N, dv = 1e-6 * h;
      PetscReal       dmu, mu                       = RollerFrictionTableMu(tab, v, &dmu);

      PetscCheck(mu >= lo - eps && mu <= hi + eps, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: mu(%g) = %.17g overshoots the interval's points %g, %g", name, (double)v, (double)mu, (double)tab->mu[i], (double)tab->mu[i + 1]);
      PetscCheck(dir > 0 ? mu >= prev - eps : (dir < 0 ? mu <= prev + eps : PetscAbsReal(mu - prev) <= eps), PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: not monotone between v = %g and %g: mu %.17g after %.17g", name, (double)tab->v[i], (double)tab->v[i + 1], (double)mu, (double)prev);
      PetscCheck(dir > 0 ? dmu >= -1e-12 * dscale : (dir < 0 ? dmu <= 1e-12 * dscale : PetscAbsReal(dmu) <= 1e-12 * dscale), PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: the slope %g at v = %g points against the interval's %g", name, (double)dmu, (double)v, (double)dir);
      if (k < N) { /* central differences: O(dv^2 mu''') + round-off 1e-16 mu / dv */
        const PetscReal fd = (RollerFrictionTableMu(tab, v + dv, NULL) - RollerFrictionTableMu(tab, v - dv, NULL)) / (2 * dv);

        dd = PetscMax(dd, PetscAbsReal(fd - dmu));
      }
      prev = mu;
    }
  }
  PetscCheck(dd <= 1e-6 * dscale, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: the derivative differs from central differences by %g (slopes up to %g)", name, (double)dd, (double)dscale);
  for (PetscInt i = 1; i + 1 < tab->n; ++i) { /* continuous slope across the inner points: the two cubics' end slopes agree
                                                 (to dv mu'', mu'' at most 6 times the larger secant over h) */
    const PetscReal h0 = tab->v[i] - tab->v[i - 1], h1 = tab->v[i + 1] - tab->v[i], dv = 1e-9 * PetscMin(h0, h1);
    const PetscReal S = PetscMax(PetscAbsReal(tab->mu[i] - tab->mu[i - 1]) / h0, PetscAbsReal(tab->mu[i + 1] - tab->mu[i]) / h1);
    PetscReal       dl, dr;

    (void)RollerFrictionTableMu(tab, tab->v[i] - dv, &dl);
    (void)RollerFrictionTableMu(tab, tab->v[i] + dv, &dr);
    PetscCheck(PetscAbsReal(dl - dr) <= 1e-7 * S + 1e-12, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: the slope jumps at v_%" PetscInt_FMT " = %g: %g left, %g right", name, i + 1, (double)tab->v[i], (double)dl, (double)dr);
    if ((tab->mu[i] - tab->mu[i - 1]) * (tab->mu[i + 1] - tab->mu[i]) <= 0) PetscCheck(tab->s[i] == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: the slope at the turning point v_%" PetscInt_FMT " is %g, not 0", name, i + 1, (double)tab->s[i]);
  }
  { /* constant beyond the ends (below v_1 if v_1 > 0), even in v */
    PetscReal d0 = 0, d1, d2;
    PetscReal m0 = tab->v[0] > 0 ? RollerFrictionTableMu(tab, 0.5 * tab->v[0], &d0) : tab->mu[0], m1 = RollerFrictionTableMu(tab, 2 * tab->v[tab->n - 1] + 1, &d1), m2 = RollerFrictionTableMu(tab, -tab->v[1], &d2);

    PetscCheck(m0 == tab->mu[0] && m1 == tab->mu[tab->n - 1] && d0 == 0 && d1 == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: not constant beyond the ends: %g (slope %g), %g (slope %g)", name, (double)m0, (double)d0, (double)m1, (double)d1);
    PetscCheck(m2 == tab->mu[1], PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: mu(-v_2) = %g, not mu(v_2) = %g", name, (double)m2, (double)tab->mu[1]);
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s: %" PetscInt_FMT " points: exact at the points, monotone and within them on every interval (%" PetscInt_FMT " samples each), slope within %.1e of central differences, continuous\n", name, tab->n, N, (double)dd));
  PetscFunctionReturn(0);
}

/* The exponential law mu + (mu_s - mu) exp(-v/v_c) sampled at v = 0, h, 2h, ..., 12 v_c: the interpolant's largest
   error in mu and mu' over [0, 12 v_c] against the law (RollerFrictionMu without a table), relative to mu_s - mu. */
static PetscErrorCode SampledExponential(PetscInt per_vc, PetscReal *err, PetscReal *derr)
{
  RollerObstacle  o   = {0};
  const PetscReal v_c = 0.03, h = v_c / per_vc;
  const PetscInt  n = 12 * per_vc + 1;
  char           *text, entry[64];

  PetscFunctionBeginUser;
  o.friction        = 0.5;
  o.friction_static = 1.0;
  o.friction_decay  = v_c;
  PetscCall(PetscCalloc1((size_t)n * 64, &text));
  for (PetscInt i = 0; i < n; ++i) {
    PetscCall(PetscSNPrintf(entry, sizeof(entry), "%s%.17g:%.17g", i ? "," : "", (double)(i * h), (double)RollerFrictionMu(&o, i * h, NULL)));
    PetscCall(PetscStrlcat(text, entry, (size_t)n * 64));
  }
  {
    RollerObstacle t = o;

    PetscCall(RollerFrictionTableSetUp(PETSC_COMM_SELF, text, &t.table));
    *err = *derr = 0;
    for (PetscInt k = 0; k <= 100 * (n - 1); ++k) {
      const PetscReal v = k * h / 100;
      PetscReal       d, dt, m = RollerFrictionMu(&o, v, &d), mt = RollerFrictionMu(&t, v, &dt);

      *err  = PetscMax(*err, PetscAbsReal(mt - m) / 0.5);
      *derr = PetscMax(*derr, PetscAbsReal(dt - d) * v_c / 0.5);
    }
    PetscCall(RollerFrictionTableDestroy(&t.table));
  }
  PetscCall(PetscFree(text));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  RollerFrictionTable tab   = {0};
  const char *const   bad[] = {"", "0:1", "0:1,0:2", "0:1,0.1:0.9,0.05:1", "-1:1,1:2", "0:1,1:0", "0:1,1:-0.5", "0:1,x:2", "0:1,1:2,", "0:1;1:2", "0:1,1:nan", "0:1,inf:2", "0:1,1:2:3"};
  PetscReal           e[2], de[2];

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  /* rubber on paper: rises at low slip speed, falls at higher (the rise-then-fall) */
  PetscCall(RollerFrictionTableSetUp(PETSC_COMM_SELF, "0:0.6,0.002:0.75,0.01:1.05,0.05:0.95,0.3:0.8,1:0.78,3:0.78", &tab));
  PetscCall(CheckShape("rise-then-fall", &tab));
  {
    RollerObstacle o = {0};
    PetscReal      range[2], vmax = 0, mmax = 0;

    o.table = tab;
    RollerFrictionRange(&o, range);
    PetscCheck(range[0] == 0.6 && range[1] == 1.05 && RollerFrictionVaries(&o), PETSC_COMM_SELF, PETSC_ERR_PLIB, "rise-then-fall: range [%g, %g], expected [0.6, 1.05]", (double)range[0], (double)range[1]);
    for (PetscInt k = 0; k <= 30000; ++k) { /* the peak is the largest point, not beyond it */
      const PetscReal v = 1e-4 * k, m = RollerFrictionMu(&o, v, NULL);

      if (m > mmax) mmax = m, vmax = v;
    }
    PetscCheck(mmax <= 1.05 && PetscAbsReal(vmax - 0.01) <= 1e-4 && RollerFrictionMu(&o, 0.01, NULL) == 1.05, PETSC_COMM_SELF, PETSC_ERR_PLIB, "rise-then-fall: the largest mu %.17g at v = %g, not the point's 1.05 at 0.01", (double)mmax, (double)vmax);
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "rise-then-fall: the largest mu over [0, 3] is the peak point's 1.05 at v = 0.01 (slope 0 there); the range [%g, %g]\n", (double)range[0], (double)range[1]));
  }
  PetscCall(RollerFrictionTableDestroy(&tab));
  /* a flat stretch stays flat; two points are a straight line; a monotone table gives a monotone curve */
  PetscCall(RollerFrictionTableSetUp(PETSC_COMM_SELF, "0.001:1,0.01:1,0.02:0.7,0.5:0.7,0.6:0.9", &tab));
  PetscCall(CheckShape("flat stretches", &tab));
  PetscCall(RollerFrictionTableSetUp(PETSC_COMM_SELF, " 0 : 0.9 , 2 : 0.5", &tab));
  PetscCall(CheckShape("two points", &tab));
  PetscCheck(PetscAbsReal(RollerFrictionTableMu(&tab, 0.5, NULL) - 0.8) < 1e-15, PETSC_COMM_SELF, PETSC_ERR_PLIB, "two points: mu(0.5) = %.17g, not the line's 0.8", (double)RollerFrictionTableMu(&tab, 0.5, NULL));
  PetscCall(RollerFrictionTableDestroy(&tab));

  /* the exponential law sampled densely: the interpolation error falls as h^3 or faster (PCHIP: O(h^3) where the
     data are strictly monotone); docs/friction.md section 1 states the bound 1e-4 (mu_s - mu) at h = v_c/10 */
  PetscCall(SampledExponential(10, &e[0], &de[0]));
  PetscCall(SampledExponential(20, &e[1], &de[1]));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "exponential law sampled at h = v_c/10, v_c/20 on [0, 12 v_c]: |mu - law| <= %.2e, %.2e (mu_s - mu) (ratio %.1f); |mu' - law'| <= %.2e, %.2e (mu_s - mu)/v_c\n", (double)e[0], (double)e[1], (double)(e[0] / e[1]), (double)de[0], (double)de[1]));
  PetscCheck(e[0] < 1e-4 && e[0] / e[1] > 6 && de[0] < 1e-2, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the sampled exponential law: error %g (h = v_c/10), %g (v_c/20), slope error %g", (double)e[0], (double)e[1], (double)de[0]);

  /* refused tables: every one an error (the messages are tests/bad_input.py's) */
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); ++i) {
    PetscErrorCode ierr = RollerFrictionTableSetUp(PETSC_COMM_SELF, bad[i], &tab);

    PetscCheck(ierr != 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the table '%s' was accepted", bad[i]);
  }
  PetscCall(PetscPopErrorHandler());
  PetscCall(RollerFrictionTableDestroy(&tab));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%d bad tables refused\n", (int)(sizeof(bad) / sizeof(bad[0]))));
  PetscCall(PetscFinalize());
  return 0;
}
