/* Coulomb friction of one step solved directly (docs/friction.md section 3): the primal-dual active-set method
   of Hueber, Stadler & Wohlmuth (SIAM J. Sci. Comput. 30, 2008), a semismooth Newton method on the
   complementarity functions of Signorini's and Coulomb's laws, on the condensed problem of the friction's box QP
   (G, d built by contact/contact_friction.c: gap = (G x + d)_N, slip = (G x + d)_T, x = (lambda_N, lambda_T)). Each node is
   inactive (lambda = 0), sticking (gap = 0, slip = 0) or slipping (gap = 0, lambda_T = s mu lambda_N, s = +-1); the
   states follow from the last iterate with c = 1/G_aa:
     in contact   iff  lambda_N - c_N gap > 0,
     sticking     iff  |lambda_T - c_T slip| < mu (lambda_N - c_N gap),  else slipping with s = sign(lambda_T - c_T slip),
   and each iterate solves the linear (non-symmetric) system of its states. The step to that solution is globalized
   by backtracking on the merit ||F||^2 of the complementarity functions F (the rule above as a projection,
   Hintermueller, Ito & Kunisch, SIAM J. Optim. 13, 2002): without it the iteration can cycle between two iterates
   of the same states (velocity weakening: Newton on the convex exponential mu(v) overshoots the slip) or of two
   sets of states (a node at the stick/slip boundary); ten iterations without a decrease of the least merit so far
   end it as failed. It ends when the states repeat after a full step and the
   solution satisfies the laws (lambda_N >= 0, gap >= 0, |lambda_T| <= mu lambda_N, a slipping node moving against
   its force); otherwise *converged is false and the caller falls back on the fixed point of Tresca steps. A few
   dense LU solves instead of the fixed point's tens of QPs. */
#include "friction/friction.h"
#include <petscblaslapack.h>

typedef struct {
  PetscInt     *idx_n, *idx_t, *state;              /* unknown numbers in the reduced system (-1: none); state 0 off, 1 stick, 2 slip */
  PetscBLASInt *piv;                                /* the LU's pivots */
  PetscReal    *sign, *R, *rhs, *sol, *w, *x0, *x1; /* x0: the iterate, x1: the full step from it */
} CoulombWork;

/* The states of the last iterate (x, w = G x + d); returns how many changed. */
static PetscInt States(PetscInt m, const PetscReal G[], const PetscReal mu[], const PetscReal x[], const PetscReal w[], CoulombWork *cw)
{
  PetscInt changed = 0;

  for (PetscInt a = 0; a < m; ++a) {
    const PetscReal ln = x[a] - w[a] / G[a + (size_t)a * 2 * m], z = x[m + a] - w[m + a] / G[m + a + (size_t)(m + a) * 2 * m];
    PetscInt        st = 0;
    PetscReal       s  = 0.0;

    if (ln > 0.0) {
      st = PetscAbsReal(z) < mu[a] * ln ? 1 : 2;
      s  = st == 2 ? PetscSign(z) : 0.0;
    }
    if (st != cw->state[a] || s != cw->sign[a]) changed++;
    cw->state[a] = st;
    cw->sign[a]  = s;
  }
  return changed;
}

/* The linear system of the states: gap = 0 at every node in contact, slip = 0 at every sticking one, with
   lambda_T = s mu lambda_N substituted at the slipping ones; x from its solution. */
static PetscErrorCode SolveStates(PetscInt m, const PetscReal G[], const PetscReal d[], const PetscReal mu[], const PetscReal kv[], CoulombWork *cw, PetscReal x[])
{
  const PetscInt m2 = 2 * m;
  PetscInt       k  = 0;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < m; ++a) cw->idx_n[a] = cw->state[a] ? k++ : -1;
  for (PetscInt a = 0; a < m; ++a) cw->idx_t[a] = cw->state[a] == 1 || (cw->state[a] == 2 && kv && kv[a] != 0.0) ? k++ : -1;
  PetscCall(PetscArrayzero(x, m2));
  if (!k) PetscFunctionReturn(0);
  PetscCall(PetscArrayzero(cw->R, (size_t)k * k));
  for (PetscInt a = 0; a < m; ++a)
    for (PetscInt part = 0; part < 2; ++part) { /* the gap row (N) of a node in contact, the slip row (T) of a sticking one */
      const PetscInt row = part ? cw->idx_t[a] : cw->idx_n[a], ga = part ? m + a : a;

      if (row < 0) continue;
      if (part && cw->state[a] == 2) { /* velocity weakening, linearized: lambda_T = s (mu lambda_N + kv w_T + kv0) */
        cw->R[row + (size_t)row * k] += 1.0;
        cw->R[row + (size_t)cw->idx_n[a] * k] -= cw->sign[a] * mu[a];
        cw->rhs[row] = cw->sign[a] * (kv[a] * d[ga] + kv[m + a]);
        for (PetscInt b = 0; b < m; ++b) {
          const PetscReal gn = -cw->sign[a] * kv[a] * G[ga + (size_t)b * m2], gt = -cw->sign[a] * kv[a] * G[ga + (size_t)(m + b) * m2];

          if (cw->idx_n[b] >= 0) cw->R[row + (size_t)cw->idx_n[b] * k] += gn + (cw->state[b] == 2 && cw->idx_t[b] < 0 ? gt * cw->sign[b] * mu[b] : 0.0);
          if (cw->idx_t[b] >= 0) cw->R[row + (size_t)cw->idx_t[b] * k] += gt;
        }
        continue;
      }
      cw->rhs[row] = -d[ga];
      for (PetscInt b = 0; b < m; ++b) {
        const PetscReal gn = G[ga + (size_t)b * m2], gt = G[ga + (size_t)(m + b) * m2];

        if (cw->idx_n[b] >= 0) cw->R[row + (size_t)cw->idx_n[b] * k] += gn + (cw->state[b] == 2 && cw->idx_t[b] < 0 ? gt * cw->sign[b] * mu[b] : 0.0);
        if (cw->idx_t[b] >= 0) cw->R[row + (size_t)cw->idx_t[b] * k] += gt;
      }
    }
  { /* LAPACK's LU (dense.c: its factors, without the reference BLAS's overhead on 40 unknowns) and its solve directly (a
       PETSc Mat made and destroyed for each of these small systems cost more than its solve) */
    PetscBLASInt nb, one = 1, info;

    PetscCall(PetscBLASIntCast(k, &nb));
    PetscCall(PetscArraycpy(cw->sol, cw->rhs, k));
    PetscCall(RollerDenseLUFactor(nb, cw->R, cw->piv, &info));
    PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_MAT_LU_ZRPVT, "Coulomb's states: the system of %" PetscInt_FMT " unknowns is singular (zero pivot %d)", k, (int)info);
    PetscCallBLAS("LAPACKgetrs", LAPACKgetrs_("N", &nb, &one, cw->R, &nb, cw->piv, cw->sol, &nb, &info));
    PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "Coulomb's states: LAPACK getrs info %d", (int)info);
  }
  for (PetscInt a = 0; a < m; ++a) {
    if (cw->idx_n[a] >= 0) x[a] = cw->sol[cw->idx_n[a]];
    if (cw->idx_t[a] >= 0) x[m + a] = cw->sol[cw->idx_t[a]];
    else if (cw->state[a] == 2) x[m + a] = cw->sign[a] * mu[a] * x[a];
  }
  PetscFunctionReturn(0);
}

/* The laws at the solution, to round-off relative to the largest force and the largest datum. */
static PetscBool LawsHold(PetscInt m, const PetscReal mu[], const PetscReal x[], const PetscReal w[], const PetscReal d[], const CoulombWork *cw)
{
  PetscReal fmax = 0.0, dmax = 0.0;

  for (PetscInt a = 0; a < m; ++a) fmax = PetscMax(fmax, PetscAbsReal(x[a]));
  for (PetscInt a = 0; a < 2 * m; ++a) dmax = PetscMax(dmax, PetscAbsReal(d[a]));
  for (PetscInt a = 0; a < m; ++a) {
    if (x[a] < -1e-12 * fmax || w[a] < -1e-10 * dmax) return PETSC_FALSE;
    if (PetscAbsReal(x[m + a]) > mu[a] * PetscMax(x[a], 0.0) * (1.0 + 1e-12) + 1e-14 * fmax) return PETSC_FALSE;
    if (cw->state[a] == 2 && cw->sign[a] * w[m + a] > 1e-10 * dmax) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

/* ||F(x)||^2, F the complementarity functions of the states' rule at x (w = G x + d), with c = 1/G_aa:
     F_N = lambda_N - max(0, lambda_N - c_N gap),  F_T = lambda_T - P(lambda_T - c_T slip),
   P the projection onto [-mu l, mu l], l = max(0, lambda_N - c_N gap); mu = mu(|slip|/(2 dt)) with velocity weakening
   (law given; two_dt = 2 dt), else mu[] as given. */
static PetscReal Merit(PetscInt m, const PetscReal G[], const RollerObstacle *law, PetscReal two_dt, const PetscReal mu[], const PetscReal x[], const PetscReal w[])
{
  PetscReal phi = 0.0;

  for (PetscInt a = 0; a < m; ++a) {
    const PetscReal l = PetscMax(0.0, x[a] - w[a] / G[a + (size_t)a * 2 * m]), z = x[m + a] - w[m + a] / G[m + a + (size_t)(m + a) * 2 * m];
    const PetscReal mv = law ? RollerFrictionMu(law, PetscAbsReal(w[m + a]) / two_dt, NULL) : mu[a];
    const PetscReal fn = x[a] - l, ft = x[m + a] - PetscMin(PetscMax(z, -mv * l), mv * l);

    phi += fn * fn + ft * ft;
  }
  return phi;
}

/* mu(|v|) at the slips w (v = |w_T|/two_dt): mu into mu[], the linearization of the slip law at the
   nodes in contact into kv (kv[a] = lambda_N mu'(v) sign(w_T)/(2 dt), kv[m + a] = -lambda_N mu'(v) |v|); the largest
   change of mu at the nodes that slipped in the last solve (cw->state): only their mu enters the states' system; a
   sticking node's or a free one's decides its state only, which the next States checks with the new mu. */
static PetscReal WeakeningMu(PetscInt m, const RollerObstacle *law, PetscReal two_dt, const PetscReal x[], const PetscReal w[], const CoulombWork *cw, PetscReal mu[], PetscReal kv[])
{
  PetscReal change = 0.0;

  for (PetscInt a = 0; a < m; ++a) {
    const PetscReal v = PetscAbsReal(w[m + a]) / two_dt, sw = w[m + a] != 0.0 ? PetscSign(w[m + a]) : -cw->sign[a];
    PetscReal       dmu, mun                                = RollerFrictionMu(law, v, &dmu);

    if (cw->state[a] == 2) change = PetscMax(change, PetscAbsReal(mun - mu[a]));
    mu[a]     = mun;
    kv[a]     = PetscMax(x[a], 0.0) * dmu * sw / two_dt;
    kv[m + a] = -PetscMax(x[a], 0.0) * dmu * v;
  }
  return change;
}

/* On the box QP's data G, d (2m; the residual w = G x + d): x (2m: lambda_N, lambda_T) in: the initial guess (the
   frictionless multipliers), out: the solution if *converged. Up to maxit iterations (*its). */
PetscErrorCode RollerFrictionCoulombNewton(PetscInt m, const PetscReal G[], const PetscReal d[], const RollerObstacle *law, PetscReal two_dt, PetscReal mu[], PetscReal x[], PetscInt maxit, PetscInt *its, PetscBool *converged)
{
  CoulombWork cw;
  PetscReal  *kv = NULL, dmu = 0.0, range[2] = {0.0, 0.0}; /* of mu(v): its largest the scale of mu's change */
  PetscBool   full    = PETSC_TRUE;                        /* the last step was the whole Newton step */
  PetscReal   best    = PETSC_MAX_REAL, hist[4];           /* hist: the merits of the last four iterates */
  PetscInt    stalled = 0;                                 /* the least merit so far, iterations since it decreased */

  PetscFunctionBeginUser;
  *converged = PETSC_FALSE;
  *its       = 0;
  PetscCall(PetscMalloc4(m, &cw.idx_n, m, &cw.idx_t, m, &cw.state, 2 * m, &cw.piv));
  PetscCall(PetscMalloc7(m, &cw.sign, (size_t)4 * m * m, &cw.R, 2 * m, &cw.rhs, 2 * m, &cw.sol, 2 * m, &cw.w, 2 * m, &cw.x0, 2 * m, &cw.x1));
  for (PetscInt a = 0; a < m; ++a) {
    cw.state[a] = -1; /* no state yet: the first pass counts as a change */
    cw.sign[a]  = 0.0;
  }
  if (law) {
    RollerFrictionRange(law, range);
    PetscCall(PetscMalloc1(2 * m, &kv));
  }
  RollerDenseMultAdd(2 * m, G, d, 1.0, x, cw.w);
  for (*its = 1; *its <= maxit; ++*its) {
    PetscReal phi0, ref = 0.0, alpha = 1.0;

    if (kv && *its > 1) dmu = WeakeningMu(m, law, two_dt, x, cw.w, &cw, mu, kv); /* the first iterate takes mu as given */
    if (!States(m, G, mu, x, cw.w, &cw) && full && (!kv || (*its > 1 && dmu <= 1e-10 * range[1]))) {
      for (PetscInt a = 0; a < m; ++a)
        if (cw.state[a] == 2) x[m + a] = cw.sign[a] * mu[a] * x[a];
      RollerDenseMultAdd(2 * m, G, d, 1.0, x, cw.w);
      *converged = LawsHold(m, mu, x, cw.w, d, &cw);
      break;
    }
    phi0                 = Merit(m, G, law, two_dt, mu, x, cw.w);
    hist[(*its - 1) % 4] = phi0;
    for (PetscInt h = 0; h < PetscMin(*its, 4); ++h) ref = h ? PetscMax(ref, hist[h]) : hist[h];
    if (phi0 < (1.0 - 1e-4) * best) best = phi0, stalled = 0;
    else if (++stalled >= 10) break; /* ten iterations without progress: a cycle (or no solution of these laws) */
    PetscCall(PetscArraycpy(cw.x0, x, 2 * m));
    PetscCall(SolveStates(m, G, d, mu, *its > 1 ? kv : NULL, &cw, x));
    PetscCall(PetscArraycpy(cw.x1, x, 2 * m));
    RollerDenseMultAdd(2 * m, G, d, 1.0, x, cw.w);
    /* non-monotone Armijo backtracking against the largest of the last four merits (Grippo, Lampariello & Lucidi,
       SIAM J. Numer. Anal. 23, 1986: the active-set iteration's own full steps are kept while it makes progress
       over a few iterations); without a decrease in 10 halvings the full step */
    while (Merit(m, G, law, two_dt, mu, x, cw.w) > ref - 1e-4 * alpha * phi0 && alpha > 1e-3) {
      alpha *= 0.5;
      for (PetscInt a = 0; a < 2 * m; ++a) x[a] = cw.x0[a] + 0.5 * (x[a] - cw.x0[a]);
      RollerDenseMultAdd(2 * m, G, d, 1.0, x, cw.w);
    }
    if (alpha <= 1e-3) {
      PetscCall(PetscArraycpy(x, cw.x1, 2 * m));
      RollerDenseMultAdd(2 * m, G, d, 1.0, x, cw.w);
      alpha = 1.0;
    }
    full = (PetscBool)(alpha == 1.0);
  }
  PetscCall(PetscFree(kv));
  PetscCall(PetscFree4(cw.idx_n, cw.idx_t, cw.state, cw.piv));
  PetscCall(PetscFree7(cw.sign, cw.R, cw.rhs, cw.sol, cw.w, cw.x0, cw.x1));
  PetscFunctionReturn(0);
}
