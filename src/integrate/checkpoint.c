/* Checkpoint and restart: the full state of the time scheme (xi^k, xi^{k-1}, xi^{k-2}, the vectors the scheme
   keeps beyond them, the step k and its time, the cumulative works and the angular momentum of the last two
   levels; theta and the obstacle height are functions of time), and what other components registered
   (RollerCheckpointAddVec, RollerCheckpointAddReals), in an HDF5 file, written to a temporary name and renamed so
   that a kill during a write never leaves a corrupt latest checkpoint. It restarts on any number of ranks: the
   vectors are read in this run's order by the positions of their points (integrate/checkpoint_order.c); a
   checkpoint of another mesh, degree, dt or scheme is refused by name (integrate/checkpoint_identity.c).
   SIGTERM/SIGINT (what a batch scheduler sends before the kill) make the driver finish the step, write a
   checkpoint and stop cleanly, as -ts_max_wall does (integrate/driver.c). -checkpoint_every N is an observer of
   the run that writes it every N steps. */
#include "integrate/integrate.h"
#include <petscviewerhdf5.h>
#include <signal.h>
#include <stdio.h>

/* The checkpoint's format: 2 since a checkpoint holds its nodes' positions and what it was written for (it restarts
   on any number of ranks). Format 1 files (no format attribute) were read in the writer's numbering: refused. */
#define ROLLER_CHECKPOINT_FORMAT 2

static volatile sig_atomic_t roller_signal = 0;

static void RollerSignalHandler(int sig)
{
  roller_signal = sig;
}

/* The scheme's history, in the order it is written. */
static void History(Roller ctx, Vec v[3])
{
  v[0] = ctx->state.cur;
  v[1] = ctx->state.prev;
  v[2] = ctx->state.prev2;
}

static const char *const history_names[3] = {"xi_k", "xi_k1", "xi_k2"};
static const char *const work_names[3]    = {"shaft_work", "sheet_work", "friction_work"}; /* state.works */
static const char        nodes_name[]     = "nodes";                                       /* ops.coordinates */

PetscErrorCode RollerCheckpointSetFromOptions(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: checkpoint and restart", NULL);
  PetscCall(PetscOptionsString("-checkpoint", "HDF5 file of the full state (written every N steps, on SIGTERM/SIGINT, at -ts_max_wall and when a step fails)", NULL, ctx->ck.file, ctx->ck.file, sizeof(ctx->ck.file), NULL));
  PetscCall(PetscOptionsInt("-checkpoint_every", "Write the checkpoint every N steps (0: only on a signal, -ts_max_wall or a failed step)", NULL, ctx->ck.every, &ctx->ck.every, NULL));
  PetscCall(PetscOptionsString("-restart", "Continue from this checkpoint (same mesh, -degree, -ts_dt and -ts_scheme; any number of ranks)", NULL, ctx->ck.restart, ctx->ck.restart, sizeof(ctx->ck.restart), NULL));
  PetscOptionsEnd();
  PetscCheck(ctx->ck.every >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint_every %" PetscInt_FMT " must be >= 0", ctx->ck.every);
  PetscCheck(ctx->ck.file[0], ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint needs a file name");
  PetscFunctionReturn(0);
}

/* A component's state in the checkpoint, registered at its set-up (before the restart reads it, after the scheme's
   set-up: RollerCheckpointReadItems): *v by name (the address of the component's field: a step that swaps its vectors
   is followed), its points at the positions where ((x, y) per point; v has the same number of points, any number of
   entries per point), a dataset where_name shared by the vectors of the same points; where NULL: the displacement's
   free nodes (where_name "nodes"). Written at every checkpoint, read at a restart (any number of ranks). */
PetscErrorCode RollerCheckpointAddVec(Roller ctx, const char name[], Vec *v, const char where_name[], Vec where)
{
  RollerCheckpointItem *item = &ctx->ck.items[ctx->ck.nitems];

  PetscFunctionBeginUser;
  PetscCheck(ctx->ck.nitems < ROLLER_CHECKPOINT_ITEMS, ctx->comm, PETSC_ERR_SUP, "Checkpoint item %s: at most %d (ROLLER_CHECKPOINT_ITEMS)", name, ROLLER_CHECKPOINT_ITEMS);
  for (PetscInt i = 0; i < ctx->ck.nitems; ++i) PetscCheck(strcmp(ctx->ck.items[i].name, name) && strcmp(ctx->ck.items[i].where_name, name), ctx->comm, PETSC_ERR_ARG_WRONG, "Checkpoint item %s registered twice", name);
  for (PetscInt i = 0; i < 3; ++i) PetscCheck(strcmp(history_names[i], name) && strcmp(nodes_name, name), ctx->comm, PETSC_ERR_ARG_WRONG, "Checkpoint item %s: the name of a dataset of the state", name);
  PetscCall(PetscStrncpy(item->name, name, sizeof(item->name)));
  PetscCall(PetscStrncpy(item->where_name, where ? where_name : nodes_name, sizeof(item->where_name)));
  item->v     = v;
  item->where = where ? where : ctx->ops.coordinates;
  ctx->ck.nitems++;
  PetscFunctionReturn(0);
}

/* What the run keeps beyond the levels: the scheme's vectors (its kept products and internal fields, by address: the
   levels swap) and, with -axle, the hub's levels and its spring's anchor (model/axle.h). After the scheme's set-up. */
PetscErrorCode RollerCheckpointRegister(Roller ctx)
{
  Vec        *kept[ROLLER_SCHEME_KEPT];
  const char *names[ROLLER_SCHEME_KEPT];
  PetscInt    n;

  PetscFunctionBeginUser;
  PetscCall(RollerSchemeKept(ctx, &n, kept, names));
  for (PetscInt i = 0; i < n; ++i) PetscCall(RollerCheckpointAddVec(ctx, names[i], kept[i], NULL, NULL));
  if (RollerContactSheetMoves(ctx->contact)) PetscCall(RollerCheckpointAddReals(ctx, "sheet", 4, RollerContactSheetState(ctx->contact))); /* X^k, X^{k-1}, X^{k-2}, its case */
  if (RollerContactHasFriction(ctx->contact)) {                                                                                           /* the last solve's multipliers: the first Newton iterate of the next */
    PetscInt   nc;
    PetscReal *lambda, *lambda_t;

    PetscCall(RollerContactMultipliers(ctx->contact, &nc, &lambda, &lambda_t));
    PetscCall(RollerCheckpointAddReals(ctx, "contact_lambda", nc, lambda));
    ctx->ck.items[ctx->ck.nitems - 1].optional = PETSC_TRUE; /* a frictionless press restarted with friction: no warm start */
    PetscCall(RollerCheckpointAddReals(ctx, "friction_lambda_t", nc, lambda_t));
    ctx->ck.items[ctx->ck.nitems - 1].optional = PETSC_TRUE;
  }
  if (ctx->axle.hub) {
    RollerHubState *s = &ctx->axle.hub->s;

    PetscCall(RollerCheckpointAddReals(ctx, "hub_q_k", 3, s->cur));
    PetscCall(RollerCheckpointAddReals(ctx, "hub_q_k1", 3, s->prev));
    PetscCall(RollerCheckpointAddReals(ctx, "hub_q_k2", 3, s->prev2));
    PetscCall(RollerCheckpointAddReals(ctx, "hub_anchor", 2, s->anchor));
    if (ctx->material.rubber == ROLLER_RUBBER_MAXWELL) PetscCall(RollerCheckpointAddReals(ctx, "hub_zeta", 2 * ROLLER_MAX_BRANCHES * 3, &s->zeta[0][0][0]));
  }
  PetscFunctionReturn(0);
}

/* n reals by name, the same on every rank (rank 0's are written; a restart gives them to every rank). */
PetscErrorCode RollerCheckpointAddReals(Roller ctx, const char name[], PetscInt n, PetscReal values[])
{
  PetscFunctionBeginUser;
  PetscCall(RollerCheckpointAddVec(ctx, name, NULL, NULL, NULL));
  ctx->ck.items[ctx->ck.nitems - 1].n      = n;
  ctx->ck.items[ctx->ck.nitems - 1].values = values;
  PetscFunctionReturn(0);
}

/* Reals as a dataset held by rank 0: written, or read and given to every rank. */
static PetscErrorCode RealsView(Roller ctx, PetscViewer viewer, RollerCheckpointItem *item, PetscBool load)
{
  Vec          v;
  PetscScalar *a;
  PetscMPIInt  rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  PetscCall(VecCreateMPI(ctx->comm, rank ? 0 : item->n, item->n, &v));
  PetscCall(PetscObjectSetName((PetscObject)v, item->name));
  if (load) PetscCall(VecLoad(v, viewer));
  PetscCall(VecGetArray(v, &a));
  for (PetscInt i = 0; i < (rank ? 0 : item->n); ++i) {
    if (load) item->values[i] = PetscRealPart(a[i]);
    else a[i] = item->values[i];
  }
  PetscCall(VecRestoreArray(v, &a));
  if (load) PetscCallMPI(MPI_Bcast(item->values, (PetscMPIInt)item->n, MPIU_REAL, 0, ctx->comm));
  else PetscCall(VecView(v, viewer));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

/* The registered items and, once each, the positions of their points. */
static PetscErrorCode ItemsWrite(Roller ctx, PetscViewer viewer)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ctx->ck.nitems; ++i) {
    RollerCheckpointItem *item  = &ctx->ck.items[i];
    PetscBool             first = PETSC_TRUE;

    if (!item->v) {
      PetscCall(RealsView(ctx, viewer, item, PETSC_FALSE));
      continue;
    }
    PetscCall(RollerPlainVecView(*item->v, item->name, viewer, PETSC_FALSE));
    for (PetscInt j = 0; j < i; ++j) first = (PetscBool)(first && (!ctx->ck.items[j].v || strcmp(ctx->ck.items[j].where_name, item->where_name)));
    if (first && strcmp(item->where_name, nodes_name)) PetscCall(RollerPlainVecView(item->where, item->where_name, viewer, PETSC_FALSE));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerCheckpointWrite(Roller ctx, const char *path)
{
  char        tmp[PETSC_MAX_PATH_LEN];
  PetscViewer viewer;
  Vec         v[3];
  PetscInt    format = ROLLER_CHECKPOINT_FORMAT;

  PetscFunctionBeginUser;
  PetscCall(RollerJoinPath(tmp, sizeof(tmp), path, ".tmp", "-checkpoint"));
  PetscCall(PetscViewerHDF5Open(ctx->comm, tmp, FILE_MODE_WRITE, &viewer));
  PetscCall(RollerPlainVecView(ctx->ops.coordinates, nodes_name, viewer, PETSC_FALSE));
  History(ctx, v);
  for (PetscInt i = 0; i < 3; ++i) PetscCall(RollerPlainVecView(v[i], history_names[i], viewer, PETSC_FALSE));
  PetscCall(ItemsWrite(ctx, viewer));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "format", PETSC_INT, &format));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "step", PETSC_INT, &ctx->state.step));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "time", PETSC_REAL, &ctx->state.time));
  PetscCall(RollerCheckpointIdentityWrite(ctx, viewer));
  for (PetscInt i = 0; i < 3; ++i) PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", work_names[i], PETSC_REAL, &ctx->state.works[i]));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "momentum", PETSC_REAL, &ctx->state.momentum[0]));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "momentum_prev", PETSC_REAL, &ctx->state.momentum[1]));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "momentum_step", PETSC_INT, &ctx->state.momentum_step));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(RollerRenameFile(ctx->comm, tmp, path));
  PetscFunctionReturn(0);
}

/* Open the checkpoint for reading: a readable file that a Roller run wrote (it has the step attribute) in the
   layout this one reads. */
static PetscErrorCode CheckpointOpen(Roller ctx, const char *path, PetscViewer *viewer)
{
  PetscBool exists;
  PetscInt  format = 1;

  PetscFunctionBeginUser;
  PetscCall(PetscTestFile(path, 'r', &exists));
  PetscCheck(exists, ctx->comm, PETSC_ERR_FILE_OPEN, "-restart %s: no such readable file", path);
  PetscCall(RollerHDF5Probe(ctx->comm, "-restart", path)); /* one line for a file that is not HDF5 or truncated */
  PetscCall(PetscViewerHDF5Open(ctx->comm, path, FILE_MODE_READ, viewer));
  PetscCall(PetscViewerHDF5HasAttribute(*viewer, "/", "step", &exists));
  PetscCheck(exists, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "-restart %s: not a Roller checkpoint (no step attribute)", path);
  PetscCall(PetscViewerHDF5HasAttribute(*viewer, "/", "format", &exists));
  if (exists) PetscCall(PetscViewerHDF5ReadAttribute(*viewer, "/", "format", PETSC_INT, NULL, &format));
  PetscCheck(format == ROLLER_CHECKPOINT_FORMAT, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "-restart %s: checkpoint format %" PetscInt_FMT ", this Roller reads %d (format 1, before restarts on any number of ranks, held no node positions: restart it with the Roller that wrote it)", path, format, ROLLER_CHECKPOINT_FORMAT);
  PetscFunctionReturn(0);
}

/* The discretization a restart continues with where the options do not give it: the checkpoint's -ts_dt,
   -ts_scheme, -degree (and -mesh_curved) and -mesh_h (the accurate defaults would follow the new -ts_max_time), and
   with that -mesh_h its grading (-mesh_h_contact, -mesh_contact_layer) unless -mesh_h_contact is given. Called before the mesh is
   built; what the options give and differs is refused by RollerCheckpointRead. */
PetscErrorCode RollerCheckpointDiscretization(Roller ctx, const char *path)
{
  PetscViewer viewer;

  PetscFunctionBeginUser;
  PetscCall(CheckpointOpen(ctx, path, &viewer));
  if (!ctx->ts.dt_set) {
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "dt", PETSC_REAL, NULL, &ctx->ts.dt));
    ctx->ts.dt_set     = PETSC_TRUE;
    ctx->ts.dt_restart = PETSC_TRUE;
  }
  if (!ctx->ts.scheme[0]) {
    char *scheme;

    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "scheme", PETSC_STRING, NULL, &scheme));
    PetscCall(PetscStrncpy(ctx->ts.scheme, scheme, sizeof(ctx->ts.scheme)));
    PetscCall(PetscFree(scheme));
    ctx->ts.scheme_restart = PETSC_TRUE;
  }
  if (!ctx->disc.degree_set) { /* the degree (P3 is the default only when -mesh_h comes from -ts_phase_error) */
    PetscBool curved_set;
    PetscInt  curved;

    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "degree", PETSC_INT, NULL, &ctx->disc.degree));
    PetscCall(PetscOptionsHasName(NULL, NULL, "-mesh_curved", &curved_set));
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "mesh_curved", PETSC_INT, NULL, &curved));
    if (!curved_set) ctx->mesh.curved = (PetscBool)(curved != 0);
  }
  if (!ctx->mesh.h_set && !ctx->mesh.file[0]) {
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "mesh_h", PETSC_REAL, NULL, &ctx->mesh.h));
    ctx->mesh.h_set     = PETSC_TRUE;
    ctx->mesh.h_restart = PETSC_TRUE;
  }
  if (ctx->mesh.h_restart && ctx->mesh.h_contact == 0) { /* the grading with the h it was made for */
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "mesh_h_contact", PETSC_REAL, NULL, &ctx->mesh.h_contact));
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "mesh_contact_layer", PETSC_REAL, NULL, &ctx->mesh.contact_layer));
  }
  PetscCall(PetscViewerDestroy(&viewer));
  PetscFunctionReturn(0);
}

/* Continue from a checkpoint of the same discretization (refused otherwise), on any number of ranks. */
PetscErrorCode RollerCheckpointRead(Roller ctx, const char *path)
{
  PetscViewer viewer;
  Vec         v[3];
  PetscInt    npoints, *from;

  PetscFunctionBeginUser;
  PetscCall(CheckpointOpen(ctx, path, &viewer));
  PetscCall(RollerCheckpointIdentityCheck(ctx, viewer, path));
  PetscCall(RollerCheckpointOrderCreate(ctx, viewer, "-restart", path, nodes_name, ctx->ops.coordinates, &npoints, &from));
  History(ctx, v);
  for (PetscInt i = 0; i < 3; ++i) PetscCall(RollerCheckpointOrderLoad(viewer, history_names[i], npoints, from, v[i]));
  PetscCall(PetscFree(from));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "step", PETSC_INT, NULL, &ctx->state.step));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "time", PETSC_REAL, NULL, &ctx->state.time));
  for (PetscInt i = 0; i < 3; ++i) PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", work_names[i], PETSC_REAL, NULL, &ctx->state.works[i])); /* up to the checkpoint's step */
  ctx->state.work_step = ctx->state.step;
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "momentum", PETSC_REAL, NULL, &ctx->state.momentum[0]));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "momentum_prev", PETSC_REAL, NULL, &ctx->state.momentum[1]));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "momentum_step", PETSC_INT, NULL, &ctx->state.momentum_step));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(MatMult(ctx->ops.K, ctx->state.cur, ctx->state.Kcur));
  PetscCall(MatMult(ctx->ops.K, ctx->state.prev, ctx->state.Kprev));
  PetscCall(MatMult(ctx->ops.K, ctx->state.prev2, ctx->state.Kprev2));
  PetscFunctionReturn(0);
}

/* After the scheme's set-up: the registered items (the vectors the scheme keeps beyond the levels, as the
   checkpoint holds them: re-made from the levels they would differ in the last bits, and a restart would not repeat
   the run exactly; the other components' state), each vector through the match of its points. A checkpoint without
   one was written without the component that registered it: refused by name, unless it is optional (the friction's
   first iterate: a checkpoint of a frictionless run restarts with friction from the frictionless multipliers). */
PetscErrorCode RollerCheckpointReadItems(Roller ctx, const char *path)
{
  PetscViewer viewer;
  PetscInt    npoints = 0, *from = NULL;
  const char *matched = NULL; /* the positions from[] is of */

  PetscFunctionBeginUser;
  if (!ctx->ck.nitems) PetscFunctionReturn(0);
  PetscCall(CheckpointOpen(ctx, path, &viewer));
  for (PetscInt i = 0; i < ctx->ck.nitems; ++i) {
    RollerCheckpointItem *item = &ctx->ck.items[i];
    PetscBool             has;

    PetscCall(PetscViewerHDF5HasDataset(viewer, item->name, &has));
    if (!has && item->optional) continue;
    PetscCheck(has, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "-restart %s: refused, no %s in the checkpoint (written without the component that keeps it)", path, item->name);
    if (!item->v) {
      PetscCall(RealsView(ctx, viewer, item, PETSC_TRUE));
      continue;
    }
    if (!matched || strcmp(matched, item->where_name)) {
      PetscCall(PetscFree(from));
      PetscCall(RollerCheckpointOrderCreate(ctx, viewer, "-restart", path, item->where_name, item->where, &npoints, &from));
      matched = item->where_name;
    }
    PetscCall(RollerCheckpointOrderLoad(viewer, item->name, npoints, from, *item->v));
  }
  PetscCall(PetscFree(from));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscFunctionReturn(0);
}

/* -checkpoint_every N: after every N-th step, once the step's outputs are written (a restart continues after
   the CSV row of its step, so that row must be on disk before the checkpoint that names it). */
static PetscErrorCode MonitorCheckpoint(Roller ctx, RollerMonitorEvent event, void *mctx)
{
  PetscFunctionBeginUser;
  if (event == ROLLER_MONITOR_STEP && ctx->state.step % ctx->ck.every == 0) PetscCall(RollerCheckpointWrite(ctx, ctx->ck.file));
  PetscFunctionReturn(0);
}

/* Set after the outputs' observers (see MonitorCheckpoint). */
PetscErrorCode RollerCheckpointMonitorSetUp(Roller ctx)
{
  PetscFunctionBeginUser;
  if (ctx->ck.every) PetscCall(RollerMonitorSet(ctx, MonitorCheckpoint, NULL, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSignalsInstall(void)
{
  struct sigaction sa;

  PetscFunctionBeginUser;
  sa.sa_handler = RollerSignalHandler;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;
  PetscCheck(sigaction(SIGTERM, &sa, NULL) == 0 && sigaction(SIGINT, &sa, NULL) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS, "Cannot install the SIGTERM/SIGINT handler");
  PetscFunctionReturn(0);
}

/* The signal caught on any rank (0 if none), agreed on by all ranks. */
PetscErrorCode RollerSignalCaught(Roller ctx, PetscInt *sig)
{
  PetscInt local = (PetscInt)roller_signal;

  PetscFunctionBeginUser;
  PetscCall(MPIU_Allreduce(&local, sig, 1, MPIU_INT, MPI_MAX, ctx->comm));
  PetscFunctionReturn(0);
}
