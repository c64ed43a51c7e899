/* The obstacle QP of one step (docs/model.md section 2): the contact context's life (options, create,
   destroy) and the dispatch of a step: its candidate set and the solver of -contact_solver with the re-solve loop
   that makes its answer free of penetration (RollerContactSolveWith, contact_registry.c). Which solvers exist is the
   registry's business; nothing here names one. */
#include "contact_impl.h"

/* The bool values -contact_monitor took before it was a viewer (-contact_monitor false/0/no/off, true/1/...). */
static PetscErrorCode IsBoolString(const char value[], PetscBool *isbool, PetscBool *on)
{
  const char *yes[] = {"1", "true", "yes", "on"}, *no[] = {"0", "false", "no", "off"};

  PetscFunctionBeginUser;
  *isbool = *on = PETSC_FALSE;
  for (size_t i = 0; i < sizeof(yes) / sizeof(yes[0]) && !*isbool; ++i) {
    PetscBool y, n;

    PetscCall(PetscStrcasecmp(value, yes[i], &y));
    PetscCall(PetscStrcasecmp(value, no[i], &n));
    *isbool = (y || n) ? PETSC_TRUE : PETSC_FALSE;
    *on     = y;
  }
  PetscFunctionReturn(0);
}

/* -contact_monitor [viewer]: alone (or true), the text lines on stdout; ascii:F.csv:ascii_csv, a CSV file. */
static PetscErrorCode ContactMonitorCreate(Roller ctx, RollerContact c, const char value[])
{
  PetscBool isbool, on, ascii;

  PetscFunctionBeginUser;
  PetscCall(IsBoolString(value, &isbool, &on));
  if (isbool && on) {
    PetscCall(PetscViewerASCIIGetStdout(ctx->comm, &c->opt.monitor));
    PetscCall(PetscObjectReference((PetscObject)c->opt.monitor));
  }
  if (isbool) PetscFunctionReturn(0);
  PetscCall(PetscOptionsGetViewer(ctx->comm, NULL, NULL, "-contact_monitor", &c->opt.monitor, &c->opt.monitor_format, NULL));
  PetscCall(PetscObjectTypeCompare((PetscObject)c->opt.monitor, PETSCVIEWERASCII, &ascii));
  PetscCheck(ascii, ctx->comm, PETSC_ERR_SUP, "-contact_monitor %s: only ASCII viewers (stdout, ascii:F.txt, ascii:F.csv:ascii_csv)", value);
  PetscFunctionReturn(0);
}

/* Every registered solver is created (cheap; each is set up when first used) so that the one block lists
   all their options, with or without -obstacle. monitor receives the value of -contact_monitor, if given. */
static PetscErrorCode ContactSetFromOptions(Roller ctx, RollerContact c, char monitor[], size_t len, PetscBool *monitor_set)
{
  const char **names;
  int          n;

  PetscFunctionBeginUser;
  PetscCall(RollerContactSolversRegisterAll());
  PetscCall(PetscFunctionListGet(RollerContactSolverList, &names, &n));
  for (c->nsolvers = 0; names[c->nsolvers]; ++c->nsolvers) continue;
  PetscCall(PetscCalloc1(c->nsolvers, &c->solvers));
  for (PetscInt k = 0; k < c->nsolvers; ++k) PetscCall(RollerContactSolverCreate(names[k], &c->solvers[k]));
  PetscCall(PetscFree(names));

  PetscCall(PetscStrncpy(c->opt.solver, "condensed", sizeof(c->opt.solver)));
  c->opt.margin          = 2e-3 * ctx->mesh.r_outer;
  c->opt.rtol            = 1e-12;
  c->opt.max_resolves    = 20;
  c->opt.friction_qp     = ROLLER_BOXQP_ACTIVESET;
  c->opt.friction_rtol   = 1e-10;
  c->opt.friction_max_it = 50;
  c->opt.friction_newton = PETSC_TRUE;
  monitor[0]             = 0;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: contact QP (docs/contact.md)", NULL);
  PetscCall(PetscOptionsFList("-contact_solver", "Per-step QP solver: condensed (Schur complement on Gamma_C, fast), vi (SNES VI), tao (TAO), pcg (the paper's projected CG)", "RollerContactSolverRegister", RollerContactSolverList, "condensed", c->opt.solver,
                              sizeof(c->opt.solver), NULL));
  PetscCall(PetscOptionsBool("-contact_check", "Each step also solve with every other solver; print the differences and KKT residuals", NULL, c->opt.check, &c->opt.check, NULL));
  PetscCall(PetscOptionsString("-contact_monitor", "Print the contact set of every step: nodes, force, extent and centroid along t^k (a viewer: alone stdout, ascii:F.csv:ascii_csv a CSV file)", NULL, monitor, monitor, len, monitor_set));
  PetscCall(PetscOptionsReal("-contact_margin", "Reach of the candidate set beyond the predicted gap (length; < 0 shrinks it, to test the penetration check)", NULL, c->opt.margin, &c->opt.margin, NULL));
  PetscCall(PetscOptionsReal("-contact_rtol", "Relative tolerance of vi, tao (-contact_tao_type, default tron) and the condensed TAO", NULL, c->opt.rtol, &c->opt.rtol, NULL));
  PetscCall(PetscOptionsInt("-contact_max_resolves", "Re-solves allowed per step when a node outside the candidate set penetrates", NULL, c->opt.max_resolves, &c->opt.max_resolves, NULL));
  PetscCall(PetscOptionsEnum("-contact_friction_qp", "With -friction: solver of each Tresca step's box QP (activeset, tao, vi), or lemke: Coulomb as one LCP", NULL, RollerBoxQPTypes, (PetscEnum)c->opt.friction_qp, (PetscEnum *)&c->opt.friction_qp, NULL));
  PetscCall(PetscOptionsReal("-contact_friction_rtol", "With -friction: relative tolerance of the Coulomb fixed point on lambda_N and mu(v)", NULL, c->opt.friction_rtol, &c->opt.friction_rtol, NULL));
  PetscCall(PetscOptionsBool("-contact_friction_newton", "With -friction: solve Coulomb by the semismooth Newton (primal-dual active set) method first, the fixed point of Tresca steps only if it fails", NULL, c->opt.friction_newton, &c->opt.friction_newton, NULL));
  PetscCall(PetscOptionsInt("-contact_friction_max_it", "With -friction: Tresca steps of the fixed point before Lemke's method takes over", NULL, c->opt.friction_max_it, &c->opt.friction_max_it, NULL));
  for (PetscInt k = 0; k < c->nsolvers; ++k)
    if (c->solvers[k]->ops->setfromoptions) PetscCall((*c->solvers[k]->ops->setfromoptions)(c->solvers[k], PetscOptionsObject));
  PetscOptionsEnd();
  RollerCheckOption(ctx->comm, "-contact_friction_rtol", c->opt.friction_rtol, c->opt.friction_rtol > 0 && c->opt.friction_rtol < 1, "in (0, 1)");
  PetscCheck(c->opt.friction_max_it >= 1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_friction_max_it %" PetscInt_FMT " must be >= 1", c->opt.friction_max_it);
  RollerCheckOption(ctx->comm, "-contact_margin", c->opt.margin, c->opt.margin > -ctx->mesh.r_outer, "> -r_outer");
  RollerCheckOption(ctx->comm, "-contact_rtol", c->opt.rtol, c->opt.rtol > 0 && c->opt.rtol < 1, "in (0, 1)");
  PetscCheck(c->opt.max_resolves >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_max_resolves %" PetscInt_FMT " must be >= 0", c->opt.max_resolves);
  for (PetscInt k = 0; k < c->nsolvers; ++k) {
    PetscBool match;

    PetscCall(PetscStrcmp(c->solvers[k]->name, c->opt.solver, &match));
    if (match) c->solver = c->solvers[k];
  }
  if (!c->solver) {
    char names[256] = "";

    for (PetscInt k = 0; k < c->nsolvers; ++k) {
      PetscCall(PetscStrlcat(names, " ", sizeof(names)));
      PetscCall(PetscStrlcat(names, c->solvers[k]->name, sizeof(names)));
    }
    SETERRQ(ctx->comm, PETSC_ERR_USER_INPUT, "-contact_solver %s: no such solver; allowed:%s", c->opt.solver, names);
  }
  {
    PetscBool match;

    PetscCall(PetscStrcmp(c->opt.solver, "condensed", &match));
    PetscCheck(!ctx->axle.on || (match && !c->opt.check), ctx->comm, PETSC_ERR_ARG_INCOMP, "-axle takes -contact_solver condensed (the hub's unknowns are eliminated in its Schur complement), not %s%s", c->opt.solver, c->opt.check ? " or -contact_check" : "");
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactSolversDestroy(RollerContact c)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < c->nsolvers; ++k) PetscCall(RollerContactSolverDestroy(&c->solvers[k]));
  PetscCall(PetscFree(c->solvers));
  c->nsolvers = 0;
  c->solver   = NULL;
  PetscFunctionReturn(0);
}

/* -help without -obstacle: list the contact options and their defaults too (the same block as a run with
   the obstacle reads), without building any of the machinery. */
PetscErrorCode RollerContactHelp(Roller ctx)
{
  struct _n_RollerContact c;
  char                    monitor[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&c, sizeof(c)));
  PetscCall(ContactSetFromOptions(ctx, &c, monitor, sizeof(monitor), NULL));
  PetscCall(ContactSolversDestroy(&c));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactCreate(Roller ctx, RollerContact *contact)
{
  RollerContact c;
  char          monitor[PETSC_MAX_PATH_LEN];
  PetscBool     monitor_set = PETSC_FALSE;
  PetscInt      nc;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&c));
  c->comm = ctx->comm;
  PetscCall(ContactSetFromOptions(ctx, c, monitor, sizeof(monitor), &monitor_set));
  if (monitor_set) PetscCall(ContactMonitorCreate(ctx, c, monitor));
  PetscCall(RollerContactNodesCreate(ctx, c));
  nc = c->nodes.nc;
  PetscCall(PetscMalloc6(nc, &c->step.cand, nc, &c->step.is_cand, nc, &c->step.on_obstacle, nc, &c->step.lower, nc, &c->step.gap, nc, &c->acc.result.lambda));
  PetscCall(PetscArrayzero(c->acc.result.lambda, nc));
  PetscCall(PetscArrayzero(c->step.is_cand, nc));
  PetscCall(VecDuplicate(ctx->state.cur, &c->acc.b));
  PetscCall(VecDuplicate(ctx->state.cur, &c->acc.force));
  PetscCall(VecDuplicate(ctx->state.cur, &c->acc.work));
  /* the step's solver is set up by RollerContactPrepare, in the set-up stage, when the scheme has made its step
     matrices; -contact_check's others when first used */
  if (ctx->obstacle.friction > 0) PetscCall(RollerContactFrictionCreate(ctx, c)); /* none at -friction 0 */
  PetscCall(RollerContactSheetSetUp(ctx, c));
  PetscCall(PetscInfo(NULL, "Contact: %" PetscInt_FMT " Gamma_C nodes (%" PetscInt_FMT " on this rank), solver %s\n", nc, c->nodes.nown, c->solver->name));
  *contact = c;
  PetscFunctionReturn(0);
}

/* xi = argmin 1/2 xi^T A xi - b^T xi over the admissible set at t (docs/model.md section 2), A the stage's
   operator. */
PetscErrorCode RollerContactSolve(Roller ctx, RollerContact c, const RollerContactStage *stage, PetscReal t, Vec b, Vec xi)
{
  PetscFunctionBeginUser;
  c->step.op = stage->op;
  PetscCall(RollerContactFrictionRemember(c));
  { /* -rom_residual with the branches: the level two back */
    PetscReal *from;

    PetscCall(RollerContactResidualOf(c, stage->x_aux, &from));
    PetscCall(RollerContactResidualBegin(c, from));
  }
  PetscCall(RollerContactSetUpStep(ctx, c, stage, t));
  PetscCall(VecCopy(b, c->acc.b));
  PetscCall(RollerContactSolveWith(ctx, c, c->solver, b, xi, &c->acc.result));
  if (RollerContactSheetMoves(c)) { /* the sheet's case (sliding either way, or held): solved again in the one that holds */
    PetscBool holds;

    PetscCall(RollerContactSheetAccept(ctx, c, c->acc.result.lambda_t, &holds));
    for (PetscInt k = 0; !holds && k < 2; ++k) {
      PetscCall(RollerContactSolveWith(ctx, c, c->solver, b, xi, &c->acc.result));
      PetscCall(RollerContactSheetAccept(ctx, c, c->acc.result.lambda_t, &holds));
    }
    if (!holds) { /* none holds: held at its bound (contact_sheet.c) */
      c->sheet.X[3] = 0.0;
      PetscCall(RollerContactSolveWith(ctx, c, c->solver, b, xi, &c->acc.result));
      PetscCall(RollerContactSheetHoldAtBound(ctx, c));
    }
  }
  c->acc.solved = PETSC_TRUE;
  if (c->opt.check) PetscCall(RollerContactCheckStep(ctx, c, b, xi));
  PetscFunctionReturn(0);
}

/* The contact force of the last solve as a vector of the displacement space, E (N lambda + T lambda_t): the solve's
   xi satisfies A xi = b + f (a scheme gets M xi from this instead of a product with M). */
PetscErrorCode RollerContactForceVector(RollerContact c, Vec f)
{
  PetscFunctionBeginUser;
  PetscCall(RollerContactForce(c, c->acc.result.lambda, c->friction ? c->acc.result.lambda_t : NULL, f));
  PetscFunctionReturn(0);
}

/* Set-up for the step matrix op of a scheme, in the set-up stage: the solver's work that depends on the matrix
   (the condensed solver's S = E^T A^{-1} E, for the Gamma_C nodes the run will need). */
PetscErrorCode RollerContactPrepare(Roller ctx, RollerContact c, const RollerStepOperator *op)
{
  PetscFunctionBeginUser;
  c->step.op = op;
  PetscCall(RollerContactSolverSetUp(c->solver, ctx, c));
  if (c->solver->ops->prepare) PetscCall((*c->solver->ops->prepare)(c->solver, ctx, c, op));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactDestroy(RollerContact *contact)
{
  RollerContact c = *contact;

  PetscFunctionBeginUser;
  if (!c) PetscFunctionReturn(0);
  PetscCall(RollerContactCheckSummary(c));
  PetscCall(ContactSolversDestroy(c));
  PetscCall(RollerContactFrictionDestroy(c->comm, &c->friction));
  if (c->sheet.bound_steps)
    PetscCall(PetscPrintf(c->comm, "sheet: in %" PetscInt_FMT " steps no case of the sheet was consistent with the step's mu(v); it was held with the force the step needed, above -sheet_resistance (the CSV's coulomb_fallback 4)\n", c->sheet.bound_steps));
  PetscCall(PetscFree(c->acc.result.lambda_t));
  PetscCall(PetscViewerDestroy(&c->opt.monitor));
  PetscCall(RollerContactNodesDestroy(c));
  PetscCall(VecDestroy(&c->acc.b));
  PetscCall(VecDestroy(&c->acc.force));
  PetscCall(VecDestroy(&c->acc.work));
  PetscCall(VecDestroy(&c->check.xi));
  PetscCall(PetscFree(c->check.result.lambda));
  PetscCall(PetscFree2(c->check.max_diff, c->check.max_kkt));
  PetscCall(PetscFree6(c->step.cand, c->step.is_cand, c->step.on_obstacle, c->step.lower, c->step.gap, c->acc.result.lambda));
  PetscCall(PetscFree(c));
  *contact = NULL;
  PetscFunctionReturn(0);
}
