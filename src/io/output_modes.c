/* The mode shapes of -modes (-modes_output F.h5, docs/squeal.md): the straight-sided mesh, every mode's real and
   imaginary parts at the vertices (mode_re, mode_im: P1, 3 components, as /vertex_fields series indexed by the
   mode, whose XDMF "time" is the mode's row in the eigenvalue CSV), the eigenvalues (/modes attributes re, im,
   order), the run's /parameters (with -rubber maxwell its branches maxwell_tau_i, maxwell_weight_i), and the full FE vectors shape_<j>_re, shape_<j>_im (and with -obstacle the
   steady state, steady) that -initial_condition mode reads back. Written as F.part and renamed when complete; the index F.xmf beside it. */
#include "output.h"

PetscErrorCode RollerModeShapesWrite(Roller ctx, const char path[], PetscInt n, const PetscReal re[], const PetscReal im[], const PetscInt order[], Vec xr[], Vec xi[], Vec steady)
{
  struct _n_RollerOutput out;
  PetscBool              has;
  DM                     vdm;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&out, sizeof(out)));
  PetscCall(PetscStrncpy(out.h5_path, path, sizeof(out.h5_path)));
  PetscCall(RollerXdmfPaths(&out));
  PetscCall(RollerJoinPath(out.h5_part, sizeof(out.h5_part), path, ".part", "-modes_output"));
  PetscCall(RollerRemoveStale(ctx->comm, out.h5_path));
  PetscCall(RollerRemoveStale(ctx->comm, out.xdmf.path));
  PetscCall(RollerCheckWritable(ctx->comm, "-modes_output", out.h5_part));
  PetscCall(PetscViewerHDF5Open(ctx->comm, out.h5_part, FILE_MODE_WRITE, &out.h5));
  PetscCall(DMView(ctx->mesh.dm_view, out.h5));
  PetscCall(RollerWriteParameters(ctx, out.h5));
  PetscCall(PetscViewerHDF5HasDataset(out.h5, "/viz/geometry/vertices", &has));
  PetscCall(RollerDatasetQuery(out.h5, has ? "/viz/geometry/vertices" : "/geometry/vertices", &out.xdmf.vertices));
  PetscCall(RollerDatasetQuery(out.h5, "/viz/topology/cells", &out.xdmf.cells));
  PetscCall(RollerOutputSpace(ctx, 3, "shape", &vdm));
  out.vdm = vdm;
  PetscCall(RollerFieldCreate(vdm, "mode_re", &out.field[0]));
  PetscCall(RollerFieldCreate(vdm, "mode_im", &out.field[1]));
  out.nfields = 2;
  PetscCall(PetscMalloc1(PetscMax(n, 1), &out.xdmf.times));
  for (PetscInt j = 0; j < n; ++j) {
    char name[64];

    PetscCall(RollerProjectAtVertices(ctx, xr[j], RollerPadVector, INSERT_VALUES, out.field[0].vec));
    PetscCall(RollerProjectAtVertices(ctx, xi[j], RollerPadVector, INSERT_VALUES, out.field[1].vec));
    PetscCall(DMSetOutputSequenceNumber(vdm, j, (PetscReal)j));
    PetscCall(VecView(out.field[0].vec, out.h5));
    PetscCall(VecView(out.field[1].vec, out.h5));
    out.xdmf.times[out.xdmf.written++] = j;
    PetscCall(PetscSNPrintf(name, sizeof(name), "shape_%" PetscInt_FMT "_re", j));
    PetscCall(RollerPlainVecView(xr[j], name, out.h5, PETSC_FALSE));
    PetscCall(PetscSNPrintf(name, sizeof(name), "shape_%" PetscInt_FMT "_im", j));
    PetscCall(RollerPlainVecView(xi[j], name, out.h5, PETSC_FALSE));
  }
  {
    const PetscReal frame = ctx->eig.frame;

    PetscCall(PetscViewerHDF5WriteAttribute(out.h5, "/parameters", "modes", PETSC_INT, &n));
    PetscCall(PetscViewerHDF5WriteAttribute(out.h5, "/parameters", "modes_frame", PETSC_REAL, &frame));
    if (ctx->eig.skew_defect[0] >= 0) PetscCall(PetscViewerHDF5WriteAttribute(out.h5, "/parameters", "skew_defect_A_L", PETSC_REAL, &ctx->eig.skew_defect[0]));
    if (ctx->eig.skew_defect[1] >= 0) PetscCall(PetscViewerHDF5WriteAttribute(out.h5, "/parameters", "skew_defect_B_L", PETSC_REAL, &ctx->eig.skew_defect[1]));
    if (ctx->material.rubber == ROLLER_RUBBER_MAXWELL) { /* the rubber the modes are of: the branches, given or fitted */
      PetscCall(PetscViewerHDF5WriteAttribute(out.h5, "/parameters", "maxwell_branches", PETSC_INT, &ctx->material.nbranch));
      for (PetscInt i = 0; i < ctx->material.nbranch; ++i) {
        char name[32];

        PetscCall(PetscSNPrintf(name, sizeof(name), "maxwell_tau_%" PetscInt_FMT, i));
        PetscCall(PetscViewerHDF5WriteAttribute(out.h5, "/parameters", name, PETSC_REAL, &ctx->material.tau[i]));
        PetscCall(PetscSNPrintf(name, sizeof(name), "maxwell_weight_%" PetscInt_FMT, i));
        PetscCall(PetscViewerHDF5WriteAttribute(out.h5, "/parameters", name, PETSC_REAL, &ctx->material.g[i]));
      }
    }
  }
  if (steady) PetscCall(RollerPlainVecView(steady, "steady", out.h5, PETSC_FALSE)); /* the state the modes linearize about (lab frame) */
  if (n) {
    for (PetscInt j = 0; j < n; ++j) {
      char group[64];

      PetscCall(PetscSNPrintf(group, sizeof(group), "/modes/%" PetscInt_FMT, j));
      PetscCall(PetscViewerHDF5WriteAttribute(out.h5, group, "re", PETSC_REAL, &re[j]));
      PetscCall(PetscViewerHDF5WriteAttribute(out.h5, group, "im", PETSC_REAL, &im[j]));
      PetscCall(PetscViewerHDF5WriteAttribute(out.h5, group, "order", PETSC_INT, &order[j]));
    }
    PetscCall(RollerLayoutUpdate(&out));
  }
  PetscCall(PetscViewerDestroy(&out.h5));
  PetscCall(RollerRenameFile(ctx->comm, out.h5_part, out.h5_path));
  if (n) PetscCall(RollerXdmfWrite(ctx->comm, &out, out.h5_path, out.xdmf.path));
  PetscCall(VecDestroy(&out.field[0].vec));
  PetscCall(VecDestroy(&out.field[1].vec));
  PetscCall(DMDestroy(&vdm));
  PetscCall(PetscFree(out.xdmf.times));
  PetscFunctionReturn(0);
}

/* Mode j of a -modes_output file, for -initial_condition mode, in one opening: the frame it was computed in, its
   eigenvalue and shape, and (lab-frame squeal modes) the steady state in steady (*has_steady false, steady untouched,
   without one). The file must be readable and describe this run's roller (RollerCheckParameters). */
PetscErrorCode RollerModeFileRead(Roller ctx, const char path[], PetscInt j, RollerFrame *frame, PetscReal *re, PetscReal *im, Vec xr, Vec xi, Vec steady, PetscBool *has_steady)
{
  PetscViewer h5;
  PetscInt    n = 0;
  PetscReal   f = ROLLER_FRAME_ROTATING;
  PetscBool   has;
  char        name[64];

  PetscFunctionBeginUser;
  PetscCall(PetscTestFile(path, 'r', &has));
  PetscCheck(has, ctx->comm, PETSC_ERR_FILE_OPEN, "-initial_mode_file %s: no such readable file (write one with -modes -modes_output)", path);
  PetscCall(RollerHDF5Probe(ctx->comm, "-initial_mode_file", path));
  PetscCall(PetscViewerHDF5Open(ctx->comm, path, FILE_MODE_READ, &h5));
  PetscCall(RollerCheckParameters(ctx, h5, "-initial_mode_file", path));
  PetscCall(PetscViewerHDF5HasAttribute(h5, "/parameters", "modes_frame", &has));
  if (has) PetscCall(PetscViewerHDF5ReadAttribute(h5, "/parameters", "modes_frame", PETSC_REAL, NULL, &f));
  *frame = (RollerFrame)(PetscInt)f;
  PetscCall(PetscViewerHDF5HasAttribute(h5, "/parameters", "modes", &has));
  if (has) PetscCall(PetscViewerHDF5ReadAttribute(h5, "/parameters", "modes", PETSC_INT, NULL, &n));
  PetscCheck(j >= 0 && j < n, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-initial_mode %" PetscInt_FMT ": %s has modes 0..%" PetscInt_FMT, j, path, n - 1);
  PetscCall(PetscSNPrintf(name, sizeof(name), "/modes/%" PetscInt_FMT, j));
  PetscCall(PetscViewerHDF5ReadAttribute(h5, name, "re", PETSC_REAL, NULL, re));
  PetscCall(PetscViewerHDF5ReadAttribute(h5, name, "im", PETSC_REAL, NULL, im));
  PetscCall(PetscSNPrintf(name, sizeof(name), "shape_%" PetscInt_FMT "_re", j));
  PetscCall(RollerPlainVecView(xr, name, h5, PETSC_TRUE));
  PetscCall(PetscSNPrintf(name, sizeof(name), "shape_%" PetscInt_FMT "_im", j));
  PetscCall(RollerPlainVecView(xi, name, h5, PETSC_TRUE));
  PetscCall(PetscViewerHDF5HasDataset(h5, "/steady", has_steady));
  if (*has_steady) PetscCall(RollerPlainVecView(steady, "steady", h5, PETSC_TRUE));
  PetscCall(PetscViewerDestroy(&h5));
  PetscFunctionReturn(0);
}
