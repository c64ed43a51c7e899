/* -contact_solver vi: SNES VI (reduced-space active set Newton, vinewtonrsls, by default) on the rotated primal
   problem of contact_primal.c, with a full Newton step (the problem is quadratic) and a direct solve of each
   reduced system; options prefix contact_vi_. */
#include "contact_impl.h"

typedef struct {
  RollerContactPrimal pr;
  SNES                snes;
} VI;

/* F(z) = A_hat z - b_hat, the gradient of 1/2 z^T A_hat z - b_hat^T z. */
static PetscErrorCode VIFunction(SNES snes, Vec z, Vec f, void *ptr)
{
  RollerContactPrimal *pr = (RollerContactPrimal *)ptr;

  PetscFunctionBeginUser;
  PetscCall(MatMult(pr->Ahat, z, f));
  PetscCall(VecAXPY(f, -1.0, pr->bhat));
  PetscFunctionReturn(0);
}

static PetscErrorCode VIJacobian(SNES snes, Vec z, Mat J, Mat P, void *ptr)
{
  PetscFunctionBeginUser;
  PetscFunctionReturn(0); /* A_hat, refreshed by RollerContactPrimalSetUpStep */
}

static PetscErrorCode VISetUp(RollerContactSolver s, Roller ctx, RollerContact c)
{
  VI            *vi = (VI *)s->data;
  KSP            ksp;
  Vec            f;
  SNESLineSearch ls;

  PetscFunctionBeginUser;
  PetscCall(RollerContactPrimalSetUp(ctx, c, &vi->pr));
  PetscCall(SNESCreate(ctx->comm, &vi->snes));
  PetscCall(SNESSetOptionsPrefix(vi->snes, "contact_vi_"));
  PetscCall(SNESSetType(vi->snes, SNESVINEWTONRSLS));
  PetscCall(VecDuplicate(vi->pr.z, &f));
  PetscCall(SNESSetFunction(vi->snes, f, VIFunction, &vi->pr));
  PetscCall(VecDestroy(&f));
  PetscCall(SNESSetJacobian(vi->snes, vi->pr.Ahat, vi->pr.Ahat, VIJacobian, &vi->pr));
  PetscCall(SNESGetLineSearch(vi->snes, &ls));
  PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHBASIC));
  PetscCall(SNESGetKSP(vi->snes, &ksp));
  PetscCall(RollerDirectSolverDefaults(ksp, PCCHOLESKY));
  PetscCall(SNESSetTolerances(vi->snes, PETSC_DEFAULT, c->opt.rtol, 1e-14, 100, PETSC_DEFAULT));
  PetscCall(SNESSetFromOptions(vi->snes));
  PetscFunctionReturn(0);
}

static PetscErrorCode VISolve(RollerContactSolver s, Roller ctx, RollerContact c, Vec b, Vec xi, RollerContactResult *res)
{
  VI                 *vi = (VI *)s->data;
  SNESConvergedReason reason;
  PetscReal           rtol, stol;
  PetscInt            maxit, maxf;

  PetscFunctionBeginUser;
  PetscCall(RollerContactPrimalSetUpStep(ctx, c, &vi->pr, b));
  /* the absolute tolerance follows the force scale of the step */
  PetscCall(SNESGetTolerances(vi->snes, NULL, &rtol, &stol, &maxit, &maxf));
  PetscCall(SNESSetTolerances(vi->snes, c->opt.rtol * vi->pr.fscale, rtol, stol, maxit, maxf));
  PetscCall(SNESVISetVariableBounds(vi->snes, vi->pr.lower, vi->pr.upper));
  PetscCall(SNESSolve(vi->snes, NULL, vi->pr.z));
  PetscCall(SNESGetConvergedReason(vi->snes, &reason));
  PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "Contact QP at t = %g: SNES VI did not converge: %s", (double)c->step.t, SNESConvergedReasons[reason]);
  PetscCall(SNESGetIterationNumber(vi->snes, &res->its));
  PetscCall(RollerContactPrimalFinish(ctx, c, &vi->pr, xi, res));
  PetscFunctionReturn(0);
}

static PetscErrorCode VIDestroy(RollerContactSolver s)
{
  VI *vi = (VI *)s->data;

  PetscFunctionBeginUser;
  PetscCall(SNESDestroy(&vi->snes));
  PetscCall(RollerContactPrimalDestroy(&vi->pr));
  PetscFunctionReturn(0);
}

static const RollerContactSolverOps ops = {.setup = VISetUp, .solve = VISolve, .destroy = VIDestroy};

PetscErrorCode RollerContactSolverCreate_VI(RollerContactSolver s)
{
  VI *vi;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&vi));
  s->data = vi;
  *s->ops = ops;
  PetscFunctionReturn(0);
}
