/* The command-line contract of docs/model.md section 6: every option read in one place, validated, listed by -help. */
#include <roller_impl.h>

const char *const RollerInitialConditions[]  = {"rest", "bump", "mms", "RollerInitialCondition", "ROLLER_IC_", NULL};
const char *const RollerMMSTypes[]           = {"none", "linear", "sine", "RollerMMSType", "ROLLER_MMS_", NULL};
const char *const RollerCoriolisVelocities[] = {"backward", "extrapolated", "centered", "RollerCoriolisVelocity", "ROLLER_CORIOLIS_", NULL};

/* Plane-strain Lame constants (docs/model.md section 1). */
PetscErrorCode RollerLameFromYoung(PetscReal young, PetscReal poisson, PetscReal *lambda, PetscReal *mu)
{
  PetscFunctionBeginUser;
  *lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
  *mu     = young / (2.0 * (1.0 + poisson));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerCreate(MPI_Comm comm, Roller *roller)
{
  Roller ctx;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&ctx));
  ctx->comm           = comm;
  ctx->r_inner        = 0.25;
  ctx->r_outer        = 0.5;
  ctx->degree         = 2;
  ctx->coriolis       = ROLLER_CORIOLIS_EXTRAPOLATED;
  ctx->phase_error    = 0.01;
  ctx->young          = 0.1;
  ctx->poisson        = 0.49;
  ctx->density        = 1.0;
  ctx->omega          = PETSC_PI / 10.0;
  ctx->obstacle_speed = 0.005;
  ctx->obstacle_depth = 0.025;
  ctx->max_time       = 20.0;
  ctx->max_steps      = -1;
  ctx->ic             = ROLLER_IC_REST;
  ctx->ic_amplitude   = 1e-3;
  ctx->mms            = ROLLER_MMS_NONE;
  PetscCall(PetscStrncpy(ctx->checkpoint, "checkpoint.h5", sizeof(ctx->checkpoint)));
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
  PetscCall(PetscOptionsReal("-mesh_h", "Edge length of the gmsh annulus mesh (0: chosen from -ts_phase_error)", NULL, ctx->mesh_h, &ctx->mesh_h, &ctx->mesh_h_set));
  PetscCall(PetscOptionsString("-dm_plex_filename", "gmsh mesh file (physical groups inner, outer, body) instead of -mesh_h", NULL, ctx->mesh_file, ctx->mesh_file, sizeof(ctx->mesh_file), NULL));
  PetscCall(PetscOptionsReal("-r_inner", "Inner radius r_D (Gamma_D, driven)", NULL, ctx->r_inner, &ctx->r_inner, NULL));
  PetscCall(PetscOptionsReal("-r_outer", "Outer radius r_C (Gamma_C, contact)", NULL, ctx->r_outer, &ctx->r_outer, NULL));
  PetscCall(PetscOptionsBool("-partition_view", "Print the partition sizes and edge cut", NULL, ctx->partition_view, &ctx->partition_view, NULL));
  PetscOptionsEnd();

  PetscOptionsBegin(ctx->comm, NULL, "Roller: discretization and material", NULL);
  PetscCall(PetscOptionsInt("-degree", "Lagrange degree of the displacement (1 = the paper, 2)", NULL, ctx->degree, &ctx->degree, NULL));
  ctx->curved = (PetscBool)(ctx->degree == 2);
  PetscCall(PetscOptionsBool("-mesh_curved", "Curved (isoparametric P2) boundary: mid-edge nodes of Gamma_D, Gamma_C on the circles (default: on with -degree 2)", NULL, ctx->curved, &ctx->curved, NULL));
  PetscCall(PetscOptionsEnum("-coriolis_velocity", "Coriolis velocity: backward (the paper, explicit, 1st order), extrapolated (explicit, 2nd order), centered (implicit, 2nd order, stable)", "RollerCoriolisVelocity", RollerCoriolisVelocities,
                             (PetscEnum)ctx->coriolis, (PetscEnum *)&ctx->coriolis, NULL));
  PetscCall(PetscOptionsBool("-clamp_outer", "Also clamp Gamma_C (xi = 0 on the whole boundary, Theorem 1)", NULL, ctx->clamp_outer, &ctx->clamp_outer, NULL));
  PetscCall(PetscOptionsReal("-young", "Young's modulus E", NULL, ctx->young, &ctx->young, NULL));
  PetscCall(PetscOptionsReal("-poisson", "Poisson's ratio nu", NULL, ctx->poisson, &ctx->poisson, NULL));
  PetscCall(PetscOptionsReal("-density", "Density rho", NULL, ctx->density, &ctx->density, NULL));
  PetscOptionsEnd();

  PetscOptionsBegin(ctx->comm, NULL, "Roller: rotation theta(t) = omega t + a cos(b t), obstacle g(t) = min(speed t, depth) - r_outer", NULL);
  PetscCall(PetscOptionsReal("-omega", "Angular velocity omega", NULL, ctx->omega, &ctx->omega, NULL));
  PetscCall(PetscOptionsReal("-theta_a", "Amplitude a of the rotation perturbation", NULL, ctx->theta_a, &ctx->theta_a, NULL));
  PetscCall(PetscOptionsReal("-theta_b", "Angular frequency b of the rotation perturbation", NULL, ctx->theta_b, &ctx->theta_b, NULL));
  PetscCall(PetscOptionsBool("-obstacle", "Enable the rigid flat obstacle", NULL, ctx->obstacle, &ctx->obstacle, NULL));
  PetscCall(PetscOptionsReal("-obstacle_speed", "Obstacle speed v", NULL, ctx->obstacle_speed, &ctx->obstacle_speed, NULL));
  PetscCall(PetscOptionsReal("-obstacle_depth", "Final indentation depth", NULL, ctx->obstacle_depth, &ctx->obstacle_depth, NULL));
  PetscCall(PetscOptionsReal("-damping", "Damping eta of the DMF functional", NULL, ctx->damping, &ctx->damping, NULL));
  PetscCall(PetscOptionsBool("-static", "Solve the static contact (Signorini) problem K xi = E N lambda at the obstacle of t = -ts_max_time in one step, the state a damped run with -omega 0 comes to rest in (docs/validation.md section 5)", NULL, ctx->static_solve,
                             &ctx->static_solve, NULL));
  PetscOptionsEnd();

  PetscOptionsBegin(ctx->comm, NULL, "Roller: time stepping", NULL);
  PetscCall(PetscOptionsReal("-ts_dt", "Time step dt (0: chosen from -ts_phase_error)", NULL, ctx->dt, &ctx->dt, &ctx->dt_set));
  PetscCall(PetscOptionsReal("-ts_max_time", "End time", NULL, ctx->max_time, &ctx->max_time, NULL));
  PetscCall(PetscOptionsReal("-ts_phase_error", "Accuracy target that sets the default -ts_dt and -mesh_h: phase error of the fastest excited mode at the end time", NULL, ctx->phase_error, &ctx->phase_error, NULL));
  PetscCall(PetscOptionsBool("-ts_view", "Print the discretization (degree, h, dt, Coriolis velocity) and the rule that chose it (also with -ts_monitor)", NULL, ctx->discretization_view, &ctx->discretization_view, NULL));
  if (!ctx->discretization_view) PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_monitor", &ctx->discretization_view));
  PetscCall(PetscOptionsInt("-ts_max_steps", "Cap on the number of steps (-1: none)", NULL, ctx->max_steps, &ctx->max_steps, NULL));
  PetscCall(PetscOptionsBool("-quiet", "Silence the progress line", NULL, ctx->quiet, &ctx->quiet, NULL));
  PetscCall(PetscOptionsEnum("-initial_condition", "Initial state xi0, eta0", "RollerInitialCondition", RollerInitialConditions, (PetscEnum)ctx->ic, (PetscEnum *)&ctx->ic, NULL));
  PetscCall(PetscOptionsReal("-ic_amplitude", "Amplitude of the bump initial displacement", NULL, ctx->ic_amplitude, &ctx->ic_amplitude, NULL));
  PetscCall(PetscOptionsEnum("-mms", "Manufactured solution for verification (adds its body force)", "RollerMMSType", RollerMMSTypes, (PetscEnum)ctx->mms, (PetscEnum *)&ctx->mms, NULL));
  PetscOptionsEnd();

  PetscOptionsBegin(ctx->comm, NULL, "Roller: checkpoint and restart", NULL);
  PetscCall(PetscOptionsString("-checkpoint", "HDF5 file of the full state (written every N steps, on SIGTERM/SIGINT, and when a step fails)", NULL, ctx->checkpoint, ctx->checkpoint, sizeof(ctx->checkpoint), NULL));
  PetscCall(PetscOptionsInt("-checkpoint_every", "Write the checkpoint every N steps (0: only on a signal or a failed step)", NULL, ctx->checkpoint_every, &ctx->checkpoint_every, NULL));
  PetscCall(PetscOptionsString("-restart", "Continue from this checkpoint (same mesh, -degree, -ts_dt and ranks)", NULL, ctx->restart, ctx->restart, sizeof(ctx->restart), NULL));
  PetscOptionsEnd();

  PetscCheck(ctx->checkpoint_every >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint_every %" PetscInt_FMT " must be >= 0", ctx->checkpoint_every);
  PetscCheck(ctx->checkpoint[0], ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint needs a file name");
  PetscCheck(ctx->phase_error > 0 && ctx->phase_error < 1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ts_phase_error %g must lie in (0, 1)", (double)ctx->phase_error);
  PetscCheck(ctx->mesh_h >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_h %g must be > 0 (or 0: chosen from -ts_phase_error)", (double)ctx->mesh_h);
  ctx->mesh_h_set = (PetscBool)(ctx->mesh_h > 0);
  PetscCheck(ctx->r_inner > 0 && ctx->r_inner < ctx->r_outer, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-r_inner %g and -r_outer %g must satisfy 0 < r_inner < r_outer", (double)ctx->r_inner, (double)ctx->r_outer);
  PetscCheck(ctx->mesh_file[0] || !ctx->mesh_h_set || ctx->mesh_h < ctx->r_outer - ctx->r_inner, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_h %g must be smaller than the annulus width r_outer - r_inner = %g", (double)ctx->mesh_h,
             (double)(ctx->r_outer - ctx->r_inner));
  PetscCheck(ctx->degree == 1 || ctx->degree == 2, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-degree %" PetscInt_FMT " must be 1 or 2", ctx->degree);
  PetscCheck(!ctx->curved || ctx->degree == 2, ctx->comm, PETSC_ERR_ARG_INCOMP, "-mesh_curved needs -degree 2 (a P1 field cannot see a curved edge), got -degree %" PetscInt_FMT, ctx->degree);
  PetscCheck(ctx->young > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-young %g must be > 0", (double)ctx->young);
  PetscCheck(ctx->poisson > -1 && ctx->poisson < 0.5, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-poisson %g must lie in (-1, 0.5)", (double)ctx->poisson);
  PetscCheck(ctx->density > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-density %g must be > 0", (double)ctx->density);
  PetscCheck(ctx->dt >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ts_dt %g must be > 0 (or 0: chosen from -ts_phase_error)", (double)ctx->dt);
  ctx->dt_set = (PetscBool)(ctx->dt > 0);
  PetscCheck(ctx->max_time >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ts_max_time %g must be >= 0", (double)ctx->max_time);
  PetscCheck(ctx->max_steps >= -1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ts_max_steps %" PetscInt_FMT " must be >= 0 (or -1 for no cap)", ctx->max_steps);
  PetscCheck(ctx->damping >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-damping %g must be >= 0", (double)ctx->damping);
  PetscCheck(ctx->obstacle_speed > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-obstacle_speed %g must be > 0", (double)ctx->obstacle_speed);
  PetscCheck(ctx->obstacle_depth >= 0 && ctx->obstacle_depth < ctx->r_outer - ctx->r_inner, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-obstacle_depth %g must lie in [0, r_outer - r_inner = %g)", (double)ctx->obstacle_depth, (double)(ctx->r_outer - ctx->r_inner));
  PetscCheck(ctx->theta_b >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-theta_b %g must be >= 0", (double)ctx->theta_b);
  PetscCheck(ctx->ic_amplitude >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ic_amplitude %g must be >= 0", (double)ctx->ic_amplitude);
  PetscCheck(ctx->ic != ROLLER_IC_BUMP || ctx->clamp_outer, ctx->comm, PETSC_ERR_ARG_INCOMP, "-initial_condition bump needs -clamp_outer (the bump vanishes on both circles)");
  PetscCheck(ctx->mms == ROLLER_MMS_NONE || (ctx->clamp_outer && !ctx->obstacle), ctx->comm, PETSC_ERR_ARG_INCOMP, "-mms %s needs -clamp_outer and no -obstacle", RollerMMSTypes[ctx->mms]);
  PetscCheck(!(ctx->obstacle && ctx->coriolis == ROLLER_CORIOLIS_CENTERED), ctx->comm, PETSC_ERR_ARG_INCOMP, "-coriolis_velocity centered makes the step matrix non-symmetric: the step is then no longer a minimization, and -obstacle needs one (use backward or extrapolated)");
  PetscCheck(!(ctx->obstacle && ctx->clamp_outer), ctx->comm, PETSC_ERR_ARG_INCOMP, "-obstacle cannot be combined with -clamp_outer (Gamma_C would be fixed)");
  PetscCheck(!ctx->static_solve || (ctx->omega == 0 && ctx->theta_a == 0 && ctx->ic == ROLLER_IC_REST && ctx->mms == ROLLER_MMS_NONE && !ctx->restart[0] && ctx->max_time > 0), ctx->comm, PETSC_ERR_ARG_INCOMP, "-static needs -omega 0, -theta_a 0, the rest initial condition, no -mms or -restart, and -ts_max_time > 0");
  if (ctx->static_solve) { /* one step from rest to t = max_time with A = K: the right-hand side is 0 */
    ctx->dt        = ctx->max_time;
    ctx->dt_set    = PETSC_TRUE; /* not the accurate default's dt */
    ctx->max_steps = 1;
  }
  if (ctx->mms != ROLLER_MMS_NONE) ctx->ic = ROLLER_IC_MMS;
  PetscCheck(ctx->ic != ROLLER_IC_MMS || ctx->mms != ROLLER_MMS_NONE, ctx->comm, PETSC_ERR_ARG_INCOMP, "-initial_condition mms needs -mms linear or sine");
  PetscCall(RollerLameFromYoung(ctx->young, ctx->poisson, &ctx->lambda, &ctx->mu));
  if (ctx->restart[0]) PetscCall(RollerCheckpointDiscretization(ctx, ctx->restart));
  PetscCall(RollerChooseMeshSize(ctx));
  PetscFunctionReturn(0);
}
