/* The step QP on the primal unknowns in rotated contact coordinates (docs/model.md section 2), for SNES VI and TAO
   (and the projected CG of contact_pcg.c): xi = Q z, where Q is the identity except for a 2x2 block
   [t^k n^k] at every candidate node, so z = (s, q) there and the obstacle is the lower bound
   q_n >= g^k - x_n . n^k; every other unknown is unbounded. A_hat = Q^T A Q is refreshed each step with
   MatPtAP(MAT_REUSE_MATRIX): Q keeps a 2x2 pattern at every Gamma_C node (explicit zeros where it is the
   identity), so the pattern never changes. The multipliers are the normal components of
   A_hat z - b_hat at the candidates whose bound is active. */
#include "contact_impl.h"

/* Q (pattern: 2x2 blocks at every Gamma_C node, diagonal elsewhere), A_hat, and the vectors. */
static PetscErrorCode PrimalCreate(Roller ctx, RollerContact c)
{
  RollerContactPrimal *pr = &c->primal;
  PetscInt             nlocal, rstart, rend, *nnz;
  PetscBool           *on_gamma;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(ctx->state.cur, &nlocal));
  PetscCall(VecGetOwnershipRange(ctx->state.cur, &rstart, &rend));
  PetscCall(PetscCalloc2(nlocal, &nnz, nlocal, &on_gamma));
  for (PetscInt k = 0; k < c->nown; ++k) on_gamma[c->own_off[k]] = on_gamma[c->own_off[k] + 1] = PETSC_TRUE;
  for (PetscInt r = 0; r < nlocal; ++r) nnz[r] = on_gamma[r] ? 2 : 1;
  PetscCall(MatCreate(ctx->comm, &pr->Q));
  PetscCall(MatSetSizes(pr->Q, nlocal, nlocal, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetType(pr->Q, MATAIJ));
  PetscCall(MatSeqAIJSetPreallocation(pr->Q, 0, nnz));
  PetscCall(MatMPIAIJSetPreallocation(pr->Q, 0, nnz, 0, NULL));
  PetscCall(MatSetOption(pr->Q, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  for (PetscInt r = 0; r < nlocal; ++r)
    if (!on_gamma[r]) PetscCall(MatSetValue(pr->Q, rstart + r, rstart + r, 1.0, INSERT_VALUES));
  for (PetscInt k = 0; k < c->nown; ++k) {
    const PetscInt    rows[2] = {rstart + c->own_off[k], rstart + c->own_off[k] + 1};
    const PetscScalar id[4]   = {1.0, 0.0, 0.0, 1.0};

    PetscCall(MatSetValues(pr->Q, 2, rows, 2, rows, id, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(pr->Q, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pr->Q, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscFree2(nnz, on_gamma));
  PetscCall(MatPtAP(ctx->ops.A, pr->Q, MAT_INITIAL_MATRIX, 1.0, &pr->Ahat));
  PetscCall(PetscObjectSetName((PetscObject)pr->Ahat, "A_hat"));
  PetscCall(VecDuplicate(ctx->state.cur, &pr->z));
  PetscCall(VecDuplicate(ctx->state.cur, &pr->bhat));
  PetscCall(VecDuplicate(ctx->state.cur, &pr->lower));
  PetscCall(VecDuplicate(ctx->state.cur, &pr->upper));
  PetscCall(VecDuplicate(ctx->state.cur, &pr->r));
  PetscCall(VecDuplicateVecs(ctx->state.cur, 4, &pr->work));
  PetscCall(VecSet(pr->upper, PETSC_INFINITY));
  PetscCall(MatNorm(ctx->ops.A, NORM_INFINITY, &pr->Anorm));
  pr->ksp         = ctx->ops.ksp;
  c->primal_ready = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* Q for the candidate set and (t^k, n^k) of the step; A_hat = Q^T A Q, b_hat = Q^T b; the bounds; the warm
   start z = max(Q^T xi^{k-1}, lower), feasible; the force scale of the tolerances, max(||b||, ||A|| ||z||):
   ||A||_inf ||z||_2 bounds ||A z||_2 (A symmetric) and sets the round-off floor of the gradient. */
PetscErrorCode RollerContactPrimalSetUpStep(Roller ctx, RollerContact c, Vec b)
{
  RollerContactPrimal *pr = &c->primal;
  PetscInt             rstart;
  PetscScalar         *l;
  PetscReal            nb, nz;

  PetscFunctionBeginUser;
  if (!c->primal_ready) PetscCall(PrimalCreate(ctx, c));
  PetscCall(VecGetOwnershipRange(ctx->state.cur, &rstart, NULL));
  for (PetscInt k = 0; k < c->nown; ++k) {
    const PetscInt    i = c->own_node[k], rows[2] = {rstart + c->own_off[k], rstart + c->own_off[k] + 1};
    const PetscScalar id[4] = {1.0, 0.0, 0.0, 1.0};
    /* row-major [t n]: xi_n = s t^k + q n^k */
    const PetscScalar rot[4] = {c->tangent[0], c->normal[0], c->tangent[1], c->normal[1]};

    PetscCall(MatSetValues(pr->Q, 2, rows, 2, rows, c->is_cand[i] ? rot : id, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(pr->Q, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pr->Q, MAT_FINAL_ASSEMBLY));
  PetscCall(MatPtAP(ctx->ops.A, pr->Q, MAT_REUSE_MATRIX, 1.0, &pr->Ahat));
  PetscCall(MatSetOption(pr->Ahat, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(pr->Ahat, MAT_SPD, PETSC_TRUE));
  PetscCall(MatMultTranspose(pr->Q, b, pr->bhat));
  PetscCall(VecSet(pr->lower, PETSC_NINFINITY));
  PetscCall(VecGetArray(pr->lower, &l));
  for (PetscInt k = 0; k < c->nown; ++k)
    if (c->is_cand[c->own_node[k]]) l[c->own_off[k] + 1] = c->lower[c->own_node[k]];
  PetscCall(VecRestoreArray(pr->lower, &l));
  PetscCall(MatMultTranspose(pr->Q, ctx->state.cur, pr->z));
  PetscCall(VecPointwiseMax(pr->z, pr->z, pr->lower));
  PetscCall(VecNorm(pr->z, NORM_2, &nz));
  PetscCall(VecNorm(pr->bhat, NORM_2, &nb));
  pr->fscale = PetscMax(nb, pr->Anorm * nz);
  if (pr->fscale == 0.0) pr->fscale = 1.0;
  PetscFunctionReturn(0);
}

/* xi = Q z; lambda_n = (A_hat z - b_hat)_q at the candidates whose bound is active, 0 elsewhere. */
PetscErrorCode RollerContactPrimalFinish(Roller ctx, RollerContact c, Vec xi, RollerContactResult *res)
{
  RollerContactPrimal *pr  = &c->primal;
  const PetscReal      tol = RollerContactGapTolerance(ctx);
  const PetscScalar   *r, *z;

  PetscFunctionBeginUser;
  PetscCall(MatMult(pr->Q, pr->z, xi));
  PetscCall(MatMult(pr->Ahat, pr->z, pr->r));
  PetscCall(VecAXPY(pr->r, -1.0, pr->bhat));
  PetscCall(RollerContactGather(c, pr->r, c->red));
  PetscCall(RollerContactGather(c, pr->z, c->red2));
  PetscCall(VecGetArrayRead(c->red, &r));
  PetscCall(VecGetArrayRead(c->red2, &z));
  for (PetscInt i = 0; i < c->nc; ++i) res->lambda[i] = (c->is_cand[i] && PetscRealPart(z[2 * i + 1]) <= c->lower[i] + tol) ? PetscRealPart(r[2 * i + 1]) : 0.0;
  PetscCall(VecRestoreArrayRead(c->red, &r));
  PetscCall(VecRestoreArrayRead(c->red2, &z));
  PetscFunctionReturn(0);
}

/* F(z) = A_hat z - b_hat, the gradient of 1/2 z^T A_hat z - b_hat^T z. */
static PetscErrorCode VIFunction(SNES snes, Vec z, Vec f, void *ptr)
{
  RollerContact c = (RollerContact)ptr;

  PetscFunctionBeginUser;
  PetscCall(MatMult(c->primal.Ahat, z, f));
  PetscCall(VecAXPY(f, -1.0, c->primal.bhat));
  PetscFunctionReturn(0);
}

static PetscErrorCode VIJacobian(SNES snes, Vec z, Mat J, Mat P, void *ptr)
{
  PetscFunctionBeginUser;
  PetscFunctionReturn(0); /* A_hat, refreshed by RollerContactPrimalSetUpStep */
}

/* -contact_solver vi: SNES VI (reduced-space active set Newton, vinewtonrsls, by default) with a full Newton
   step (the problem is quadratic) and a direct solve of each reduced system; options prefix contact_vi_. */
PetscErrorCode RollerContactVISolve(Roller ctx, RollerContact c, Vec b, Vec xi, RollerContactResult *res)
{
  RollerContactPrimal *pr = &c->primal;
  SNESConvergedReason  reason;
  PetscReal            rtol, stol;
  PetscInt             maxit, maxf;

  PetscFunctionBeginUser;
  PetscCall(RollerContactPrimalSetUpStep(ctx, c, b));
  if (!pr->snes) {
    KSP            ksp;
    Vec            f;
    SNESLineSearch ls;

    PetscCall(SNESCreate(ctx->comm, &pr->snes));
    PetscCall(SNESSetOptionsPrefix(pr->snes, "contact_vi_"));
    PetscCall(SNESSetType(pr->snes, SNESVINEWTONRSLS));
    PetscCall(VecDuplicate(pr->z, &f));
    PetscCall(SNESSetFunction(pr->snes, f, VIFunction, c));
    PetscCall(VecDestroy(&f));
    PetscCall(SNESSetJacobian(pr->snes, pr->Ahat, pr->Ahat, VIJacobian, c));
    PetscCall(SNESGetLineSearch(pr->snes, &ls));
    PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHBASIC));
    PetscCall(SNESGetKSP(pr->snes, &ksp));
    PetscCall(RollerDirectSolverDefaults(ksp, PCCHOLESKY));
    PetscCall(SNESSetTolerances(pr->snes, PETSC_DEFAULT, c->rtol, 1e-14, 100, PETSC_DEFAULT));
    PetscCall(SNESSetFromOptions(pr->snes));
  }
  /* the absolute tolerance follows the force scale of the step */
  PetscCall(SNESGetTolerances(pr->snes, NULL, &rtol, &stol, &maxit, &maxf));
  PetscCall(SNESSetTolerances(pr->snes, c->rtol * pr->fscale, rtol, stol, maxit, maxf));
  PetscCall(SNESVISetVariableBounds(pr->snes, pr->lower, pr->upper));
  PetscCall(SNESSolve(pr->snes, NULL, pr->z));
  PetscCall(SNESGetConvergedReason(pr->snes, &reason));
  PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "Contact QP at t = %g: SNES VI did not converge: %s", (double)c->t, SNESConvergedReasons[reason]);
  PetscCall(SNESGetIterationNumber(pr->snes, &res->its));
  PetscCall(RollerContactPrimalFinish(ctx, c, xi, res));
  PetscFunctionReturn(0);
}

static PetscErrorCode TaoObjectiveGradient(Tao tao, Vec z, PetscReal *f, Vec g, void *ptr)
{
  RollerContact c = (RollerContact)ptr;
  PetscScalar   zAz, bz;

  PetscFunctionBeginUser;
  PetscCall(MatMult(c->primal.Ahat, z, g));
  PetscCall(VecDot(z, g, &zAz));
  PetscCall(VecDot(c->primal.bhat, z, &bz));
  *f = PetscRealPart(0.5 * zAz - bz);
  PetscCall(VecAXPY(g, -1.0, c->primal.bhat));
  PetscFunctionReturn(0);
}

static PetscErrorCode TaoHessian(Tao tao, Vec z, Mat H, Mat P, void *ptr)
{
  PetscFunctionBeginUser;
  PetscFunctionReturn(0); /* A_hat, refreshed by RollerContactPrimalSetUpStep */
}

/* y = A_hat^{-1} x = Q^T A^{-1} Q x (Q is orthogonal): the step factorization, no new one. */
static PetscErrorCode ApplyInverse(PC pc, Vec x, Vec y)
{
  RollerContact c;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &c));
  PetscCall(MatMult(c->primal.Q, x, c->primal.work[0]));
  PetscCall(KSPSolve(c->primal.ksp, c->primal.work[0], c->primal.work[1]));
  PetscCall(MatMultTranspose(c->primal.Q, c->primal.work[1], y));
  PetscFunctionReturn(0);
}

/* -contact_solver tao: a TAO bound-constrained solver on the same problem, options prefix contact_
   (-contact_tao_type, default tron: the fastest TAO type measured, docs/contact.md). A quasi-Newton type
   (bqnls, bqnk*) gets the exact inverse Hessian Q^T A^{-1} Q as its initial matrix J0 (-contact_tao_j0,
   default on), a solve with the step factorization. */
PetscErrorCode RollerContactTaoSolve(Roller ctx, RollerContact c, Vec b, Vec xi, RollerContactResult *res)
{
  RollerContactPrimal *pr = &c->primal;
  TaoType              ttype;
  TaoConvergedReason   reason;

  PetscFunctionBeginUser;
  PetscCall(RollerContactPrimalSetUpStep(ctx, c, b));
  if (!pr->tao) {
    PetscBool qn;

    PetscCall(TaoCreate(ctx->comm, &pr->tao));
    PetscCall(TaoSetOptionsPrefix(pr->tao, "contact_"));
    PetscCall(TaoSetType(pr->tao, TAOTRON));
    PetscCall(TaoSetSolution(pr->tao, pr->z));
    PetscCall(TaoSetObjectiveAndGradient(pr->tao, NULL, TaoObjectiveGradient, c));
    PetscCall(TaoSetHessian(pr->tao, pr->Ahat, pr->Ahat, TaoHessian, c));
    PetscCall(TaoSetMaximumIterations(pr->tao, 100000));
    PetscCall(TaoSetMaximumFunctionEvaluations(pr->tao, 1000000));
    PetscCall(TaoSetFromOptions(pr->tao));
    PetscCall(PetscObjectTypeCompareAny((PetscObject)pr->tao, &qn, TAOBQNLS, TAOBQNKLS, TAOBQNKTR, TAOBQNKTL, ""));
    if (qn && c->tao_j0) {
      Mat B;
      PC  pc;

      PetscCall(TaoGetLMVMMatrix(pr->tao, &B));
      PetscCall(PCCreate(ctx->comm, &pc));
      PetscCall(PCSetType(pc, PCSHELL));
      PetscCall(PCSetOperators(pc, pr->Ahat, pr->Ahat));
      PetscCall(PCShellSetContext(pc, c));
      PetscCall(PCShellSetApply(pc, ApplyInverse));
      PetscCall(PCShellSetName(pc, "Q^T A^-1 Q"));
      PetscCall(MatLMVMSetJ0PC(B, pc));
      PetscCall(PCDestroy(&pc));
    }
  }
  PetscCall(TaoSetVariableBounds(pr->tao, pr->lower, pr->upper));
  PetscCall(TaoSetTolerances(pr->tao, c->rtol * pr->fscale, 0.0, 0.0));
  PetscCall(TaoSolve(pr->tao));
  PetscCall(TaoGetConvergedReason(pr->tao, &reason));
  PetscCall(TaoGetType(pr->tao, &ttype));
  PetscCheck(reason > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "Contact QP at t = %g: TAO %s did not converge: %s", (double)c->t, ttype, TaoConvergedReasons[reason]);
  PetscCall(TaoGetIterationNumber(pr->tao, &res->its));
  PetscCall(RollerContactPrimalFinish(ctx, c, xi, res));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactPrimalDestroy(RollerContact c)
{
  RollerContactPrimal *pr = &c->primal;

  PetscFunctionBeginUser;
  if (!c->primal_ready) PetscFunctionReturn(0);
  PetscCall(SNESDestroy(&pr->snes));
  PetscCall(TaoDestroy(&pr->tao));
  PetscCall(MatDestroy(&pr->Q));
  PetscCall(MatDestroy(&pr->Ahat));
  PetscCall(VecDestroy(&pr->z));
  PetscCall(VecDestroy(&pr->bhat));
  PetscCall(VecDestroy(&pr->lower));
  PetscCall(VecDestroy(&pr->upper));
  PetscCall(VecDestroy(&pr->r));
  PetscCall(VecDestroyVecs(4, &pr->work));
  c->primal_ready = PETSC_FALSE;
  PetscFunctionReturn(0);
}
