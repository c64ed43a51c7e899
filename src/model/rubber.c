/* The rubber's generalized Maxwell solid (-rubber maxwell, docs/model.md section 1.1): deviatoric branches of shear
   modulus g_i mu and relaxation time tau_i in parallel with the relaxed (static) solid of -young, -poisson; the bulk
   stays elastic. Its complex shear modulus

     G*(w) = mu (1 + sum_i g_i i w tau_i / (1 + i w tau_i)),   loss factor eta(w) = G''/G',

   the options that give the branches (fitted to a flat loss factor over a band, or explicit), their validation, the
   fit, and what -ts_view prints about them. */
#include "model/model.h"

const char *const RollerRubbers[] = {"kelvin_voigt", "maxwell", "RollerRubber", "ROLLER_RUBBER_", NULL};

#define FIT_POINTS   200  /* the log grid of the band the weights are fitted on */
#define CHECK_POINTS 2000 /* the denser grid the fit's error is measured on */
#define FIT_MARGINS  25   /* the spectrum's margins beyond the band tried: factors 10^(k/24), k = 0..24 */
#define FIT_REWEIGHT 3    /* refits with the rows weighted by 1/G'(w): the residual becomes the loss factor's relative error */

/* G*(s)/mu = 1 + sum_i g_i s tau_i/(1 + s tau_i) at the complex s = sr + i si (s = i w: G'/mu + i G''/mu; the
   continuation to a complex eigenvalue s, docs/model.md section 1.1). */
void RollerRubberModulus(PetscInt n, const PetscReal tau[], const PetscReal g[], PetscReal sr, PetscReal si, PetscReal *re, PetscReal *im)
{
  *re = 1.0;
  *im = 0.0;
  for (PetscInt i = 0; i < n; ++i) {
    const PetscReal a = sr * tau[i], b = si * tau[i], d = (1.0 + a) * (1.0 + a) + b * b;

    *re += g[i] * (a * (1.0 + a) + b * b) / d;
    *im += g[i] * b / d;
  }
}

/* The largest relative error of the loss factor against eta over CHECK_POINTS log-spaced angular frequencies of [w1, w2]
   (with a Kelvin-Voigt term tau_kv beside the branches: G''/mu + w tau_kv). */
static PetscReal LossFactorError(PetscInt n, const PetscReal tau[], const PetscReal g[], PetscReal tau_kv, PetscReal eta, PetscReal w1, PetscReal w2)
{
  PetscReal err = 0.0;

  for (PetscInt k = 0; k < CHECK_POINTS; ++k) {
    const PetscReal w = w1 * PetscPowReal(w2 / w1, (PetscReal)k / (CHECK_POINTS - 1));
    PetscReal       re, im;

    RollerRubberModulus(n, tau, g, 0.0, w, &re, &im);
    err = PetscMax(err, PetscAbsReal((im + w * tau_kv) / (re * eta) - 1.0));
  }
  return err;
}

/* x_P = argmin |A_P x - b| over the columns in P (A m x n column-major): Householder QR of A_P (its columns, the
   branches' responses over the band, are far from orthogonal: no normal equations). */
static PetscErrorCode PassiveLeastSquares(PetscInt m, PetscInt n, const PetscReal A[], const PetscReal b[], const PetscBool P[], PetscReal x[])
{
  PetscReal Q[FIT_POINTS * ROLLER_MAX_BRANCHES], y[FIT_POINTS], R[ROLLER_MAX_BRANCHES], xp[ROLLER_MAX_BRANCHES];
  PetscInt  N = 0;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < n; ++j)
    if (P[j]) PetscCall(PetscArraycpy(&Q[(N++) * m], &A[j * m], m));
  PetscCall(PetscArraycpy(y, b, m));
  for (PetscInt j = 0; j < N; ++j) { /* column j: reflect its entries j..m-1 onto e_j */
    PetscReal *v = &Q[j * m], norm = 0.0, vnorm2, alpha;

    for (PetscInt i = j; i < m; ++i) norm += v[i] * v[i];
    norm = PetscSqrtReal(norm);
    PetscCheck(norm > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Prony fit: a branch without response over the band");
    alpha = v[j] > 0 ? -norm : norm;
    v[j] -= alpha;
    vnorm2 = 0.0;
    for (PetscInt i = j; i < m; ++i) vnorm2 += v[i] * v[i];
    for (PetscInt k = j + 1; k <= N; ++k) { /* the later columns, then the right-hand side */
      PetscReal *c = k < N ? &Q[k * m] : y, d = 0.0;

      for (PetscInt i = j; i < m; ++i) d += v[i] * c[i];
      for (PetscInt i = j; i < m; ++i) c[i] -= 2.0 * d / vnorm2 * v[i];
    }
    R[j] = alpha; /* the diagonal of R; its upper part is left in Q's rows above the reflector */
  }
  for (PetscInt j = N - 1; j >= 0; --j) {
    xp[j] = y[j];
    for (PetscInt k = j + 1; k < N; ++k) xp[j] -= Q[k * m + j] * xp[k];
    xp[j] /= R[j];
  }
  for (PetscInt j = 0, k = 0; j < n; ++j) x[j] = P[j] ? xp[k++] : 0.0;
  PetscFunctionReturn(0);
}

/* Lawson and Hanson's non-negative least squares, min |A x - b| with x >= 0 (A m x n column-major, n small). */
static PetscErrorCode NonNegativeLeastSquares(PetscInt m, PetscInt n, const PetscReal A[], const PetscReal b[], PetscReal x[])
{
  PetscBool P[ROLLER_MAX_BRANCHES] = {PETSC_FALSE};
  PetscReal s[ROLLER_MAX_BRANCHES], w[ROLLER_MAX_BRANCHES], r[FIT_POINTS], scale = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < m; ++i) scale = PetscMax(scale, PetscAbsReal(b[i]));
  for (PetscInt j = 0; j < n; ++j) x[j] = 0.0;
  for (PetscInt it = 0; it < 3 * n + 3; ++it) {
    PetscInt  jmax = -1;
    PetscReal wmax = 1e-12 * scale;

    for (PetscInt i = 0; i < m; ++i) {
      r[i] = b[i];
      for (PetscInt j = 0; j < n; ++j) r[i] -= A[j * m + i] * x[j];
    }
    for (PetscInt j = 0; j < n; ++j) {
      w[j] = 0.0;
      for (PetscInt i = 0; i < m; ++i) w[j] += A[j * m + i] * r[i];
      if (!P[j] && w[j] > wmax) {
        wmax = w[j];
        jmax = j;
      }
    }
    if (jmax < 0) break; /* the Kuhn-Tucker conditions hold */
    P[jmax] = PETSC_TRUE;
    for (;;) { /* step toward the passive set's solution until a weight reaches 0; that one (at least) leaves the set */
      PetscReal alpha = 1.0;
      PetscInt  jmin  = -1;

      PetscCall(PassiveLeastSquares(m, n, A, b, P, s));
      for (PetscInt j = 0; j < n; ++j)
        if (P[j] && s[j] <= 0.0 && (jmin < 0 || x[j] / (x[j] - s[j]) < alpha)) {
          alpha = x[j] / (x[j] - s[j]);
          jmin  = j;
        }
      if (jmin < 0) break;
      for (PetscInt j = 0; j < n; ++j) {
        x[j] += alpha * (s[j] - x[j]);
        if (P[j] && (j == jmin || x[j] <= 1e-15 * scale)) {
          P[j] = PETSC_FALSE;
          x[j] = 0.0;
        }
      }
    }
    for (PetscInt j = 0; j < n; ++j) x[j] = P[j] ? s[j] : 0.0;
  }
  PetscFunctionReturn(0);
}

/* The weights of n branches at the given times for the loss factor eta over [w1, w2]: G'' = eta G' is linear in g,
     sum_i g_i (w tau_i - eta w^2 tau_i^2)/(1 + w^2 tau_i^2) = eta - w tau_kv
   (a Kelvin-Voigt term tau_kv beside the branches carries w tau_kv of the loss factor),
   solved by non-negative least squares on FIT_POINTS log-spaced w, then again with each row weighted by 1/G'(w) of
   the last weights (so that the residual is the loss factor's relative error). */
static PetscErrorCode FitWeights(PetscInt n, const PetscReal tau[], PetscReal tau_kv, PetscReal eta, PetscReal w1, PetscReal w2, PetscReal g[])
{
  PetscReal A[FIT_POINTS * ROLLER_MAX_BRANCHES], b[FIT_POINTS], weight[FIT_POINTS];

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < FIT_POINTS; ++k) weight[k] = 1.0;
  for (PetscInt pass = 0; pass <= FIT_REWEIGHT; ++pass) {
    for (PetscInt k = 0; k < FIT_POINTS; ++k) {
      const PetscReal w = w1 * PetscPowReal(w2 / w1, (PetscReal)k / (FIT_POINTS - 1));

      for (PetscInt i = 0; i < n; ++i) {
        const PetscReal x = w * tau[i];

        A[i * FIT_POINTS + k] = weight[k] * (x - eta * x * x) / (1.0 + x * x);
      }
      b[k] = weight[k] * (eta - w * tau_kv);
    }
    PetscCall(NonNegativeLeastSquares(FIT_POINTS, n, A, b, g));
    for (PetscInt k = 0; k < FIT_POINTS; ++k) {
      const PetscReal w = w1 * PetscPowReal(w2 / w1, (PetscReal)k / (FIT_POINTS - 1));
      PetscReal       re, im;

      RollerRubberModulus(n, tau, g, 0.0, w, &re, &im);
      weight[k] = 1.0 / re;
    }
  }
  PetscFunctionReturn(0);
}

/*
  RollerRubberFit - the branches of a flat loss factor eta over the band [f1, f2] (cycles per unit time), with a
  Kelvin-Voigt term tau_kv beside them (0: none; its share w tau_kv must stay below eta over the band): n relaxation
  times log-spaced from 1/(c w2) to c/w1 (w = 2 pi f; one branch: 1/sqrt(w1 w2)), the margin c in [1, 10] the one of
  least error, the weights by FitWeights; n grows from 1 until the loss factor is within tol (relative) of eta on a
  dense grid of the band. Returns the branches with a positive weight (n <= nmax), their largest relative error err;
  n = 0 if no n <= nmax meets tol (err: the best reached).
*/
PetscErrorCode RollerRubberFit(PetscReal eta, PetscReal tau_kv, PetscReal f1, PetscReal f2, PetscReal tol, PetscInt nmax, PetscInt *n, PetscReal tau[], PetscReal g[], PetscReal *err)
{
  const PetscReal w1 = 2 * PETSC_PI * f1, w2 = 2 * PETSC_PI * f2;

  PetscFunctionBeginUser;
  PetscCheck(eta > 0 && f1 > 0 && f2 >= f1 && nmax >= 1 && nmax <= ROLLER_MAX_BRANCHES && tau_kv >= 0 && w2 * tau_kv < eta, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "RollerRubberFit: eta %g > 0, 0 < f1 %g <= f2 %g, nmax %" PetscInt_FMT " in [1, %d], 0 <= 2 pi f2 tau_kv %g < eta", (double)eta, (double)f1, (double)f2, nmax, ROLLER_MAX_BRANCHES, (double)(w2 * tau_kv));
  *n   = 0;
  *err = PETSC_MAX_REAL;
  for (PetscInt nb = 1; nb <= nmax && *n == 0; ++nb) {
    PetscReal best = PETSC_MAX_REAL, t[ROLLER_MAX_BRANCHES], w[ROLLER_MAX_BRANCHES], bt[ROLLER_MAX_BRANCHES], bw[ROLLER_MAX_BRANCHES];

    for (PetscInt k = 0; k < (nb > 1 ? FIT_MARGINS : 1); ++k) {
      const PetscReal c = PetscPowReal(10.0, (PetscReal)k / (FIT_MARGINS - 1)), lo = 1.0 / (c * w2), hi = c / w1;
      PetscReal       e;

      for (PetscInt i = 0; i < nb; ++i) t[i] = nb > 1 ? lo * PetscPowReal(hi / lo, (PetscReal)i / (nb - 1)) : 1.0 / PetscSqrtReal(w1 * w2);
      PetscCall(FitWeights(nb, t, tau_kv, eta, w1, w2, w));
      e = LossFactorError(nb, t, w, tau_kv, eta, w1, w2);
      if (e < best) {
        best = e;
        PetscCall(PetscArraycpy(bt, t, nb));
        PetscCall(PetscArraycpy(bw, w, nb));
      }
    }
    *err = PetscMin(*err, best);
    if (best <= tol)
      for (PetscInt i = 0; i < nb; ++i)
        if (bw[i] > 0) {
          tau[*n] = bt[i];
          g[*n]   = bw[i];
          (*n)++;
        }
  }
  PetscFunctionReturn(0);
}

/* The instantaneous (unrelaxed, high-frequency) moduli: the shear modulus mu (1 + sum g_i), the bulk modulus
   lambda + 2 mu/3 unchanged (the branches are deviatoric), so lambda - 2/3 mu sum g_i; the relaxed ones without
   branches. */
void RollerRubberInstantaneous(const RollerMaterial *m, PetscReal *lambda, PetscReal *mu)
{
  PetscReal sum = 0.0;

  if (m->rubber == ROLLER_RUBBER_MAXWELL)
    for (PetscInt i = 0; i < m->nbranch; ++i) sum += m->g[i];
  *mu     = m->mu * (1.0 + sum);
  *lambda = m->lambda - 2.0 / 3.0 * m->mu * sum;
}

/*
  RollerRubberSetUp - validates the rubber's options (read in the material's block: given[] says which of
  -rubber_loss_factor, -rubber_band, -maxwell_tau, -maxwell_weight were; nband, ntau, nweight their counts, at most
  ROLLER_MAX_BRANCHES + 1 read so that one too many is seen) and fits or copies the branches.
*/
PetscErrorCode RollerRubberSetUp(Roller ctx, const PetscBool given[4], PetscInt nband, PetscInt ntau, const PetscReal tau[], PetscInt nweight, const PetscReal weight[])
{
  RollerMaterial   *m       = &ctx->material;
  const char *const names[] = {"-rubber_loss_factor", "-rubber_band", "-maxwell_tau", "-maxwell_weight"};
  const PetscReal   tol     = 0.04; /* below the 5 % asked for (docs/model.md section 1.1), on a grid of CHECK_POINTS */

  PetscFunctionBeginUser;
  m->nbranch = 0;
  if (m->rubber != ROLLER_RUBBER_MAXWELL) {
    for (PetscInt i = 0; i < 4; ++i) PetscCheck(!given[i], ctx->comm, PETSC_ERR_ARG_INCOMP, "%s: a parameter of the generalized Maxwell solid, needs -rubber maxwell (the rubber is %s)", names[i], RollerRubbers[m->rubber]);
    PetscFunctionReturn(0);
  }
  PetscCheck(!((given[0] || given[1]) && (given[2] || given[3])), ctx->comm, PETSC_ERR_ARG_INCOMP, "-rubber maxwell: give either the fit (-rubber_loss_factor ETA -rubber_band F1,F2) or the branches (-maxwell_tau T1,... -maxwell_weight g1,...), not both");
  if (given[0] || given[1]) {
    PetscCheck(given[0] && given[1], ctx->comm, PETSC_ERR_ARG_WRONG, "-rubber maxwell: the fit needs both -rubber_loss_factor ETA and -rubber_band F1,F2 (%s is missing)", given[0] ? "-rubber_band" : "-rubber_loss_factor");
    RollerCheckOption(ctx->comm, "-rubber_loss_factor", m->loss_factor, m->loss_factor > 0 && m->loss_factor <= 1, "in (0, 1]");
    PetscCheck(nband == 2, ctx->comm, PETSC_ERR_USER_INPUT, "-rubber_band: %" PetscInt_FMT " value%s given, needs two frequencies F1,F2 (cycles per unit time)", nband, nband == 1 ? "" : "s");
    RollerCheckOption(ctx->comm, "-rubber_band", m->band[0], m->band[0] > 0, "> 0 (F1 of F1,F2, cycles per unit time)");
    RollerCheckOption(ctx->comm, "-rubber_band", m->band[1], m->band[1] >= m->band[0] && m->band[1] <= 1e6 * m->band[0], ">= F1 and <= 1e6 F1 (F2 of F1,F2)");
    PetscCheck(2 * PETSC_PI * m->band[1] * m->viscosity < 0.5 * m->loss_factor, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-viscosity %g with -rubber maxwell: the Kelvin-Voigt term's loss factor at the band's high end, 2 pi F2 tau = %g, must stay below half of -rubber_loss_factor %g (the branches carry the rest of it over the band)",
               (double)m->viscosity, (double)(2 * PETSC_PI * m->band[1] * m->viscosity), (double)m->loss_factor);
    PetscCall(RollerRubberFit(m->loss_factor, m->viscosity, m->band[0], m->band[1], tol, ROLLER_MAX_BRANCHES, &m->nbranch, m->tau, m->g, &m->fit_error));
    PetscCheck(m->nbranch > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-rubber_loss_factor %g -rubber_band %g,%g: no Prony series of at most %d branches keeps the loss factor within %g %% of it over the band (best: %.3g %%); narrow the band", (double)m->loss_factor,
               (double)m->band[0], (double)m->band[1], ROLLER_MAX_BRANCHES, (double)(100 * tol), (double)(100 * m->fit_error));
    PetscFunctionReturn(0);
  }
  PetscCheck(given[2] && given[3], ctx->comm, PETSC_ERR_ARG_WRONG, "-rubber maxwell needs the fit (-rubber_loss_factor ETA -rubber_band F1,F2) or the branches (-maxwell_tau T1,... -maxwell_weight g1,...)%s", given[2] || given[3] ? (given[2] ? ": -maxwell_weight is missing" : ": -maxwell_tau is missing") : "");
  PetscCheck(ntau >= 1 && ntau <= ROLLER_MAX_BRANCHES, ctx->comm, PETSC_ERR_USER_INPUT, "-maxwell_tau: %" PetscInt_FMT " value%s given, allowed 1 to %d branches", ntau, ntau == 1 ? "" : "s", ROLLER_MAX_BRANCHES);
  PetscCheck(nweight == ntau, ctx->comm, PETSC_ERR_USER_INPUT, "-maxwell_weight: %" PetscInt_FMT " value%s given, needs one per -maxwell_tau (%" PetscInt_FMT ")", nweight, nweight == 1 ? "" : "s", ntau);
  for (PetscInt i = 0; i < ntau; ++i) {
    RollerCheckOption(ctx->comm, "-maxwell_tau", tau[i], tau[i] > 0, "> 0 (a relaxation time)");
    RollerCheckOption(ctx->comm, "-maxwell_weight", weight[i], weight[i] > 0, "> 0 (a branch's shear modulus over the relaxed one, mu = young/(2 (1 + poisson)))");
    m->tau[i] = tau[i];
    m->g[i]   = weight[i];
  }
  m->nbranch     = ntau;
  m->loss_factor = 0.0;
  PetscFunctionReturn(0);
}

/* -ts_view: the branches, and the storage modulus (over the relaxed one, and absolute) and the loss factor at the
   band's ends (fitted) and at the nw angular frequencies w[] named what[]. */
PetscErrorCode RollerRubberView(Roller ctx, PetscInt nw, const PetscReal w[], const char *const what[])
{
  const RollerMaterial *m   = &ctx->material;
  PetscReal             sum = 0.0;

  PetscFunctionBeginUser;
  if (m->rubber != ROLLER_RUBBER_MAXWELL) PetscFunctionReturn(0);
  for (PetscInt i = 0; i < m->nbranch; ++i) sum += m->g[i];
  if (m->loss_factor > 0)
    PetscCall(PetscPrintf(ctx->comm, "roller: -rubber maxwell, %" PetscInt_FMT " branches fitted to the loss factor %g over %g-%g (cycles per unit time): within %.2f %% of it (the fewest branches within 4 %%)\n", m->nbranch, (double)m->loss_factor,
                          (double)m->band[0], (double)m->band[1], (double)(100 * m->fit_error)));
  else PetscCall(PetscPrintf(ctx->comm, "roller: -rubber maxwell, %" PetscInt_FMT " branches given\n", m->nbranch));
  PetscCall(PetscPrintf(ctx->comm, "roller: branches (shear modulus g mu over the relaxed mu = %g, relaxation time tau):", (double)m->mu));
  for (PetscInt i = 0; i < m->nbranch; ++i) PetscCall(PetscPrintf(ctx->comm, " g %.4g tau %.4g;", (double)m->g[i], (double)m->tau[i]));
  PetscCall(PetscPrintf(ctx->comm, " instantaneous shear modulus %g = %.4g mu (the bulk's stays elastic)\n", (double)(m->mu * (1 + sum)), (double)(1 + sum)));
  if (m->viscosity > 0)
    PetscCall(PetscPrintf(ctx->comm, "roller: beside them the Kelvin-Voigt term -viscosity %g (sigma += tau C:eps_t): its loss factor w tau is 0.01 at f = %g and 1 at f = %g (cycles per unit time; in the loss factors below)\n", (double)m->viscosity, (double)(0.01 / (2 * PETSC_PI * m->viscosity)), (double)(1.0 / (2 * PETSC_PI * m->viscosity))));
  for (PetscInt pass = 0; pass < 2; ++pass) {
    const PetscInt k = pass == 0 ? (m->loss_factor > 0 ? 2 : 0) : nw;

    for (PetscInt j = 0; j < k; ++j) {
      const PetscReal wj = pass == 0 ? 2 * PETSC_PI * m->band[j] : w[j];
      PetscReal       re, im;

      RollerRubberModulus(m->nbranch, m->tau, m->g, 0.0, wj, &re, &im);
      im += wj * m->viscosity; /* the Kelvin-Voigt term's G''/mu */
      PetscCall(PetscPrintf(ctx->comm, "roller:   at %s f = %g (w %g): shear storage modulus G' = %.4g mu = %g, loss factor G''/G' %.4g\n", pass == 0 ? (j == 0 ? "the band's low end" : "the band's high end") : what[j], (double)(wj / (2 * PETSC_PI)), (double)wj, (double)re, (double)(re * m->mu), (double)(im / re)));
    }
  }
  PetscFunctionReturn(0);
}
