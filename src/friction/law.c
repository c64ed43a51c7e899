/* The friction coefficient of the slip speed (docs/friction.md section 1), the one law of the transient's Coulomb
   solves (contact/contact_friction*.c, coulomb.c) and of the steady state and its linearization (modes/):
     mu(v) = mu + (mu_s - mu) exp(-|v| / v_c)      -friction, -friction_static, -friction_decay (v_c = 0: constant mu)
   or a measured curve, -friction_table v_1:mu_1,...,v_n:mu_n: the monotone piecewise cubic Hermite interpolant of the
   points (Fritsch & Carlson, SIAM J. Numer. Anal. 17, 1980, with the slopes of Fritsch & Butland, SIAM J. Sci. Stat.
   Comput. 5, 1984, as scipy's PchipInterpolator), constant beyond the first and the last speed. On each interval it
   is monotone between its two points, so it never overshoots them: a table that rises and then falls peaks at its
   largest point, with slope 0 there. Its slope is continuous from v_1 to v_n; the slope returned at a point where it
   is not (v_1, v_n, and v = 0 of the exponential's |v|) is the one from the right, as |v| grows. */
#include "friction/friction.h"

/* mu(|v|) of the exponential law; *dmu its derivative in |v| (if dmu) */
static PetscReal Exponential(PetscReal mu, PetscReal mu_s, PetscReal v_c, PetscReal v, PetscReal *dmu)
{
  const PetscReal e = v_c > 0 ? PetscExpReal(-PetscAbsReal(v) / v_c) : 0.0;

  if (dmu) *dmu = v_c > 0 ? -(mu_s - mu) / v_c * e : 0.0;
  return mu + (mu_s - mu) * e;
}

PetscReal RollerFrictionTableMu(const RollerFrictionTable *tab, PetscReal v, PetscReal *dmu)
{
  const PetscInt n  = tab->n;
  PetscInt       lo = 0, hi = n - 1;
  PetscReal      h, t, d0, d1;

  v = PetscAbsReal(v);
  if (dmu) *dmu = 0.0; /* the slope from the right, as |v| grows: s_1 at v_1, 0 at v_n */
  if (v < tab->v[0]) return tab->mu[0];
  if (v >= tab->v[n - 1]) return tab->mu[n - 1];
  while (hi - lo > 1) { /* v[lo] < v < v[hi] */
    const PetscInt mid = (lo + hi) / 2;

    if (tab->v[mid] <= v) lo = mid;
    else hi = mid;
  }
  h  = tab->v[hi] - tab->v[lo];
  t  = (v - tab->v[lo]) / h;
  d0 = h * tab->s[lo];
  d1 = h * tab->s[hi];
  /* the cubic Hermite basis h00 = (1 + 2t)(1 - t)^2, h10 = t (1 - t)^2, h01 = t^2 (3 - 2t), h11 = t^2 (t - 1) */
  if (dmu) *dmu = (6.0 * t * (t - 1.0) * (tab->mu[lo] - tab->mu[hi]) + (1.0 - t) * (1.0 - 3.0 * t) * d0 + t * (3.0 * t - 2.0) * d1) / h;
  return (1.0 + 2.0 * t) * (1.0 - t) * (1.0 - t) * tab->mu[lo] + t * (1.0 - t) * (1.0 - t) * d0 + t * t * (3.0 - 2.0 * t) * tab->mu[hi] + t * t * (t - 1.0) * d1;
}

PetscReal RollerFrictionMu(const RollerObstacle *o, PetscReal v, PetscReal *dmu)
{
  if (o->table.n) return RollerFrictionTableMu(&o->table, v, dmu);
  return Exponential(o->friction, o->friction_static, o->friction_decay, v, dmu);
}

PetscBool RollerFrictionVaries(const RollerObstacle *o)
{
  return o->table.n || o->friction_decay > 0 ? PETSC_TRUE : PETSC_FALSE;
}

void RollerFrictionRange(const RollerObstacle *o, PetscReal range[2])
{
  if (!o->table.n) {
    range[0] = PetscMin(o->friction, o->friction_static);
    range[1] = PetscMax(o->friction, o->friction_static);
    return;
  }
  range[0] = range[1] = o->table.mu[0];
  for (PetscInt i = 1; i < o->table.n; ++i) {
    range[0] = PetscMin(range[0], o->table.mu[i]);
    range[1] = PetscMax(range[1], o->table.mu[i]);
  }
}

static PetscReal Sign(PetscReal x)
{
  return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0);
}

/* The slope at an end from its two intervals (widths h0 at the end, h1 next; secants d0, d1): the three-point
   formula, 0 if it points against d0, at most 3 d0 where the data turn (the Fritsch-Carlson bound). */
static PetscReal EndSlope(PetscReal h0, PetscReal h1, PetscReal d0, PetscReal d1)
{
  const PetscReal s = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);

  if (Sign(s) != Sign(d0)) return 0.0;
  if (Sign(d0) != Sign(d1) && PetscAbsReal(s) > 3.0 * PetscAbsReal(d0)) return 3.0 * d0;
  return s;
}

/* The slopes s_i: at an interior point 0 where the secants d_{i-1}, d_i differ in sign or one is 0, else their
   weighted harmonic mean (Fritsch & Butland), which keeps every interval's cubic monotone. */
static PetscErrorCode Slopes(RollerFrictionTable *tab)
{
  const PetscInt n = tab->n;
  PetscReal     *d;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n - 1, &d));
  for (PetscInt i = 0; i < n - 1; ++i) d[i] = (tab->mu[i + 1] - tab->mu[i]) / (tab->v[i + 1] - tab->v[i]);
  if (n == 2) tab->s[0] = tab->s[1] = d[0];
  else {
    for (PetscInt i = 1; i < n - 1; ++i) {
      const PetscReal h0 = tab->v[i] - tab->v[i - 1], h1 = tab->v[i + 1] - tab->v[i], w0 = 2.0 * h1 + h0, w1 = h1 + 2.0 * h0;

      tab->s[i] = d[i - 1] * d[i] > 0 ? (w0 + w1) / (w0 / d[i - 1] + w1 / d[i]) : 0.0;
    }
    tab->s[0]     = EndSlope(tab->v[1] - tab->v[0], tab->v[2] - tab->v[1], d[0], d[1]);
    tab->s[n - 1] = EndSlope(tab->v[n - 1] - tab->v[n - 2], tab->v[n - 2] - tab->v[n - 3], d[n - 2], d[n - 3]);
  }
  PetscCall(PetscFree(d));
  PetscFunctionReturn(0);
}

/* One entry "v:mu" of the table (len characters at e): both numbers finite, nothing else but blanks. */
static PetscBool ParseEntry(const char *e, size_t len, PetscReal *v, PetscReal *mu)
{
  char  buf[128], *end;
  char *colon;

  if (len >= sizeof(buf)) return PETSC_FALSE;
  memcpy(buf, e, len);
  buf[len] = 0;
  colon    = strchr(buf, ':');
  if (!colon) return PETSC_FALSE;
  *colon = 0;
  *v     = (PetscReal)strtod(buf, &end);
  if (end == buf) return PETSC_FALSE;
  while (*end == ' ') ++end;
  if (*end) return PETSC_FALSE;
  *mu = (PetscReal)strtod(colon + 1, &end);
  if (end == colon + 1) return PETSC_FALSE;
  while (*end == ' ') ++end;
  return *end || PetscIsInfOrNanReal(*v) || PetscIsInfOrNanReal(*mu) ? PETSC_FALSE : PETSC_TRUE;
}

PetscErrorCode RollerFrictionTableSetUp(MPI_Comm comm, const char text[], RollerFrictionTable *tab)
{
  PetscInt    n = text[0] ? 1 : 0;
  const char *e = text;

  PetscFunctionBeginUser;
  PetscCall(RollerFrictionTableDestroy(tab));
  for (const char *p = text; *p; ++p) n += *p == ',';
  PetscCheck(n >= 2, comm, PETSC_ERR_USER_INPUT, "-friction_table '%s': %" PetscInt_FMT " point%s; give at least 2 (speed:coefficient,speed:coefficient,...)", text, n, n == 1 ? "" : "s");
  PetscCall(PetscMalloc3(n, &tab->v, n, &tab->mu, n, &tab->s));
  tab->n = n;
  for (PetscInt i = 0; i < n; ++i) {
    const char *next = strchr(e, ',');
    const int   len  = (int)(next ? (size_t)(next - e) : strlen(e));
    PetscBool   ok   = ParseEntry(e, (size_t)len, &tab->v[i], &tab->mu[i]);

    PetscCheck(ok, comm, PETSC_ERR_USER_INPUT, "-friction_table: entry %" PetscInt_FMT " '%.*s' is not speed:coefficient (two finite numbers)", i + 1, len, e);
    PetscCheck(tab->v[i] >= 0, comm, PETSC_ERR_USER_INPUT, "-friction_table: entry %" PetscInt_FMT " '%.*s': the slip speed %g must be >= 0", i + 1, len, e, (double)tab->v[i]);
    PetscCheck(!i || tab->v[i] > tab->v[i - 1], comm, PETSC_ERR_USER_INPUT, "-friction_table: entry %" PetscInt_FMT " '%.*s': the slip speed %g must exceed the previous entry's %g (strictly increasing speeds)", i + 1, len, e, (double)tab->v[i],
               (double)(i ? tab->v[i - 1] : 0));
    PetscCheck(tab->mu[i] > 0, comm, PETSC_ERR_USER_INPUT, "-friction_table: entry %" PetscInt_FMT " '%.*s': the coefficient %g must be > 0", i + 1, len, e, (double)tab->mu[i]);
    e = next ? next + 1 : e + len;
  }
  PetscCall(Slopes(tab));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerFrictionTableDestroy(RollerFrictionTable *tab)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree3(tab->v, tab->mu, tab->s));
  tab->n = 0;
  PetscFunctionReturn(0);
}
