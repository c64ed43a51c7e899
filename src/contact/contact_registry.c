/* The registry of contact solvers (-contact_solver NAME) and the life of a solver object: create, set up, a solve
   with the re-solve loop that makes its answer free of penetration (RollerContactSolveWith: the step's solve in
   contact.c, -contact_check's others in contact_report.c), destroy. A solver is one file with a create function
   that fills the object's ops and data; RollerContactSolversRegisterAll names the built-in ones, and the dispatch
   (contact.c) only calls ops, so adding a solver is that file and one line below (docs/contact.md, "Adding a
   contact solver"). */
#include "contact_impl.h"

PetscFunctionList RollerContactSolverList = NULL;
static PetscBool  RegisterAllCalled       = PETSC_FALSE;

/* At PetscFinalize: the list is PETSc memory, and a later PetscInitialize starts a fresh one. */
static PetscErrorCode ContactSolversFinalize(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&RollerContactSolverList));
  RegisterAllCalled = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* The built-in solvers; their order is the order of -contact_check and of the -help list. */
PetscErrorCode RollerContactSolversRegisterAll(void)
{
  PetscFunctionBeginUser;
  if (RegisterAllCalled) PetscFunctionReturn(0);
  RegisterAllCalled = PETSC_TRUE; /* first: RollerContactSolverRegister calls this function */
  PetscCall(PetscRegisterFinalize(ContactSolversFinalize));
  PetscCall(RollerContactSolverRegister("condensed", RollerContactSolverCreate_Condensed));
  PetscCall(RollerContactSolverRegister("vi", RollerContactSolverCreate_VI));
  PetscCall(RollerContactSolverRegister("tao", RollerContactSolverCreate_Tao));
  PetscCall(RollerContactSolverRegister("pcg", RollerContactSolverCreate_PCG));
  PetscFunctionReturn(0);
}

/* Adds (or replaces) a solver under name; the built-in ones are registered first, so the order is stable. */
PetscErrorCode RollerContactSolverRegister(const char name[], PetscErrorCode (*create)(RollerContactSolver))
{
  PetscFunctionBeginUser;
  PetscCall(RollerContactSolversRegisterAll());
  PetscCall(PetscFunctionListAdd(&RollerContactSolverList, name, create));
  PetscFunctionReturn(0);
}

/* The solver registered as name, with its ops and data but not set up (cheap: every registered solver is
   created with the contact so that -help lists their options and -contact_check can use them). */
PetscErrorCode RollerContactSolverCreate(const char name[], RollerContactSolver *solver)
{
  PetscErrorCode (*create)(RollerContactSolver) = NULL;
  RollerContactSolver s;

  PetscFunctionBeginUser;
  PetscCall(RollerContactSolversRegisterAll());
  PetscCall(PetscFunctionListFind(RollerContactSolverList, name, &create));
  PetscCheck(create, PETSC_COMM_SELF, PETSC_ERR_ARG_UNKNOWN_TYPE, "Unknown contact solver %s (registered: see -help, -contact_solver)", name);
  PetscCall(PetscNew(&s));
  PetscCall(PetscStrallocpy(name, &s->name));
  PetscCall((*create)(s));
  PetscCheck(s->ops->solve, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Contact solver %s has no solve operation", name);
  *solver = s;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactSolverSetUp(RollerContactSolver s, Roller ctx, RollerContact c)
{
  PetscFunctionBeginUser;
  if (s->setupcalled) PetscFunctionReturn(0);
  if (s->ops->setup) PetscCall((*s->ops->setup)(s, ctx, c));
  s->setupcalled = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* Solve with one solver on the step's candidate set; then check ALL Gamma_C nodes, add every non-candidate
   that penetrates, re-solve. res->its sums the iterations of all passes. */
PetscErrorCode RollerContactSolveWith(Roller ctx, RollerContact c, RollerContactSolver s, Vec b, Vec xi, RollerContactResult *res)
{
  PetscInt its = 0;

  PetscFunctionBeginUser;
  PetscCall(RollerContactSolverSetUp(s, ctx, c));
  for (PetscInt pass = 0;; ++pass) {
    PetscInt  added;
    PetscReal gap_min;

    PetscCall((*s->ops->solve)(s, ctx, c, b, xi, res));
    PetscCall(RollerContactReducedResidual(c, res, xi)); /* -rom_residual: the level's R f_C */
    its += res->its;
    PetscCall(RollerContactGather(c, xi, c->nodes.red));
    PetscCall(RollerContactGaps(c, c->nodes.red, c->step.gap, &gap_min));
    PetscCall(RollerContactAddPenetrating(ctx, c, &added));
    if (!added) break;
    c->step.resolves++;
    PetscCall(PetscInfo(NULL, "Contact %s: %" PetscInt_FMT " nodes outside the candidate set penetrate (gap %g), re-solving with %" PetscInt_FMT " candidates\n", s->name, added, (double)gap_min, c->step.ncand));
    PetscCheck(pass < c->opt.max_resolves, ctx->comm, PETSC_ERR_CONV_FAILED, "Contact at t = %g: nodes outside the candidate set still penetrate after %" PetscInt_FMT " re-solves (-contact_max_resolves)", (double)c->step.t, c->opt.max_resolves);
  }
  res->its = its;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactSolverDestroy(RollerContactSolver *solver)
{
  RollerContactSolver s = *solver;

  PetscFunctionBeginUser;
  if (!s) PetscFunctionReturn(0);
  if (s->ops->destroy) PetscCall((*s->ops->destroy)(s)); /* what the data holds */
  PetscCall(PetscFree(s->data));
  PetscCall(PetscFree(s->name));
  PetscCall(PetscFree(s));
  *solver = NULL;
  PetscFunctionReturn(0);
}
