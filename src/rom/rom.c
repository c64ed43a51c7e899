/* -rom (docs/performance.md "Reduced-order transient"): the options, the default cutoff, the set-up that puts the
   reduced model in the context, and -ts_view's account of it. */
#include "rom/rom.h"
#include "integrate/integrate.h"
#include "contact/contact.h"

PetscErrorCode RollerRomSetFromOptions(Roller ctx)
{
  PetscBool on     = PETSC_FALSE;
  PetscInt  modes  = 0;
  PetscReal cutoff = 0.0;

  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: reduced-order transient (docs/performance.md); its eigensolver takes -rom_eps_* and -rom_st_* options (SLEPc EPS)", NULL);
  PetscCall(PetscOptionsBool("-rom", "Step the reduced model: the modes of the roller clamped at the shaft below the cutoff and the static load responses", NULL, on, &on, NULL));
  PetscCall(PetscOptionsInt("-rom_modes", "Modes kept (0: those below -rom_cutoff)", NULL, modes, &modes, NULL));
  PetscCall(PetscOptionsReal("-rom_cutoff", "Cutoff frequency of the kept modes, cycles per unit time (0: the default, the highest frequency the time step resolves to -ts_phase_error, -ts_view)", NULL, cutoff, &cutoff, NULL));
  PetscOptionsEnd();
  RollerCheckOption(ctx->comm, "-rom_modes", (PetscReal)modes, modes >= 0, ">= 0 (0: from -rom_cutoff)");
  RollerCheckOption(ctx->comm, "-rom_cutoff", cutoff, cutoff >= 0, ">= 0 (0: the default)");
  if (!on) PetscFunctionReturn(0);
  PetscCheck(!ctx->init.mms, ctx->comm, PETSC_ERR_ARG_INCOMP, "-rom steps the roller's own loads: -mms is the full model's");
  PetscCheck(!ctx->axle.on, ctx->comm, PETSC_ERR_SUP, "-rom with -axle: the hub's unknowns are not in the reduced model (clamped at the shaft)");
  PetscCheck(ctx->material.rubber != ROLLER_RUBBER_MAXWELL, ctx->comm, PETSC_ERR_SUP, "-rom with -rubber maxwell: the branches' internal variables are not reduced (Kelvin-Voigt -viscosity is)");
  PetscCheck(!ctx->ck.restart[0], ctx->comm, PETSC_ERR_SUP, "-rom with -restart %s: a checkpoint holds the full model's nodal state", ctx->ck.restart);
  PetscCall(PetscNew(&ctx->rom));
  ctx->rom->modes_req = modes;
  ctx->rom->cutoff    = cutoff;
  PetscFunctionReturn(0);
}

/* The default cutoff: the angular frequency w at which the run's scheme at its dt has the relative frequency error
   -ts_phase_error P (|W dt - w dt| = P w dt; the trapezoidal rule: (w dt)^2/12 = P); a mode above it the full model
   integrates no better. */
static PetscErrorCode DefaultCutoff(Roller ctx, PetscReal *w_cut)
{
  const PetscReal dt = ctx->ts.dt, P = ctx->ts.phase_error;
  PetscReal       lo = 1e-6, hi = 3.0;

  PetscFunctionBeginUser;
  for (PetscInt it = 0; it < 60; ++it) {
    const PetscReal x = 0.5 * (lo + hi);
    PetscReal       e;

    PetscCall(RollerSchemePhase(ctx, x, &e));
    if (e > P * x) hi = x;
    else lo = x;
  }
  *w_cut = lo / dt;
  PetscFunctionReturn(0);
}

static PetscErrorCode View(Roller ctx, RollerRom rom)
{
  PetscInt N;

  PetscFunctionBeginUser;
  PetscCall(MatGetSize(rom->V, &N, NULL));
  PetscCall(PetscPrintf(ctx->comm, "roller: -rom: %" PetscInt_FMT " modes of the roller clamped at the shaft (below %g cycles per unit time%s) + 2 static load responses = %" PetscInt_FMT " coordinates for %" PetscInt_FMT " unknowns; highest kept w %g (w dt %.3g); basis round-off %.1e; set-up %.2f s (modes) + %.2f s (reduced operators)\n",
                        rom->nmodes, (double)(rom->w_cut / (2 * PETSC_PI)),
                        rom->modes_req    ? ", -rom_modes"
                        : rom->cutoff > 0 ? ", -rom_cutoff"
                                          : ": the default, where the step's relative frequency error reaches -ts_phase_error",
                        rom->nq, N, rom->nmodes ? (double)PetscSqrtReal(rom->lambda[rom->nmodes - 1] / ctx->material.density) : 0.0, rom->nmodes ? (double)(PetscSqrtReal(rom->lambda[rom->nmodes - 1] / ctx->material.density) * ctx->ts.dt) : 0.0,
                        (double)rom->offdiag, rom->t_modes, rom->t_reduce));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerRomSetUp(Roller ctx)
{
  RollerRom      rom = ctx->rom;
  PetscLogDouble t0, t1, t2;

  PetscFunctionBeginUser;
  PetscCheck(!ctx->ops.G, ctx->comm, PETSC_ERR_ARG_INCOMP, "-rom: the centred -coriolis_velocity puts the Coriolis matrix in the step matrix; the reduced model takes it explicitly (backward or extrapolated)");
  PetscCheck(rom->cutoff * ctx->ts.dt <= 0.5, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-rom_cutoff %g must not exceed the step's Nyquist frequency 1/(2 dt) = %g", (double)rom->cutoff, (double)(0.5 / ctx->ts.dt));
  if (rom->cutoff > 0) rom->w_cut = 2 * PETSC_PI * rom->cutoff;
  else PetscCall(DefaultCutoff(ctx, &rom->w_cut));
  if (ctx->contact) PetscCall(RollerContactCheckReduced(ctx, ctx->contact));
  PetscCall(PetscTime(&t0));
  PetscCall(RollerRomBasis(ctx, rom));
  PetscCall(PetscTime(&t1));
  PetscCall(RollerRomReduce(ctx, rom));
  if (ctx->contact) PetscCall(RollerContactSetBasis(ctx, ctx->contact, rom->V, ctx->state.cur)); /* u_C = Phi q */
  PetscCall(PetscTime(&t2));
  rom->t_modes  = t1 - t0;
  rom->t_reduce = t2 - t1;
  if (ctx->ts.view) PetscCall(View(ctx, rom));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerRomDestroy(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&ctx->ops.R90));
  PetscCall(MatDestroy(&ctx->ops.V));
  PetscCall(MatDestroy(&ctx->ops.M_full));
  if (!ctx->rom) PetscFunctionReturn(0);
  PetscCall(MatDestroy(&ctx->rom->V));
  PetscCall(PetscFree(ctx->rom->lambda));
  PetscCall(PetscFree(ctx->rom));
  PetscFunctionReturn(0);
}
