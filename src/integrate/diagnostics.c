/* What every step reports (docs/model.md sections 4 and 6): the mean radial and tangential displacements of
   Gamma_C, the discrete energy of Theorem 1, and the contact quantities. */
#include "integrate/integrate.h"

/* E^k = rho/2 |xi^k - xi^{k-1}|^2_M / dt^2 + (a(xi^k, xi^k) + a(xi^{k-1}, xi^{k-1}))/4 (docs/model.md section 2). */
static PetscErrorCode Energy(Roller ctx, PetscReal *energy)
{
  PetscScalar kin, pot1, pot2;

  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(ctx->state.work, -1.0, ctx->state.prev, ctx->state.cur));
  PetscCall(MatMult(ctx->ops.M, ctx->state.work, ctx->state.next));
  PetscCall(VecDot(ctx->state.work, ctx->state.next, &kin));
  PetscCall(VecDot(ctx->state.cur, ctx->state.Kcur, &pot1));
  PetscCall(VecDot(ctx->state.prev, ctx->state.Kprev, &pot2));
  *energy = 0.5 * ctx->material.density * PetscRealPart(kin) / (ctx->ts.dt * ctx->ts.dt) + 0.25 * PetscRealPart(pot1 + pot2);
  PetscFunctionReturn(0);
}

/* The energy balance of the step from xi^{k-1} to xi^k (docs/model.md section 2, "Dampings and the energy balance"): with D = xi^k - xi^{k-2},
   multiplying the step equation by D gives
     E^k - E^{k-1} = 1/2 F^{k-1} . D + 1/2 (E N lambda^k) . D - eta/(4 dt) D^T M D - tau/(4 dt) D^T K D,
   the load's work, the contact's (the obstacle's work minus the contact dissipation: contact layer), the
   mass damping's and the Kelvin-Voigt dissipation (dt tau a(v, v), v = D/(2 dt)). Zero before the first step. */
static PetscErrorCode EnergyBalance(Roller ctx, RollerStepInfo *info)
{
  const PetscReal dt = ctx->ts.dt;
  Vec             D = ctx->state.work, MD = ctx->state.next; /* scratch between steps */
  PetscScalar     dot;

  PetscFunctionBeginUser;
  info->load_work = info->damping_dissipation = info->viscous_dissipation = 0.0;
  if (ctx->state.step == 0) PetscFunctionReturn(0);
  PetscCall(VecWAXPY(D, -1.0, ctx->state.prev2, ctx->state.cur));
  PetscCall(VecDot(ctx->state.load, D, &dot));
  info->load_work = 0.5 * PetscRealPart(dot);
  if (ctx->disc.damping > 0) {
    PetscCall(MatMult(ctx->ops.M, D, MD));
    PetscCall(VecDot(D, MD, &dot));
    info->damping_dissipation = ctx->disc.damping / (4.0 * dt) * PetscRealPart(dot);
  }
  if (ctx->material.viscosity > 0) {
    PetscCall(VecWAXPY(MD, -1.0, ctx->state.Kprev2, ctx->state.Kcur));
    PetscCall(VecDot(D, MD, &dot));
    info->viscous_dissipation = ctx->material.viscosity / (4.0 * dt) * PetscRealPart(dot);
  }
  PetscFunctionReturn(0);
}

/* L = rho int (x + xi) x (xi_t + theta' J (x + xi)): the angular momentum in the lab of level xi (at t) with the
   velocity (xi - xi_prev)/dt. With M acting alike on both components, p x v = p . R(-pi/2) v, and with the
   rigid part written apart (its difference over a step would cancel to round-off over 1/dt),
     L = rho theta' I_0 + L_rel,  I_0 = x . M x,
     L_rel = rho [(M x + M xi) . R(-pi/2) (xi - xi_prev)/dt + theta' (2 xi . M x + xi . M xi)],
   M x being the centrifugal load L_centrifugal. Returns L_rel and I_0. Scratch: work, next, rhs. */
static PetscErrorCode AngularMomentum(Roller ctx, Vec xi, Vec xi_prev, PetscReal t, PetscReal *L_rel, PetscReal *I0)
{
  Vec         Mxi = ctx->state.next, d = ctx->state.work, v = ctx->state.rhs, Mx = ctx->ops.L_centrifugal;
  PetscReal   td;
  PetscScalar a, b, c, e;

  PetscFunctionBeginUser;
  RollerTheta(ctx, t, NULL, &td, NULL);
  PetscCall(MatMult(ctx->ops.M, xi, Mxi));
  PetscCall(VecDot(xi, Mx, &a));
  PetscCall(VecDot(xi, Mxi, &b));
  PetscCall(VecDot(ctx->ops.coordinates, Mx, &e));
  PetscCall(VecWAXPY(d, -1.0, xi_prev, xi));
  PetscCall(RollerApplyRotate90(d, v));
  PetscCall(VecAXPY(Mxi, 1.0, Mx));
  PetscCall(VecDot(v, Mxi, &c));
  *L_rel = ctx->material.density * (PetscRealPart(c) / ctx->ts.dt + td * (2.0 * PetscRealPart(a) + PetscRealPart(b)));
  *I0    = PetscRealPart(e);
  PetscFunctionReturn(0);
}

/* The shaft torque T^k = (L^k - L^{k-1})/dt - (the contact forces' moment, already in info: contact layer), and
   the cumulative works: the shaft's (the rigid loads' work and the contact's rotation parts), the sheet's, the
   friction dissipation (docs/friction.md), each step added once (a restart reads them from the checkpoint). */
static PetscErrorCode DriveAndWorks(Roller ctx, RollerStepInfo *info)
{
  RollerState *st = &ctx->state;
  PetscReal    L, Lprev = 0.0, I0, td, td_prev;

  PetscFunctionBeginUser;
  if (st->step > 0) {
    if (st->momentum_step == st->step - 1) Lprev = st->momentum;
    else PetscCall(AngularMomentum(ctx, st->prev, st->prev2, st->time - ctx->ts.dt, &Lprev, &I0));
  }
  PetscCall(AngularMomentum(ctx, st->cur, st->prev, st->time, &L, &I0));
  RollerTheta(ctx, st->time, NULL, &td, NULL);
  RollerTheta(ctx, st->time - ctx->ts.dt, NULL, &td_prev, NULL);
  if (st->step > 0) info->friction.torque += (L - Lprev) / ctx->ts.dt + ctx->material.density * I0 * (td - td_prev) / ctx->ts.dt;
  st->momentum      = L;
  st->momentum_step = st->step;
  if (st->step > st->work_step) {
    st->works[0] += info->load_work + info->friction.shaft_step;
    st->works[1] += info->friction.sheet_step;
    st->works[2] += info->friction.dissipation;
    st->work_step = st->step;
  }
  info->friction.shaft_work = st->works[0];
  info->friction.sheet_work = st->works[1];
  info->friction.work       = st->works[2];
  PetscFunctionReturn(0);
}

/* Fill ctx->info for the newest level xi1 = xi^k at t = k dt. */
PetscErrorCode RollerComputeStepInfo(Roller ctx)
{
  PetscScalar     r, a;
  RollerStepInfo *info = &ctx->info;

  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_DIAGNOSTICS]));
  PetscCall(VecDot(ctx->ops.w_R, ctx->state.cur, &r));
  PetscCall(VecDot(ctx->ops.w_alpha, ctx->state.cur, &a));
  info->R     = PetscRealPart(r) / ctx->mesh.boundary_length;
  info->alpha = PetscRealPart(a) / ctx->mesh.boundary_length;
  PetscCall(Energy(ctx, &info->energy));
  PetscCall(EnergyBalance(ctx, info));
  PetscCall(PetscMemzero(&info->friction, sizeof(info->friction)));
  if (ctx->contact) PetscCall(RollerContactInfo(ctx, ctx->contact, ctx->state.cur, ctx->state.time, info));
  else {
    /* no obstacle: no contact, and no gap to report (docs/output.md) */
    info->contact_nodes = 0;
    info->contact_force = 0.0;
    info->gap_min       = (PetscReal)NAN;
    info->qp_iterations = 0;
    info->kkt_residual  = 0.0;
    info->obstacle_work = info->contact_dissipation = 0.0;
    info->contact_flips = info->contact_reversals = 0;
  }
  PetscCall(DriveAndWorks(ctx, info));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}
