/* Coulomb friction between Gamma_C and the sheet (docs/friction.md), a part of the condensed solver built only
   when -friction > 0. A node's lab coordinate along e1 is s_n = t(t) . (x_n + xi_n) (t(t) = R(-theta) e1, the
   step's tangent); its slip over the step is the increment the DMF energy identity pairs the forces with,
     Delta s_n = t^k . (x_n + xi^k_n) - t^{k-2} . (x_n + xi^{k-2}_n) - (X(t_k) - X(t_{k-2})).
   With the normal forces fixed (Tresca) the step is min J^k(xi) + sum_n g_n |Delta s_n(xi)| under the obstacle
   bound; condensed on the candidates (contact_condensed.c) its dual is the box QP of contact_boxqp.c in
   x = (lambda_N, lambda_T): G = B^T S B, d = (gaps, slips of the free solution), lambda_N >= 0,
   |lambda_T| <= g. Coulomb is solved first directly by the semismooth Newton method (friction/coulomb.c), with
   the velocity weakening mu(v) (v = |Delta s|/(2 dt) the slip speed) inside it, its first iterate the last solve's
   multipliers (checkpointed) where they were in contact, with mu of their slips there, else the frictionless ones at
   mu of the last step's slip speeds; where that fails, with mu frozen per Newton solve and iterated about them (Anderson's
   acceleration, contact_anderson.c). Without weakening, if Newton fails: the fixed point g = mu lambda_N of Tresca
   steps from the frictionless multipliers, then, after -contact_friction_max_it steps, Coulomb as one LCP by
   Lemke's method (contact_lemke.c), and if that ends on a ray the step fails with an error. With weakening the
   step's mu(v) can have no attracting solution (the fixed point's gain above 1, docs/friction.md section 3): if
   Newton fails both ways, mu at the last step's slip speeds is used for the step. Each fallback is counted: the
   CSV's coulomb_fallback (1 Tresca passes, 2 Lemke, 3 mu of the last step, 4 the sheet held at its bound:
   contact_sheet.c), one line at the end of the run. */
#include "contact_impl.h"

static PetscReal FrictionCoefficient(RollerContactFriction fr, PetscReal v)
{
  return RollerFrictionMu(fr->law, v, NULL);
}

PetscErrorCode RollerContactFrictionCreate(Roller ctx, RollerContact c)
{
  RollerContactFriction fr;
  const PetscInt        nc = c->nodes.nc;
  PetscBool             condensed;

  PetscFunctionBeginUser;
  PetscCall(PetscStrcmp(c->solver->name, "condensed", &condensed));
  PetscCheck(condensed, ctx->comm, PETSC_ERR_ARG_INCOMP, "%s %g needs -contact_solver condensed (given: %s); its Tresca QP solver is -contact_friction_qp activeset, tao, vi or lemke", ctx->obstacle.table.n ? "-friction_table, mu at its end" : "-friction",
             (double)ctx->obstacle.friction, c->solver->name);
  PetscCheck(!c->opt.check, ctx->comm, PETSC_ERR_ARG_INCOMP, "-contact_check compares the frictionless solvers; with -friction compare runs with -contact_friction_qp activeset, tao, vi and lemke");
  PetscCall(PetscNew(&fr));
  fr->law    = &ctx->obstacle;
  fr->varies = RollerFrictionVaries(fr->law);
  RollerFrictionRange(fr->law, fr->range);
  PetscCall(RollerContactBoxQPCreate(2 * nc, &fr->box));
  PetscCall(PetscMalloc7(2 * nc, &fr->state, nc, &fr->lam_n, nc, &fr->mu_n, 2 * nc, &fr->x, nc, &fr->node_state, 2 * nc, &fr->g, 2 * nc, &fr->y));
  PetscCall(PetscCalloc1(2 * nc, &fr->warm));
  PetscCall(RollerContactAndersonCreate(2 * nc, 5, &fr->aa));
  PetscCall(PetscArrayzero(fr->node_state, nc));
  PetscCall(PetscMalloc1(nc, &c->acc.result.lambda_t));
  PetscCall(PetscArrayzero(c->acc.result.lambda_t, nc));
  c->friction = fr;
  PetscFunctionReturn(0);
}

/* At the end of a run, with one line on comm if the Coulomb solve fell back (never silent). */
PetscErrorCode RollerContactFrictionDestroy(MPI_Comm comm, RollerContactFriction *friction)
{
  RollerContactFriction fr = *friction;

  PetscFunctionBeginUser;
  if (!fr) PetscFunctionReturn(0);
  if (fr->count.newton_failures || fr->count.lemke_steps || fr->count.lagged_steps)
    PetscCall(PetscPrintf(comm, "friction: of %" PetscInt_FMT " Coulomb solves, the semismooth Newton method failed in %" PetscInt_FMT "; Lemke's method was needed in %" PetscInt_FMT "; mu of the last step's slip speeds was used in %" PetscInt_FMT " (mu(v) did not settle); the others of those by Tresca passes (the CSV's coulomb_fallback)\n",
                          fr->count.steps, fr->count.newton_failures, fr->count.lemke_steps, fr->count.lagged_steps));
  PetscCall(RollerContactBoxQPDestroy(&fr->box));
  PetscCall(PetscFree7(fr->state, fr->lam_n, fr->mu_n, fr->x, fr->node_state, fr->g, fr->y));
  PetscCall(PetscFree(fr->warm));
  PetscCall(RollerContactAndersonDestroy(&fr->aa));
  PetscCall(PetscFree3(fr->M, fr->q, fr->z));
  PetscCall(PetscFree(fr));
  *friction = NULL;
  PetscFunctionReturn(0);
}

/* Before a step's (or stage's) solve: the multipliers of the last one (c->acc.result, a part of the checkpoint, so a
   restart starts its first Newton solve where the uninterrupted run did), the semismooth Newton's first iterate. */
PetscErrorCode RollerContactFrictionRemember(RollerContact c)
{
  const PetscInt nc = c->nodes.nc;

  PetscFunctionBeginUser;
  if (!c->friction) PetscFunctionReturn(0);
  PetscCall(PetscArraycpy(c->friction->warm, c->acc.result.lambda, nc));
  PetscCall(PetscArraycpy(c->friction->warm + nc, c->acc.result.lambda_t, nc));
  PetscFunctionReturn(0);
}

/* u^T S_ij v: the entry of S between node i along u and node j along v (S: 2 nc x 2 nc, column-major). */
static inline PetscReal Entry(const PetscReal *S, PetscInt n, const PetscReal u[2], const PetscReal v[2], PetscInt i, PetscInt j)
{
  const PetscReal *c0 = S + (size_t)(2 * j) * n, *c1 = S + (size_t)(2 * j + 1) * n;

  return u[0] * (v[0] * c0[2 * i] + v[1] * c1[2 * i]) + u[1] * (v[0] * c0[2 * i + 1] + v[1] * c1[2 * i + 1]);
}

/* The frame of the slip at t = t_k: the sheet's tangent t^{k-2} of t_{k-2} and its advance X(t_k) - X(t_{k-2});
   Delta s_n = t^k . (x_n + xi^k_n) - t^{k-2} . (x_n + xi^{k-2}_n) - dX. */
static void SlipFrame(Roller ctx, PetscReal t, PetscReal t2[2], PetscReal *dX)
{
  RollerContactSheetTangent(ctx, t - 2.0 * ctx->ts.dt, t2);
  *dX = RollerSheetPosition(ctx, t) - RollerSheetPosition(ctx, t - 2.0 * ctx->ts.dt);
}

static PetscErrorCode LemkeAlloc(RollerContactFriction fr, PetscInt m)
{
  PetscFunctionBeginUser;
  if (m <= fr->lemke_cap) PetscFunctionReturn(0);
  PetscCall(PetscFree3(fr->M, fr->q, fr->z));
  PetscCall(PetscMalloc3((size_t)16 * m * m, &fr->M, 4 * m, &fr->q, 4 * m, &fr->z));
  fr->lemke_cap = m;
  PetscFunctionReturn(0);
}

/* Coulomb as one LCP in z = (lambda_N, lambda_+, lambda_-, beta), lambda_T = lambda_+ - lambda_-, from the box
   QP's G (2m) and d: w_N = gap, rho_+- = beta +- Delta s, zeta = mu lambda_N - lambda_+ - lambda_- (each >= 0,
   complementary to its z): a slipping node has beta = |Delta s| and its force mu lambda_N against the slip. */
static PetscErrorCode CoulombLemke(RollerContactFriction fr, PetscInt m, PetscReal t, PetscReal x[])
{
  const PetscInt   n = 4 * m, m2 = 2 * m;
  const PetscReal *G = fr->box.G, *d = fr->box.d;
  PetscInt         pivots;
  PetscBool        solved;

  PetscFunctionBeginUser;
  PetscCall(LemkeAlloc(fr, m));
  PetscCall(PetscArrayzero(fr->M, (size_t)n * n));
  for (PetscInt a = 0; a < m; ++a) {
    for (PetscInt b = 0; b < m; ++b) {
      const PetscReal nn = G[a + (size_t)b * m2], nt = G[a + (size_t)(m + b) * m2], tn = G[m + a + (size_t)b * m2], tt = G[m + a + (size_t)(m + b) * m2];
      const PetscReal blk[3][3] = {
        {nn,  nt,  -nt},
        {tn,  tt,  -tt},
        {-tn, -tt, tt }
      };

      for (PetscInt r = 0; r < 3; ++r)
        for (PetscInt s = 0; s < 3; ++s) fr->M[r * m + a + (size_t)(s * m + b) * n] = blk[r][s];
    }
    fr->M[m + a + (size_t)(3 * m + a) * n]     = 1.0; /* rho_+ += beta */
    fr->M[2 * m + a + (size_t)(3 * m + a) * n] = 1.0; /* rho_- += beta */
    fr->M[3 * m + a + (size_t)a * n]           = fr->mu_n[a];
    fr->M[3 * m + a + (size_t)(m + a) * n]     = -1.0;
    fr->M[3 * m + a + (size_t)(2 * m + a) * n] = -1.0;
    fr->q[a]                                   = d[a];
    fr->q[m + a]                               = d[m + a];
    fr->q[2 * m + a]                           = -d[m + a];
    fr->q[3 * m + a]                           = 0.0;
  }
  PetscCall(RollerContactLemke(n, fr->M, fr->q, fr->z, &pivots, &solved));
  PetscCheck(solved, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "Coulomb friction at t = %g: the fixed point of Tresca steps did not converge and Lemke's method ended on a ray after %" PetscInt_FMT " pivots; try a smaller -ts_dt or -friction", (double)t, pivots);
  for (PetscInt a = 0; a < m; ++a) {
    x[a]     = fr->z[a];
    x[m + a] = fr->z[m + a] - fr->z[2 * m + a];
  }
  PetscFunctionReturn(0);
}

/* The dual data of the step on the m candidates: G = B^T S B, d = (gaps, slips) of the free solution, from
   the gathered free solution c->nodes.red and the normal gaps gf of the candidates. */
static PetscErrorCode FrictionData(Roller ctx, RollerContact c, const PetscReal S[], const PetscReal gf[])
{
  RollerContactFriction fr = c->friction;
  const PetscInt        m = c->step.ncand, m2 = 2 * m, n = 2 * c->nodes.nc, *cand = c->step.cand;
  const PetscReal      *nr = c->step.normal, *tg = c->step.tangent, *xc = c->nodes.xc;
  const PetscScalar    *uf, *u2;
  PetscReal             t2[2], dX, compliance = 0.0, *yn, *yt; /* the hub's rows of the candidates along n and t */

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(3 * m, &yn, 3 * m, &yt));
  for (PetscInt a = 0; a < m; ++a) {
    RollerContactBorderRow(&c->step, nr, cand[a], n, yn + 3 * a);
    RollerContactBorderRow(&c->step, tg, cand[a], n, yt + 3 * a);
  }
  SlipFrame(ctx, c->step.t, t2, &dX);
  if (RollerContactSheetMoves(c)) RollerContactSheetFree(ctx, c, &dX, &compliance); /* the sheet's own motion */
  PetscCall(RollerContactGather(c, ctx->state.prev, c->nodes.red2));                /* xi^{k-2} */
  PetscCall(VecGetArrayRead(c->nodes.red, &uf));
  PetscCall(VecGetArrayRead(c->nodes.red2, &u2));
  for (PetscInt a = 0; a < m; ++a) {
    const PetscInt i = cand[a];

    fr->box.d[a]     = gf[a];
    fr->box.d[m + a] = RollerContactAlong(xc, uf, i, tg) - (RollerContactAlong(xc, u2, i, t2) + dX);
    for (PetscInt b = 0; b < m; ++b) {
      const PetscInt j = cand[b];

      fr->box.G[a + (size_t)b * m2]           = Entry(S, n, nr, nr, i, j) + RollerContactBorderPair(&c->step, yn + 3 * a, yn + 3 * b);
      fr->box.G[a + (size_t)(m + b) * m2]     = Entry(S, n, nr, tg, i, j) + RollerContactBorderPair(&c->step, yn + 3 * a, yt + 3 * b);
      fr->box.G[m + a + (size_t)b * m2]       = Entry(S, n, tg, nr, i, j) + RollerContactBorderPair(&c->step, yt + 3 * a, yn + 3 * b);
      fr->box.G[m + a + (size_t)(m + b) * m2] = Entry(S, n, tg, tg, i, j) + RollerContactBorderPair(&c->step, yt + 3 * a, yt + 3 * b) + compliance;
    }
  }
  PetscCall(VecRestoreArrayRead(c->nodes.red, &uf));
  PetscCall(VecRestoreArrayRead(c->nodes.red2, &u2));
  PetscCall(PetscFree2(yn, yt));
  PetscFunctionReturn(0);
}

/* Coulomb with mu of the last step's slip speeds (RollerContactFrictionLaggedMu), from the frictionless multipliers lam: by the semismooth
   Newton method, else by one Lemke solve (fallback 3). */
static PetscErrorCode LaggedSolve(Roller ctx, RollerContact c, PetscInt m, const PetscReal lam[])
{
  RollerContactFriction fr = c->friction;
  PetscInt              its;
  PetscBool             converged;

  PetscFunctionBeginUser;
  PetscCall(PetscInfo(NULL, "Friction at t = %g: mu of the last step's slip speeds\n", (double)c->step.t));
  fr->count.lagged_steps++;
  fr->fallback = 3;
  PetscCall(RollerContactFrictionLaggedMu(ctx, c, m));
  RollerContactFrictionStart(m, lam, fr->x);
  PetscCall(RollerFrictionCoulombNewton(m, fr->box.G, fr->box.d, NULL, 2.0 * ctx->ts.dt, fr->mu_n, fr->x, 4 * m + 20, &its, &converged));
  fr->its += its;
  if (!converged) PetscCall(CoulombLemke(fr, m, c->step.t, fr->x));
  PetscFunctionReturn(0);
}

/* The multipliers of the step with friction, from the frictionless ones in lcp (its lam on the candidates);
   S is the condensed solver's E^T A^{-1} E, gf the gaps of its free solution, c->nodes.red its gathered free
   solution. res->lambda, res->lambda_t receive the Coulomb multipliers of every node; res->its adds the QP
   iterations. */
PetscErrorCode RollerContactFrictionSolve(Roller ctx, RollerContact c, const PetscReal S[], RollerContactLCP *lcp, RollerContactResult *res)
{
  RollerContactFriction fr = c->friction;
  const PetscInt        m = c->step.ncand, m2 = 2 * m, *cand = c->step.cand;
  const PetscReal       t = c->step.t, dt = ctx->ts.dt;
  PetscReal             dmax = 0.0, change = 0.0, lmax = 0.0, dmu = 0.0;
  PetscBool             lemke = (PetscBool)(c->opt.friction_qp == ROLLER_BOXQP_LEMKE);

  PetscFunctionBeginUser;
  PetscCall(PetscArrayzero(res->lambda_t, c->nodes.nc));
  fr->its      = 0;
  fr->fallback = 0;
  for (PetscInt a = 0; a < m; ++a) lmax = PetscMax(lmax, lcp->lam[a]);
  if (lmax <= 0.0) PetscFunctionReturn(0); /* nothing touches: no friction either */
  fr->count.steps++;
  PetscCall(FrictionData(ctx, c, S, lcp->d));
  for (PetscInt a = 0; a < m2; ++a) dmax = PetscMax(dmax, PetscAbsReal(fr->box.d[a]));
  for (PetscInt a = 0; a < m; ++a) {
    fr->lam_n[a]     = lcp->lam[a];
    fr->mu_n[a]      = FrictionCoefficient(fr, 0.0);
    fr->state[a]     = lcp->lam[a] > 0.0 ? 0 : -1;
    fr->state[m + a] = 0;
  }
  if (c->opt.friction_newton && !lemke) {
    PetscBool done = PETSC_FALSE;

    PetscCall(RollerContactFrictionNewton(ctx, c, m, &done));
    if (done) goto accept;
    if (fr->varies) { /* the fixed point on mu(v) failed inside Newton: the passes would meet the same map */
      PetscCall(LaggedSolve(ctx, c, m, lcp->lam));
      goto accept;
    }
    for (PetscInt a = 0; a < m; ++a) fr->lam_n[a] = lcp->lam[a]; /* the fixed point starts afresh */
  }
  RollerContactAndersonReset(&fr->aa, m2);
  for (PetscInt it = 1;; ++it) {
    PetscInt its = 0;

    if (lemke) PetscCall(CoulombLemke(fr, m, t, fr->x));
    else {
      for (PetscInt a = 0; a < m; ++a) {
        fr->box.lo[a]     = 0.0;
        fr->box.up[a]     = PETSC_MAX_REAL;
        fr->box.up[m + a] = fr->mu_n[a] * fr->lam_n[a];
        fr->box.lo[m + a] = -fr->box.up[m + a];
      }
      PetscCall(RollerContactBoxQPSolve(&fr->box, c->opt.friction_qp, m2, c->opt.friction_qp == ROLLER_BOXQP_ACTIVESET ? 1e-13 * dmax : c->opt.rtol * dmax, t, fr->state, fr->x, &its));
    }
    fr->its++;
    res->its += its;
    RollerContactFrictionUpdate(fr, m, dt, &change, &lmax, &dmu);
    PetscCall(PetscInfo(NULL, "Friction at t = %g: iterate %" PetscInt_FMT " (%" PetscInt_FMT " QP its): change of lambda_N %g of %g, of mu %g\n", (double)t, it, its, (double)change, (double)lmax, (double)dmu));
    if (change <= c->opt.friction_rtol * lmax && dmu <= c->opt.friction_rtol * fr->range[1]) {
      PetscCall(PetscArraycpy(fr->lam_n, fr->x, m));
      PetscCall(PetscArraycpy(fr->mu_n, fr->g + m, m));
      break;
    }
    PetscCall(RollerContactFrictionNext(fr, m, PETSC_TRUE));
    if (it >= c->opt.friction_max_it) {
      if (lemke) { /* mu(v) did not settle: Coulomb with mu of the last step's slip speeds */
        PetscCall(PetscInfo(NULL, "Friction at t = %g: mu(v) did not settle in %" PetscInt_FMT " Lemke solves (change of mu %g)\n", (double)t, it, (double)dmu));
        PetscCall(LaggedSolve(ctx, c, m, lcp->lam));
        goto accept;
      }
      PetscCall(PetscInfo(NULL, "Friction at t = %g: no fixed point in %" PetscInt_FMT " Tresca steps (change %g of %g), Lemke's method\n", (double)t, it, (double)change, (double)lmax));
      lemke = PETSC_TRUE;
      fr->count.lemke_steps++;
      fr->fallback = 2;
      it           = 0;
      RollerContactAndersonReset(&fr->aa, m2);
    }
  }
  if (!lemke) { /* the last Tresca step bounded lambda_T by mu lambda_N of the iterate before (equal to rtol): a node
                   at that bound carries mu lambda_N of the final iterate exactly */
    for (PetscInt a = 0; a < m; ++a)
      if (PetscAbsReal(fr->x[m + a]) >= fr->box.up[m + a] * (1.0 - 1e-9)) fr->x[m + a] = PetscSign(fr->x[m + a]) * fr->mu_n[a] * fr->x[a];
  }
accept:
  PetscCall(PetscArrayzero(res->lambda, c->nodes.nc));
  for (PetscInt a = 0; a < m; ++a) {
    const PetscReal bound = fr->mu_n[a] * fr->x[a];

    if (fr->x[a] <= 0.0) continue;
    res->lambda[cand[a]]   = fr->x[a];
    res->lambda_t[cand[a]] = PetscMin(PetscMax(-bound, fr->x[m + a]), bound);
  }
  PetscFunctionReturn(0);
}

/* The friction columns of the accepted step xi^k (state.cur, gathered in c->nodes.red by the caller; xi^{k-2} is
   state.prev2): the slips, the friction
   force, the stick and slip nodes, the law's residual, the friction dissipation and the tangential parts of the
   shaft's and the sheet's works (docs/friction.md):
     1/2 lambda_T t^k . (xi^k - xi^{k-2}) = 1/2 lambda_T Delta s + 1/2 lambda_T (X^k - X^{k-2})
                                            - 1/2 lambda_T (t^k - t^{k-2}) . (x_n + xi^{k-2}_n),
   the first minus the dissipation (>= 0 by the law), the second the sheet's, the third the shaft's.
   The law's residual, relative: at every node with lambda_N > 0, max(0, |lambda_T| - mu lambda_N)/(mu lambda_N);
   a sticking node (|lambda_T| < mu lambda_N (1 - 1e-9)) |Delta s|/s, s the largest tangential motion of a contact
   node over the step, the sheet's travel or the rim's by the rotation, at least 1e-6 r_C (round-off when nothing moves); a slipping one |lambda_T + mu lambda_N sign(Delta s)|/(mu lambda_N). */
PetscErrorCode RollerContactFrictionInfo(Roller ctx, RollerContact c, const PetscReal lambda[], RollerStepInfo *info)
{
  RollerContactFriction fr = c->friction;
  RollerStepFriction   *f  = &info->friction;
  const PetscReal      *lt = c->acc.result.lambda_t, *xc = c->nodes.xc, *tg = c->step.tangent, t = c->step.t, dt = ctx->ts.dt;
  const PetscScalar    *u, *u2;
  PetscReal             t2[2], dX, sscale = 1e-6 * ctx->mesh.r_outer, *slip = fr->box.mu;

  PetscFunctionBeginUser;
  f->force = f->dissipation = f->residual = 0.0;
  f->stick = f->slip = 0;
  f->iterations      = fr->its;
  f->fallback        = c->sheet.held_at_bound ? 4 : fr->fallback;
  SlipFrame(ctx, t, t2, &dX);
  if (RollerContactSheetMoves(c)) { /* the sheet's own advance X^k - X^{k-2}: internal, the resistance dissipates */
    dX = c->sheet.X[0] - c->sheet.X[2];
    f->dissipation += c->sheet.dissipation;
  }
  { /* the drive's own motion of the contact nodes over the step: the scale of a sticking node's slip */
    PetscReal th0, th2;

    RollerTheta(ctx, t, &th0, NULL, NULL);
    RollerTheta(ctx, t - 2.0 * dt, &th2, NULL, NULL);
    sscale = PetscMax(sscale, PetscMax(PetscAbsReal(dX), PetscAbsReal(th0 - th2) * ctx->mesh.r_outer));
  }
  PetscCall(RollerContactGather(c, ctx->state.prev2, c->nodes.red2)); /* xi^k is in c->nodes.red (RollerContactInfo) */
  PetscCall(VecGetArrayRead(c->nodes.red, &u));
  PetscCall(VecGetArrayRead(c->nodes.red2, &u2));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscReal p2[2]  = {xc[2 * i] + PetscRealPart(u2[2 * i]), xc[2 * i + 1] + PetscRealPart(u2[2 * i + 1])};
    const PetscReal motion = RollerContactAlong(xc, u, i, tg) - RollerContactAlong(xc, u2, i, t2);

    slip[i] = motion - dX;
    if (lambda[i] > 0.0) sscale = PetscMax(sscale, PetscMax(PetscAbsReal(motion), PetscAbsReal(slip[i])));
    f->force += lt[i];
    f->dissipation -= 0.5 * lt[i] * slip[i];
    if (!RollerContactSheetMoves(c)) f->sheet_step += 0.5 * lt[i] * dX;
    f->shaft_step -= 0.5 * lt[i] * ((tg[0] - t2[0]) * p2[0] + (tg[1] - t2[1]) * p2[1]);
  }
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscReal bound = FrictionCoefficient(fr, PetscAbsReal(slip[i]) / (2.0 * dt)) * lambda[i];
    PetscReal       r;

    fr->node_state[i] = 0;
    if (lambda[i] <= 0.0) continue;
    r = PetscMax(0.0, PetscAbsReal(lt[i]) - bound) / bound;
    if (PetscAbsReal(lt[i]) < bound * (1.0 - 1e-9)) r = PetscMax(r, PetscAbsReal(slip[i]) / sscale);
    else if (PetscAbsReal(slip[i]) > 1e-9 * sscale) r = PetscMax(r, PetscAbsReal(lt[i] + PetscSign(slip[i]) * bound) / bound);
    fr->node_state[i] = (PetscAbsReal(lt[i]) >= bound * (1.0 - 1e-9) && PetscAbsReal(slip[i]) > 1e-9 * sscale) ? 2 : 1;
    if (fr->node_state[i] == 2) f->slip++;
    else f->stick++;
    f->residual = PetscMax(f->residual, r);
  }
  PetscCall(VecRestoreArrayRead(c->nodes.red, &u));
  PetscCall(VecRestoreArrayRead(c->nodes.red2, &u2));
  PetscFunctionReturn(0);
}

/* The stick/slip state of every Gamma_C node of the accepted step (0 off the sheet, 1 stick, 2 slip) as reals,
   for the output field. */
PetscErrorCode RollerContactFrictionState(RollerContact c, PetscReal state[])
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->nodes.nc; ++i) state[i] = c->friction ? (PetscReal)c->friction->node_state[i] : 0.0;
  PetscFunctionReturn(0);
}
