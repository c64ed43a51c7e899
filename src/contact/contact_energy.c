/* The contact's part of the step's energy balance and the contact-set changes (docs/model.md section 2, "Dampings and the energy balance",
   docs/contact.md "Energy and chatter"). With D_n = xi^k_n - xi^{k-2}_n, lambda^k gap^k = 0 and the force
   lambda_n n^k on node n, the contact's work 1/2 lambda . N^T D splits into
     obstacle_work       W = 1/2 sum_n lambda^k_n [(g^k - g^{k-2}) - (x_n + xi^{k-2}_n) . (n^k - n^{k-2})]
                             (the obstacle's motion relative to the frame: its approach and the rotation of
                             its line, i.e. the work of the drive against the rolling resistance), and
     contact_dissipation D = 1/2 sum_n lambda^k_n gap^{k-2}_n >= 0
                             (a node arriving between t_{k-2} and t_k; xi^{k-2} is admissible at t_{k-2}).
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

PetscErrorCode RollerContactEnergy(Roller ctx, RollerContact c, const PetscReal lambda[], RollerStepInfo *info)
{
  const PetscReal    t = ctx->state.time, dt = ctx->ts.dt, tol = RollerContactGapTolerance(ctx);
  const PetscReal   *gap0 = c->step.gap; /* gap^k: the step's gaps of xi^k, computed by the caller (RollerContactInfo) */
  PetscReal         *gap1, *gap2, n0[2], n2[2], g0, g2;
  const PetscScalar *u2;

  PetscFunctionBeginUser;
  info->obstacle_work = info->contact_dissipation = 0.0;
  info->contact_flips = info->contact_reversals = 0;
  info->friction.shaft_step = info->friction.sheet_step = 0.0;
  PetscCall(ContactMoment(c, lambda, info));
  if (ctx->state.step == 0) PetscFunctionReturn(0);
  PetscCall(PetscMalloc2(c->nodes.nc, &gap1, c->nodes.nc, &gap2));
  RollerContactObstacleAt(ctx, t, n0, &g0);
  RollerContactObstacleAt(ctx, t - 2.0 * dt, n2, &g2);
  PetscCall(RollerContactGather(c, ctx->state.prev, c->nodes.red1));
  PetscCall(RollerContactGapsAt(ctx, c, c->nodes.red1, t - dt, gap1));
  PetscCall(RollerContactGather(c, ctx->state.prev2, c->nodes.red2));
  PetscCall(RollerContactGapsAt(ctx, c, c->nodes.red2, t - 2.0 * dt, gap2));
  PetscCall(VecGetArrayRead(c->nodes.red2, &u2));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscBool on0 = (PetscBool)(gap0[i] <= tol), on1 = (PetscBool)(gap1[i] <= tol), on2 = (PetscBool)(gap2[i] <= tol);

    if (on0 != on1) {
      info->contact_flips++;
      if (on0 == on2) info->contact_reversals++;
    }
    if (lambda[i] <= 0.0) continue;
    info->contact_dissipation += 0.5 * lambda[i] * gap2[i];
    info->obstacle_work += 0.5 * lambda[i] * ((g0 - g2) - (c->nodes.xc[2 * i] + PetscRealPart(u2[2 * i])) * (n0[0] - n2[0]) - (c->nodes.xc[2 * i + 1] + PetscRealPart(u2[2 * i + 1])) * (n0[1] - n2[1]));
    info->friction.sheet_step += 0.5 * lambda[i] * (g0 - g2);
    info->friction.shaft_step -= 0.5 * lambda[i] * ((c->nodes.xc[2 * i] + PetscRealPart(u2[2 * i])) * (n0[0] - n2[0]) + (c->nodes.xc[2 * i + 1] + PetscRealPart(u2[2 * i + 1])) * (n0[1] - n2[1]));
  }
  PetscCall(VecRestoreArrayRead(c->nodes.red2, &u2));
  PetscCall(PetscFree2(gap1, gap2));
  PetscFunctionReturn(0);
}
