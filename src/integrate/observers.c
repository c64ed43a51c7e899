/* The observers of the run that write files (docs/output.md): the monitor CSV and the HDF5 fields. The writers are
   the io layer's; each observer asks for the step's diagnostics (RollerStepInfoGet) when it writes them, and
   completes its files at the successful end (ROLLER_MONITOR_FINAL). A restart continues after its step: the state
   it starts from is already in the files. */
#include "integrate/integrate.h"

/* -monitor_csv: a row for every state, the rename at the end. */
static PetscErrorCode MonitorCsv(Roller ctx, RollerMonitorEvent event, void *mctx)
{
  RollerCsv csv = (RollerCsv)mctx;
  PetscReal theta;

  PetscFunctionBeginUser;
  if (event == ROLLER_MONITOR_INITIAL && ctx->ck.restart[0]) PetscFunctionReturn(0);
  if (event == ROLLER_MONITOR_FINAL) {
    PetscCall(RollerCsvClose(csv));
    PetscFunctionReturn(0);
  }
  PetscCall(RollerStepInfoGet(ctx));
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_OUTPUT]));
  RollerTheta(ctx, ctx->state.time, &theta, NULL, NULL);
  PetscCall(RollerCsvRow(csv, ctx->state.step, ctx->state.time, &ctx->info, theta));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

static PetscErrorCode MonitorCsvDestroy(void **mctx)
{
  PetscFunctionBeginUser;
  PetscCall(RollerCsvDestroy((RollerCsv *)mctx));
  PetscFunctionReturn(0);
}

/* -output: the diagnostics of every state (the HDF5 file's series), the fields every -output_every steps, the files
   completed at the end. */
static PetscErrorCode MonitorFields(Roller ctx, RollerMonitorEvent event, void *mctx)
{
  RollerOutput out = (RollerOutput)mctx;

  PetscFunctionBeginUser;
  if (event == ROLLER_MONITOR_INITIAL && ctx->ck.restart[0]) PetscFunctionReturn(0);
  if (event == ROLLER_MONITOR_FINAL) {
    PetscCall(RollerFieldsClose(ctx, out));
    PetscFunctionReturn(0);
  }
  PetscCall(RollerStepInfoGet(ctx));
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_OUTPUT]));
  PetscCall(RollerFieldsStep(ctx, out));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

static PetscErrorCode MonitorFieldsDestroy(void **mctx)
{
  PetscFunctionBeginUser;
  PetscCall(RollerFieldsDestroy((RollerOutput *)mctx));
  PetscFunctionReturn(0);
}

/* The outputs the options ask for, each an observer of the run. After a restart has read its step, so that the CSV
   continues it. */
PetscErrorCode RollerOutputMonitorSetUp(Roller ctx)
{
  char      csv[PETSC_MAX_PATH_LEN], h5[PETSC_MAX_PATH_LEN];
  PetscInt  every;
  PetscReal start;

  PetscFunctionBeginUser;
  PetscCall(RollerOutputSetFromOptions(ctx, csv, h5, sizeof(csv), &every, &start));
  if (csv[0]) {
    RollerCsv writer;

    PetscCall(RollerCsvOpen(ctx->comm, csv, ctx->ck.restart[0] ? ctx->state.step : -1, &writer));
    PetscCall(RollerMonitorSet(ctx, MonitorCsv, writer, MonitorCsvDestroy));
  }
  if (h5[0]) {
    RollerOutput out;

    PetscCall(RollerFieldsCreate(ctx, h5, every, start, &out));
    PetscCall(RollerMonitorSet(ctx, MonitorFields, out, MonitorFieldsDestroy));
  }
  PetscCall(RollerSurfaceMonitorSetUp(ctx));
  PetscFunctionReturn(0);
}
