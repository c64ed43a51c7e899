/* What every step reports (docs/model.md sections 4 and 6): the mean radial and tangential displacements of
   Gamma_C, the scheme's discrete energy and its balance, the contact and friction quantities, the shaft torque and
   the cumulative works. Two parts: what must be added up every step (the works and the angular momentum, a few dot
   products of vectors the scheme keeps: RollerStepAccumulate, called by the driver) and the rest, computed only
   when an observer asks for the step's row (RollerStepInfoGet): a run without CSV or monitor spends nothing on it. */
#include "integrate/integrate.h"

/* L = rho int (x + xi) x (v + theta' J (x + xi)): the lab-frame angular momentum of the newest level with its
   velocity (state.velocity) and M xi (state.Mcur). With M acting alike on both components, p x v = p . R(-pi/2) v,
   and with the rigid part written apart (its difference over a step would cancel to round-off over 1/dt),
     L = rho theta' I_0 + L_rel,  I_0 = x . M x,
     L_rel = rho [(M x + M xi) . R(-pi/2) v + theta' (2 xi . M x + xi . M xi)],
   M x being the centrifugal load L_centrifugal (I_0: ops.I0). Returns L_rel. Scratch: work, next. */
static PetscErrorCode AngularMomentum(Roller ctx, PetscReal *L_rel)
{
  Vec         v = ctx->state.work, w = ctx->state.next, Mx = ctx->ops.L_centrifugal, xi = ctx->state.cur;
  PetscReal   td;
  PetscScalar a, b, c;

  PetscFunctionBeginUser;
  RollerTheta(ctx, ctx->state.time, NULL, &td, NULL);
  PetscCall(VecDot(xi, Mx, &a));
  PetscCall(VecDot(xi, ctx->state.Mcur, &b));
  PetscCall(RollerApplyRotate90(ctx, ctx->state.velocity, v));
  PetscCall(VecWAXPY(w, 1.0, Mx, ctx->state.Mcur));
  PetscCall(VecDot(v, w, &c));
  *L_rel = ctx->material.density * (PetscRealPart(c) + td * (2.0 * PetscRealPart(a) + PetscRealPart(b)));
  PetscFunctionReturn(0);
}

/* Every step (and at the state a run starts from): the step's energy balance terms (the scheme's; docs/model.md
   section 2), the friction columns (whose dissipation is cumulative), the angular momentum of the level, and the
   cumulative works: the shaft's (the loads' work and the contact's rotation parts), the sheet's, the friction
   dissipation (docs/friction.md), each step added once (a restart reads them and L from the checkpoint). */
PetscErrorCode RollerStepAccumulate(Roller ctx)
{
  RollerState    *st   = &ctx->state;
  RollerStepInfo *info = &ctx->info;
  PetscReal       L    = 0.0;

  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_DIAGNOSTICS]));
  info->load_work = info->obstacle_work = info->contact_dissipation = info->damping_dissipation = info->viscous_dissipation = 0.0;
  PetscCall(PetscMemzero(&info->friction, sizeof(info->friction)));
  st->info_step = -1;
  PetscCall(RollerSchemeBalance(ctx, info));
  if (st->step != st->momentum_step) {
    PetscCall(AngularMomentum(ctx, &L));
    st->momentum[1]   = st->momentum_step == st->step - 1 ? st->momentum[0] : PETSC_MAX_REAL;
    st->momentum[0]   = L;
    st->momentum_step = st->step;
  }
  if (RollerContactWantsRow(ctx->contact)) PetscCall(RollerStepInfoGet(ctx)); /* the friction dissipation, the contact monitor */
  if (st->step > st->work_step) {
    st->works[0] += info->load_work + info->friction.shaft_step;
    st->works[1] += info->friction.sheet_step;
    st->works[2] += info->friction.dissipation;
    st->work_step = st->step;
  }
  if (st->info_step == st->step) { /* the row made above for the friction dissipation: its works up to this step */
    info->friction.shaft_work = st->works[0];
    info->friction.sheet_work = st->works[1];
    info->friction.work       = st->works[2];
  }
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

/* The axle's columns (docs/model.md section 10). With -axle the motor (the frame's theta) exerts the drive's torque
   -k_d phi - c_d phi' on the hub, which is then the shaft's torque too; the hub turns at theta' + phi'. */
static PetscErrorCode AxleColumns(Roller ctx, RollerStepInfo *info)
{
  PetscReal td;

  PetscFunctionBeginUser;
  RollerTheta(ctx, ctx->state.time, NULL, &td, NULL);
  info->axle.y            = 0.0;
  info->axle.hub_rate     = td;
  info->axle.drive_torque = info->friction.torque;
  info->axle.sheet_speed  = ctx->contact ? RollerContactSheetSpeed(ctx, ctx->contact) : ctx->obstacle.sheet_speed;
  if (ctx->axle.on) {
    const RollerHubState *s    = &ctx->axle.hub->s;
    const PetscReal       rate = (s->cur[2] - s->prev[2]) / ctx->ts.dt;
    PetscReal             n[2], th, th_prev;

    RollerAxleFrame(ctx, ctx->state.time, n);
    info->axle.y = n[0] * s->cur[0] + n[1] * s->cur[1];
    /* the hub's angle theta + phi differenced over the step, both parts alike: theta'(t) beside phi's backward
       difference was a first-order mismatch that a fast ripple (w dt ~ 0.6) showed as a spurious response rising as w */
    RollerTheta(ctx, ctx->state.time, &th, NULL, NULL);
    RollerTheta(ctx, ctx->state.time - ctx->ts.dt, &th_prev, NULL, NULL);
    info->axle.hub_rate     = (th - th_prev) / ctx->ts.dt + rate;
    info->axle.drive_torque = -ctx->axle.drive_stiffness * s->cur[2] - ctx->axle.drive_damping * rate;
    info->friction.torque   = info->axle.drive_torque;
  }
  PetscFunctionReturn(0);
}

/* The row of the newest level xi^k at t = k dt, once per step, when an observer asks: R, alpha, the energy, the
   contact columns and the shaft torque T^k = (L^k - L^{k-1})/dt + rho I_0 (theta'^k - theta'^{k-1})/dt - (the
   contact forces' moment, contact layer). */
PetscErrorCode RollerStepInfoGet(Roller ctx)
{
  RollerState    *st   = &ctx->state;
  RollerStepInfo *info = &ctx->info;
  PetscScalar     r, a;

  PetscFunctionBeginUser;
  if (st->info_step == st->step) PetscFunctionReturn(0);
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_DIAGNOSTICS]));
  st->info_step = st->step;
  PetscCall(VecDot(ctx->ops.w_R, st->cur, &r));
  PetscCall(VecDot(ctx->ops.w_alpha, st->cur, &a));
  {
    PetscReal wr = PetscRealPart(r), wa = PetscRealPart(a);

    PetscCall(RollerContactResidualDots(ctx->contact, st->cur, &wr, &wa)); /* -rom_residual: the Gamma_C residual's part */
    info->R     = wr / ctx->mesh.boundary_length;
    info->alpha = wa / ctx->mesh.boundary_length;
  }
  PetscCall(RollerSchemeEnergy(ctx, &info->energy));
  info->friction.torque = 0.0;
  if (ctx->contact) PetscCall(RollerContactInfo(ctx, ctx->contact, st->cur, st->Mcur, st->Kcur, st->time, info));
  else {
    /* no obstacle: no contact, and no gap to report (docs/output.md) */
    info->contact_nodes = 0;
    info->contact_force = 0.0;
    info->gap_min       = (PetscReal)NAN;
    info->qp_iterations = 0;
    info->kkt_residual  = 0.0;
    info->contact_flips = info->contact_reversals = 0;
  }
  if (st->step > 0 && st->momentum[1] != PETSC_MAX_REAL) {
    PetscReal td, td_prev;

    RollerTheta(ctx, st->time, NULL, &td, NULL);
    RollerTheta(ctx, st->time - ctx->ts.dt, NULL, &td_prev, NULL);
    info->friction.torque += (st->momentum[0] - st->momentum[1]) / ctx->ts.dt + ctx->material.density * ctx->ops.I0 * (td - td_prev) / ctx->ts.dt;
  }
  info->friction.shaft_work = st->works[0];
  info->friction.sheet_work = st->works[1];
  info->friction.work       = st->works[2];
  PetscCall(AxleColumns(ctx, info));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}
