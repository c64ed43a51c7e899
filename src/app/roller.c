/* The life of a Roller context: set up every component in order, each setting its observers of the run, and
   destroy them all. */
#include "integrate/integrate.h"
#include "modes/modes.h"
#include "rom/rom.h"

PetscErrorCode RollerSetUp(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_SETUP]));
  PetscCall(RollerMeshCreate(ctx));
  PetscCall(RollerMeshDistribute(ctx));
  PetscCall(RollerSchemeChoose(ctx)); /* the scheme and its dt: after the mesh (a mesh file's radii) */
  PetscCall(RollerGeometrySetUp(ctx));
  PetscCall(RollerDiscretizationSetUp(ctx));
  PetscCall(RollerOperatorsSetUp(ctx));
  PetscCall(RollerAxleSetUp(ctx));
  PetscCall(RollerComputeBoundaryFunctionals(ctx));
  if (!ctx->eig.on) PetscCall(RollerCheckRotation(ctx)); /* the time step's limit; -modes maps past the critical speeds */
  PetscCall(RollerInitialState(ctx));
  if (ctx->ck.restart[0]) PetscCall(RollerCheckpointRead(ctx, ctx->ck.restart));
  if (ctx->obstacle.on && !ctx->eig.on) PetscCall(RollerContactCreate(ctx, &ctx->contact)); /* -modes: its own steady contact (modes/steady.c) */
  else {
    PetscBool help;

    PetscCall(PetscOptionsHasHelp(NULL, &help));
    if (help) PetscCall(RollerContactHelp(ctx)); /* -help lists every option, the contact ones too */
  }
  if (ctx->rom) PetscCall(RollerRomSetUp(ctx)); /* the reduced model replaces the operators and the state */
  if (!ctx->eig.on) {                           /* the step matrices (the contact's condensation with them), and what the scheme and the components keep */
    PetscCall(RollerSchemeSetUp(ctx));
    PetscCall(RollerCheckpointRegister(ctx));
    if (ctx->ck.restart[0]) PetscCall(RollerCheckpointReadItems(ctx, ctx->ck.restart));
  }
  /* The observers, in the order they see every state: the console lines, the outputs (CSV, fields), the
     periodic checkpoint (after the outputs: a restart continues after the CSV row of its step), the MMS errors */
  { /* a typo refused before any output file is opened (the outputs' options read, not yet acted on) */
    char      csv[PETSC_MAX_PATH_LEN], h5[PETSC_MAX_PATH_LEN];
    PetscInt  every;
    PetscReal start;
    PetscBool help;

    PetscCall(PetscOptionsHasHelp(NULL, &help));
    if (!ctx->eig.on && !help) PetscCall(RollerOutputSetFromOptions(ctx, csv, h5, sizeof(csv), &every, &start));
    PetscCall(RollerOptionsCheck(ctx->comm, PETSC_FALSE));
  }
  if (!ctx->eig.on) {
    PetscCall(RollerTimeStepMonitorSetUp(ctx));
    PetscCall(RollerOutputMonitorSetUp(ctx));
    PetscCall(RollerCheckpointMonitorSetUp(ctx));
    PetscCall(RollerInitialMonitorSetUp(ctx));
  }
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

/* The run: the time loop (integrate/driver.c), or with -modes the eigenproblem (modes/modes.c). */
PetscErrorCode RollerSolve(Roller ctx)
{
  PetscFunctionBeginUser;
  if (ctx->eig.on) PetscCall(RollerModesSolve(ctx));
  else PetscCall(RollerRun(ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerDestroy(Roller *roller)
{
  Roller ctx = *roller;

  PetscFunctionBeginUser;
  if (!ctx) PetscFunctionReturn(0);
  PetscCall(RollerMonitorCancel(ctx));
  PetscCall(PetscViewerDestroy(&ctx->init.mms_view));
  PetscCall(RollerContactDestroy(&ctx->contact));
  PetscCall(RollerModesDestroy(ctx));
  PetscCall(RollerRomDestroy(ctx));
  PetscCall(RollerFrictionTableDestroy(&ctx->obstacle.table));
  PetscCall(RollerSchemesDestroy(ctx));
  PetscCall(RollerAxleDestroy(ctx));
  PetscCall(MatDestroy(&ctx->ops.M));
  PetscCall(MatDestroy(&ctx->ops.K));
  PetscCall(MatDestroy(&ctx->ops.Kd));
  PetscCall(MatDestroy(&ctx->ops.G));
  PetscCall(VecDestroy(&ctx->ops.L_euler));
  PetscCall(VecDestroy(&ctx->ops.L_centrifugal));
  PetscCall(VecDestroy(&ctx->ops.coordinates));
  PetscCall(VecDestroy(&ctx->state.next));
  PetscCall(VecDestroy(&ctx->state.cur));
  PetscCall(VecDestroy(&ctx->state.prev));
  PetscCall(VecDestroy(&ctx->state.prev2));
  PetscCall(VecDestroy(&ctx->state.Kcur));
  PetscCall(VecDestroy(&ctx->state.Kprev));
  PetscCall(VecDestroy(&ctx->state.Kprev2));
  PetscCall(VecDestroy(&ctx->state.Mcur));
  PetscCall(VecDestroy(&ctx->state.velocity));
  PetscCall(VecDestroy(&ctx->state.rhs));
  PetscCall(VecDestroy(&ctx->state.load));
  PetscCall(VecDestroy(&ctx->state.work));
  PetscCall(VecDestroy(&ctx->ops.w_R));
  PetscCall(VecDestroy(&ctx->ops.w_alpha));
  PetscCall(DMDestroy(&ctx->init.dm));
  PetscCall(DMDestroy(&ctx->mesh.dm_view));
  PetscCall(DMDestroy(&ctx->mesh.dm));
  PetscCall(PetscFree(ctx));
  *roller = NULL;
  PetscFunctionReturn(0);
}
