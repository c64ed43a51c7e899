/* The initial state xi^0, eta^0 (-initial_condition, -ic_amplitude) and the manufactured solution that
   verifies the scheme (-mms, verify/mms.c), whose L2 and H1 errors at the end of the run are reported by an
   observer (-mms_view: stdout by default, or e.g. ascii:errors.csv:ascii_csv for a CSV t,L2,H1). */
#include "integrate/integrate.h"

PetscErrorCode RollerInitialSetFromOptions(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: initial condition and manufactured solution", NULL);
  PetscCall(PetscOptionsEnum("-initial_condition", "Initial state xi0, eta0", "RollerInitialCondition", RollerInitialConditions, (PetscEnum)ctx->init.type, (PetscEnum *)&ctx->init.type, NULL));
  PetscCall(PetscOptionsReal("-ic_amplitude", "Amplitude of the bump, or of the mode's largest displacement (-initial_condition mode)", NULL, ctx->init.amplitude, &ctx->init.amplitude, NULL));
  PetscCall(PetscOptionsString("-initial_mode_file", "-initial_condition mode: the -modes_output file holding the mode (co-rotating; or lab, the squeal modes with the steady state)", NULL, ctx->init.mode_file, ctx->init.mode_file, sizeof(ctx->init.mode_file), NULL));
  PetscCall(PetscOptionsInt("-initial_mode", "-initial_condition mode: the mode's row in that file's eigenvalue CSV", NULL, ctx->init.mode_index, &ctx->init.mode_index, NULL));
  PetscCall(PetscOptionsEnum("-mms", "Manufactured solution for verification (adds its body force)", "RollerMMSType", RollerMMSTypes, (PetscEnum)ctx->init.mms, (PetscEnum *)&ctx->init.mms, NULL));
  PetscCall(PetscViewerDestroy(&ctx->init.mms_view));
  PetscCall(PetscOptionsViewer("-mms_view", "Where the L2 and H1 errors against the manufactured solution go at the end (default stdout; ascii:F:ascii_csv writes the CSV t,L2,H1)", NULL, &ctx->init.mms_view, &ctx->init.mms_format, NULL));
  PetscOptionsEnd();
  if (ctx->init.mms != ROLLER_MMS_NONE) ctx->init.type = ROLLER_IC_MMS; /* -mms implies its initial condition */
  PetscCheck(ctx->init.mode_index >= 0, ctx->comm, PETSC_ERR_USER_INPUT, "-initial_mode %" PetscInt_FMT ": a row of the eigenvalue CSV, must be >= 0", ctx->init.mode_index);
  RollerCheckOption(ctx->comm, "-ic_amplitude", ctx->init.amplitude, ctx->init.amplitude >= 0, ">= 0");
  PetscCheck(ctx->init.type != ROLLER_IC_MODE || ctx->init.mode_file[0], ctx->comm, PETSC_ERR_ARG_WRONG, "-initial_condition mode needs -initial_mode_file F.h5 (written by -modes -modes_output F.h5)");
  PetscCheck(ctx->init.type != ROLLER_IC_MMS || ctx->init.mms != ROLLER_MMS_NONE, ctx->comm, PETSC_ERR_ARG_INCOMP, "-initial_condition mms needs -mms linear or sine");
  PetscFunctionReturn(0);
}

/* xi^0 and xi^{-1} = xi^0 - dt eta^0 (docs/model.md section 2), and eta^0 itself (state.velocity: the one-step
   schemes start from it; the three-level ones replace it by (xi^0 - xi^{-1})/dt). */
PetscErrorCode RollerInitialState(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, &ctx->state.next));
  PetscCall(PetscObjectSetName((PetscObject)ctx->state.next, "displacement"));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.cur));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.prev));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.prev2));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.Kcur));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.Kprev));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.Kprev2));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.Mcur));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.velocity));
  PetscCall(PetscObjectSetName((PetscObject)ctx->state.velocity, "velocity"));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.rhs));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.load));
  PetscCall(VecDuplicate(ctx->state.next, &ctx->state.work));
  PetscCall(VecZeroEntries(ctx->state.velocity));
  switch (ctx->init.type) {
  case ROLLER_IC_REST:
    PetscCall(VecZeroEntries(ctx->state.cur));
    PetscCall(VecZeroEntries(ctx->state.prev));
    PetscCall(VecZeroEntries(ctx->state.prev2));
    break;
  case ROLLER_IC_BUMP: /* at rest: xi^{-2} = xi^{-1} = xi^0 */
    PetscCall(RollerMMSExact(ctx, 0.0, ctx->state.cur));
    PetscCall(VecCopy(ctx->state.cur, ctx->state.prev));
    PetscCall(VecCopy(ctx->state.cur, ctx->state.prev2));
    break;
  case ROLLER_IC_MODE:
    PetscCall(RollerInitialModeState(ctx));
    break;
  case ROLLER_IC_MMS: /* the exact solution at t = 0, -dt, -2 dt, and its velocity at 0 */
    PetscCall(RollerMMSExact(ctx, 0.0, ctx->state.cur));
    PetscCall(RollerMMSExact(ctx, -ctx->ts.dt, ctx->state.prev));
    PetscCall(RollerMMSExact(ctx, -2.0 * ctx->ts.dt, ctx->state.prev2));
    PetscCall(RollerMMSVelocity(ctx, 0.0, ctx->state.velocity));
    break;
  }
  PetscCall(MatMult(ctx->ops.K, ctx->state.cur, ctx->state.Kcur));
  PetscCall(MatMult(ctx->ops.K, ctx->state.prev, ctx->state.Kprev));
  PetscCall(MatMult(ctx->ops.K, ctx->state.prev2, ctx->state.Kprev2));
  ctx->state.step          = 0;
  ctx->state.time          = 0.0;
  ctx->state.work_step     = 0;
  ctx->state.momentum_step = -1;
  ctx->state.info_step     = -1;
  for (PetscInt i = 0; i < 3; ++i) ctx->state.works[i] = 0.0;
  PetscFunctionReturn(0);
}

/* The errors of the newest level against the manufactured solution at the end of the run. */
static PetscErrorCode MonitorMMSErrors(Roller ctx, RollerMonitorEvent event, void *mctx)
{
  PetscViewer viewer = ctx->init.mms_view ? ctx->init.mms_view : PETSC_VIEWER_STDOUT_(ctx->comm);
  PetscReal   l2, h1;
  PetscBool   ascii;

  PetscFunctionBeginUser;
  if (event != ROLLER_MONITOR_FINAL) PetscFunctionReturn(0);
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  PetscCheck(ascii, ctx->comm, PETSC_ERR_SUP, "-mms_view: only ASCII viewers (stdout, or ascii:F[:ascii_csv])");
  PetscCall(RollerComputeErrors(ctx, ctx->state.time, &l2, &h1));
  if (ctx->init.mms_view && ctx->init.mms_format == PETSC_VIEWER_ASCII_CSV) PetscCall(PetscViewerASCIIPrintf(viewer, "t,L2,H1\n%.17g,%.17g,%.17g\n", (double)ctx->state.time, (double)l2, (double)h1));
  else PetscCall(PetscViewerASCIIPrintf(viewer, "mms: t %.17g L2 %.17g H1 %.17g\n", (double)ctx->state.time, (double)l2, (double)h1));
  PetscCall(PetscViewerFlush(viewer));
  PetscFunctionReturn(0);
}

/* With -mms, the error report at the end. */
PetscErrorCode RollerInitialMonitorSetUp(Roller ctx)
{
  PetscFunctionBeginUser;
  if (ctx->init.mms != ROLLER_MMS_NONE) PetscCall(RollerMonitorSet(ctx, MonitorMMSErrors, NULL, NULL));
  PetscFunctionReturn(0);
}
