/* The three-level schemes' energy identity (docs/model.md section 2): the energy E^k of the newest level, the terms of
   the balance of the last step, and the vectors a checkpoint keeps so that a restart repeats the run to the last bit. */
#include "scheme_newmark.h"
#include "model/model.h"

/* The kinetic term d . M d, d = xi^k - xi^{k-1}, when asked: for the DMF with its own product (its golden energy
   bits), else from the kept products, M xi^k - M xi^{k-1} (no product; the cancellation costs 1e-15 of E). */
PetscErrorCode RollerNewmarkEnergy(RollerScheme s, Roller ctx, PetscReal *energy)
{
  Newmark        *nm = (Newmark *)s->data;
  const PetscReal dt = ctx->ts.dt;
  PetscScalar     pot1, pot2, cross = 0.0;

  PetscFunctionBeginUser;
  if (nm->kinetic_step != ctx->state.step) {
    Vec         d = ctx->state.work, Md = ctx->state.next; /* scratch between steps */
    PetscScalar kin;

    PetscCall(VecWAXPY(d, -1.0, ctx->state.prev, ctx->state.cur));
    if (nm->beta == 0.5) PetscCall(MatMult(ctx->ops.M, d, Md)); /* the DMF's historical bits */
    else PetscCall(VecWAXPY(Md, -1.0, nm->Mprev, ctx->state.Mcur));
    PetscCall(VecDot(d, Md, &kin));
    nm->kinetic      = PetscRealPart(kin);
    nm->kinetic_step = ctx->state.step;
  }
  PetscCall(VecDot(ctx->state.cur, ctx->state.Kcur, &pot1));
  PetscCall(VecDot(ctx->state.prev, ctx->state.Kprev, &pot2));
  if (nm->beta != 0.5) PetscCall(VecDot(ctx->state.cur, ctx->state.Kprev, &cross));
  *energy = 0.5 * ctx->material.density * nm->kinetic / (dt * dt) + 0.5 * nm->beta * PetscRealPart(pot1 + pot2) + 0.5 * (1.0 - 2.0 * nm->beta) * PetscRealPart(cross);
  if (nm->mx) PetscCall(RollerMaxwellEnergyAdd(nm->mx, ctx, energy));
  if (ctx->axle.on) PetscCall(RollerHubEnergy(ctx, nm->beta, energy));                               /* adds q's terms */
  if (RollerContactSheetMoves(ctx->contact)) *energy += RollerContactSheetEnergy(ctx, ctx->contact); /* -sheet_mass: its kinetic energy */
  PetscCall(RollerContactResidualEnergy(ctx->contact, ctx->state.cur, ctx->state.prev, energy));     /* -rom_residual: R's static energy */
  PetscFunctionReturn(0);
}

/* The energy balance of the step from xi^{k-1} to xi^k (docs/model.md section 2): with D = xi^k - xi^{k-2},
     E^k - E^{k-1} = 1/2 F^{k-1} . D + 1/2 (E N lambda^k) . D - eta/(4 dt) D . M D - tau/(4 dt) D . K D,
   the load's work, the contact's (contact layer), the mass damping's and the Kelvin-Voigt (or Maxwell) dissipation. */
PetscErrorCode RollerNewmarkBalance(RollerScheme s, Roller ctx, RollerStepInfo *info)
{
  Newmark        *nm = (Newmark *)s->data;
  const PetscReal dt = ctx->ts.dt;
  Vec             D = ctx->state.work, W = ctx->state.next; /* scratch between steps */
  PetscScalar     dot;

  PetscFunctionBeginUser;
  if (ctx->state.step == 0) PetscFunctionReturn(0);
  PetscCall(VecWAXPY(D, -1.0, ctx->state.prev2, ctx->state.cur));
  PetscCall(VecDot(ctx->state.load, D, &dot));
  info->load_work = 0.5 * PetscRealPart(dot);
  if (ctx->disc.damping > 0) {
    PetscCall(VecWAXPY(W, -1.0, nm->Mprev2, ctx->state.Mcur));
    PetscCall(VecDot(D, W, &dot));
    info->damping_dissipation = ctx->disc.damping / (4.0 * dt) * PetscRealPart(dot);
  }
  if (ctx->material.viscosity > 0) {
    PetscCall(VecWAXPY(W, -1.0, ctx->state.Kprev2, ctx->state.Kcur));
    PetscCall(VecDot(D, W, &dot));
    info->viscous_dissipation = ctx->material.viscosity / (4.0 * dt) * PetscRealPart(dot);
  }
  if (nm->mx) info->viscous_dissipation += RollerMaxwellDissipation(nm->mx, ctx);
  if (ctx->contact) PetscCall(RollerContactEnergyAdd(ctx, ctx->contact, ctx->state.prev2, ctx->state.time - 2.0 * dt, 0.5, info));
  if (ctx->contact) PetscCall(RollerContactResidualDissipation(ctx->contact, ctx->state.cur, ctx->state.prev2, &info->contact_dissipation, &info->viscous_dissipation)); /* -rom_residual */
  if (ctx->axle.on) PetscCall(RollerHubBalance(ctx, nm->beta, info));
  PetscFunctionReturn(0);
}

/* M xi of the three levels: made from the step's equation, a product of the level would differ in its last bits, so a
   restart reads them from the checkpoint; and the Maxwell branches'. */
PetscErrorCode RollerNewmarkKept(RollerScheme s, Roller ctx, PetscInt *n, Vec *v[], const char *names[])
{
  Newmark          *nm       = (Newmark *)s->data;
  Vec              *M[3]     = {&ctx->state.Mcur, &nm->Mprev, &nm->Mprev2}; /* the levels swap: their fields' addresses */
  const char *const Mname[3] = {"M_xi_k", "M_xi_k1", "M_xi_k2"};

  PetscFunctionBeginUser;
  for (*n = 0; *n < 3; ++*n) {
    v[*n]     = M[*n];
    names[*n] = Mname[*n];
  }
  if (nm->mx) PetscCall(RollerMaxwellKept(nm->mx, n, v, names));
  PetscFunctionReturn(0);
}
