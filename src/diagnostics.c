/* What every step reports (docs/model.md sections 4 and 6): the mean radial and tangential displacements of
   Gamma_C, the discrete energy of Theorem 1, and the contact quantities. */
#include <roller_impl.h>

/* E^k = rho/2 |xi^k - xi^{k-1}|^2_M / dt^2 + (a(xi^k, xi^k) + a(xi^{k-1}, xi^{k-1}))/4 (docs/model.md section 2). */
static PetscErrorCode Energy(Roller ctx, PetscReal *energy)
{
  PetscScalar kin, pot1, pot2;

  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(ctx->work, -1.0, ctx->xi2, ctx->xi1));
  PetscCall(MatMult(ctx->M, ctx->work, ctx->xi));
  PetscCall(VecDot(ctx->work, ctx->xi, &kin));
  PetscCall(VecDot(ctx->xi1, ctx->Kxi1, &pot1));
  PetscCall(VecDot(ctx->xi2, ctx->Kxi2, &pot2));
  *energy = 0.5 * ctx->density * PetscRealPart(kin) / (ctx->dt * ctx->dt) + 0.25 * PetscRealPart(pot1 + pot2);
  PetscFunctionReturn(0);
}

/* Fill ctx->info for the newest level xi1 = xi^k at t = k dt. */
PetscErrorCode RollerComputeStepInfo(Roller ctx)
{
  PetscScalar     r, a;
  RollerStepInfo *info = &ctx->info;

  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_DIAGNOSTICS]));
  PetscCall(VecDot(ctx->w_R, ctx->xi1, &r));
  PetscCall(VecDot(ctx->w_alpha, ctx->xi1, &a));
  info->R     = PetscRealPart(r) / ctx->boundary_length;
  info->alpha = PetscRealPart(a) / ctx->boundary_length;
  PetscCall(Energy(ctx, &info->energy));
  if (ctx->contact) PetscCall(RollerContactInfo(ctx, ctx->contact, ctx->xi1, ctx->time, info));
  else {
    /* no obstacle: no contact, and no gap to report (docs/output.md) */
    info->contact_nodes = 0;
    info->contact_force = 0.0;
    info->gap_min       = (PetscReal)NAN;
    info->qp_iterations = 0;
    info->kkt_residual  = 0.0;
  }
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}
