/* -contact_solver tao: a TAO bound-constrained solver on the rotated primal problem of contact_primal.c,
   options prefix contact_ (-contact_tao_type, default tron: the fastest TAO type measured, docs/contact.md).
   A quasi-Newton type (bqnls, bqnk*) gets the exact inverse Hessian Q^T A^{-1} Q as its initial matrix J0
   (-contact_tao_j0, default on), a solve with the step factorization. */
#include "contact_impl.h"

typedef struct {
  RollerContactPrimal pr;
  RollerContactTaoQP  qp; /* 1/2 z^T A_hat z - b_hat^T z */
  Tao                 tao;
  PetscBool           j0;
} TaoSolver;

static PetscErrorCode TaoSolverSetFromOptions(RollerContactSolver s, PetscOptionItems *PetscOptionsObject)
{
  TaoSolver *ts = (TaoSolver *)s->data;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsBool("-contact_tao_j0", "Quasi-Newton TAO types (bqnls, bqnk*): the exact inverse Hessian Q^T A^{-1} Q as J0", NULL, ts->j0, &ts->j0, NULL));
  PetscFunctionReturn(0);
}

/* f = 1/2 x^T H x + sign c^T x and its gradient H x + sign c: the callbacks of this solver (sign -1, c = b_hat)
   and of the condensed TAO (contact_lcp.c: sign +1, c = d). */
PetscErrorCode RollerContactTaoQPObjective(Tao tao, Vec x, PetscReal *f, Vec g, void *ptr)
{
  RollerContactTaoQP *qp = (RollerContactTaoQP *)ptr;
  PetscScalar         xHx, cx;

  PetscFunctionBeginUser;
  PetscCall(MatMult(qp->H, x, g));
  PetscCall(VecDot(x, g, &xHx));
  PetscCall(VecDot(qp->c, x, &cx));
  *f = PetscRealPart(0.5 * xHx + qp->sign * cx);
  PetscCall(VecAXPY(g, qp->sign, qp->c));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactTaoQPHessian(Tao tao, Vec x, Mat H, Mat P, void *ptr)
{
  PetscFunctionBeginUser;
  PetscFunctionReturn(0); /* H is constant (G), or refreshed in place before each solve (A_hat) */
}

/* y = A_hat^{-1} x = Q^T A^{-1} Q x (Q is orthogonal): the step factorization, no new one. */
static PetscErrorCode ApplyInverse(PC pc, Vec x, Vec y)
{
  RollerContactPrimal *pr;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &pr));
  PetscCall(MatMult(pr->Q, x, pr->work[0]));
  PetscCall(KSPSolve(pr->ksp, pr->work[0], pr->work[1]));
  PetscCall(MatMultTranspose(pr->Q, pr->work[1], y));
  PetscFunctionReturn(0);
}

static PetscErrorCode TaoSolverSetUp(RollerContactSolver s, Roller ctx, RollerContact c)
{
  TaoSolver *ts = (TaoSolver *)s->data;
  PetscBool  qn;

  PetscFunctionBeginUser;
  PetscCall(RollerContactPrimalSetUp(ctx, c, &ts->pr));
  PetscCall(TaoCreate(ctx->comm, &ts->tao));
  PetscCall(TaoSetOptionsPrefix(ts->tao, "contact_"));
  PetscCall(TaoSetType(ts->tao, TAOTRON));
  PetscCall(TaoSetSolution(ts->tao, ts->pr.z));
  ts->qp.H    = ts->pr.Ahat;
  ts->qp.c    = ts->pr.bhat;
  ts->qp.sign = -1.0;
  PetscCall(TaoSetObjectiveAndGradient(ts->tao, NULL, RollerContactTaoQPObjective, &ts->qp));
  PetscCall(TaoSetHessian(ts->tao, ts->pr.Ahat, ts->pr.Ahat, RollerContactTaoQPHessian, &ts->qp));
  PetscCall(TaoSetMaximumIterations(ts->tao, 100000));
  PetscCall(TaoSetMaximumFunctionEvaluations(ts->tao, 1000000));
  PetscCall(TaoSetFromOptions(ts->tao));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)ts->tao, &qn, TAOBQNLS, TAOBQNKLS, TAOBQNKTR, TAOBQNKTL, ""));
  if (qn && ts->j0) {
    Mat B;
    PC  pc;

    PetscCall(TaoGetLMVMMatrix(ts->tao, &B));
    PetscCall(PCCreate(ctx->comm, &pc));
    PetscCall(PCSetType(pc, PCSHELL));
    PetscCall(PCSetOperators(pc, ts->pr.Ahat, ts->pr.Ahat));
    PetscCall(PCShellSetContext(pc, &ts->pr));
    PetscCall(PCShellSetApply(pc, ApplyInverse));
    PetscCall(PCShellSetName(pc, "Q^T A^-1 Q"));
    PetscCall(MatLMVMSetJ0PC(B, pc));
    PetscCall(PCDestroy(&pc));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode TaoSolverSolve(RollerContactSolver s, Roller ctx, RollerContact c, Vec b, Vec xi, RollerContactResult *res)
{
  TaoSolver         *ts = (TaoSolver *)s->data;
  TaoType            ttype;
  TaoConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(RollerContactPrimalSetUpStep(ctx, c, &ts->pr, b));
  PetscCall(TaoSetVariableBounds(ts->tao, ts->pr.lower, ts->pr.upper));
  PetscCall(TaoSetTolerances(ts->tao, c->opt.rtol * ts->pr.fscale, 0.0, 0.0));
  PetscCall(TaoSolve(ts->tao));
  PetscCall(TaoGetConvergedReason(ts->tao, &reason));
  PetscCall(TaoGetType(ts->tao, &ttype));
  PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "Contact QP at t = %g: TAO %s did not converge: %s", (double)c->step.t, ttype, TaoConvergedReasons[reason]);
  PetscCall(TaoGetIterationNumber(ts->tao, &res->its));
  PetscCall(RollerContactPrimalFinish(ctx, c, &ts->pr, xi, res));
  PetscFunctionReturn(0);
}

static PetscErrorCode TaoSolverDestroy(RollerContactSolver s)
{
  TaoSolver *ts = (TaoSolver *)s->data;

  PetscFunctionBeginUser;
  PetscCall(TaoDestroy(&ts->tao));
  PetscCall(RollerContactPrimalDestroy(&ts->pr));
  PetscFunctionReturn(0);
}

static const RollerContactSolverOps ops = {.setfromoptions = TaoSolverSetFromOptions, .setup = TaoSolverSetUp, .solve = TaoSolverSolve, .destroy = TaoSolverDestroy};

PetscErrorCode RollerContactSolverCreate_Tao(RollerContactSolver s)
{
  TaoSolver *ts;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&ts));
  ts->j0  = PETSC_TRUE;
  s->data = ts;
  *s->ops = ops;
  PetscFunctionReturn(0);
}
