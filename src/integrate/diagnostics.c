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
   velocity (xi - xi_prev)/dt; with M acting alike on both components, p x v = p . R(-pi/2) v and
   L = rho (M p) . (R(-pi/2) (xi - xi_prev)/dt + theta' p), p = x + xi. Scratch: work, next, rhs. */
static PetscErrorCode AngularMomentum(Roller ctx, Vec xi, Vec xi_prev, PetscReal t, PetscReal *L)
{
  Vec         p = ctx->state.work, Mp = ctx->state.next, v = ctx->state.rhs;
  PetscReal   td;
  PetscScalar a, b;

  PetscFunctionBeginUser;
  RollerTheta(ctx, t, NULL, &td, NULL);
  PetscCall(VecWAXPY(p, 1.0, ctx->ops.coordinates, xi));
  PetscCall(MatMult(ctx->ops.M, p, Mp));
  PetscCall(VecDot(p, Mp, &a));
  PetscCall(VecWAXPY(p, -1.0, xi_prev, xi));
  PetscCall(RollerApplyRotate90(p, v));
  PetscCall(VecDot(v, Mp, &b));
  *L = ctx->material.density * (PetscRealPart(b) / ctx->ts.dt + td * PetscRealPart(a));
  PetscFunctionReturn(0);
}

/* The shaft torque T^k = (L^k - L^{k-1})/dt - (the contact forces' moment, already in info: contact layer), and
   the cumulative works: the shaft's (the rigid loads' work and the contact's rotation parts), the sheet's, the
   friction dissipation (docs/friction.md), each step added once (a restart reads them from the checkpoint). */
static PetscErrorCode DriveAndWorks(Roller ctx, RollerStepInfo *info)
{
  RollerState *st = &ctx->state;
  PetscReal    L, Lprev = 0.0;

  PetscFunctionBeginUser;
  if (st->step > 0) {
    if (st->momentum_step == st->step - 1) Lprev = st->momentum;
    else PetscCall(AngularMomentum(ctx, st->prev, st->prev2, st->time - ctx->ts.dt, &Lprev));
  }
  PetscCall(AngularMomentum(ctx, st->cur, st->prev, st->time, &L));
  if (st->step > 0) info->friction.torque += (L - Lprev) / ctx->ts.dt;
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
