/* The TS-like driver: advances the three-level DMF scheme from t = 0 to -ts_max_time (or
   -ts_max_steps), runs the diagnostics and monitors of every step and prints a progress line. */
#include "integrate/integrate.h"

typedef struct {
  PetscBool      monitor, quiet;
  PetscLogDouble start, last;
} Progress;

static PetscErrorCode Monitor(Roller ctx, Progress *p, PetscInt nsteps)
{
  const RollerStepInfo *info = &ctx->info;
  PetscLogDouble        now;

  PetscFunctionBeginUser;
  if (p->monitor) {
    PetscCall(PetscPrintf(ctx->comm, "%5" PetscInt_FMT " t %-10.6g R %+.6e alpha %+.6e energy %.10e", ctx->state.step, (double)ctx->state.time, (double)info->R, (double)info->alpha, (double)info->energy));
    if (ctx->contact)
      PetscCall(PetscPrintf(ctx->comm, " contact %" PetscInt_FMT " force %.6e gap %+.3e its %" PetscInt_FMT " kkt %.2e", info->contact_nodes, (double)info->contact_force, (double)info->gap_min, info->qp_iterations, (double)info->kkt_residual));
    PetscCall(PetscPrintf(ctx->comm, "\n"));
  }
  if (p->quiet || ctx->state.step == 0) PetscFunctionReturn(0);
  PetscCall(PetscTime(&now));
  if (now - p->last >= 5.0 || ctx->state.step == nsteps) {
    const PetscLogDouble eta = (now - p->start) * (nsteps - ctx->state.step) / ctx->state.step;
    PetscCall(PetscPrintf(ctx->comm, "roller: step %" PetscInt_FMT "/%" PetscInt_FMT " t = %g, %.1f s elapsed, ETA %.1f s\n", ctx->state.step, nsteps, (double)ctx->state.time, now - p->start, eta));
    p->last = now;
  }
  PetscFunctionReturn(0);
}

/* Number of steps: floor(max_time/dt) (to a rounding tolerance), capped by -ts_max_steps. */
static PetscInt StepCount(Roller ctx)
{
  PetscReal n = PetscFloorReal(ctx->ts.max_time / ctx->ts.dt + 1e-9);

  if (ctx->ts.max_steps >= 0) n = PetscMin(n, (PetscReal)ctx->ts.max_steps);
  return (PetscInt)PetscMin(n, (PetscReal)PETSC_MAX_INT);
}

/* A step failed (the step solve, the contact solver, a non-finite solution): the history still holds the
   last good state (RollerStep rotates it only on success), so write it to the checkpoint before the error
   goes up, and say how to go on. Collective, like the failures it follows. */
static PetscErrorCode StepFailed(Roller ctx, PetscErrorCode ierr)
{
  PetscFunctionBeginUser;
  PetscCall(RollerCheckpointWrite(ctx, ctx->ck.file));
  PetscCall(PetscPrintf(ctx->comm, "roller: step %" PetscInt_FMT " (t = %g) failed; the last good state (step %" PetscInt_FMT ", t = %g) is in the checkpoint %s: continue with the same options and -restart %s (after changing what failed)\n",
                        ctx->state.step + 1, (double)((ctx->state.step + 1) * ctx->ts.dt), ctx->state.step, (double)ctx->state.time, ctx->ck.file, ctx->ck.file));
  SETERRQ(ctx->comm, ierr, "Step %" PetscInt_FMT " failed; the last good state is in the checkpoint %s", ctx->state.step + 1, ctx->ck.file);
}

PetscErrorCode RollerSolve(Roller ctx)
{
  Progress  p      = {PETSC_FALSE, ctx->ts.quiet, 0, 0};
  PetscInt  nsteps = StepCount(ctx);
  PetscBool help;

  PetscFunctionBeginUser;
  /* -help lists every option (with the solvers', which setup has read): no need to run the scene */
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (help) nsteps = 0;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: monitors", NULL);
  PetscCall(PetscOptionsBool("-ts_monitor", "Print R, alpha, energy (and contact) every step", NULL, p.monitor, &p.monitor, NULL));
  PetscOptionsEnd();
  PetscCall(PetscTime(&p.start));
  p.last = p.start;
  PetscCall(RollerComputeStepInfo(ctx));
  PetscCall(Monitor(ctx, &p, nsteps));
  if (!ctx->ck.restart[0]) PetscCall(RollerOutputStep(ctx, ctx->output)); /* a restart continues after its row */
  while (ctx->state.step < nsteps) {
    PetscInt sig;

    PetscErrorCode ierr;

    PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_STEP]));
    ierr = RollerStep(ctx);
    if (ierr) PetscCall(StepFailed(ctx, ierr));
    PetscCall(PetscLogStagePop());
    PetscCall(RollerComputeStepInfo(ctx));
    PetscCall(Monitor(ctx, &p, nsteps));
    PetscCall(RollerOutputStep(ctx, ctx->output));
    if (ctx->ck.every && ctx->state.step % ctx->ck.every == 0) PetscCall(RollerCheckpointWrite(ctx, ctx->ck.file));
    PetscCall(RollerSignalCaught(ctx, &sig));
    if (sig) {
      PetscCall(RollerCheckpointWrite(ctx, ctx->ck.file));
      PetscCall(PetscPrintf(ctx->comm, "roller: caught signal %d after step %" PetscInt_FMT " (t = %g); the state is in %s. Continue with the same options and -restart %s\n", (int)sig, ctx->state.step, (double)ctx->state.time, ctx->ck.file, ctx->ck.file));
      break;
    }
  }
  if (ctx->init.mms != ROLLER_MMS_NONE) {
    PetscReal l2, h1;

    PetscCall(RollerComputeErrors(ctx, ctx->state.time, &l2, &h1));
    PetscCall(PetscPrintf(ctx->comm, "mms: t %.17g L2 %.17g H1 %.17g\n", (double)ctx->state.time, (double)l2, (double)h1));
  }
  PetscFunctionReturn(0);
}
