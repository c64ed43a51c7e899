/* The generalized Maxwell solid in the three-level schemes (-rubber maxwell, docs/model.md section 2.2). Branch i: a
   nodal displacement-like field z_i (the branch's viscous strain is dev eps[z_i], exactly: the strain is linear in the
   displacement and the flow rule is linear; docs/model.md section 1.1), stored energy 1/2 g_i (xi - z_i) . K_d (xi - z_i), flow rule
   tau_i z_i' = xi - z_i. In the step's stiffness term K xbar, xbar = beta xi^k + (1 - 2 beta) xi^{k-1} + beta xi^{k-2},
   the branches add sum_i g_i K_d m_i, the flow rule by the midpoint rule,
     z_i^new - z_i^old = 2 a_i m_i,   m_i = xbar - (z_i^new + z_i^old)/2 = (xbar - z_i^old)/(1 + a_i),
   eliminated per node in closed form, so the step stays one convex QP with the constant SPD matrix A + c_D K_d,
   c_D = beta sum_i g_i/(1 + a_i):
     dmf (beta = 1/2)          z at the integer levels, z^old = z^{k-2}, z^new = z^k, a_i = dt/tau_i; branch energy
                               sum_i g_i/4 [W_i(k) + W_i(k-1)], W_i(j) = (xi^j - z_i^j) . K_d (xi^j - z_i^j);
     trapezoidal (beta = 1/4)  z at the half levels with y^j = (xi^j + xi^{j-1})/2, z^old = z^{k-1}, a_i = dt/(2 tau_i);
                               branch energy 1/2 sum_i g_i (y^k - z_i^k) . K_d (y^k - z_i^k).
   Paired with D/2 = (xi^k - xi^{k-2})/2, the branch forces' work is the change of their energy plus the dissipation
   g_i (dt/tau_i) m_i . K_d m_i >= 0: the scheme's balance stays exact. No product with K_d but K_d xi^k a step: the
   products P_i = K_d z_i follow the z_i (P_i^new = P_i^old + 2 a_i K_d m_i, K_d m_i from K_d xbar and P_i^old; their
   round-off against K_d z_i does not accumulate: the update contracts it by (1 - a_i)/(1 + a_i) a step) and the
   checkpoint keeps them with the z_i (scheme's kept vectors), so that a restart repeats the run to the last bit. */
#include "scheme_impl.h"
#include "model/model.h"

struct _n_RollerMaxwell {
  PetscInt  n, nlev;                                                                              /* branches; z levels kept: 2 (dmf: k, k-1), 1 (trapezoidal) */
  PetscReal beta, g[ROLLER_MAX_BRANCHES], a[ROLLER_MAX_BRANCHES], rate[ROLLER_MAX_BRANCHES], c_D; /* rate_i = dt/tau_i */
  Vec       z[2][ROLLER_MAX_BRANCHES], P[2][ROLLER_MAX_BRANCHES];                                 /* z_i of level k and k-1 (dmf); P = K_d z */
  Vec       Kd[3];                                                                                /* K_d xi of the last three levels */
  Vec       xbar, Kxbar, m, Km;                                                                   /* scratch */
  PetscReal dissipation;                                                                          /* of step dissipation_step */
  PetscInt  dissipation_step;
  char      names[4 * ROLLER_MAX_BRANCHES][24];
};

/* The branches of the material for the three-level scheme of this beta (NULL without -rubber maxwell or with -static,
   whose one step is the relaxed solid's: A = K); K_d xi of the levels, z_i = K_d z_i = 0: the branches start
   unstretched, the rest state's (a checkpoint's are read after: RollerCheckpointReadKept). */
PetscErrorCode RollerMaxwellCreate(Roller ctx, PetscReal beta, RollerMaxwell *maxwell)
{
  const RollerMaterial *mat    = &ctx->material;
  const Vec             lev[3] = {ctx->state.cur, ctx->state.prev, ctx->state.prev2};
  RollerMaxwell         mx;

  PetscFunctionBeginUser;
  *maxwell = NULL;
  if (mat->rubber != ROLLER_RUBBER_MAXWELL || ctx->disc.static_solve) PetscFunctionReturn(0);
  PetscCheck(beta == 0.5 || beta == 0.25, ctx->comm, PETSC_ERR_SUP, "-rubber maxwell: the three-level scheme of beta %g has no branch update (dmf: 1/2, trapezoidal: 1/4)", (double)beta);
  PetscCall(PetscNew(&mx));
  mx->n                = mat->nbranch;
  mx->nlev             = beta == 0.5 ? 2 : 1;
  mx->beta             = beta;
  mx->dissipation_step = -1;
  for (PetscInt i = 0; i < mx->n; ++i) {
    mx->g[i]    = mat->g[i];
    mx->rate[i] = ctx->ts.dt / mat->tau[i];
    mx->a[i]    = beta == 0.5 ? mx->rate[i] : 0.5 * mx->rate[i];
    mx->c_D += beta * mx->g[i] / (1.0 + mx->a[i]);
    for (PetscInt l = 0; l < mx->nlev; ++l) {
      PetscCall(VecDuplicate(ctx->state.cur, &mx->z[l][i]));
      PetscCall(VecDuplicate(ctx->state.cur, &mx->P[l][i]));
      PetscCall(VecZeroEntries(mx->z[l][i]));
      PetscCall(VecZeroEntries(mx->P[l][i]));
      PetscCall(PetscSNPrintf(mx->names[2 * (l * mx->n + i)], sizeof(mx->names[0]), "maxwell_z%" PetscInt_FMT "_k%s", i, l ? "1" : ""));
      PetscCall(PetscSNPrintf(mx->names[2 * (l * mx->n + i) + 1], sizeof(mx->names[0]), "maxwell_Kdz%" PetscInt_FMT "_k%s", i, l ? "1" : ""));
    }
  }
  for (PetscInt l = 0; l < 3; ++l) {
    PetscCall(VecDuplicate(ctx->state.cur, &mx->Kd[l]));
    PetscCall(MatMult(ctx->ops.Kd, lev[l], mx->Kd[l]));
  }
  PetscCall(VecDuplicate(ctx->state.cur, &mx->xbar));
  PetscCall(VecDuplicate(ctx->state.cur, &mx->Kxbar));
  PetscCall(VecDuplicate(ctx->state.cur, &mx->m));
  PetscCall(VecDuplicate(ctx->state.cur, &mx->Km));
  *maxwell = mx;
  PetscFunctionReturn(0);
}

/* c_D of the step matrix A + c_D K_d */
PetscReal RollerMaxwellStiffness(RollerMaxwell mx)
{
  return mx ? mx->c_D : 0.0;
}

/* K_d xi^k (after the levels moved) */
Vec RollerMaxwellKdCur(RollerMaxwell mx)
{
  return mx->Kd[0];
}

/* Before the step (cur = xi^{k-1}, prev = xi^{k-2}): b -= sum_i g_i/(1 + a_i) K_d ((1 - 2 beta) xi^{k-1} + beta xi^{k-2}
   - z_i^old), the branch forces' part that is known; for the second difference Delta = xi^k - 2 xi^{k-1} + xi^{k-2}
   (b - A (2 xi^{k-1} - xi^{k-2})), b -= sum_i g_i/(1 + a_i) K_d (xi^{k-1} - z_i^old). No product: K_d xi and the P_i. */
PetscErrorCode RollerMaxwellRightHandSide(RollerMaxwell mx, PetscBool second, Vec b)
{
  const PetscInt old = mx->nlev - 1;
  PetscReal      C   = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < mx->n; ++i) {
    C += mx->g[i] / (1.0 + mx->a[i]);
    PetscCall(VecAXPY(b, mx->g[i] / (1.0 + mx->a[i]), mx->P[old][i]));
  }
  if (second) PetscCall(VecAXPY(b, -C, mx->Kd[0]));
  else PetscCall(VecAXPBYPCZ(b, -C * (1.0 - 2.0 * mx->beta), -C * mx->beta, 1.0, mx->Kd[0], mx->Kd[1]));
  PetscFunctionReturn(0);
}

/* -axle (model/axle.h): the hub's part zeta_i of branch i, the rigid field of z_i on Gamma_D, with the coupling
   C_D = K_d,fG r_G, D_D = r_G^T K_d,GG r_G of the augmented K_d: the branch energy 1/2 g_i u^T K_d,aug u over u = (xi - z_i,
   q - zeta_i). C_D^T z = -r_f . K_d z = -RF . P_i: no product with K_d. */
static PetscErrorCode HubZ(RollerMaxwell mx, RollerHub *hub, Vec P, PetscReal CDz[3])
{
  PetscScalar d[3];

  PetscFunctionBeginUser;
  PetscCall(VecMDot(P, 3, hub->c.RF, d));
  for (PetscInt j = 0; j < 3; ++j) CDz[j] = -PetscRealPart(d[j]);
  PetscFunctionReturn(0);
}

/* Before the step: b -= sum_i g_i/(1 + a_i) C_D ((1 - 2 beta) q^{k-1} + beta q^{k-2} - zeta_i^old) and
   b_q -= sum_i g_i/(1 + a_i) [C_D^T ((1 - 2 beta) xi^{k-1} + beta xi^{k-2} - z_i^old) + D_D ((1 - 2 beta) q^{k-1} + beta q^{k-2} - zeta_i^old)]. */
PetscErrorCode RollerMaxwellHubRightHandSide(RollerMaxwell mx, Roller ctx, Vec b, PetscReal bq[3])
{
  RollerHub      *hub  = ctx->axle.hub;
  RollerHubState *s    = &hub->s;
  const PetscInt  old  = mx->nlev - 1;
  const PetscReal bt   = mx->beta;
  PetscReal       w[3] = {0, 0, 0}, u[3], CDz[3], Du[3];
  PetscScalar     ws[3];

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < mx->n; ++i) {
    const PetscReal gc = mx->g[i] / (1.0 + mx->a[i]);

    PetscCall(HubZ(mx, hub, mx->P[old][i], CDz));
    for (PetscInt j = 0; j < 3; ++j) u[j] = (1.0 - 2.0 * bt) * s->cur[j] + bt * s->prev[j] - s->zeta[old][i][j];
    RollerMat3Vec(hub->c.DD, u, Du);
    for (PetscInt j = 0; j < 3; ++j) {
      w[j] += gc * u[j];
      bq[j] -= gc * ((1.0 - 2.0 * bt) * s->P[0][9 + j] + bt * s->P[1][9 + j] - CDz[j] + Du[j]);
    }
  }
  for (PetscInt j = 0; j < 3; ++j) ws[j] = -w[j];
  PetscCall(VecMAXPY(b, 3, ws, hub->c.CD));
  PetscFunctionReturn(0);
}

/* After the step (the hub's levels moved: cur = q^k), before branch i's own update: zeta_i^new = zeta_i^old + 2 a_i mu_i,
   mu_i = (qbar - zeta_i^old)/(1 + a_i), and the coupling's part of the dissipation g_i (dt/tau_i) (2 mu_i . C_D^T m_i +
   mu_i . D_D mu_i), C_D^T m_i from the levels' products and P_i^old. */
static PetscErrorCode HubBranchUpdate(RollerMaxwell mx, Roller ctx, PetscInt i)
{
  RollerHub      *hub = ctx->axle.hub;
  RollerHubState *s   = &hub->s;
  const PetscInt  old = mx->nlev - 1;
  const PetscReal bt = mx->beta, c = 1.0 / (1.0 + mx->a[i]);
  PetscReal       mu[3], CDm[3], CDz[3], Dmu[3];

  PetscFunctionBeginUser;
  PetscCall(HubZ(mx, hub, mx->P[old][i], CDz));
  for (PetscInt j = 0; j < 3; ++j) {
    mu[j]  = bt * s->cur[j] + (1.0 - 2.0 * bt) * s->prev[j] + bt * s->prev2[j] - s->zeta[old][i][j];
    CDm[j] = bt * s->P[0][9 + j] + (1.0 - 2.0 * bt) * s->P[1][9 + j] + bt * s->P[2][9 + j] - CDz[j];
  }
  RollerMat3Vec(hub->c.DD, mu, Dmu);
  mx->dissipation += mx->g[i] * mx->rate[i] * c * c * (2.0 * RollerDot3(mu, CDm) + RollerDot3(mu, Dmu));
  for (PetscInt j = 0; j < 3; ++j) s->zeta[old][i][j] += 2.0 * mx->a[i] * c * mu[j];
  PetscFunctionReturn(0);
}

/* The coupling's part of branch i's stored energy at the level l (dmf: l = 0 the level k, 1 the level k-1; trapezoidal:
   the half level y^k): 2 u_q . C_D^T u + u_q . D_D u_q. */
static PetscErrorCode HubBranchEnergy(RollerMaxwell mx, Roller ctx, PetscInt i, PetscInt l, PetscReal *e)
{
  RollerHub      *hub = ctx->axle.hub;
  RollerHubState *s   = &hub->s;
  PetscReal       uq[3], CDu[3], CDz[3], Du[3];

  PetscFunctionBeginUser;
  PetscCall(HubZ(mx, hub, mx->P[l][i], CDz));
  for (PetscInt j = 0; j < 3; ++j) {
    const PetscReal q = mx->nlev == 1 ? 0.5 * (s->cur[j] + s->prev[j]) : (l ? s->prev[j] : s->cur[j]);
    const PetscReal P = mx->nlev == 1 ? 0.5 * (s->P[0][9 + j] + s->P[1][9 + j]) : s->P[l][9 + j];

    uq[j]  = q - s->zeta[l][i][j];
    CDu[j] = P - CDz[j];
  }
  RollerMat3Vec(hub->c.DD, uq, Du);
  *e = 2.0 * RollerDot3(uq, CDu) + RollerDot3(uq, Du);
  PetscFunctionReturn(0);
}

/* After the step (the levels moved: cur = xi^k): K_d xi^k, and each branch's update z_i^new = z_i^old + 2 a_i m_i
   (with P_i) and its dissipation g_i (dt/tau_i) m_i . K_d m_i. */
PetscErrorCode RollerMaxwellNewLevel(RollerMaxwell mx, Roller ctx)
{
  const PetscReal beta = mx->beta;
  Vec             tmp  = mx->Kd[2];

  PetscFunctionBeginUser;
  mx->Kd[2] = mx->Kd[1];
  mx->Kd[1] = mx->Kd[0];
  mx->Kd[0] = tmp;
  PetscCall(MatMult(ctx->ops.Kd, ctx->state.cur, mx->Kd[0]));
  PetscCall(VecAXPBYPCZ(mx->xbar, beta, beta, 0.0, ctx->state.cur, ctx->state.prev2));
  PetscCall(VecAXPBYPCZ(mx->Kxbar, beta, beta, 0.0, mx->Kd[0], mx->Kd[2]));
  if (beta != 0.5) {
    PetscCall(VecAXPY(mx->xbar, 1.0 - 2.0 * beta, ctx->state.prev));
    PetscCall(VecAXPY(mx->Kxbar, 1.0 - 2.0 * beta, mx->Kd[1]));
  }
  mx->dissipation = 0.0;
  for (PetscInt i = 0; i < mx->n; ++i) {
    const PetscInt old = mx->nlev - 1;
    PetscScalar    d;

    const PetscReal c = 1.0 / (1.0 + mx->a[i]);

    if (ctx->axle.hub) PetscCall(HubBranchUpdate(mx, ctx, i));

    PetscCall(VecWAXPY(mx->m, -1.0, mx->z[old][i], mx->xbar)); /* (1 + a_i) m_i and K_d of it */
    PetscCall(VecWAXPY(mx->Km, -1.0, mx->P[old][i], mx->Kxbar));
    PetscCall(VecDot(mx->m, mx->Km, &d));
    mx->dissipation += mx->g[i] * mx->rate[i] * c * c * PetscRealPart(d);
    PetscCall(VecAXPY(mx->z[old][i], 2.0 * mx->a[i] * c, mx->m)); /* z^old becomes z^new */
    PetscCall(VecAXPY(mx->P[old][i], 2.0 * mx->a[i] * c, mx->Km));
    if (mx->nlev == 2) { /* dmf: the new level is k, the other k-1 */
      tmp         = mx->z[1][i];
      mx->z[1][i] = mx->z[0][i];
      mx->z[0][i] = tmp;
      tmp         = mx->P[1][i];
      mx->P[1][i] = mx->P[0][i];
      mx->P[0][i] = tmp;
      if (ctx->axle.hub) { /* the hub's parts follow */
        PetscReal(*zeta)[ROLLER_MAX_BRANCHES][3] = ctx->axle.hub->s.zeta, w[3];

        PetscCall(PetscArraycpy(w, zeta[1][i], 3));
        PetscCall(PetscArraycpy(zeta[1][i], zeta[0][i], 3));
        PetscCall(PetscArraycpy(zeta[0][i], w, 3));
      }
    }
  }
  mx->dissipation_step = ctx->state.step + 1; /* the step being made */
  PetscFunctionReturn(0);
}

/* The branches' dissipation in the last step (0 at a state no step made here: the start, a restart) */
PetscReal RollerMaxwellDissipation(RollerMaxwell mx, Roller ctx)
{
  return mx->dissipation_step == ctx->state.step ? mx->dissipation : 0.0;
}

/* energy += the branches' stored energy of the newest level (the scheme's: see above). Scratch: xbar, Kxbar (y^k and
   K_d y^k, trapezoidal), m, Km. */
PetscErrorCode RollerMaxwellEnergyAdd(RollerMaxwell mx, Roller ctx, PetscReal *energy)
{
  PetscFunctionBeginUser;
  if (mx->nlev == 1) {
    PetscCall(VecAXPBYPCZ(mx->xbar, 0.5, 0.5, 0.0, ctx->state.cur, ctx->state.prev));
    PetscCall(VecAXPBYPCZ(mx->Kxbar, 0.5, 0.5, 0.0, mx->Kd[0], mx->Kd[1]));
  }
  for (PetscInt i = 0; i < mx->n; ++i) {
    for (PetscInt l = 0; l < mx->nlev; ++l) { /* dmf: W_i(k), W_i(k-1); trapezoidal: y^k - z_i^k */
      PetscScalar w;

      PetscCall(VecWAXPY(mx->m, -1.0, mx->z[l][i], mx->nlev == 1 ? mx->xbar : (l ? ctx->state.prev : ctx->state.cur)));
      PetscCall(VecWAXPY(mx->Km, -1.0, mx->P[l][i], mx->nlev == 1 ? mx->Kxbar : mx->Kd[l]));
      PetscCall(VecDot(mx->m, mx->Km, &w));
      *energy += (mx->nlev == 2 ? 0.25 : 0.5) * mx->g[i] * PetscRealPart(w);
      if (ctx->axle.hub) {
        PetscReal e = 0.0;

        PetscCall(HubBranchEnergy(mx, ctx, i, l, &e));
        *energy += (mx->nlev == 2 ? 0.25 : 0.5) * mx->g[i] * e;
      }
    }
  }
  PetscFunctionReturn(0);
}

/* The addresses of the z_i and P_i = K_d z_i of the kept levels (the levels swap), appended to v[*n], names[*n] (the
   checkpoint's). */
PetscErrorCode RollerMaxwellKept(RollerMaxwell mx, PetscInt *n, Vec *v[], const char *names[])
{
  PetscFunctionBeginUser;
  for (PetscInt l = 0; l < mx->nlev; ++l)
    for (PetscInt i = 0; i < mx->n; ++i) {
      const PetscInt k = 2 * (l * mx->n + i);

      v[*n]     = &mx->z[l][i];
      names[*n] = mx->names[k];
      (*n)++;
      v[*n]     = &mx->P[l][i];
      names[*n] = mx->names[k + 1];
      (*n)++;
    }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerMaxwellDestroy(RollerMaxwell *maxwell)
{
  RollerMaxwell mx = *maxwell;

  PetscFunctionBeginUser;
  if (!mx) PetscFunctionReturn(0);
  for (PetscInt l = 0; l < 2; ++l)
    for (PetscInt i = 0; i < mx->n; ++i) {
      PetscCall(VecDestroy(&mx->z[l][i]));
      PetscCall(VecDestroy(&mx->P[l][i]));
    }
  for (PetscInt l = 0; l < 3; ++l) PetscCall(VecDestroy(&mx->Kd[l]));
  PetscCall(VecDestroy(&mx->xbar));
  PetscCall(VecDestroy(&mx->Kxbar));
  PetscCall(VecDestroy(&mx->m));
  PetscCall(VecDestroy(&mx->Km));
  PetscCall(PetscFree(mx));
  *maxwell = NULL;
  PetscFunctionReturn(0);
}
