/* The command-line contract of docs/model.md section 6: every option read in one place, validated, listed by -help. */
#include "integrate/integrate.h"

const char *const RollerInitialConditions[] = {"rest", "bump", "mms", "RollerInitialCondition", "ROLLER_IC_", NULL};
const char *const RollerMMSTypes[]          = {"none", "linear", "sine", "RollerMMSType", "ROLLER_MMS_", NULL};

PetscErrorCode RollerCreate(MPI_Comm comm, Roller *roller)
{
  Roller ctx;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&ctx));
  ctx->comm             = comm;
  ctx->mesh.r_inner     = 0.25;
  ctx->mesh.r_outer     = 0.5;
  ctx->disc.degree      = 2;
  ctx->disc.coriolis    = ROLLER_CORIOLIS_EXTRAPOLATED;
  ctx->ts.phase_error   = 0.01;
  ctx->material.young   = 0.1;
  ctx->material.poisson = 0.49;
  ctx->material.density = 1.0;
  ctx->rotation.omega   = PETSC_PI / 10.0;
  ctx->obstacle.speed   = 0.005;
  ctx->obstacle.depth   = 0.025;
  ctx->ts.max_time      = 20.0;
  ctx->ts.max_steps     = -1;
  ctx->init.type        = ROLLER_IC_REST;
  ctx->init.amplitude   = 1e-3;
  ctx->init.mms         = ROLLER_MMS_NONE;
  PetscCall(PetscStrncpy(ctx->ck.file, "checkpoint.h5", sizeof(ctx->ck.file)));
  PetscCall(RollerSignalsInstall()); /* a SIGTERM during setup still ends in a checkpoint after step 1 */
  PetscCall(PetscLogStageRegister("Roller setup", &ctx->stage[ROLLER_STAGE_SETUP]));
  PetscCall(PetscLogStageRegister("Roller step", &ctx->stage[ROLLER_STAGE_STEP]));
  PetscCall(PetscLogStageRegister("Roller contact", &ctx->stage[ROLLER_STAGE_CONTACT]));
  PetscCall(PetscLogStageRegister("Roller diagnostics", &ctx->stage[ROLLER_STAGE_DIAGNOSTICS]));
  PetscCall(PetscLogStageRegister("Roller output", &ctx->stage[ROLLER_STAGE_OUTPUT]));
  *roller = ctx;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSetFromOptions(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: geometry and mesh", NULL);
  PetscCall(PetscOptionsReal("-mesh_h", "Edge length of the gmsh annulus mesh (0: chosen from -ts_phase_error)", NULL, ctx->mesh.h, &ctx->mesh.h, &ctx->mesh.h_set));
  PetscCall(PetscOptionsString("-dm_plex_filename", "gmsh mesh file (physical groups inner, outer, body) instead of -mesh_h", NULL, ctx->mesh.file, ctx->mesh.file, sizeof(ctx->mesh.file), NULL));
  PetscCall(PetscOptionsReal("-r_inner", "Inner radius r_D (Gamma_D, driven)", NULL, ctx->mesh.r_inner, &ctx->mesh.r_inner, NULL));
  PetscCall(PetscOptionsReal("-r_outer", "Outer radius r_C (Gamma_C, contact)", NULL, ctx->mesh.r_outer, &ctx->mesh.r_outer, NULL));
  PetscCall(PetscOptionsBool("-partition_view", "Print the partition sizes and edge cut", NULL, ctx->mesh.partition_view, &ctx->mesh.partition_view, NULL));
  PetscOptionsEnd();

  PetscCall(RollerDiscretizationSetFromOptions(ctx));
  PetscCall(RollerMaterialSetFromOptions(ctx));
  PetscCall(RollerRotationSetFromOptions(ctx));

  PetscOptionsBegin(ctx->comm, NULL, "Roller: obstacle g(t) = min(speed t, depth) - r_outer", NULL);
  PetscCall(PetscOptionsBool("-obstacle", "Enable the rigid flat obstacle", NULL, ctx->obstacle.on, &ctx->obstacle.on, NULL));
  PetscCall(PetscOptionsReal("-obstacle_speed", "Obstacle speed v", NULL, ctx->obstacle.speed, &ctx->obstacle.speed, NULL));
  PetscCall(PetscOptionsReal("-obstacle_depth", "Final indentation depth", NULL, ctx->obstacle.depth, &ctx->obstacle.depth, NULL));
  PetscOptionsEnd();

  PetscOptionsBegin(ctx->comm, NULL, "Roller: time stepping", NULL);
  PetscCall(PetscOptionsReal("-ts_dt", "Time step dt (0: chosen from -ts_phase_error)", NULL, ctx->ts.dt, &ctx->ts.dt, &ctx->ts.dt_set));
  PetscCall(PetscOptionsReal("-ts_max_time", "End time", NULL, ctx->ts.max_time, &ctx->ts.max_time, NULL));
  PetscCall(PetscOptionsReal("-ts_phase_error", "Accuracy target that sets the default -ts_dt and -mesh_h: phase error of the fastest excited mode at the end time", NULL, ctx->ts.phase_error, &ctx->ts.phase_error, NULL));
  PetscCall(PetscOptionsBool("-ts_view", "Print the discretization (degree, h, dt, Coriolis velocity) and the rule that chose it (also with -ts_monitor)", NULL, ctx->ts.view, &ctx->ts.view, NULL));
  if (!ctx->ts.view) PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_monitor", &ctx->ts.view));
  PetscCall(PetscOptionsInt("-ts_max_steps", "Cap on the number of steps (-1: none)", NULL, ctx->ts.max_steps, &ctx->ts.max_steps, NULL));
  PetscCall(PetscOptionsBool("-quiet", "Silence the progress line", NULL, ctx->ts.quiet, &ctx->ts.quiet, NULL));
  PetscCall(PetscOptionsEnum("-initial_condition", "Initial state xi0, eta0", "RollerInitialCondition", RollerInitialConditions, (PetscEnum)ctx->init.type, (PetscEnum *)&ctx->init.type, NULL));
  PetscCall(PetscOptionsReal("-ic_amplitude", "Amplitude of the bump initial displacement", NULL, ctx->init.amplitude, &ctx->init.amplitude, NULL));
  PetscCall(PetscOptionsEnum("-mms", "Manufactured solution for verification (adds its body force)", "RollerMMSType", RollerMMSTypes, (PetscEnum)ctx->init.mms, (PetscEnum *)&ctx->init.mms, NULL));
  PetscOptionsEnd();

  PetscOptionsBegin(ctx->comm, NULL, "Roller: checkpoint and restart", NULL);
  PetscCall(PetscOptionsString("-checkpoint", "HDF5 file of the full state (written every N steps, on SIGTERM/SIGINT, and when a step fails)", NULL, ctx->ck.file, ctx->ck.file, sizeof(ctx->ck.file), NULL));
  PetscCall(PetscOptionsInt("-checkpoint_every", "Write the checkpoint every N steps (0: only on a signal or a failed step)", NULL, ctx->ck.every, &ctx->ck.every, NULL));
  PetscCall(PetscOptionsString("-restart", "Continue from this checkpoint (same mesh, -degree, -ts_dt and ranks)", NULL, ctx->ck.restart, ctx->ck.restart, sizeof(ctx->ck.restart), NULL));
  PetscOptionsEnd();

  PetscCheck(ctx->ck.every >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint_every %" PetscInt_FMT " must be >= 0", ctx->ck.every);
  PetscCheck(ctx->ck.file[0], ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint needs a file name");
  PetscCheck(ctx->ts.phase_error > 0 && ctx->ts.phase_error < 1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ts_phase_error %g must lie in (0, 1)", (double)ctx->ts.phase_error);
  PetscCheck(ctx->mesh.h >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_h %g must be > 0 (or 0: chosen from -ts_phase_error)", (double)ctx->mesh.h);
  ctx->mesh.h_set = (PetscBool)(ctx->mesh.h > 0);
  PetscCheck(ctx->mesh.r_inner > 0 && ctx->mesh.r_inner < ctx->mesh.r_outer, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-r_inner %g and -r_outer %g must satisfy 0 < r_inner < r_outer", (double)ctx->mesh.r_inner, (double)ctx->mesh.r_outer);
  PetscCheck(ctx->mesh.file[0] || !ctx->mesh.h_set || ctx->mesh.h < ctx->mesh.r_outer - ctx->mesh.r_inner, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_h %g must be smaller than the annulus width r_outer - r_inner = %g", (double)ctx->mesh.h,
             (double)(ctx->mesh.r_outer - ctx->mesh.r_inner));
  PetscCheck(ctx->ts.dt >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ts_dt %g must be > 0 (or 0: chosen from -ts_phase_error)", (double)ctx->ts.dt);
  ctx->ts.dt_set = (PetscBool)(ctx->ts.dt > 0);
  PetscCheck(ctx->ts.max_time >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ts_max_time %g must be >= 0", (double)ctx->ts.max_time);
  PetscCheck(ctx->ts.max_steps >= -1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ts_max_steps %" PetscInt_FMT " must be >= 0 (or -1 for no cap)", ctx->ts.max_steps);
  PetscCheck(ctx->obstacle.speed > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-obstacle_speed %g must be > 0", (double)ctx->obstacle.speed);
  PetscCheck(ctx->obstacle.depth >= 0 && ctx->obstacle.depth < ctx->mesh.r_outer - ctx->mesh.r_inner, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-obstacle_depth %g must lie in [0, r_outer - r_inner = %g)", (double)ctx->obstacle.depth,
             (double)(ctx->mesh.r_outer - ctx->mesh.r_inner));
  PetscCheck(ctx->init.amplitude >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ic_amplitude %g must be >= 0", (double)ctx->init.amplitude);
  PetscCheck(ctx->init.type != ROLLER_IC_BUMP || ctx->disc.clamp_outer, ctx->comm, PETSC_ERR_ARG_INCOMP, "-initial_condition bump needs -clamp_outer (the bump vanishes on both circles)");
  PetscCheck(ctx->init.mms == ROLLER_MMS_NONE || (ctx->disc.clamp_outer && !ctx->obstacle.on), ctx->comm, PETSC_ERR_ARG_INCOMP, "-mms %s needs -clamp_outer and no -obstacle", RollerMMSTypes[ctx->init.mms]);
  PetscCheck(!(ctx->obstacle.on && ctx->disc.coriolis == ROLLER_CORIOLIS_CENTERED), ctx->comm, PETSC_ERR_ARG_INCOMP, "-coriolis_velocity centered makes the step matrix non-symmetric: the step is then no longer a minimization, and -obstacle needs one (use backward or extrapolated)");
  PetscCheck(!(ctx->obstacle.on && ctx->disc.clamp_outer), ctx->comm, PETSC_ERR_ARG_INCOMP, "-obstacle cannot be combined with -clamp_outer (Gamma_C would be fixed)");
  PetscCheck(!ctx->disc.static_solve || (ctx->rotation.omega == 0 && ctx->rotation.a == 0 && ctx->init.type == ROLLER_IC_REST && ctx->init.mms == ROLLER_MMS_NONE && !ctx->ck.restart[0] && ctx->ts.max_time > 0), ctx->comm, PETSC_ERR_ARG_INCOMP, "-static needs -omega 0, -theta_a 0, the rest initial condition, no -mms or -restart, and -ts_max_time > 0");
  if (ctx->disc.static_solve) { /* one step from rest to t = max_time with A = K: the right-hand side is 0 */
    ctx->ts.dt        = ctx->ts.max_time;
    ctx->ts.dt_set    = PETSC_TRUE; /* not the accurate default's dt */
    ctx->ts.max_steps = 1;
  }
  if (ctx->init.mms != ROLLER_MMS_NONE) ctx->init.type = ROLLER_IC_MMS;
  PetscCheck(ctx->init.type != ROLLER_IC_MMS || ctx->init.mms != ROLLER_MMS_NONE, ctx->comm, PETSC_ERR_ARG_INCOMP, "-initial_condition mms needs -mms linear or sine");
  if (ctx->ck.restart[0]) PetscCall(RollerCheckpointDiscretization(ctx, ctx->ck.restart));
  PetscCall(RollerChooseMeshSize(ctx));
  PetscFunctionReturn(0);
}
