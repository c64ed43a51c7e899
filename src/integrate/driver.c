/* The TS-like driver: advances the time scheme (-ts_scheme) from t = 0 (or a restart's step) to -ts_max_time
   (or -ts_max_steps), adds up the works of every step and hands every state to the observers (integrate/monitor.c),
   which ask for the rest of the step's diagnostics when they write them; a failed step, a caught signal or the
   wall-time limit (-ts_max_wall) ends in a checkpoint. */
#include "integrate/integrate.h"

/* A step failed (the step solve, the contact solver, a non-finite solution): the history still holds the
   last good state (a scheme moves its levels up only on success), so write it to the checkpoint before the error
   goes up, and say how to go on. Collective, like the failures it follows. */
static PetscErrorCode StepFailed(Roller ctx, PetscErrorCode ierr)
{
  PetscFunctionBeginUser;
  PetscCall(RollerCheckpointWrite(ctx, ctx->ck.file));
  PetscCall(PetscPrintf(ctx->comm, "roller: step %" PetscInt_FMT " (t = %g) failed; the last good state (step %" PetscInt_FMT ", t = %g) is in the checkpoint %s: continue with the same options and -restart %s (after changing what failed)\n",
                        ctx->state.step + 1, (double)((ctx->state.step + 1) * ctx->ts.dt), ctx->state.step, (double)ctx->state.time, ctx->ck.file, ctx->ck.file));
  SETERRQ(ctx->comm, ierr, "Step %" PetscInt_FMT " failed; the last good state is in the checkpoint %s", ctx->state.step + 1, ctx->ck.file);
}

/* -ts_max_wall: after a step of this process (steps of them since loop_start), whether the next one would end
   past the limit, at the mean step time so far (the observers' time included), on the slowest rank's clock. */
static PetscErrorCode WallLimitReached(Roller ctx, PetscLogDouble loop_start, PetscInt steps, PetscBool *stop, PetscLogDouble *wall)
{
  PetscLogDouble now, local[2], global[2];

  PetscFunctionBeginUser;
  *stop = PETSC_FALSE;
  if (ctx->ts.max_wall <= 0) PetscFunctionReturn(0);
  PetscCall(PetscTime(&now));
  local[0] = now - ctx->ts.wall_start;
  local[1] = (now - loop_start) / steps;
  PetscCall(MPIU_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, ctx->comm));
  *stop   = (PetscBool)(global[0] + global[1] > ctx->ts.max_wall);
  wall[0] = global[0];
  wall[1] = global[1];
  PetscFunctionReturn(0);
}

PetscErrorCode RollerRun(Roller ctx)
{
  PetscInt       nsteps, first;
  PetscLogDouble loop_start;

  PetscFunctionBeginUser;
  PetscCall(RollerStepCount(ctx, &nsteps));
  PetscCall(RollerStepAccumulate(ctx));
  PetscCall(RollerMonitorRun(ctx, ROLLER_MONITOR_INITIAL));
  PetscCall(PetscTime(&loop_start));
  first = ctx->state.step;
  while (ctx->state.step < nsteps) {
    PetscBool      stop;
    PetscLogDouble wall[2];
    PetscInt       sig;
    PetscErrorCode ierr;

    PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_STEP]));
    ierr = RollerSchemeStep(ctx);
    PetscCall(PetscLogStagePop()); /* also when the step failed: the checkpoint is written outside it */
    if (ierr) PetscCall(StepFailed(ctx, ierr));
    PetscCall(RollerStepAccumulate(ctx));
    PetscCall(RollerMonitorRun(ctx, ROLLER_MONITOR_STEP));
    PetscCall(RollerSignalCaught(ctx, &sig));
    if (sig) {
      PetscCall(RollerCheckpointWrite(ctx, ctx->ck.file));
      PetscCall(PetscPrintf(ctx->comm, "roller: caught signal %d after step %" PetscInt_FMT " (t = %g); the state is in %s. Continue with the same options and -restart %s\n", (int)sig, ctx->state.step, (double)ctx->state.time, ctx->ck.file, ctx->ck.file));
      break;
    }
    PetscCall(WallLimitReached(ctx, loop_start, ctx->state.step - first, &stop, wall));
    if (stop && ctx->state.step < nsteps) {
      PetscCall(RollerCheckpointWrite(ctx, ctx->ck.file));
      PetscCall(PetscPrintf(ctx->comm, "roller: -ts_max_wall %.1f s: stopped after step %" PetscInt_FMT " (t = %g) at %.1f s, the next step (%.3g s on average) would end past it; the state is in %s. Resume with the same options and -restart %s\n",
                            (double)ctx->ts.max_wall, ctx->state.step, (double)ctx->state.time, wall[0], wall[1], ctx->ck.file, ctx->ck.file));
      break;
    }
  }
  PetscCall(RollerMonitorRun(ctx, ROLLER_MONITOR_FINAL));
  PetscFunctionReturn(0);
}
