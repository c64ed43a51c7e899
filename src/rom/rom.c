/* -rom (docs/performance.md "Reduced-order transient"): the options, the default cutoff, the set-up that puts the
   reduced model in the context, and -ts_view's account of it. */
#include "rom/rom.h"
#include "integrate/integrate.h"
#include "contact/contact.h"

PetscErrorCode RollerRomSetFromOptions(Roller ctx)
{
  PetscBool on = PETSC_FALSE, residual = PETSC_TRUE, branches = PETSC_TRUE;
  char      input[PETSC_MAX_PATH_LEN] = "", output[PETSC_MAX_PATH_LEN] = "";
  PetscInt  modes  = 0;
  PetscReal cutoff = 0.0;

  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: reduced-order transient (docs/performance.md); its eigensolver takes -rom_eps_* and -rom_st_* options (SLEPc EPS)", NULL);
  PetscCall(PetscOptionsBool("-rom", "Step the reduced model: the modes of the roller clamped at the shaft below the cutoff and the static load responses", NULL, on, &on, NULL));
  PetscCall(PetscOptionsInt("-rom_modes", "Modes kept (0: those below -rom_cutoff)", NULL, modes, &modes, NULL));
  PetscCall(PetscOptionsReal("-rom_cutoff", "Cutoff frequency of the kept modes, cycles per unit time (0: the default, the highest frequency the time step resolves to -ts_phase_error, -ts_view)", NULL, cutoff, &cutoff, NULL));
  PetscCall(PetscOptionsBool("-rom_residual", "With contact: MacNeal's static residual flexibility of the modes above the cutoff at Gamma_C (false: the modes alone, whose patch is too stiff)", NULL, residual, &residual, NULL));
  PetscCall(PetscOptionsBool("-rom_residual_branches", "With -rubber maxwell: the residual flexibility relaxes with the rubber's branches (false: the relaxed rubber's, elastic)", NULL, branches, &branches, NULL));
  PetscCall(PetscOptionsString("-rom_output", "Save the reduced basis (and the residual flexibility) to this HDF5 file, for -rom_input of runs on the same mesh and rubber", NULL, output, output, sizeof(output), NULL));
  PetscCall(PetscOptionsString("-rom_input", "Read the reduced basis from this -rom_output file instead of computing it (refused if made for another mesh, rubber, cutoff or contact)", NULL, input, input, sizeof(input), NULL));
  PetscOptionsEnd();
  RollerCheckOption(ctx->comm, "-rom_modes", (PetscReal)modes, modes >= 0, ">= 0 (0: from -rom_cutoff)");
  RollerCheckOption(ctx->comm, "-rom_cutoff", cutoff, cutoff >= 0, ">= 0 (0: the default)");
  if (!on) PetscFunctionReturn(0);
  PetscCheck(!ctx->init.mms, ctx->comm, PETSC_ERR_ARG_INCOMP, "-rom steps the roller's own loads: -mms is the full model's");
  PetscCheck(!ctx->ck.restart[0], ctx->comm, PETSC_ERR_SUP, "-rom with -restart %s: a checkpoint holds the full model's nodal state", ctx->ck.restart);
  PetscCall(PetscNew(&ctx->rom));
  ctx->rom->modes_req         = modes;
  ctx->rom->cutoff            = cutoff;
  ctx->rom->residual          = residual;
  ctx->rom->residual_branches = branches;
  ctx->rom->kappa             = -1.0; /* no viscoelastic residual (set with it: Residual, RollerRomLoadResidual) */
  PetscCall(PetscStrncpy(ctx->rom->input, input, sizeof(input)));
  PetscCall(PetscStrncpy(ctx->rom->output, output, sizeof(output)));
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
  PetscCall(PetscPrintf(ctx->comm, "roller: -rom: %" PetscInt_FMT " modes of the roller clamped at the shaft (below %g cycles per unit time%s) + 2 static load responses%s = %" PetscInt_FMT " coordinates for %" PetscInt_FMT " unknowns; highest kept w %g (w dt %.3g); basis round-off %.1e; set-up %.2f s (modes%s%s) + %.2f s (reduced operators) + %.2f s (%s)\n",
                        rom->nmodes, (double)(rom->w_cut / (2 * PETSC_PI)),
                        rom->modes_req    ? ", -rom_modes"
                        : rom->cutoff > 0 ? ", -rom_cutoff"
                                          : ": the default, where the step's relative frequency error reaches -ts_phase_error",
                        ctx->axle.on ? " + 3 constraint modes of the hub (-axle: its unknowns kept)" : "", rom->nq, N, rom->nmodes ? (double)PetscSqrtReal(rom->lambda[rom->nmodes - 1] / ctx->material.density) : 0.0,
                        rom->nmodes ? (double)(PetscSqrtReal(rom->lambda[rom->nmodes - 1] / ctx->material.density) * ctx->ts.dt) : 0.0, (double)rom->offdiag, rom->t_modes, rom->input[0] ? " read from -rom_input " : "", rom->input, rom->t_reduce, rom->t_residual,
                        ctx->contact && rom->residual ? "with contact: MacNeal's static residual flexibility of the modes above the cutoff at the Gamma_C dofs, -rom_residual" : "no residual flexibility"));
  if (rom->kappa >= 0)
    PetscCall(PetscPrintf(ctx->comm, "roller: -rom: the residual relaxes with the rubber's %" PetscInt_FMT " branches (-rom_residual_branches), their share of its stiffness kappa %.4f (R(c) ~ R/(1 + kappa c) for the storage stiffness K + c K_d)\n",
                          ctx->material.nbranch, (double)rom->kappa));
  PetscFunctionReturn(0);
}

/* MacNeal's residual flexibility at Gamma_C of a stiffness K + c K_d: from K's factorization (the eigensolver's, shift
   0) and V^T K V at c = 0, else from its own Cholesky factorization. */
static PetscErrorCode ResidualOf(Roller ctx, RollerRom rom, Mat Kd, PetscReal c)
{
  const PetscInt nq = rom->nq;
  PetscReal     *Kr;
  ST             st;
  KSP            ksp;

  PetscFunctionBeginUser;
  PetscCall(EPSGetST(rom->eps, &st));
  PetscCall(STGetKSP(st, &ksp));
  PetscCall(PetscCalloc1((size_t)nq * nq, &Kr));
  for (PetscInt i = 0; i < nq; ++i) Kr[i + (size_t)i * nq] = rom->lambda[i];
  if (c > 0) {
    Mat        K, Keff, KdV;
    KSP        kk;
    PetscReal *g;

    PetscCall(EPSGetOperators(rom->eps, &K, NULL));
    PetscCall(MatDuplicate(K, MAT_COPY_VALUES, &Keff));
    PetscCall(MatAXPY(Keff, c, Kd, SAME_NONZERO_PATTERN)); /* K_d has K's pattern */
    PetscCall(KSPCreate(ctx->comm, &kk));
    PetscCall(KSPSetOperators(kk, Keff, Keff));
    PetscCall(RollerDirectSolverDefaults(kk, PCCHOLESKY));
    PetscCall(KSPSetUp(kk));
    PetscCall(MatMatMult(Kd, rom->V, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &KdV));
    PetscCall(PetscMalloc1((size_t)nq * nq, &g));
    PetscCall(RollerRomGram(rom->V, KdV, g));
    for (size_t k = 0; k < (size_t)nq * nq; ++k) Kr[k] += c * g[k];
    PetscCall(RollerContactSetResidualFlexibility(ctx, ctx->contact, kk, Kr));
    PetscCall(PetscFree(g));
    PetscCall(MatDestroy(&KdV));
    PetscCall(KSPDestroy(&kk));
    PetscCall(MatDestroy(&Keff));
  } else PetscCall(RollerContactSetResidualFlexibility(ctx, ctx->contact, ksp, Kr));
  PetscCall(PetscFree(Kr));
  PetscFunctionReturn(0);
}

/* The residual flexibility R of the relaxed rubber; with the Maxwell rubber's branches (-rom_residual_branches) also
   kappa, their share of the residual's stiffness: the storage stiffness K + c K_d has R(c) ~ R/(1 + kappa c)
   (contact_residual_branches.c), kappa from the traces at c1 = sum_i g_i/2, half the glassy rubber's,
   tr R/tr R(c1) = 1 + kappa c1 (R(c1) a second factorization and 2 nc solves, then discarded). */
static PetscErrorCode Residual(Roller ctx, RollerRom rom, Mat Kd)
{
  PetscReal c1 = 0.0, tr1 = 0.0, tr0;

  PetscFunctionBeginUser;
  rom->kappa = -1.0;
  if (Kd && rom->residual_branches) {
    for (PetscInt i = 0; i < ctx->material.nbranch; ++i) c1 += 0.5 * ctx->material.g[i];
    PetscCall(ResidualOf(ctx, rom, Kd, c1));
    PetscCall(RollerContactResidualTrace(ctx->contact, &tr1));
  }
  PetscCall(ResidualOf(ctx, rom, Kd, 0.0));
  if (c1 > 0) {
    PetscCall(RollerContactResidualTrace(ctx->contact, &tr0));
    rom->kappa = (tr0 / tr1 - 1.0) / c1;
  }
  PetscFunctionReturn(0);
}

/* The viscoelastic residual's branches, once R and kappa are known (computed or read). */
static PetscErrorCode ResidualBranches(Roller ctx, RollerRom rom)
{
  PetscFunctionBeginUser;
  if (rom->kappa < 0) PetscFunctionReturn(0);
  PetscCall(RollerContactSetResidualBranches(ctx->contact, ctx->material.nbranch, ctx->material.g, ctx->material.tau, rom->kappa, ctx->ts.dt));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerRomSetUp(Roller ctx)
{
  RollerRom      rom = ctx->rom;
  PetscLogDouble t0, t1, t2, t3;
  Mat            Kd = NULL;

  PetscFunctionBeginUser;
  PetscCheck(!ctx->ops.G, ctx->comm, PETSC_ERR_ARG_INCOMP, "-rom: the centred -coriolis_velocity puts the Coriolis matrix in the step matrix; the reduced model takes it explicitly (backward or extrapolated)");
  PetscCheck(rom->cutoff * ctx->ts.dt <= 0.5, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-rom_cutoff %g must not exceed the step's Nyquist frequency 1/(2 dt) = %g", (double)rom->cutoff, (double)(0.5 / ctx->ts.dt));
  if (rom->cutoff > 0) rom->w_cut = 2 * PETSC_PI * rom->cutoff;
  else PetscCall(DefaultCutoff(ctx, &rom->w_cut));
  PetscCheck(!ctx->eig.on || ctx->material.rubber != ROLLER_RUBBER_MAXWELL, ctx->comm, PETSC_ERR_SUP, "-modes with -rom and -rubber maxwell: the branches' augmented eigenproblem is the full model's (run -modes without -rom)");
  PetscCheck(!ctx->eig.on || !ctx->axle.on, ctx->comm, PETSC_ERR_SUP, "-modes with -rom and -axle: the hub's bordered eigenproblem is the full model's (run -modes without -rom)");
  if (ctx->contact) PetscCall(RollerContactCheckReduced(ctx, ctx->contact));
  PetscCall(PetscTime(&t0));
  if (rom->input[0]) PetscCall(RollerRomLoad(ctx, rom, rom->input)); /* the basis of an earlier run */
  else PetscCall(RollerRomBasis(ctx, rom));
  PetscCall(PetscTime(&t1));
  if (ctx->contact && rom->residual) { /* before the reduction replaces them: the functionals' and the levels' Gamma_C rows */
    const Vec lev[3] = {ctx->state.cur, ctx->state.prev, ctx->state.prev2};

    PetscCall(RollerContactResidualFunctionals(ctx->contact, ctx->ops.w_R, ctx->ops.w_alpha));
    PetscCall(RollerContactResidualLevelsBegin(ctx->contact, lev));
  }
  if (ctx->ops.Kd) { /* the full K_d, for the residual's storage stiffness (the reduction replaces ops.Kd) */
    Kd = ctx->ops.Kd;
    PetscCall(PetscObjectReference((PetscObject)Kd));
  }
  PetscCall(RollerRomReduce(ctx, rom));
  if (ctx->contact) PetscCall(RollerContactSetBasis(ctx, ctx->contact, rom->V, ctx->state.cur)); /* u_C = Phi q */
  PetscCall(PetscTime(&t2));
  if (ctx->contact && rom->residual && rom->input[0]) PetscCall(RollerRomLoadResidual(ctx, rom, rom->input));
  else if (ctx->contact && rom->residual) PetscCall(Residual(ctx, rom, Kd));
  if (ctx->contact && rom->residual) PetscCall(ResidualBranches(ctx, rom));
  PetscCall(MatDestroy(&Kd));
  if (ctx->contact && rom->residual) { /* the initial levels' Gamma_C remainder, with its force */
    const Vec lev[3] = {ctx->state.cur, ctx->state.prev, ctx->state.prev2};

    PetscCall(RollerContactResidualLevelsEnd(ctx->contact, lev));
  }
  PetscCall(EPSDestroy(&rom->eps));
  if (rom->output[0]) PetscCall(RollerRomSave(ctx, rom, rom->output));
  PetscCall(PetscTime(&t3));
  rom->t_modes    = t1 - t0;
  rom->t_reduce   = t2 - t1;
  rom->t_residual = t3 - t2;
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
