/* What a run leaves behind (docs/model.md section 6, docs/output.md): the monitor CSV, one row per step, and the
   fields every N steps to HDF5 with an XDMF index so ParaView opens it directly. Output is what was
   asked: without -monitor_csv no CSV, without -output no field is computed.

   This layer writes; the observers of the run that call the writers are the driver's (integrate/observers.c). The
   options are read here (RollerOutputSetFromOptions): the CSV (output_csv.c) and the fields (this file). A run that
   fails must not leave output that looks complete:
   the files are written as F.part (CSV and HDF5) and <base>.part.xmf (the index) and renamed to F and
   <base>.xmf at the end of the run (ROLLER_MONITOR_FINAL), which only a successful run reaches. After every field write the HDF5 file is flushed and the new step appended to
   the index in place (XdmfAppend: written once, not rewritten, so N steps cost O(N)), so a killed run
   still has a readable F.part indexed up to its last written step; the final <base>.xmf is written whole
   once, at the end.

   The fields are written at the mesh vertices (P1), vectors with a zero third component: ParaView's
   vector filters (Warp By Vector, Glyph) need 3-component vectors, and the XDMF Function "JOIN" that
   would pad a 2-component dataset is read differently by the Xdmf2 (interlaces) and Xdmf3 (concatenates)
   readers, so the padding is in the data, where every reader agrees. */
#include "output.h"
#include "model/kernels.h"

/* Projection kernels (DMProjectField evaluates them at the vertices). */
void RollerPadVector(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[])
{
  f[0] = u[0];
  f[1] = u[1];
  f[2] = 0.0;
}

static void f_one(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[])
{
  f[0] = 1.0;
}

/* Evaluate a kernel of the field u (on ctx->mesh.dm) at the vertices of the output space of X. ADD_VALUES sums
   over the cells around each vertex (then divided by their number: a derivative such as sigma is
   discontinuous across cells and its vertex value is the mean of the cells' values). */
PetscErrorCode RollerProjectAtVertices(Roller ctx, Vec u, RollerPointFunc kernel, InsertMode mode, Vec X)
{
  RollerPointFunc funcs[1] = {kernel};
  DM              dm;
  Vec             ul, Xl;

  PetscFunctionBeginUser;
  PetscCall(VecGetDM(X, &dm));
  PetscCall(DMGetLocalVector(ctx->mesh.dm, &ul));
  PetscCall(DMGetLocalVector(dm, &Xl));
  /* the Dirichlet dofs are not in the global vector: set them (xi = 0, and so xi_t = 0, on Gamma_D) */
  PetscCall(DMPlexInsertBoundaryValues(ctx->mesh.dm, PETSC_TRUE, ul, ctx->state.time, NULL, NULL, NULL));
  PetscCall(DMGlobalToLocal(ctx->mesh.dm, u, INSERT_VALUES, ul));
  PetscCall(VecZeroEntries(Xl));
  PetscCall(DMProjectFieldLocal(dm, ctx->state.time, ul, funcs, mode, Xl));
  PetscCall(VecZeroEntries(X));
  PetscCall(DMLocalToGlobal(dm, Xl, mode, X));
  PetscCall(DMRestoreLocalVector(dm, &Xl));
  PetscCall(DMRestoreLocalVector(ctx->mesh.dm, &ul));
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------
   Set-up */

/* A P1 space on the mesh of ctx->mesh.dm with nc components, its field named name (PETSc names the vertex
   datasets <vec>_<field>). */
PetscErrorCode RollerOutputSpace(Roller ctx, PetscInt nc, const char name[], DM *dm)
{
  PetscFE fe;

  PetscFunctionBeginUser;
  PetscCall(DMClone(ctx->mesh.dm, dm));
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 2, nc, PETSC_TRUE, 1, PETSC_DETERMINE, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, name));
  PetscCall(DMSetField(*dm, 0, NULL, (PetscObject)fe));
  PetscCall(PetscFEDestroy(&fe));
  PetscCall(DMCreateDS(*dm));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerFieldCreate(DM dm, const char name[], OutputField *field)
{
  PetscSection section;
  const char  *fname;

  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(dm, &field->vec));
  PetscCall(PetscObjectSetName((PetscObject)field->vec, name));
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(PetscSectionGetFieldName(section, 0, &fname));
  PetscCall(PetscSNPrintf(field->data.path, sizeof(field->data.path), "/vertex_fields/%s_%s", name, fname));
  PetscFunctionReturn(0);
}

/* The run's parameters: written as attributes of /parameters (RollerWriteParameters), so that scripts
   (rollerplots.fields) need not be told; the physical ones (the roller, its material, rotation and friction) are those a
   file computed for another roller differs in (RollerCheckParameters). */
typedef struct {
  const char *name;
  PetscReal   value;
  PetscBool   physical;
} Parameter;

#define NUM_PARAMETERS 18

static void Parameters(Roller ctx, Parameter p[NUM_PARAMETERS])
{
  const Parameter all[NUM_PARAMETERS] = {
    {"r_inner",         ctx->mesh.r_inner,             PETSC_TRUE },
    {"r_outer",         ctx->mesh.r_outer,             PETSC_TRUE },
    {"young",           ctx->material.young,           PETSC_TRUE },
    {"poisson",         ctx->material.poisson,         PETSC_TRUE },
    {"density",         ctx->material.density,         PETSC_TRUE },
    {"viscosity",       ctx->material.viscosity,       PETSC_TRUE },
    {"omega",           ctx->rotation.omega,           PETSC_TRUE },
    {"theta_a",         ctx->rotation.a,               PETSC_FALSE},
    {"theta_b",         ctx->rotation.b,               PETSC_FALSE},
    {"theta_start",     ctx->rotation.start,           PETSC_FALSE},
    {"obstacle_speed",  ctx->obstacle.speed,           PETSC_FALSE},
    {"obstacle_depth",  ctx->obstacle.depth,           PETSC_FALSE},
    {"sheet_speed",     ctx->obstacle.sheet_speed,     PETSC_FALSE},
    {"friction",        ctx->obstacle.friction,        PETSC_TRUE },
    {"friction_static", ctx->obstacle.friction_static, PETSC_FALSE},
    {"friction_decay",  ctx->obstacle.friction_decay,  PETSC_FALSE},
    {"damping",         ctx->disc.damping,             PETSC_FALSE},
    {"dt",              ctx->ts.dt,                    PETSC_FALSE},
  };

  for (PetscInt i = 0; i < NUM_PARAMETERS; ++i) p[i] = all[i];
}

PetscErrorCode RollerWriteParameters(Roller ctx, PetscViewer h5)
{
  Parameter      p[NUM_PARAMETERS];
  const PetscInt obstacle = ctx->obstacle.on ? 1 : 0;

  PetscFunctionBeginUser;
  Parameters(ctx, p);
  for (PetscInt i = 0; i < NUM_PARAMETERS; ++i) PetscCall(PetscViewerHDF5WriteAttribute(h5, "/parameters", p[i].name, PETSC_REAL, &p[i].value));
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/parameters", "obstacle", PETSC_INT, &obstacle));
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/parameters", "degree", PETSC_INT, &ctx->disc.degree));
  /* the mesh as built (its accurate default follows -ts_max_time): what a later run on the same mesh, e.g. a
     transient seeded from a -modes_output file (rollerreport.run), gives as -mesh_h, -mesh_h_contact, -mesh_contact_layer */
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/parameters", "mesh_h", PETSC_REAL, &ctx->mesh.h));
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/parameters", "mesh_h_contact", PETSC_REAL, &ctx->mesh.h_contact));
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/parameters", "mesh_contact_layer", PETSC_REAL, &ctx->mesh.contact_layer));
  PetscFunctionReturn(0);
}

/* A file's physical parameters (its /parameters, where present) equal this run's (1e-12): an error naming the option
   that gave the file, the parameter and both values otherwise. */
PetscErrorCode RollerCheckParameters(Roller ctx, PetscViewer h5, const char option[], const char file[])
{
  Parameter p[NUM_PARAMETERS];

  PetscFunctionBeginUser;
  Parameters(ctx, p);
  for (PetscInt i = 0; i < NUM_PARAMETERS; ++i) {
    PetscReal v;
    PetscBool has;

    if (!p[i].physical) continue;
    PetscCall(PetscViewerHDF5HasAttribute(h5, "/parameters", p[i].name, &has));
    if (!has) continue;
    PetscCall(PetscViewerHDF5ReadAttribute(h5, "/parameters", p[i].name, PETSC_REAL, NULL, &v));
    PetscCheck(PetscAbsReal(v - p[i].value) <= 1e-12 * PetscMax(PetscAbsReal(v), PetscAbsReal(p[i].value)), ctx->comm, PETSC_ERR_ARG_INCOMP, "%s %s: it was computed with -%s %g, this run has -%s %g: give the same", option, file, p[i].name, (double)v,
               p[i].name, (double)p[i].value);
  }
  PetscFunctionReturn(0);
}

/* -output path, every N steps from the time start on: the HDF5 file (as path.part), the mesh, the parameters, the output spaces. */
PetscErrorCode RollerFieldsCreate(Roller ctx, const char path[], PetscInt every, PetscReal start, RollerOutput *output)
{
  PetscErrorCode (*position[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {RollerPosition};
  PetscBool    has;
  RollerOutput out;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&out));
  out->every   = every;
  out->start   = start;
  out->xdmf.fd = -1;
  PetscCall(PetscStrncpy(out->h5_path, path, sizeof(out->h5_path)));
  *output = out;
  PetscCall(RollerXdmfPaths(out));
  PetscCall(RollerJoinPath(out->h5_part, sizeof(out->h5_part), out->h5_path, ".part", "-output"));
  PetscCall(RollerRemoveStale(ctx->comm, out->h5_path));
  PetscCall(RollerRemoveStale(ctx->comm, out->xdmf.path));
  PetscCall(RollerRemoveStale(ctx->comm, out->xdmf.part)); /* would index the new file before it has a step */
  PetscCall(RollerCheckWritable(ctx->comm, "-output", out->h5_part));
  PetscCall(PetscViewerHDF5Open(ctx->comm, out->h5_part, FILE_MODE_WRITE, &out->h5));
  PetscCall(DMView(ctx->mesh.dm_view, out->h5)); /* straight-sided: XDMF draws linear triangles */
  PetscCall(RollerWriteParameters(ctx, out->h5));
  PetscCall(PetscViewerHDF5HasDataset(out->h5, "/viz/geometry/vertices", &has));
  PetscCall(RollerDatasetQuery(out->h5, has ? "/viz/geometry/vertices" : "/geometry/vertices", &out->xdmf.vertices));
  PetscCall(RollerDatasetQuery(out->h5, "/viz/topology/cells", &out->xdmf.cells));
  PetscCheck(out->xdmf.vertices.ndims == 2 && out->xdmf.cells.ndims == 2, ctx->comm, PETSC_ERR_LIB, "Unexpected mesh layout in %s", out->h5_part);

  PetscCall(RollerOutputSpace(ctx, 3, "displacement", &out->vdm));
  PetscCall(RollerOutputSpace(ctx, 1, "stress_norm", &out->sdm));
  PetscCall(RollerFieldCreate(out->vdm, "displacement", &out->field[FIELD_DISPLACEMENT]));
  PetscCall(RollerFieldCreate(out->vdm, "displacement_lab", &out->field[FIELD_LAB]));
  PetscCall(RollerFieldCreate(out->vdm, "velocity", &out->field[FIELD_VELOCITY]));
  PetscCall(RollerFieldCreate(out->sdm, "stress_norm", &out->field[FIELD_STRESS]));
  out->nfields = FIELD_STRESS + 1;
  if (ctx->contact) {
    PetscCall(RollerOutputSpace(ctx, 1, "contact_pressure", &out->pdm));
    PetscCall(RollerFieldCreate(out->pdm, "contact_pressure", &out->field[FIELD_CONTACT_PRESSURE]));
    out->nfields = FIELD_CONTACT_PRESSURE + 1;
  }
  if (RollerContactHasFriction(ctx->contact)) {
    PetscCall(RollerOutputSpace(ctx, 1, "contact_traction", &out->tdm));
    PetscCall(RollerOutputSpace(ctx, 1, "contact_state", &out->cdm));
    PetscCall(RollerFieldCreate(out->tdm, "contact_traction", &out->field[FIELD_CONTACT_TRACTION]));
    PetscCall(RollerFieldCreate(out->cdm, "contact_state", &out->field[FIELD_CONTACT_STATE]));
    out->nfields = FIELD_CONTACT_STATE + 1;
  }
  PetscCall(DMCreateGlobalVector(out->sdm, &out->count));
  PetscCall(DMCreateGlobalVector(out->vdm, &out->position));
  PetscCall(DMProjectFunction(out->vdm, 0.0, position, NULL, INSERT_VALUES, out->position));
  if (ctx->ops.V) { /* -rom: the fields of the full model's layout */
    PetscCall(DMCreateGlobalVector(ctx->mesh.dm, &out->xfull));
    PetscCall(VecDuplicate(out->xfull, &out->vfull));
  }
  PetscCall(RollerProjectAtVertices(ctx, out->xfull ? out->xfull : ctx->state.cur, f_one, ADD_VALUES, out->count));
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------
   Every step */

/* Lab-frame displacement phi(x) - x = R(theta)(x + xi) - x (docs/model.md section 1) at every vertex. */
static PetscErrorCode LabDisplacement(RollerOutput out, PetscReal theta, Vec xi, Vec lab)
{
  const PetscScalar *x, *u;
  PetscScalar       *l;
  PetscInt           n;
  const PetscReal    c = PetscCosReal(theta), s = PetscSinReal(theta);

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(xi, &n));
  PetscCall(VecGetArrayRead(out->position, &x));
  PetscCall(VecGetArrayRead(xi, &u));
  PetscCall(VecGetArrayWrite(lab, &l));
  for (PetscInt i = 0; i < n; i += 3) {
    const PetscScalar p0 = x[i] + u[i], p1 = x[i + 1] + u[i + 1];

    l[i]     = c * p0 - s * p1 - x[i];
    l[i + 1] = s * p0 + c * p1 - x[i + 1];
    l[i + 2] = 0.0;
  }
  PetscCall(VecRestoreArrayRead(out->position, &x));
  PetscCall(VecRestoreArrayRead(xi, &u));
  PetscCall(VecRestoreArrayWrite(lab, &l));
  PetscFunctionReturn(0);
}

static PetscErrorCode WriteFields(Roller ctx, RollerOutput out)
{
  PetscReal theta;
  Vec       xi = ctx->state.cur, v = ctx->state.velocity;

  PetscFunctionBeginUser;
  RollerTheta(ctx, ctx->state.time, &theta, NULL, NULL);
  if (out->xfull) { /* -rom: xi = V q + the residual at Gamma_C (exact there: the patch), v = V q' */
    PetscCall(MatMult(ctx->ops.V, ctx->state.cur, out->xfull));
    PetscCall(RollerContactResidualAddFull(ctx->contact, ctx->state.cur, out->xfull));
    PetscCall(MatMult(ctx->ops.V, ctx->state.velocity, out->vfull));
    xi = out->xfull;
    v  = out->vfull;
  }
  PetscCall(RollerProjectAtVertices(ctx, xi, RollerPadVector, INSERT_VALUES, out->field[FIELD_DISPLACEMENT].vec));
  PetscCall(RollerProjectAtVertices(ctx, v, RollerPadVector, INSERT_VALUES, out->field[FIELD_VELOCITY].vec));
  if (ctx->axle.on) PetscCall(RollerOutputHubAtVertices(ctx, out, out->field[FIELD_DISPLACEMENT].vec, out->field[FIELD_VELOCITY].vec));
  PetscCall(LabDisplacement(out, theta, out->field[FIELD_DISPLACEMENT].vec, out->field[FIELD_LAB].vec));
  /* |sigma| (docs/model.md section 4); DMProjectField hands the kernel the constants of the input DS, ctx->mesh.dm's */
  PetscCall(RollerProjectAtVertices(ctx, xi, f_stress_norm, ADD_VALUES, out->field[FIELD_STRESS].vec));
  PetscCall(VecPointwiseDivide(out->field[FIELD_STRESS].vec, out->field[FIELD_STRESS].vec, out->count));
  /* multiplier / tributary length at the Gamma_C vertices (docs/contact.md) */
  if (out->nfields > FIELD_CONTACT_PRESSURE)
    PetscCall(RollerContactFields(ctx, ctx->contact, out->field[FIELD_CONTACT_PRESSURE].vec, out->nfields > FIELD_CONTACT_TRACTION ? out->field[FIELD_CONTACT_TRACTION].vec : NULL, out->nfields > FIELD_CONTACT_STATE ? out->field[FIELD_CONTACT_STATE].vec : NULL));

  PetscCall(DMSetOutputSequenceNumber(out->vdm, out->xdmf.written, ctx->state.time));
  PetscCall(DMSetOutputSequenceNumber(out->sdm, out->xdmf.written, ctx->state.time));
  if (out->pdm) PetscCall(DMSetOutputSequenceNumber(out->pdm, out->xdmf.written, ctx->state.time));
  if (out->tdm) PetscCall(DMSetOutputSequenceNumber(out->tdm, out->xdmf.written, ctx->state.time));
  if (out->cdm) PetscCall(DMSetOutputSequenceNumber(out->cdm, out->xdmf.written, ctx->state.time));
  for (PetscInt f = 0; f < out->nfields; ++f) PetscCall(VecView(out->field[f].vec, out->h5));
  if (out->xdmf.written == out->xdmf.size) {
    out->xdmf.size = PetscMax(64, 2 * out->xdmf.size);
    PetscCall(PetscRealloc(sizeof(PetscReal) * out->xdmf.size, &out->xdmf.times));
  }
  out->xdmf.times[out->xdmf.written++] = ctx->state.time;
  PetscCall(RollerLayoutUpdate(out));
  PetscCall(RollerXdmfAppend(ctx->comm, out));
  PetscFunctionReturn(0);
}

/* The step's output: its diagnostics (ctx->info, made by the caller) to the series, the fields every -output_every
   steps from -output_start on (the level within half a step of it counts). */
PetscErrorCode RollerFieldsStep(Roller ctx, RollerOutput out)
{
  PetscFunctionBeginUser;
  PetscCall(RollerSeriesAppend(ctx, &out->series));
  if (ctx->state.step % out->every == 0 && ctx->state.time >= out->start - 0.5 * ctx->ts.dt) PetscCall(WriteFields(ctx, out));
  PetscFunctionReturn(0);
}

/* The successful end: the diagnostics series, the HDF5 file closed and renamed, the final index written. */
PetscErrorCode RollerFieldsClose(Roller ctx, RollerOutput out)
{
  PetscFunctionBeginUser;
  PetscCall(RollerSeriesWrite(ctx, out->series, out->h5));
  PetscCall(PetscViewerDestroy(&out->h5));
  PetscCall(RollerXdmfClose(out));
  PetscCall(RollerRenameFile(ctx->comm, out->h5_part, out->h5_path));
  PetscCall(RollerXdmfWrite(ctx->comm, out, out->h5_path, out->xdmf.path));
  PetscCall(RollerRemoveStale(ctx->comm, out->xdmf.part));
  PetscCallMPI(MPI_Barrier(ctx->comm));
  PetscFunctionReturn(0);
}

/* Frees the fields output; files a run did not complete stay F.part (the viewer closes the HDF5 file). */
PetscErrorCode RollerFieldsDestroy(RollerOutput *output)
{
  RollerOutput out = *output;

  PetscFunctionBeginUser;
  if (!out) PetscFunctionReturn(0);
  PetscCall(PetscViewerDestroy(&out->h5));
  PetscCall(RollerXdmfClose(out));
  for (PetscInt f = 0; f < out->nfields; ++f) PetscCall(VecDestroy(&out->field[f].vec));
  PetscCall(VecDestroy(&out->count));
  PetscCall(VecDestroy(&out->position));
  PetscCall(VecDestroy(&out->xfull));
  PetscCall(VecDestroy(&out->vfull));
  PetscCall(DMDestroy(&out->vdm));
  PetscCall(DMDestroy(&out->sdm));
  PetscCall(DMDestroy(&out->pdm));
  PetscCall(DMDestroy(&out->tdm));
  PetscCall(DMDestroy(&out->cdm));
  PetscCall(PetscFree(out->xdmf.times));
  PetscCall(RollerSeriesDestroy(&out->series));
  PetscCall(PetscFree(out));
  *output = NULL;
  PetscFunctionReturn(0);
}

/* The output options: -monitor_csv F (output_csv.c), -output F.h5 every -output_every steps from -output_start on;
   empty paths: none. */
PetscErrorCode RollerOutputSetFromOptions(Roller ctx, char csv[], char h5[], size_t len, PetscInt *every, PetscReal *start)
{
  PetscBool has_csv = PETSC_FALSE, has_h5 = PETSC_FALSE;

  PetscFunctionBeginUser;
  csv[0] = h5[0] = 0;
  *every         = 10;
  *start         = 0.0;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: output", NULL);
  PetscCall(PetscOptionsString("-monitor_csv", "One CSV row per step: step,t,R,alpha,energy,contact_nodes,contact_force,gap_min,qp_iterations,kkt_residual,theta", NULL, csv, csv, len, &has_csv));
  PetscCall(PetscOptionsString("-output", "Fields to this HDF5 file, with an XDMF index beside it (F.h5 -> F.xmf)", NULL, h5, h5, len, &has_h5));
  PetscCall(PetscOptionsInt("-output_every", "Write fields every N steps", NULL, *every, every, NULL));
  PetscCall(PetscOptionsReal("-output_start", "Write fields from this time on (a window at the end of a long run)", NULL, *start, start, NULL));
  { /* read again by the observer (integrate/observers_surface.c): listed and checked here, with the outputs */
    char      surface[PETSC_MAX_PATH_LEN] = "";
    PetscInt  orders                      = ROLLER_SURFACE_ORDERS;
    PetscBool has_surface                 = PETSC_FALSE;

    PetscCall(PetscOptionsString("-monitor_surface_csv", "One CSV row per step: step,t,theta,ur0,ur1c,ur1s,...: the lab-frame orders of the radial displacement of Gamma_C (the sound's source)", NULL, surface, surface, sizeof(surface), &has_surface));
    PetscCall(PetscOptionsInt("-monitor_surface_orders", "The orders 1..N of -monitor_surface_csv besides ur0", NULL, orders, &orders, NULL));
    RollerCheckOption(ctx->comm, "-monitor_surface_orders", orders, orders >= 1 && orders <= 64, "an integer in 1 ... 64");
    PetscCheck(!has_surface || surface[0], ctx->comm, PETSC_ERR_USER_INPUT, "-monitor_surface_csv needs a file name");
  }
  PetscOptionsEnd();
  PetscCheck(*every > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-output_every %" PetscInt_FMT " must be > 0", *every);
  RollerCheckOption(ctx->comm, "-output_start", *start, *start >= 0, ">= 0 (a time)");
  PetscCheck(!has_csv || csv[0], ctx->comm, PETSC_ERR_ARG_WRONG, "-monitor_csv needs a file name");
  PetscCheck(!has_h5 || h5[0], ctx->comm, PETSC_ERR_ARG_WRONG, "-output needs a file name");
  PetscFunctionReturn(0);
}
