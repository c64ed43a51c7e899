/* The registry of contact solvers (-contact_solver NAME) and the life of a solver object. A solver is one
   file with a create function that fills the object's ops and data; RollerContactSolversRegisterAll names
   the built-in ones, and the dispatch (contact.c) only calls ops, so adding a solver is that file and one
   line below (docs/contact.md, "Adding a contact solver"). */
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
