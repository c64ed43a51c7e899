/* A transient map's case (docs/squeal.md section 6.5): an observer of the run records every state's time, contact
   force, friction force, stick fraction and the -sweep_fit column (what -monitor_csv would write of them,
   RollerStepInfo); at the end the series is reduced to the case's row over the window, the last -sweep_window of the
   run's time:
     window_start,window_end,contact_force,friction_force,stick_fraction,amplitude,growth_rate,frequency
   the means of the three columns over the window's states (the stick fraction stick/(stick + slip) of the states
   with contact nodes), and the oscillation of the fitted column y(t) (RollerSweepFitGrowth). */
#include "sweep/sweep.h"
#include "integrate/integrate.h"

static PetscErrorCode SeriesMonitor(Roller ctx, RollerMonitorEvent event, void *mctx)
{
  RollerSweepSeries    *s        = (RollerSweepSeries *)mctx;
  const RollerStepInfo *info     = &ctx->info;
  const PetscInt        nodes    = info->friction.stick + info->friction.slip;
  const PetscReal       column[] = {info->contact_force, info->friction.force, info->friction.torque, info->R, info->alpha};

  PetscFunctionBeginUser;
  if (event == ROLLER_MONITOR_FINAL) PetscFunctionReturn(0);
  PetscCall(RollerStepInfoGet(ctx));
  if (s->n == s->max) {
    s->max = PetscMax(1024, 2 * s->max);
    PetscCall(PetscRealloc(sizeof(PetscReal) * s->max, &s->t));
    PetscCall(PetscRealloc(sizeof(PetscReal) * s->max, &s->contact));
    PetscCall(PetscRealloc(sizeof(PetscReal) * s->max, &s->friction));
    PetscCall(PetscRealloc(sizeof(PetscReal) * s->max, &s->stick));
    PetscCall(PetscRealloc(sizeof(PetscReal) * s->max, &s->fit));
  }
  s->t[s->n]        = ctx->state.time;
  s->contact[s->n]  = info->contact_force;
  s->friction[s->n] = info->friction.force;
  s->stick[s->n]    = nodes ? (PetscReal)info->friction.stick / nodes : (PetscReal)NAN;
  s->fit[s->n]      = column[s->column];
  s->n++;
  PetscFunctionReturn(0);
}

/* Set after the Roller's set-up: it sees every state from the initial one. */
PetscErrorCode RollerSweepSeriesObserve(Roller ctx, RollerSweepSeries *s)
{
  PetscFunctionBeginUser;
  PetscCall(RollerMonitorSet(ctx, SeriesMonitor, s, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSweepSeriesDestroy(RollerSweepSeries *s)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(s->t));
  PetscCall(PetscFree(s->contact));
  PetscCall(PetscFree(s->friction));
  PetscCall(PetscFree(s->stick));
  PetscCall(PetscFree(s->fit));
  s->n = s->max = 0;
  PetscFunctionReturn(0);
}

/* The least-squares line y ~ a + b x of n points */
static void Line(PetscInt n, const PetscReal x[], const PetscReal y[], PetscReal *a, PetscReal *b)
{
  PetscReal mx = 0, my = 0, sxx = 0, sxy = 0;

  for (PetscInt i = 0; i < n; ++i) {
    mx += x[i] / n;
    my += y[i] / n;
  }
  for (PetscInt i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  *b = sxx > 0 ? sxy / sxx : 0;
  *a = my - *b * mx;
}

/* |DFT|^2 of the (windowed) w at k cycles per window, the phasor advanced by a rotation (no sin/cos per term) */
static PetscReal Power(PetscInt n, const PetscReal w[], PetscInt k)
{
  const PetscReal dc = PetscCosReal(2 * PETSC_PI * k / n), ds = -PetscSinReal(2 * PETSC_PI * k / n);
  PetscReal       re = 0, im = 0, c = 1, s = 0;

  for (PetscInt j = 0; j < n; ++j) {
    const PetscReal c1 = c * dc - s * ds;

    re += w[j] * c;
    im += w[j] * s;
    s = c * ds + s * dc;
    c = c1;
  }
  return re * re + im * im;
}

/*
  RollerSweepFitGrowth - The oscillation of a uniformly sampled series y(t_0..t_{n-1}) (docs/squeal.md section 6.5).

  The series less its least-squares line is d; amplitude is the RMS of d. The angular frequency is the peak of the
  DFT of d under a Hann window (the largest |D_k|, k >= 1 cycles per window), refined by a parabola through the
  logarithms of the peak and its two neighbours: omega = 2 pi (k + delta) / (n dt). The growth rate is the slope
  of the least-squares line of the logarithm of half the range of d, (max d - min d)/2, against the mean time of the
  maximum and the minimum, in blocks of at least one period 2 pi / omega (at least 2, at most 64 blocks): the
  envelope of d(t) ~ A exp(sigma t) cos(omega t + phi) sampled at its peaks and troughs (half the range, not max |d|,
  so that what the line leaves of a trend or of a fast growth cancels), so sigma compares with Re(lambda) of -modes
  and omega with Im(lambda). Without an oscillation
  (amplitude at round-off of max |y|, or fewer than 8 samples) both are NaN.

  Not collective. n = 0 does nothing.
*/
PetscErrorCode RollerSweepFitGrowth(PetscInt n, const PetscReal t[], const PetscReal y[], PetscReal *amplitude, PetscReal *growth, PetscReal *omega)
{
  PetscReal *d, *hd, a, b, ymax = 0, rms = 0, p[3], delta = 0, best = -1, env_t[64], env[64];
  PetscInt   kbest = 1, nb, m = 0;

  PetscFunctionBeginUser;
  if (!n) PetscFunctionReturn(0);
  *amplitude = *growth = *omega = (PetscReal)NAN;
  if (n < 8) PetscFunctionReturn(0);
  PetscCall(PetscMalloc2(n, &d, n, &hd));
  Line(n, t, y, &a, &b);
  for (PetscInt i = 0; i < n; ++i) {
    d[i]  = y[i] - (a + b * t[i]);
    hd[i] = d[i] * (0.5 - 0.5 * PetscCosReal(2 * PETSC_PI * i / (n - 1))); /* Hann */
    rms += d[i] * d[i] / n;
    ymax = PetscMax(ymax, PetscAbsReal(y[i]));
  }
  *amplitude = PetscSqrtReal(rms);
  if (*amplitude <= 1e-12 * ymax || *amplitude == 0) {
    PetscCall(PetscFree2(d, hd));
    PetscFunctionReturn(0);
  }
  for (PetscInt k = 1; k <= n / 2; ++k) {
    const PetscReal pk = Power(n, hd, k);

    if (pk > best) {
      best  = pk;
      kbest = k;
    }
  }
  if (kbest > 1 && kbest < n / 2) {
    for (PetscInt i = 0; i < 3; ++i) p[i] = PetscLogReal(PetscMax(Power(n, hd, kbest - 1 + i), PETSC_SMALL * best));
    if (p[0] - 2 * p[1] + p[2] < 0) delta = 0.5 * (p[0] - p[2]) / (p[0] - 2 * p[1] + p[2]);
  }
  *omega = 2 * PETSC_PI * (kbest + delta) / (n * (t[n - 1] - t[0]) / (n - 1));
  nb     = (PetscInt)PetscFloorReal((t[n - 1] - t[0]) * *omega / (2 * PETSC_PI));
  nb     = PetscMin(PetscMax(nb, 2), 64);
  for (PetscInt k = 0; k < nb; ++k) {
    PetscInt imax = k * n / nb, imin = imax;

    for (PetscInt i = k * n / nb; i < (k + 1) * n / nb; ++i) {
      if (d[i] > d[imax]) imax = i;
      if (d[i] < d[imin]) imin = i;
    }
    if (d[imax] == d[imin]) continue;
    env_t[m] = 0.5 * (t[imax] + t[imin]);
    env[m++] = PetscLogReal(0.5 * (d[imax] - d[imin]));
  }
  if (m >= 2) Line(m, env_t, env, &a, growth);
  PetscCall(PetscFree2(d, hd));
  PetscFunctionReturn(0);
}

/* The mean of the non-NaN values (NaN if none) */
static PetscReal Mean(PetscInt n, const PetscReal x[])
{
  PetscReal sum = 0;
  PetscInt  m   = 0;

  for (PetscInt i = 0; i < n; ++i)
    if (!PetscIsNanReal(x[i])) {
      sum += x[i];
      ++m;
    }
  return m ? sum / m : (PetscReal)NAN;
}

/* The case's columns after its swept values (",window_start,...,frequency"), and its growth rate. A failed run's
   are NaN: its series stops at the failure, not at the end the map asked for. */
PetscErrorCode RollerSweepTransientRow(const RollerSweepPlan *plan, const RollerSweepSeries *s, PetscBool failed, char row[], size_t len, PetscReal *growth)
{
  PetscReal t0 = 0, t1 = 0, amplitude = NAN, omega = NAN, contact = NAN, friction = NAN, stick = NAN;
  PetscInt  i0 = 0, n = 0;

  PetscFunctionBeginUser;
  *growth = (PetscReal)NAN;
  if (s->n && !failed) {
    t1 = s->t[s->n - 1];
    t0 = t1 - plan->window * (t1 - s->t[0]);
    while (i0 < s->n - 1 && s->t[i0] < t0 - 1e-9 * PetscAbsReal(t1)) ++i0; /* the states at t >= t0 (to round-off) */
    n        = s->n - i0;
    t0       = s->t[i0];
    contact  = Mean(n, s->contact + i0);
    friction = Mean(n, s->friction + i0);
    stick    = Mean(n, s->stick + i0);
    PetscCall(RollerSweepFitGrowth(n, s->t + i0, s->fit + i0, &amplitude, growth, &omega));
  }
  PetscCall(PetscSNPrintf(row, len, ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", (double)t0, (double)t1, (double)contact, (double)friction, (double)stick, (double)amplitude, (double)*growth, (double)omega));
  PetscFunctionReturn(0);
}
