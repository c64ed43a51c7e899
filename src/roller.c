/* The life of a Roller context: set up every component in order, destroy them all. */
#include <roller_impl.h>

PetscErrorCode RollerSetUp(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_SETUP]));
  PetscCall(RollerMeshCreate(ctx));
  PetscCall(RollerMeshDistribute(ctx));
  PetscCall(RollerChooseTimeStep(ctx));
  PetscCall(RollerGeometrySetUp(ctx));
  PetscCall(RollerDiscretizationSetUp(ctx));
  PetscCall(RollerOperatorsSetUp(ctx));
  PetscCall(RollerComputeBoundaryFunctionals(ctx));
  PetscCall(RollerCheckRotation(ctx));
  PetscCall(RollerInitialState(ctx));
  if (ctx->restart[0]) PetscCall(RollerCheckpointRead(ctx, ctx->restart));
  if (ctx->obstacle) PetscCall(RollerContactCreate(ctx, &ctx->contact));
  else {
    PetscBool help;

    PetscCall(PetscOptionsHasHelp(NULL, &help));
    if (help) PetscCall(RollerContactHelp(ctx)); /* -help lists every option, the contact ones too */
  }
  PetscCall(RollerOutputCreate(ctx, &ctx->output));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

PetscErrorCode RollerDestroy(Roller *roller)
{
  Roller ctx = *roller;

  PetscFunctionBeginUser;
  if (!ctx) PetscFunctionReturn(0);
  PetscCall(RollerOutputDestroy(ctx, &ctx->output));
  PetscCall(RollerContactDestroy(&ctx->contact));
  PetscCall(KSPDestroy(&ctx->ksp));
  PetscCall(MatDestroy(&ctx->M));
  PetscCall(MatDestroy(&ctx->K));
  PetscCall(MatDestroy(&ctx->A));
  PetscCall(MatDestroy(&ctx->A0));
  PetscCall(MatDestroy(&ctx->G));
  PetscCall(VecDestroy(&ctx->L_euler));
  PetscCall(VecDestroy(&ctx->L_centrifugal));
  PetscCall(VecDestroy(&ctx->coordinates));
  PetscCall(VecDestroy(&ctx->xi));
  PetscCall(VecDestroy(&ctx->xi1));
  PetscCall(VecDestroy(&ctx->xi2));
  PetscCall(VecDestroy(&ctx->xi3));
  PetscCall(VecDestroy(&ctx->Kxi1));
  PetscCall(VecDestroy(&ctx->Kxi2));
  PetscCall(VecDestroy(&ctx->rhs));
  PetscCall(VecDestroy(&ctx->work));
  PetscCall(VecDestroy(&ctx->w_R));
  PetscCall(VecDestroy(&ctx->w_alpha));
  PetscCall(DMDestroy(&ctx->dm_view));
  PetscCall(DMDestroy(&ctx->dm));
  PetscCall(PetscFree(ctx));
  *roller = NULL;
  PetscFunctionReturn(0);
}
