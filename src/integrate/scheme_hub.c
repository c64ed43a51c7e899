/* The hub's part of a three-level step (-axle, docs/model.md section 10; model/axle.h): the bordered system
     [[A, C], [C^T, D_A]] (xi^k, q^k) = (b, b_q) + (E N lambda, reaction),   q^k = Z p (u along the lab's vertical),
   with C = c_M C_M + c_K C_K, D_A = c_M D_M + H/dt^2 + c_K D_K + beta S + c_d/(2 dt) e_phi e_phi^T (H the hub's mass and
   inertia, S its springs, c_d the drive's damper), eliminated: the body's step is the usual one with A_eff = A - C Dz C^T
   (model/solver.c) and b_eff = b - C Dz b_q, then q^k = Dz (b_q - C^T xi^k). The same Newmark scheme on the augmented
   unknowns, so the energy identity of docs/model.md section 2 holds for (xi, q) with M_aug, K_aug; the guide's
   reaction (the constraint u = Y n(theta(t)) turns with the frame) and the preload do work, counted in load_work. */
#include "scheme_impl.h"
#include "model/model.h"

/* The products P = (C_M . x, C_K . x, R C_M . x, C_D . x) of a body level (C_D: with the Maxwell branches, else 0). */
static PetscErrorCode Products(RollerHub *hub, Vec x, PetscReal P[12])
{
  const PetscInt n = hub->c.CD[0] ? 12 : 9;
  Vec            v[12];
  PetscScalar    d[12];

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < 3; ++j) {
    v[j]     = hub->c.CM[j];
    v[3 + j] = hub->c.CK[j];
    v[6 + j] = hub->c.RCM[j];
    v[9 + j] = hub->c.CD[j];
  }
  PetscCall(VecMDot(x, n, v, d));
  for (PetscInt j = 0; j < 12; ++j) P[j] = j < n ? PetscRealPart(d[j]) : 0.0;
  PetscFunctionReturn(0);
}

/* The levels at the start of a run: q at rest on every level (a restart reads them and the anchor after: the checkpoint's
   items, RollerCheckpointRegister), the products of the body's levels (the checkpoint's already). */
PetscErrorCode RollerHubSetUp(Roller ctx)
{
  RollerHub *hub = ctx->axle.hub;

  PetscFunctionBeginUser;
  PetscCall(Products(hub, ctx->state.cur, hub->s.P[0]));
  PetscCall(Products(hub, ctx->state.prev, hub->s.P[1]));
  PetscCall(Products(hub, ctx->state.prev2, hub->s.P[2]));
  PetscFunctionReturn(0);
}

/* D_A of the step matrix op (scheme coefficient beta, drive damper c_d/(2 dt), the Maxwell branches' c_D). */
static void StepD(Roller ctx, const RollerStepOperator *op, PetscReal beta, PetscReal DA[9])
{
  const RollerHub *hub = ctx->axle.hub;
  const PetscReal  dt = ctx->ts.dt, H[3] = {ctx->axle.mass, ctx->axle.mass, ctx->axle.inertia};
  PetscReal        S[9];

  RollerAxleSprings(ctx, S);
  for (PetscInt i = 0; i < 9; ++i) DA[i] = op->c_M * hub->c.DM[i] + op->c_K * hub->c.DK[i] + op->c_D * hub->c.DD[i] + beta * S[i];
  for (PetscInt i = 0; i < 3; ++i) DA[4 * i] += H[i] / (dt * dt);
  DA[8] += ctx->axle.drive_damping / (2.0 * dt);
}

/*
  RollerHubStepBegin - the hub's terms of the step from t1 = t_{k-1} (levels cur, prev, prev2 of xi and q), Coriolis
  velocity coefficients c, after the body's right-hand side is made: the load F^{k-1} on the body rows (added to load
  and rhs) and on q, the history terms, b_q, and the elimination: rhs <- b - C Dz b_q, the operator's W of the new level.

  The rotating frame's force on the whole body, rho M_all (theta'' R (x + xi) + theta'^2 (x + xi) + 2 theta' R v), R =
  R(-pi/2), with the Gamma_D nodes at the hub's rigid field r(q): R r(q) = r(R u, 0) + phi x, so on the body rows
  C_M (R a_u, 0) + a_phi c_x + theta'^2 C_M q, a_q = theta'' q + 2 theta' v_q; on q's rows the transposes (C_M . R a =
  -RCM . a), D_M, d_x, the rigid loads' rows l_e, l_c, the hub's own mass (m (R a_u + theta'^2 u)) and inertia
  (-I theta''), the preload and the anchor.
*/
PetscErrorCode RollerHubStepBegin(Roller ctx, RollerStepOperator *op, RollerMaxwell mx, PetscReal beta, PetscReal t1, const PetscReal c[3], Vec rhs, Vec load, Vec work)
{
  RollerHub      *hub = ctx->axle.hub;
  RollerHubState *s   = &hub->s;
  const PetscReal rho = ctx->material.density, dt = ctx->ts.dt, eta = ctx->disc.damping, tau = ctx->material.viscosity, m = ctx->axle.mass;
  PetscReal       td, tdd, a[3], g[3], Fq[3], P[3], aM[3], aK[3], S[9], DA[9], tmp[3], hist[3];
  PetscScalar     w[3];

  PetscFunctionBeginUser;
  RollerTheta(ctx, t1, NULL, &td, &tdd);
  for (PetscInt i = 0; i < 3; ++i) a[i] = tdd * s->cur[i] + 2.0 * td * (c[0] * s->cur[i] + c[1] * s->prev[i] + c[2] * s->prev2[i]);
  g[0] = a[1] + td * td * s->cur[0];
  g[1] = -a[0] + td * td * s->cur[1];
  g[2] = td * td * s->cur[2];
  /* the body rows: rho (C_M g + a_phi c_x) */
  for (PetscInt i = 0; i < 3; ++i) w[i] = rho * g[i];
  PetscCall(VecSet(work, 0.0));
  PetscCall(VecMAXPY(work, 3, w, hub->c.CM));
  PetscCall(VecAXPY(work, rho * a[2], hub->c.cx));
  PetscCall(VecAXPY(load, 1.0, work));
  PetscCall(VecAXPY(rhs, 1.0, work));
  /* q's rows */
  RollerMat3Vec(hub->c.DM, g, tmp);
  for (PetscInt i = 0; i < 3; ++i) {
    const PetscReal RCMa = (tdd + 2.0 * td * c[0]) * s->P[0][6 + i] + 2.0 * td * (c[1] * s->P[1][6 + i] + c[2] * s->P[2][6 + i]);

    Fq[i] = rho * (-RCMa + tmp[i] + a[2] * hub->c.dx[i] + td * td * s->P[0][i]) + rho * (tdd * hub->c.le[i] + td * td * hub->c.lc[i]);
  }
  Fq[0] += m * (a[1] + td * td * s->cur[0]);
  Fq[1] += m * (-a[0] + td * td * s->cur[1]);
  Fq[2] -= ctx->axle.inertia * tdd;
  RollerAxleForce(ctx, t1, P);
  for (PetscInt i = 0; i < 3; ++i) s->load[i] = Fq[i] + P[i];
  /* the history: C_M (rho/dt^2 (2 q1 - q2) + eta/(2 dt) q2) + C_K (-(1 - 2 beta) q1 - (beta - tau/(2 dt)) q2) */
  for (PetscInt i = 0; i < 3; ++i) {
    aM[i] = rho / (dt * dt) * (2.0 * s->cur[i] - s->prev[i]) + eta / (2.0 * dt) * s->prev[i];
    aK[i] = -(1.0 - 2.0 * beta) * s->cur[i] - (beta - tau / (2.0 * dt)) * s->prev[i];
  }
  for (PetscInt i = 0; i < 3; ++i) w[i] = aM[i];
  PetscCall(VecMAXPY(rhs, 3, w, hub->c.CM));
  for (PetscInt i = 0; i < 3; ++i) w[i] = aK[i];
  PetscCall(VecMAXPY(rhs, 3, w, hub->c.CK));
  /* b_q = C_M^T (body's history) + C_K^T (...) + D_M aM + H/dt^2 (2 q1 - q2) + D_K aK + S (-(1 - 2 beta) q1 - beta q2)
         + c_d/(2 dt) phi2 e_phi + F_q + P */
  RollerAxleSprings(ctx, S);
  for (PetscInt i = 0; i < 3; ++i) {
    s->bq[i] = rho / (dt * dt) * (2.0 * s->P[0][i] - s->P[1][i]) + eta / (2.0 * dt) * s->P[1][i];
    s->bq[i] += -(1.0 - 2.0 * beta) * s->P[0][3 + i] - (beta - tau / (2.0 * dt)) * s->P[1][3 + i];
    hist[i] = -(1.0 - 2.0 * beta) * s->cur[i] - beta * s->prev[i];
  }
  RollerMat3Vec(hub->c.DM, aM, tmp);
  for (PetscInt i = 0; i < 3; ++i) s->bq[i] += tmp[i];
  RollerMat3Vec(hub->c.DK, aK, tmp);
  for (PetscInt i = 0; i < 3; ++i) s->bq[i] += tmp[i];
  RollerMat3Vec(S, hist, tmp);
  for (PetscInt i = 0; i < 3; ++i) s->bq[i] += tmp[i] + s->load[i];
  s->bq[0] += m / (dt * dt) * (2.0 * s->cur[0] - s->prev[0]);
  s->bq[1] += m / (dt * dt) * (2.0 * s->cur[1] - s->prev[1]);
  s->bq[2] += ctx->axle.inertia / (dt * dt) * (2.0 * s->cur[2] - s->prev[2]) + ctx->axle.drive_damping / (2.0 * dt) * s->prev[2];
  if (mx) PetscCall(RollerMaxwellHubRightHandSide(mx, ctx, rhs, s->bq)); /* the branches' known forces on both */
  /* the elimination at the new level's time t1 + dt */
  StepD(ctx, op, beta, DA);
  RollerAxleProject(ctx, t1 + dt, DA, s->Dz);
  PetscCall(RollerStepOperatorUpdateBorder(ctx, op, t1 + dt, DA));
  RollerMat3Vec(s->Dz, s->bq, tmp);
  for (PetscInt i = 0; i < 3; ++i) w[i] = -tmp[i];
  PetscCall(VecMAXPY(rhs, 3, w, op->border->C));
  PetscFunctionReturn(0);
}

/* After the body's solve (xi^k = x): q^k = Dz (b_q - C^T xi^k), the guide's reaction (C^T xi^k + D_A q^k - b_q, normal to
   the admissible motions), and delta = Dz b_q - q^k (C delta completes the body's equation for M xi^k). */
PetscErrorCode RollerHubStepEnd(Roller ctx, RollerStepOperator *op, PetscReal beta, Vec x)
{
  RollerHubState *s = &ctx->axle.hub->s;
  PetscScalar     d[3];
  PetscReal       r[3], DA[9], Dq[3];

  PetscFunctionBeginUser;
  PetscCall(VecMDot(x, 3, op->border->C, d));
  for (PetscInt i = 0; i < 3; ++i) r[i] = s->bq[i] - PetscRealPart(d[i]);
  RollerMat3Vec(s->Dz, r, s->next);
  StepD(ctx, op, beta, DA);
  RollerMat3Vec(DA, s->next, Dq);
  for (PetscInt i = 0; i < 3; ++i) s->reaction[i] = Dq[i] - r[i];
  RollerMat3Vec(s->Dz, s->bq, s->delta);
  for (PetscInt i = 0; i < 3; ++i) s->delta[i] -= s->next[i];
  PetscFunctionReturn(0);
}

/* The levels move up with the body's (x: the new cur); from the end of -nip_ramp the vertical spring holds the hub at its
   position then (the spring's quadratic energy appears at once: s.jump, for the step's balance). */
PetscErrorCode RollerHubShift(Roller ctx, Vec x)
{
  RollerHub      *hub = ctx->axle.hub;
  RollerHubState *s   = &hub->s;
  const PetscReal t   = (ctx->state.step + 1) * ctx->ts.dt;

  PetscFunctionBeginUser;
  PetscCall(PetscArraycpy(s->prev2, s->prev, 3));
  PetscCall(PetscArraycpy(s->prev, s->cur, 3));
  PetscCall(PetscArraycpy(s->cur, s->next, 3));
  PetscCall(PetscArraycpy(s->P[2], s->P[1], 12));
  PetscCall(PetscArraycpy(s->P[1], s->P[0], 12));
  PetscCall(Products(hub, x, s->P[0]));
  if (s->anchor[0] == 0 && t >= ctx->axle.nip_ramp) {
    PetscReal n[2];

    RollerAxleFrame(ctx, t, n);
    s->anchor[0] = 1.0;
    s->anchor[1] = n[0] * s->cur[0] + n[1] * s->cur[1];
    s->jump      = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

/* q's terms of E^k (levels cur = k, prev = k - 1): rho/(2 dt^2) (2 d_q . C_M^T d + d_q . D_M d_q) + H d_q . d_q/(2 dt^2)
   and the potential beta/2 (W(k, k) + W(k-1, k-1)) + (1 - 2 beta)/2 W(k, k-1), W(i, j) = q_i . C_K^T x_j + q_j . C_K^T x_i
   + q_i . (D_K + S) q_j. */
static PetscErrorCode EnergyWith(Roller ctx, PetscReal beta, const PetscReal S[9], PetscReal *E)
{
  const RollerHub      *hub = ctx->axle.hub;
  const RollerHubState *s   = &hub->s;
  const PetscReal       rho = ctx->material.density, dt = ctx->ts.dt, H[3] = {ctx->axle.mass, ctx->axle.mass, ctx->axle.inertia};
  PetscReal             dq[3], dP[3], DKS[9], tmp[3], kin = 0.0, W[3];
  const PetscReal      *q[2] = {s->cur, s->prev}, *Pk[2] = {s->P[0] + 3, s->P[1] + 3};

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < 9; ++i) DKS[i] = hub->c.DK[i] + S[i];
  for (PetscInt i = 0; i < 3; ++i) {
    dq[i] = s->cur[i] - s->prev[i];
    dP[i] = s->P[0][i] - s->P[1][i];
  }
  RollerMat3Vec(hub->c.DM, dq, tmp);
  for (PetscInt i = 0; i < 3; ++i) kin += rho * (2.0 * dq[i] * dP[i] + dq[i] * tmp[i]) + H[i] * dq[i] * dq[i];
  for (PetscInt k = 0; k < 3; ++k) { /* W(0,0), W(1,1), W(0,1) */
    const PetscInt a = k == 1 ? 1 : 0, b = k == 0 ? 0 : 1;

    RollerMat3Vec(DKS, q[b], tmp);
    W[k] = RollerDot3(q[a], Pk[b]) + RollerDot3(q[b], Pk[a]) + RollerDot3(q[a], tmp);
  }
  *E = kin / (2.0 * dt * dt) + 0.5 * beta * (W[0] + W[1]) + 0.5 * (1.0 - 2.0 * beta) * W[2];
  PetscFunctionReturn(0);
}

/* E += q's terms */
PetscErrorCode RollerHubEnergy(Roller ctx, PetscReal beta, PetscReal *E)
{
  PetscReal S[9], Eq;

  PetscFunctionBeginUser;
  RollerAxleSprings(ctx, S);
  PetscCall(EnergyWith(ctx, beta, S, &Eq));
  *E += Eq;
  PetscFunctionReturn(0);
}

/* q's terms of the balance of the step to level cur = k (D_q = q^k - q^{k-2}): the load's and the guide's work 1/2 (F_q +
   reaction) . D_q (and the spring energy the anchoring added), the mass damping's and the drive damper's dissipation,
   the Kelvin-Voigt dissipation of the rubber's coupling. */
PetscErrorCode RollerHubBalance(Roller ctx, PetscReal beta, RollerStepInfo *info)
{
  RollerHubState *s  = &ctx->axle.hub->s;
  const PetscReal dt = ctx->ts.dt, eta = ctx->disc.damping, tau = ctx->material.viscosity;
  PetscReal       D[3], dPM[3], dPK[3], tmp[3], dm = 0.0, dk = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < 3; ++i) {
    D[i]   = s->cur[i] - s->prev2[i];
    dPM[i] = s->P[0][i] - s->P[2][i];
    dPK[i] = s->P[0][3 + i] - s->P[2][3 + i];
  }
  info->load_work += 0.5 * (RollerDot3(s->load, D) + RollerDot3(s->reaction, D));
  if (s->jump) { /* the spring anchored at this step: its quadratic energy on the levels k, k - 1 */
    PetscReal S[9], E1, E0;

    RollerAxleSprings(ctx, S);
    PetscCall(EnergyWith(ctx, beta, S, &E1));
    S[0] = S[4] = 0.0;
    PetscCall(EnergyWith(ctx, beta, S, &E0));
    info->load_work += E1 - E0;
    s->jump = PETSC_FALSE;
  }
  RollerMat3Vec(ctx->axle.hub->c.DM, D, tmp);
  for (PetscInt i = 0; i < 3; ++i) dm += 2.0 * D[i] * dPM[i] + D[i] * tmp[i];
  RollerMat3Vec(ctx->axle.hub->c.DK, D, tmp);
  for (PetscInt i = 0; i < 3; ++i) dk += 2.0 * D[i] * dPK[i] + D[i] * tmp[i];
  info->damping_dissipation += eta / (4.0 * dt) * dm + ctx->axle.drive_damping / (4.0 * dt) * D[2] * D[2];
  info->viscous_dissipation += tau / (4.0 * dt) * dk;
  PetscFunctionReturn(0);
}
