/* Checkpoint and restart: the full state of the time scheme (xi^k, xi^{k-1}, xi^{k-2}, the vectors the scheme
   keeps beyond them, the step k and its time, the cumulative works and the angular momentum of the last two
   levels; theta and the obstacle height are functions of time) in an HDF5 file, written to a
   temporary name and renamed so that a kill during a write never leaves a corrupt latest checkpoint.
   SIGTERM/SIGINT (what a batch scheduler sends before the kill) make the driver finish the step, write a
   checkpoint and stop cleanly. -checkpoint_every N is an observer of the run that writes it every N steps. */
#include "integrate/integrate.h"
#include <petscviewerhdf5.h>
#include <signal.h>
#include <stdio.h>

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

PetscErrorCode RollerCheckpointSetFromOptions(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: checkpoint and restart", NULL);
  PetscCall(PetscOptionsString("-checkpoint", "HDF5 file of the full state (written every N steps, on SIGTERM/SIGINT, and when a step fails)", NULL, ctx->ck.file, ctx->ck.file, sizeof(ctx->ck.file), NULL));
  PetscCall(PetscOptionsInt("-checkpoint_every", "Write the checkpoint every N steps (0: only on a signal or a failed step)", NULL, ctx->ck.every, &ctx->ck.every, NULL));
  PetscCall(PetscOptionsString("-restart", "Continue from this checkpoint (same mesh, -degree, -ts_dt and ranks)", NULL, ctx->ck.restart, ctx->ck.restart, sizeof(ctx->ck.restart), NULL));
  PetscOptionsEnd();
  PetscCheck(ctx->ck.every >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint_every %" PetscInt_FMT " must be >= 0", ctx->ck.every);
  PetscCheck(ctx->ck.file[0], ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint needs a file name");
  PetscFunctionReturn(0);
}

PetscErrorCode RollerCheckpointWrite(Roller ctx, const char *path)
{
  char        tmp[PETSC_MAX_PATH_LEN];
  PetscViewer viewer;
  Vec         v[3];
  PetscInt    N;

  PetscFunctionBeginUser;
  PetscCall(RollerJoinPath(tmp, sizeof(tmp), path, ".tmp", "-checkpoint"));
  PetscCall(PetscViewerHDF5Open(ctx->comm, tmp, FILE_MODE_WRITE, &viewer));
  History(ctx, v);
  for (PetscInt i = 0; i < 3; ++i) PetscCall(RollerPlainVecView(v[i], history_names[i], viewer, PETSC_FALSE));
  PetscCall(VecGetSize(ctx->state.cur, &N));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "step", PETSC_INT, &ctx->state.step));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "time", PETSC_REAL, &ctx->state.time));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "dt", PETSC_REAL, &ctx->ts.dt));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "dofs", PETSC_INT, &N));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "degree", PETSC_INT, &ctx->disc.degree));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "mesh_h", PETSC_REAL, &ctx->mesh.h));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "mesh_h_contact", PETSC_REAL, &ctx->mesh.h_contact));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "mesh_contact_layer", PETSC_REAL, &ctx->mesh.contact_layer));
  for (PetscInt i = 0; i < 3; ++i) PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", work_names[i], PETSC_REAL, &ctx->state.works[i]));
  {
    Vec         kept[ROLLER_SCHEME_KEPT];
    const char *names[ROLLER_SCHEME_KEPT], *scheme = RollerSchemeName(ctx);
    PetscInt    n;

    PetscCall(RollerSchemeKept(ctx, &n, kept, names));
    for (PetscInt i = 0; i < n; ++i) PetscCall(RollerPlainVecView(kept[i], names[i], viewer, PETSC_FALSE));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "scheme", PETSC_STRING, scheme));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "momentum", PETSC_REAL, &ctx->state.momentum[0]));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "momentum_prev", PETSC_REAL, &ctx->state.momentum[1]));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "momentum_step", PETSC_INT, &ctx->state.momentum_step));
  }
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(RollerRenameFile(ctx->comm, tmp, path));
  PetscFunctionReturn(0);
}

/* Open the checkpoint for reading: a readable file that a Roller run wrote (it has the step attribute). */
static PetscErrorCode CheckpointOpen(Roller ctx, const char *path, PetscViewer *viewer)
{
  PetscBool exists;

  PetscFunctionBeginUser;
  PetscCall(PetscTestFile(path, 'r', &exists));
  PetscCheck(exists, ctx->comm, PETSC_ERR_FILE_OPEN, "-restart %s: no such readable file", path);
  PetscCall(RollerHDF5Probe(ctx->comm, "-restart", path)); /* one line for a file that is not HDF5 or truncated */
  PetscCall(PetscViewerHDF5Open(ctx->comm, path, FILE_MODE_READ, viewer));
  PetscCall(PetscViewerHDF5HasAttribute(*viewer, "/", "step", &exists));
  PetscCheck(exists, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "-restart %s: not a Roller checkpoint (no step attribute)", path);
  PetscFunctionReturn(0);
}

/* The discretization a restart continues with where the options do not give it: the checkpoint's -ts_dt and
   -mesh_h (the accurate defaults would follow the new -ts_max_time), and with that -mesh_h its grading
   (-mesh_h_contact, -mesh_contact_layer) unless -mesh_h_contact is given. Called before the mesh is built. */
PetscErrorCode RollerCheckpointDiscretization(Roller ctx, const char *path)
{
  PetscViewer viewer;
  PetscBool   exists;

  PetscFunctionBeginUser;
  PetscCall(CheckpointOpen(ctx, path, &viewer));
  if (!ctx->ts.dt_set) {
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "dt", PETSC_REAL, NULL, &ctx->ts.dt));
    ctx->ts.dt_set     = PETSC_TRUE;
    ctx->ts.dt_restart = PETSC_TRUE;
  }
  /* the scheme it was advanced with (checkpoints before the schemes: dmf) */
  PetscCall(PetscViewerHDF5HasAttribute(viewer, "/", "scheme", &exists));
  if (!ctx->ts.scheme[0]) {
    if (exists) {
      char *scheme;

      PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "scheme", PETSC_STRING, NULL, &scheme));
      PetscCall(PetscStrncpy(ctx->ts.scheme, scheme, sizeof(ctx->ts.scheme)));
      PetscCall(PetscFree(scheme));
    } else PetscCall(PetscStrncpy(ctx->ts.scheme, "dmf", sizeof(ctx->ts.scheme)));
  }
  PetscCall(PetscViewerHDF5HasAttribute(viewer, "/", "mesh_h", &exists));
  if (!ctx->mesh.h_set && !ctx->mesh.file[0] && exists) {
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "mesh_h", PETSC_REAL, NULL, &ctx->mesh.h));
    ctx->mesh.h_set     = PETSC_TRUE;
    ctx->mesh.h_restart = PETSC_TRUE;
  }
  /* the grading with the h it was made for (checkpoints before the grading have none: uniform) */
  PetscCall(PetscViewerHDF5HasAttribute(viewer, "/", "mesh_h_contact", &exists));
  if (ctx->mesh.h_restart && ctx->mesh.h_contact == 0 && exists) {
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "mesh_h_contact", PETSC_REAL, NULL, &ctx->mesh.h_contact));
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "mesh_contact_layer", PETSC_REAL, NULL, &ctx->mesh.contact_layer));
  }
  PetscCall(PetscViewerDestroy(&viewer));
  PetscFunctionReturn(0);
}

/* Continue from a checkpoint: same mesh, degree, dt and number of ranks as the run that wrote it. */
PetscErrorCode RollerCheckpointRead(Roller ctx, const char *path)
{
  PetscViewer viewer;
  Vec         v[3];
  PetscInt    N, dofs, degree;
  PetscReal   dt;

  PetscFunctionBeginUser;
  PetscCall(CheckpointOpen(ctx, path, &viewer));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "dofs", PETSC_INT, NULL, &dofs));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "degree", PETSC_INT, NULL, &degree));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "dt", PETSC_REAL, NULL, &dt));
  PetscCall(VecGetSize(ctx->state.cur, &N));
  PetscCheck(dofs == N && degree == ctx->disc.degree, ctx->comm, PETSC_ERR_ARG_INCOMP, "-restart %s: written for %" PetscInt_FMT " dofs of P%" PetscInt_FMT ", this run has %" PetscInt_FMT " of P%" PetscInt_FMT " (use the same mesh and -degree)", path, dofs, degree, N,
             ctx->disc.degree);
  PetscCheck(dt == ctx->ts.dt, ctx->comm, PETSC_ERR_ARG_INCOMP, "-restart %s: written with -ts_dt %.17g, this run has %.17g", path, (double)dt, (double)ctx->ts.dt);
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "step", PETSC_INT, NULL, &ctx->state.step));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "time", PETSC_REAL, NULL, &ctx->state.time));
  History(ctx, v);
  for (PetscInt i = 0; i < 3; ++i) PetscCall(RollerPlainVecView(v[i], history_names[i], viewer, PETSC_TRUE));
  /* the cumulative works up to the checkpoint's step (checkpoints before friction have none: 0) */
  for (PetscInt i = 0; i < 3; ++i) {
    PetscBool has;

    PetscCall(PetscViewerHDF5HasAttribute(viewer, "/", work_names[i], &has));
    ctx->state.works[i] = 0.0;
    if (has) PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", work_names[i], PETSC_REAL, NULL, &ctx->state.works[i]));
  }
  ctx->state.work_step     = ctx->state.step;
  ctx->state.momentum_step = -1;
  {
    PetscBool has;

    PetscCall(PetscViewerHDF5HasAttribute(viewer, "/", "momentum_step", &has));
    if (has) {
      PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "momentum", PETSC_REAL, NULL, &ctx->state.momentum[0]));
      PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "momentum_prev", PETSC_REAL, NULL, &ctx->state.momentum[1]));
      PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "momentum_step", PETSC_INT, NULL, &ctx->state.momentum_step));
    }
  }
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(MatMult(ctx->ops.K, ctx->state.cur, ctx->state.Kcur));
  PetscCall(MatMult(ctx->ops.K, ctx->state.prev, ctx->state.Kprev));
  PetscCall(MatMult(ctx->ops.K, ctx->state.prev2, ctx->state.Kprev2));
  PetscFunctionReturn(0);
}

/* After the scheme's set-up: the vectors it keeps beyond the levels, as the checkpoint holds them (re-made from the
   levels they would differ in the last bits, and a restart would not repeat the run exactly). */
PetscErrorCode RollerCheckpointReadKept(Roller ctx, const char *path)
{
  PetscViewer viewer;
  Vec         kept[ROLLER_SCHEME_KEPT];
  const char *names[ROLLER_SCHEME_KEPT];
  PetscInt    n;

  PetscFunctionBeginUser;
  PetscCall(RollerSchemeKept(ctx, &n, kept, names));
  if (!n) PetscFunctionReturn(0);
  PetscCall(CheckpointOpen(ctx, path, &viewer));
  for (PetscInt i = 0; i < n; ++i) {
    PetscBool has;

    PetscCall(PetscViewerHDF5HasDataset(viewer, names[i], &has));
    if (has) PetscCall(RollerPlainVecView(kept[i], names[i], viewer, PETSC_TRUE)); /* checkpoints before the schemes: the re-made ones */
  }
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
