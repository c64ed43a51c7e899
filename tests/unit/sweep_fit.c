static const char help[] = "Unit test of a transient map's fit (src/sweep/sweep_transient.c, docs/squeal.md section 6.5):\n"
                           "RollerSweepFitGrowth on sampled y(t) = a + b t + A exp(sigma t) cos(omega t + phi) (+ a second, weaker\n"
                           "tone) recovers sigma and omega; a constant has no oscillation (NaN).\n";

#include "sweep/sweep.h"

/* a + b t + A exp(sigma t) cos(omega t + phi) + A2 cos(omega2 t), n samples from t0 by dt */
typedef struct {
  PetscReal a, b, A, sigma, omega, phi, A2, omega2, t0, dt;
  PetscInt  n;
  PetscReal sigma_tol, omega_tol; /* absolute on sigma, relative on omega */
} Signal;

static PetscErrorCode Check(const Signal *s, PetscInt *failed)
{
  PetscReal *t, *y, amplitude, sigma, omega;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(s->n, &t, s->n, &y));
  for (PetscInt i = 0; i < s->n; ++i) {
    t[i] = s->t0 + i * s->dt;
    y[i] = s->a + s->b * t[i] + s->A * PetscExpReal(s->sigma * t[i]) * PetscCosReal(s->omega * t[i] + s->phi) + s->A2 * PetscCosReal(s->omega2 * t[i]);
  }
  PetscCall(RollerSweepFitGrowth(s->n, t, y, &amplitude, &sigma, &omega));
  if (s->A == 0 && s->A2 == 0) {
    const PetscBool ok = (PetscBool)(PetscIsNanReal(sigma) && PetscIsNanReal(omega));

    PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s constant %g: amplitude %.2e, growth rate %g, frequency %g (NaN: no oscillation)\n", ok ? "PASS" : "FAIL", (double)s->a, (double)amplitude, (double)sigma, (double)omega));
    *failed += !ok;
  } else {
    const PetscBool ok = (PetscBool)(PetscAbsReal(sigma - s->sigma) <= s->sigma_tol && PetscAbsReal(omega - s->omega) <= s->omega_tol * s->omega);

    PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s sigma %g omega %g (t in [%g, %g], %.1f periods): fitted %.5f (|error| %.1e <= %g), %.5f (relative %.1e <= %g); amplitude %.3e\n", ok ? "PASS" : "FAIL", (double)s->sigma, (double)s->omega, (double)s->t0, (double)t[s->n - 1], (double)((t[s->n - 1] - s->t0) * s->omega / (2 * PETSC_PI)), (double)sigma, (double)PetscAbsReal(sigma - s->sigma),
                          (double)s->sigma_tol, (double)omega, (double)(PetscAbsReal(omega - s->omega) / s->omega), (double)s->omega_tol, (double)amplitude));
    *failed += !ok;
  }
  PetscCall(PetscFree2(t, y));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  /* a, b, A, sigma, omega, phi, A2, omega2, t0, dt, n, sigma_tol, omega_tol */
  const Signal signals[] = {
    {3.0,   0.1, 0.5,  -0.2,  5.0,  0.3, 0.0, 0.0, 10.0, 0.01,    2001, 0.01, 0.005}, /* decaying, on a ramp: 16 periods */
    {-1.0,  0.0, 1e-3, 0.15,  2.3,  1.0, 0.0, 0.0, 0.0,  0.02,    2001, 0.01, 0.005}, /* growing: 15 periods */
    {0.0,   0.0, 1.0,  0.0,   1.1,  0.0, 0.3, 3.7, 0.0,  0.05,    801,  0.01, 0.01 }, /* steady, with a weaker second tone: 7 periods */
    {0.004, 0.0, 4e-4, -0.05, 0.75, 2.0, 0.0, 0.0, 20.0, 0.01414, 1415, 0.02, 0.03 }, /* a roller's order-1 ringing: 2.4 periods */
    {2.0,   0.0, 0.0,  0.0,   0.0,  0.0, 0.0, 0.0, 0.0,  0.01,    1000, 0.0,  0.0  }, /* constant */
  };
  PetscInt failed = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  for (size_t i = 0; i < sizeof(signals) / sizeof(signals[0]); ++i) PetscCall(Check(&signals[i], &failed));
  PetscCheck(!failed, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%" PetscInt_FMT " fits out of their tolerance", failed);
  PetscCall(PetscFinalize());
  return 0;
}
