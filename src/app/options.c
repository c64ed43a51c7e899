/* The command-line contract of docs/model.md section 6: each component reads and validates its own options in its
   own block (listed by -help under its own heading); the checks of combinations that span components are here,
   in one place (RollerSetFromOptions, "cross-component checks"). */
#include "integrate/integrate.h"
#include "modes/modes.h"
#include "rom/rom.h"
#include "sweep/sweep.h"

const char *const RollerInitialConditions[] = {"rest", "bump", "mms", "mode", "RollerInitialCondition", "ROLLER_IC_", NULL};
const char *const RollerMMSTypes[]          = {"none", "linear", "sine", "RollerMMSType", "ROLLER_MMS_", NULL};

/* A sweep creates a Roller per case: the stages are registered by the first and found by name by the others, so
   -log_view sums every case's set-up, modes, ... in one line each. */
static PetscErrorCode RegisterStage(const char name[], PetscLogStage *stage)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogStageGetId(name, stage));
  if (*stage < 0) PetscCall(PetscLogStageRegister(name, stage));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerCreate(MPI_Comm comm, Roller *roller)
{
  Roller ctx;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&ctx));
  ctx->comm               = comm;
  ctx->mesh.r_inner       = 0.25;
  ctx->mesh.r_outer       = 0.5;
  ctx->disc.degree        = 2;
  ctx->disc.coriolis      = ROLLER_CORIOLIS_EXTRAPOLATED;
  ctx->disc.redundant_max = 100000;
  ctx->disc.schur         = PETSC_TRUE;
  ctx->disc.schur_ranks   = 8;
  ctx->ts.phase_error     = 0.01;
  ctx->material.young     = 0.1;
  ctx->material.poisson   = 0.49;
  ctx->material.density   = 1.0;
  ctx->rotation.omega     = PETSC_PI / 10.0;
  ctx->obstacle.speed     = 0.005;
  ctx->obstacle.depth     = 0.025;
  ctx->ts.max_time        = 20.0;
  ctx->ts.max_steps       = -1;
  ctx->init.type          = ROLLER_IC_REST;
  ctx->init.amplitude     = 1e-3;
  ctx->init.mms           = ROLLER_MMS_NONE;
  PetscCall(PetscStrncpy(ctx->ck.file, "checkpoint.h5", sizeof(ctx->ck.file)));
  PetscCall(RollerSignalsInstall()); /* a SIGTERM during setup still ends in a checkpoint after step 1 */
  PetscCall(RegisterStage("Roller setup", &ctx->stage[ROLLER_STAGE_SETUP]));
  PetscCall(RegisterStage("Roller step", &ctx->stage[ROLLER_STAGE_STEP]));
  PetscCall(RegisterStage("Roller contact", &ctx->stage[ROLLER_STAGE_CONTACT]));
  PetscCall(RegisterStage("Roller diagnostics", &ctx->stage[ROLLER_STAGE_DIAGNOSTICS]));
  PetscCall(RegisterStage("Roller output", &ctx->stage[ROLLER_STAGE_OUTPUT]));
  PetscCall(RegisterStage("Roller modes", &ctx->stage[ROLLER_STAGE_MODES]));
  *roller = ctx;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSetFromOptions(Roller ctx)
{
  char      table[256] = "";
  PetscBool given[4]   = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE}; /* -friction, _static, _decay, _table */

  PetscFunctionBeginUser;
  PetscCall(RollerOptionsCheckValues(ctx->comm)); /* a word where a number goes, named before PETSc parses it */
  PetscCall(RollerMeshSetFromOptions(ctx));

  PetscCall(RollerDiscretizationSetFromOptions(ctx));
  PetscCall(RollerMaterialSetFromOptions(ctx));
  PetscCall(RollerRotationSetFromOptions(ctx));

  PetscOptionsBegin(ctx->comm, NULL, "Roller: obstacle (the sheet) g(t) = min(speed t, depth) - r_outer, X(t) = sheet_speed t; friction (docs/friction.md)", NULL);
  PetscCall(PetscOptionsBool("-obstacle", "Enable the rigid flat obstacle", NULL, ctx->obstacle.on, &ctx->obstacle.on, NULL));
  PetscCall(PetscOptionsReal("-obstacle_speed", "Obstacle speed v", NULL, ctx->obstacle.speed, &ctx->obstacle.speed, NULL));
  PetscCall(PetscOptionsReal("-obstacle_depth", "Final indentation depth", NULL, ctx->obstacle.depth, &ctx->obstacle.depth, NULL));
  PetscCall(PetscOptionsReal("-sheet_speed", "Lab-frame speed V of the sheet along e1", NULL, ctx->obstacle.sheet_speed, &ctx->obstacle.sheet_speed, NULL));
  PetscCall(PetscOptionsReal("-friction", "Coulomb friction coefficient mu (kinetic); 0: frictionless, no friction machinery", NULL, ctx->obstacle.friction, &ctx->obstacle.friction, &given[0]));
  ctx->obstacle.friction_static = ctx->obstacle.friction;
  PetscCall(PetscOptionsReal("-friction_static", "Static coefficient mu_s of mu(v) = mu + (mu_s - mu) exp(-|v|/v_c) (default: mu)", NULL, ctx->obstacle.friction_static, &ctx->obstacle.friction_static, &given[1]));
  PetscCall(PetscOptionsReal("-friction_decay", "Slip speed v_c of the velocity weakening (0: none, constant mu)", NULL, ctx->obstacle.friction_decay, &ctx->obstacle.friction_decay, &given[2]));
  PetscCall(PetscOptionsString("-friction_table", "A measured mu(|v|) instead: v1:mu1,v2:mu2,... (slip speeds >= 0 increasing, coefficients > 0), monotone cubic interpolation, constant beyond the ends; switches friction on, without -friction, -friction_static, -friction_decay (default: none)", NULL, table, table, sizeof(table), &given[3]));
  PetscOptionsEnd();
  if (given[3]) { /* the table replaces the exponential law (docs/friction.md section 1): with its options only where the
                     command line's table overrides an options file's law, with a warning */
    const char *names[]  = {"-friction", "-friction_static", "-friction_decay"};
    PetscReal   values[] = {ctx->obstacle.friction, ctx->obstacle.friction_static, ctx->obstacle.friction_decay};
    PetscBool   cli_table, cli;

    PetscCall(RollerOptionNameGivenOnCommandLine("-friction_table", &cli_table));
    for (PetscInt i = 0; i < 3; ++i) {
      if (!given[i]) continue;
      PetscCall(RollerOptionNameGivenOnCommandLine(names[i], &cli));
      PetscCheck(cli_table && !cli, ctx->comm, PETSC_ERR_ARG_INCOMP, "-friction_table is the whole law mu(v) and switches friction on: give it without %s (given: %g)", names[i], (double)values[i]);
      PetscCall(PetscFPrintf(ctx->comm, PETSC_STDERR, "Warning: %s %g, set by an options file, is replaced by the command line's -friction_table\n", names[i], (double)values[i]));
    }
  }
  RollerCheckOption(ctx->comm, "-sheet_speed", ctx->obstacle.sheet_speed, PETSC_TRUE, "");
  RollerCheckOption(ctx->comm, "-obstacle_depth", ctx->obstacle.depth, ctx->obstacle.depth >= 0, ">= 0 (and < r_outer - r_inner)");
  RollerCheckOption(ctx->comm, "-friction_static", ctx->obstacle.friction_static, PETSC_TRUE, "");
  RollerCheckOption(ctx->comm, "-friction", ctx->obstacle.friction, ctx->obstacle.friction >= 0, ">= 0");
  PetscCheck(ctx->obstacle.friction_static >= ctx->obstacle.friction, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-friction_static %g must be >= -friction %g", (double)ctx->obstacle.friction_static, (double)ctx->obstacle.friction);
  RollerCheckOption(ctx->comm, "-friction_decay", ctx->obstacle.friction_decay, ctx->obstacle.friction_decay >= 0, ">= 0 (0: no velocity weakening)");
  PetscCheck(ctx->obstacle.friction_static == ctx->obstacle.friction || ctx->obstacle.friction_decay > 0, ctx->comm, PETSC_ERR_ARG_INCOMP, "-friction_static %g differs from -friction %g: give the slip speed of the weakening, -friction_decay v_c > 0",
             (double)ctx->obstacle.friction_static, (double)ctx->obstacle.friction);
  if (given[3]) {     /* the table is the whole law mu(v): friction its end mu_n, friction_static its mu_1 (docs/friction.md section 1) */
    const char *text; /* all of it: the block's buffer holds its start (for -help) */

    PetscCall(PetscOptionsFindPair(NULL, NULL, "-friction_table", &text, NULL));
    PetscCall(RollerFrictionTableSetUp(ctx->comm, text ? text : "", &ctx->obstacle.table));
    ctx->obstacle.friction        = ctx->obstacle.table.mu[ctx->obstacle.table.n - 1];
    ctx->obstacle.friction_static = ctx->obstacle.table.mu[0];
    ctx->obstacle.friction_decay  = 0;
  }
  PetscCall(RollerMassSetFromOptions(ctx));
  PetscCall(RollerAxleSetFromOptions(ctx));

  PetscCall(RollerTimeStepSetFromOptions(ctx));
  PetscCall(RollerInitialSetFromOptions(ctx));

  PetscCall(RollerCheckpointSetFromOptions(ctx));
  PetscCall(RollerModesSetFromOptions(ctx));
  PetscCall(RollerRomSetFromOptions(ctx));
  {
    PetscBool help;

    PetscCall(PetscOptionsHasHelp(NULL, &help));
    if (help) { /* -help lists the sweep's options too (a sweep reads them in RollerSweep, before any Roller) */
      RollerSweepPlan plan;

      PetscCall(RollerSweepSetFromOptions(ctx->comm, &plan));
      PetscCall(RollerSweepPlanDestroy(&plan));
    }
  }

  RollerCheckOption(ctx->comm, "-obstacle_speed", ctx->obstacle.speed, ctx->obstacle.speed > 0, "> 0");
  /* cross-component checks */
  /* The sheet's options need -obstacle. -modes of the free annulus ignores those an options file sets, with a warning,
     so that a contact scene's YAML runs with -obstacle false -modes unchanged (jobs/printer_roller.yaml); given on
     the command line they are refused there too. */
  if (!ctx->obstacle.on) {
    const char *names[]  = {"-friction", "-sheet_speed", "-friction_static", "-friction_decay", "-friction_table"};
    PetscReal   values[] = {ctx->obstacle.friction, ctx->obstacle.sheet_speed, ctx->obstacle.friction_static, ctx->obstacle.friction_decay, (PetscReal)ctx->obstacle.table.n};

    for (PetscInt i = 0; i < 5; ++i) {
      char      value[PETSC_MAX_PATH_LEN + 2];
      PetscBool cli;

      if (values[i] == 0 || (i == 2 && values[2] == values[0]) || (ctx->obstacle.table.n && i != 1 && i != 4)) continue; /* mu_s defaults to mu; a table's ends */
      if (i == 4) PetscCall(PetscSNPrintf(value, sizeof(value), "'%s'", table));
      else PetscCall(PetscSNPrintf(value, sizeof(value), "%.6g", (double)values[i]));
      PetscCall(RollerOptionNameGivenOnCommandLine(names[i], &cli));
      PetscCheck(ctx->eig.on && !cli, ctx->comm, PETSC_ERR_ARG_INCOMP, "%s %s needs -obstacle (the sheet)%s", names[i], value, ctx->eig.on ? ": -modes without -obstacle are the free roller's" : "");
      PetscCall(PetscFPrintf(ctx->comm, PETSC_STDERR, "Warning: %s %s, set by an options file, is not used by -modes without -obstacle\n", names[i], value));
    }
  }
  PetscCheck(ctx->obstacle.depth >= 0 && ctx->obstacle.depth < ctx->mesh.r_outer - ctx->mesh.r_inner, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-obstacle_depth %g must lie in [0, r_outer - r_inner = %g)", (double)ctx->obstacle.depth,
             (double)(ctx->mesh.r_outer - ctx->mesh.r_inner));
  PetscCheck(ctx->init.type != ROLLER_IC_BUMP || ctx->disc.clamp_outer, ctx->comm, PETSC_ERR_ARG_INCOMP, "-initial_condition bump needs -clamp_outer (the bump vanishes on both circles)");
  PetscCheck(ctx->init.mms == ROLLER_MMS_NONE || (ctx->disc.clamp_outer && !ctx->obstacle.on), ctx->comm, PETSC_ERR_ARG_INCOMP, "-mms %s needs -clamp_outer and no -obstacle", RollerMMSTypes[ctx->init.mms]);
  PetscCheck(!(ctx->obstacle.on && ctx->disc.coriolis == ROLLER_CORIOLIS_CENTERED), ctx->comm, PETSC_ERR_ARG_INCOMP, "-coriolis_velocity centered makes the step matrix non-symmetric: the step is then no longer a minimization, and -obstacle needs one (use backward or extrapolated)");
  PetscCheck(!(ctx->obstacle.on && ctx->disc.clamp_outer), ctx->comm, PETSC_ERR_ARG_INCOMP, "-obstacle cannot be combined with -clamp_outer (Gamma_C would be fixed)");
  PetscCheck(!(ctx->obstacle.on && ctx->disc.degree > 2), ctx->comm, PETSC_ERR_ARG_INCOMP, "-obstacle needs -degree 1 or 2 (the contact nodes and mass layer are P1/P2), got -degree %" PetscInt_FMT, ctx->disc.degree);
  PetscCheck(!ctx->disc.static_solve || (ctx->rotation.omega == 0 && ctx->rotation.a == 0 && ctx->init.type == ROLLER_IC_REST && ctx->init.mms == ROLLER_MMS_NONE && !ctx->ck.restart[0] && ctx->ts.max_time > 0), ctx->comm, PETSC_ERR_ARG_INCOMP, "-static needs -omega 0, -theta_a 0, the rest initial condition, no -mms or -restart, and -ts_max_time > 0");
  PetscCheck(!(ctx->eig.on && ctx->obstacle.on && ctx->eig.frame != ROLLER_FRAME_LAB), ctx->comm, PETSC_ERR_ARG_INCOMP, "-modes with -obstacle linearizes about the steady rolling or sliding state, which is steady only in the lab frame: -modes_frame lab, not %s",
             RollerFrames[ctx->eig.frame]);
  PetscCheck(!(ctx->eig.on && ctx->disc.contact_mass != ROLLER_CONTACT_MASS_CONSISTENT), ctx->comm, PETSC_ERR_ARG_INCOMP, "-modes takes the consistent mass (-contact_mass consistent), not %s", RollerContactMasses[ctx->disc.contact_mass]);
  PetscCheck(!(ctx->eig.on && (ctx->rotation.a != 0 || ctx->ck.restart[0] || ctx->disc.static_solve)), ctx->comm, PETSC_ERR_ARG_INCOMP, "-modes linearizes about steady rotation: it takes no -theta_a, -restart or -static");
  PetscCheck(!(ctx->init.mms != ROLLER_MMS_NONE && ctx->material.rubber == ROLLER_RUBBER_MAXWELL), ctx->comm, PETSC_ERR_ARG_INCOMP, "-mms %s: the manufactured solutions' loads are those of the elastic or Kelvin-Voigt solid, not of -rubber maxwell",
             RollerMMSTypes[ctx->init.mms]);
  PetscCheck(!(ctx->eig.on && ctx->obstacle.sheet_mass > 0), ctx->comm, PETSC_ERR_SUP, "-sheet_mass with -modes: the steady state takes the sheet's speed -sheet_speed (the force balance of a moving sheet is the transient's)");
  if (ctx->axle.on) { /* what the hub's elimination (model/axle.h) carries */
    PetscCheck(!(ctx->eig.on && ctx->eig.frame != ROLLER_FRAME_LAB && ctx->rotation.omega != 0), ctx->comm, PETSC_ERR_ARG_INCOMP, "-axle with -modes: the hub's guide is the lab's vertical, steady in the lab frame only: -modes_frame lab (or -omega 0), not %s",
               RollerFrames[ctx->eig.frame]);
    PetscCheck(!(ctx->eig.on && ctx->disc.damping != 0 && ctx->rotation.omega != 0), ctx->comm, PETSC_ERR_SUP, "-axle with -modes and -omega != 0: the mass damping's rotational form B_L does not border the hub's rows: -damping %g must be 0 (the Kelvin-Voigt -viscosity is carried)",
               (double)ctx->disc.damping);
    PetscCheck(!(ctx->eig.on && ctx->material.rubber == ROLLER_RUBBER_MAXWELL && ctx->eig.frame == ROLLER_FRAME_LAB && ctx->rotation.omega != 0 && ctx->eig.branch_transport), ctx->comm, PETSC_ERR_SUP, "-axle with -modes, -rubber maxwell and -omega != 0: the branches' transport B_L does not border the hub's rows: -modes_branch_transport must be false (the branches frozen in the lab, docs/squeal.md 1.2), got true");
    PetscCheck(!ctx->disc.static_solve && ctx->init.mms == ROLLER_MMS_NONE, ctx->comm, PETSC_ERR_ARG_INCOMP, "-axle takes no -static or -mms");
    PetscCheck(ctx->disc.coriolis != ROLLER_CORIOLIS_CENTERED, ctx->comm, PETSC_ERR_ARG_INCOMP, "-axle takes -coriolis_velocity backward or extrapolated, not centered");
    PetscCheck(ctx->disc.contact_mass == ROLLER_CONTACT_MASS_CONSISTENT, ctx->comm, PETSC_ERR_ARG_INCOMP, "-axle takes the consistent mass (-contact_mass consistent), not %s", RollerContactMasses[ctx->disc.contact_mass]);
    PetscCheck(!ctx->disc.clamp_outer, ctx->comm, PETSC_ERR_ARG_INCOMP, "-axle cannot be combined with -clamp_outer");
  }
  if (ctx->disc.static_solve) { /* one step from rest to t = max_time with A = K: the right-hand side is 0 */
    ctx->ts.dt        = ctx->ts.max_time;
    ctx->ts.dt_set    = PETSC_TRUE; /* not the accurate default's dt */
    ctx->ts.max_steps = 1;
  }
  if (ctx->ck.restart[0]) PetscCall(RollerCheckpointDiscretization(ctx, ctx->ck.restart));
  PetscCall(RollerChooseMeshSize(ctx));
  if (ctx->obstacle.on && ctx->obstacle.depth > 0 && !ctx->mesh.file[0] && !ctx->eig.on) { /* said once */
    const PetscReal a = PetscSqrtReal(ctx->mesh.r_outer * ctx->obstacle.depth), h_c = ctx->mesh.h_contact > 0 ? ctx->mesh.h_contact : ctx->mesh.h;

    if (h_c > a)
      PetscCall(PetscFPrintf(ctx->comm, PETSC_STDERR, "Warning: the edge length on Gamma_C, %.6g, is longer than the contact half-width sqrt(r_outer depth) = %.6g: the contact patch falls between nodes (the default: no -mesh_h, or -mesh_h_contact %.6g)\n", (double)h_c, (double)a, (double)(a / 5)));
  }
  PetscFunctionReturn(0);
}
