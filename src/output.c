/* What a run leaves behind (SPEC section 6): the monitor CSV, one row per step, and the fields every N
   steps to HDF5 with an XDMF index so ParaView opens it directly. Output is what was asked: without
   -monitor_csv no CSV, without -output no field is computed. */
#include <roller_impl.h>
#include <petscviewerhdf5.h>
#include "kernels.h"

struct _n_RollerOutput {
  char        csv_path[PETSC_MAX_PATH_LEN], h5_path[PETSC_MAX_PATH_LEN];
  FILE       *csv;
  PetscInt    every, written;
  PetscViewer h5;
  DM          sdm; /* scalar P1 space for |sigma| */
  Vec         lab, velocity, stress, displacement;
};

PetscErrorCode RollerOutputCreate(Roller ctx, RollerOutput *output)
{
  RollerOutput out;
  PetscBool    has_csv = PETSC_FALSE, has_h5 = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&out));
  out->every = 10;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: output", NULL);
  PetscCall(PetscOptionsString("-monitor_csv", "One CSV row per step: step,t,R,alpha,energy,contact_nodes,contact_force,gap_min,...", NULL, out->csv_path, out->csv_path, sizeof(out->csv_path), &has_csv));
  PetscCall(PetscOptionsString("-output", "Fields to this HDF5 file (and an XDMF file beside it)", NULL, out->h5_path, out->h5_path, sizeof(out->h5_path), &has_h5));
  PetscCall(PetscOptionsInt("-output_every", "Write fields every N steps", NULL, out->every, &out->every, NULL));
  PetscOptionsEnd();
  PetscCheck(out->every > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-output_every %" PetscInt_FMT " must be > 0", out->every);
  if (has_csv && out->csv_path[0]) {
    PetscCall(PetscFOpen(ctx->comm, out->csv_path, "w", &out->csv));
    PetscCall(PetscFPrintf(ctx->comm, out->csv, "step,t,R,alpha,energy,contact_nodes,contact_force,gap_min,qp_iterations,kkt_residual,theta\n"));
  }
  if (has_h5 && out->h5_path[0]) {
    PetscFE fe;
    PetscDS ds, sds;
    PetscInt nc;
    const PetscScalar *constants;

    PetscCall(PetscViewerHDF5Open(ctx->comm, out->h5_path, FILE_MODE_WRITE, &out->h5));
    PetscCall(DMView(ctx->dm, out->h5));
    PetscCall(DMClone(ctx->dm, &out->sdm));
    PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 2, 1, PETSC_TRUE, 1, 2, &fe));
    PetscCall(PetscObjectSetName((PetscObject)fe, "stress_norm"));
    PetscCall(DMSetField(out->sdm, 0, NULL, (PetscObject)fe));
    PetscCall(PetscFEDestroy(&fe));
    PetscCall(DMCreateDS(out->sdm));
    PetscCall(DMGetDS(ctx->dm, &ds));
    PetscCall(DMGetDS(out->sdm, &sds));
    PetscCall(PetscDSGetConstants(ds, &nc, &constants));
    PetscCall(PetscDSSetConstants(sds, nc, (PetscScalar *)constants));
    PetscCall(DMCreateGlobalVector(out->sdm, &out->stress));
    PetscCall(PetscObjectSetName((PetscObject)out->stress, "stress_norm"));
    PetscCall(DMCreateGlobalVector(ctx->dm, &out->displacement));
    PetscCall(PetscObjectSetName((PetscObject)out->displacement, "displacement"));
    PetscCall(VecDuplicate(out->displacement, &out->lab));
    PetscCall(PetscObjectSetName((PetscObject)out->lab, "displacement_lab"));
    PetscCall(VecDuplicate(out->displacement, &out->velocity));
    PetscCall(PetscObjectSetName((PetscObject)out->velocity, "velocity"));
  }
  *output = out;
  PetscFunctionReturn(0);
}

/* Lab-frame displacement R(theta)(x + xi) - x at every node. */
static PetscErrorCode LabDisplacement(Roller ctx, PetscReal theta, Vec xi, Vec lab)
{
  const PetscScalar *x, *u;
  PetscScalar       *l;
  PetscInt           n;
  const PetscReal    c = PetscCosReal(theta), s = PetscSinReal(theta);

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(xi, &n));
  PetscCall(VecGetArrayRead(ctx->coordinates, &x));
  PetscCall(VecGetArrayRead(xi, &u));
  PetscCall(VecGetArrayWrite(lab, &l));
  for (PetscInt i = 0; i < n; i += 2) {
    const PetscScalar p0 = x[i] + u[i], p1 = x[i + 1] + u[i + 1];
    l[i]     = c * p0 - s * p1 - x[i];
    l[i + 1] = s * p0 + c * p1 - x[i + 1];
  }
  PetscCall(VecRestoreArrayRead(ctx->coordinates, &x));
  PetscCall(VecRestoreArrayRead(xi, &u));
  PetscCall(VecRestoreArrayWrite(lab, &l));
  PetscFunctionReturn(0);
}

static PetscErrorCode WriteFields(Roller ctx, RollerOutput out)
{
  void (*funcs[1])(PetscInt, PetscInt, PetscInt, const PetscInt[], const PetscInt[], const PetscScalar[], const PetscScalar[], const PetscScalar[], const PetscInt[], const PetscInt[], const PetscScalar[], const PetscScalar[], const PetscScalar[], PetscReal, const PetscReal[], PetscInt, const PetscScalar[], PetscScalar[]) = {f_stress_norm};
  PetscReal theta;

  PetscFunctionBeginUser;
  RollerTheta(ctx, ctx->time, &theta, NULL, NULL);
  PetscCall(VecCopy(ctx->xi1, out->displacement));
  PetscCall(LabDisplacement(ctx, theta, ctx->xi1, out->lab));
  PetscCall(VecWAXPY(out->velocity, -1.0, ctx->xi2, ctx->xi1));
  PetscCall(VecScale(out->velocity, 1.0 / ctx->dt));
  PetscCall(DMProjectField(out->sdm, ctx->time, out->displacement, funcs, INSERT_VALUES, out->stress));
  PetscCall(DMSetOutputSequenceNumber(ctx->dm, out->written, ctx->time));
  PetscCall(DMSetOutputSequenceNumber(out->sdm, out->written, ctx->time));
  PetscCall(VecView(out->displacement, out->h5));
  PetscCall(VecView(out->lab, out->h5));
  PetscCall(VecView(out->velocity, out->h5));
  PetscCall(VecView(out->stress, out->h5));
  out->written++;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerOutputStep(Roller ctx, RollerOutput out)
{
  const RollerStepInfo *info = &ctx->info;
  PetscReal             theta;

  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_OUTPUT]));
  if (out->csv) {
    RollerTheta(ctx, ctx->time, &theta, NULL, NULL);
    PetscCall(PetscFPrintf(ctx->comm, out->csv, "%" PetscInt_FMT ",%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%.17g,%.17g,%" PetscInt_FMT ",%.17g,%.17g\n", ctx->step, (double)ctx->time, (double)info->R, (double)info->alpha, (double)info->energy, info->contact_nodes, (double)info->contact_force, (double)info->gap_min, info->qp_iterations, (double)info->kkt_residual, (double)theta));
  }
  if (out->h5 && ctx->step % out->every == 0) PetscCall(WriteFields(ctx, out));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

PetscErrorCode RollerOutputDestroy(Roller ctx, RollerOutput *output)
{
  RollerOutput out = *output;

  PetscFunctionBeginUser;
  if (!out) PetscFunctionReturn(0);
  if (out->csv) PetscCall(PetscFClose(ctx->comm, out->csv));
  PetscCall(PetscViewerDestroy(&out->h5));
  PetscCall(VecDestroy(&out->lab));
  PetscCall(VecDestroy(&out->velocity));
  PetscCall(VecDestroy(&out->stress));
  PetscCall(VecDestroy(&out->displacement));
  PetscCall(DMDestroy(&out->sdm));
  PetscCall(PetscFree(out));
  *output = NULL;
  PetscFunctionReturn(0);
}
