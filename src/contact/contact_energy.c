/* The contact's part of the step's energy balance and the contact-set changes (docs/model.md section 2, "Dampings and the energy balance",
   docs/contact.md "Energy and chatter"). A scheme pairs the force of a solve with a displacement, D = xi - xi_from
   times a weight w (the three-level schemes: xi^k - xi^{k-2}, w = 1/2; a stage of a one-step scheme: its own
   increment, w = 1). With lambda gap = 0 at the solve's time t and the force lambda_n n on node n, the contact's
   work w lambda . N^T D splits into
     obstacle_work       W = w sum_n lambda_n [(g - g_from) - (x_n + xi_from,n) . (n - n_from)]
                             (the obstacle's motion relative to the frame: its approach and the rotation of
                             its line, i.e. the work of the drive against the rolling resistance), and
     contact_dissipation D = w sum_n lambda_n gap_from,n >= 0
                             (a node arriving during the step; xi_from is admissible at t_from).
   The obstacle's work splits further into the sheet's (its approach, 1/2 lambda (g^k - g^{k-2})) and the shaft's
   (the rest: the rotation of the sheet's line in the rotating frame), the contact's parts of the CSV's
   sheet_work and shaft_work; and the contact forces' moment about the axis, sum_n (x_n + xi^k_n) x f_n, enters
   the shaft torque (with the opposite sign: the torque the shaft must add). Friction adds its parts
   (contact_friction.c).
   The state "on the obstacle" of a node is gap <= tol at its level; flips count the nodes whose state at t_k
   differs from t_{k-1}, reversals those of them back in their state of t_{k-2} (a contact set that chatters).
   Both derive from the three checkpointed levels, so a restart reports the same. */
#include "contact_impl.h"

/* torque = -sum_n p_n x f_n, p_n = x_n + xi^k_n (gathered in c->nodes.red), f_n = lambda_n n^k + lambda_t,n t^k. */
static PetscErrorCode ContactMoment(RollerContact c, const PetscReal lambda[], RollerStepInfo *info)
{
  const PetscReal   *lt = c->acc.result.lambda_t, *nr = c->step.normal, *tg = c->step.tangent;
  const PetscScalar *u;

  PetscFunctionBeginUser;
  info->friction.torque = 0.0;
  PetscCall(VecGetArrayRead(c->nodes.red, &u));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscReal p0 = c->nodes.xc[2 * i] + PetscRealPart(u[2 * i]), p1 = c->nodes.xc[2 * i + 1] + PetscRealPart(u[2 * i + 1]);
    const PetscReal f0 = lambda[i] * nr[0] + (lt ? lt[i] * tg[0] : 0.0), f1 = lambda[i] * nr[1] + (lt ? lt[i] * tg[1] : 0.0);

    info->friction.torque -= p0 * f1 - p1 * f0;
  }
  PetscCall(VecRestoreArrayRead(c->nodes.red, &u));
  PetscFunctionReturn(0);
}

/* The energy terms of the last solve (multipliers c->acc.result.lambda at c->step.t) from the level x_from at t_from,
   weighted by w, added to info (the scheme sums its stages; the caller zeroes them for the step). */
PetscErrorCode RollerContactEnergyAdd(Roller ctx, RollerContact c, Vec x_from, PetscReal t_from, PetscReal w, RollerStepInfo *info)
{
  const PetscReal   *lambda = c->acc.result.lambda;
  PetscReal         *gap2, n0[2], n2[2], g0, g2;
  const PetscScalar *u2;

  PetscFunctionBeginUser;
  if (!c->acc.solved) PetscFunctionReturn(0);
  PetscCall(PetscMalloc1(c->nodes.nc, &gap2));
  RollerContactObstacleAt(ctx, c->step.t, n0, &g0);
  RollerContactObstacleAt(ctx, t_from, n2, &g2);
  PetscCall(RollerContactGather(c, x_from, c->nodes.red2));
  PetscCall(RollerContactGapsAt(ctx, c, c->nodes.red2, t_from, gap2));
  PetscCall(VecGetArrayRead(c->nodes.red2, &u2));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    if (lambda[i] <= 0.0) continue;
    info->contact_dissipation += w * lambda[i] * gap2[i];
    info->obstacle_work += w * lambda[i] * ((g0 - g2) - (c->nodes.xc[2 * i] + PetscRealPart(u2[2 * i])) * (n0[0] - n2[0]) - (c->nodes.xc[2 * i + 1] + PetscRealPart(u2[2 * i + 1])) * (n0[1] - n2[1]));
    info->friction.sheet_step += w * lambda[i] * (g0 - g2);
    info->friction.shaft_step -= w * lambda[i] * ((c->nodes.xc[2 * i] + PetscRealPart(u2[2 * i])) * (n0[0] - n2[0]) + (c->nodes.xc[2 * i + 1] + PetscRealPart(u2[2 * i + 1])) * (n0[1] - n2[1]));
  }
  PetscCall(VecRestoreArrayRead(c->nodes.red2, &u2));
  PetscCall(PetscFree(gap2));
  PetscFunctionReturn(0);
}

/* The contact-set changes of the step from the three levels xi^k (gaps in c->step.gap, computed by the caller),
   xi^{k-1}, xi^{k-2} at t, t - dt, t - 2 dt, and the contact forces' moment. */
PetscErrorCode RollerContactFlips(Roller ctx, RollerContact c, const PetscReal lambda[], RollerStepInfo *info)
{
  const PetscReal  t = ctx->state.time, dt = ctx->ts.dt, tol = RollerContactGapTolerance(ctx);
  const PetscReal *gap0 = c->step.gap;
  PetscReal       *gap1, *gap2;

  PetscFunctionBeginUser;
  info->contact_flips = info->contact_reversals = 0;
  PetscCall(ContactMoment(c, lambda, info));
  if (ctx->state.step == 0) PetscFunctionReturn(0);
  PetscCall(PetscMalloc2(c->nodes.nc, &gap1, c->nodes.nc, &gap2));
  PetscCall(RollerContactGather(c, ctx->state.prev, c->nodes.red1));
  PetscCall(RollerContactGapsAt(ctx, c, c->nodes.red1, t - dt, gap1));
  PetscCall(RollerContactGather(c, ctx->state.prev2, c->nodes.red2));
  PetscCall(RollerContactGapsAt(ctx, c, c->nodes.red2, t - 2.0 * dt, gap2));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscBool on0 = (PetscBool)(gap0[i] <= tol), on1 = (PetscBool)(gap1[i] <= tol), on2 = (PetscBool)(gap2[i] <= tol);

    if (on0 != on1) {
      info->contact_flips++;
      if (on0 == on2) info->contact_reversals++;
    }
  }
  PetscCall(PetscFree2(gap1, gap2));
  PetscFunctionReturn(0);
}
