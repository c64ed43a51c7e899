/* The step QP on the primal unknowns in rotated contact coordinates (docs/model.md section 2), shared by the
   solvers vi (contact_vi.c), tao (contact_tao.c) and pcg (contact_pcg.c), each of which owns one: xi = Q z,
   where Q is the identity except for a 2x2 block [t^k n^k] at every candidate node, so z = (s, q) there and
   the obstacle is the lower bound q_n >= g^k - x_n . n^k; every other unknown is unbounded. A_hat = Q^T A Q is
   refreshed each step with MatPtAP(MAT_REUSE_MATRIX): Q keeps a 2x2 pattern at every Gamma_C node (explicit
   zeros where it is the identity), so the pattern never changes. The multipliers are the normal components
   of A_hat z - b_hat at the candidates whose bound is active. */
#include "contact_impl.h"

/* Q (pattern: 2x2 blocks at every Gamma_C node, diagonal elsewhere), A_hat (of the step matrix c->step.op; a
   scheme's matrices share their pattern, so A_hat is re-used for all of them), and the vectors. */
PetscErrorCode RollerContactPrimalSetUp(Roller ctx, RollerContact c, RollerContactPrimal *pr)
{
  PetscInt   nlocal, rstart, rend, *nnz;
  PetscBool *on_gamma;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(ctx->state.cur, &nlocal));
  PetscCall(VecGetOwnershipRange(ctx->state.cur, &rstart, &rend));
  PetscCall(PetscCalloc2(nlocal, &nnz, nlocal, &on_gamma));
  for (PetscInt k = 0; k < c->nodes.nown; ++k) on_gamma[c->nodes.own_off[k]] = on_gamma[c->nodes.own_off[k] + 1] = PETSC_TRUE;
  for (PetscInt r = 0; r < nlocal; ++r) nnz[r] = on_gamma[r] ? 2 : 1;
  PetscCall(MatCreate(ctx->comm, &pr->Q));
  PetscCall(MatSetSizes(pr->Q, nlocal, nlocal, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetType(pr->Q, MATAIJ));
  PetscCall(MatSeqAIJSetPreallocation(pr->Q, 0, nnz));
  PetscCall(MatMPIAIJSetPreallocation(pr->Q, 0, nnz, 0, NULL));
  PetscCall(MatSetOption(pr->Q, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  for (PetscInt r = 0; r < nlocal; ++r)
    if (!on_gamma[r]) PetscCall(MatSetValue(pr->Q, rstart + r, rstart + r, 1.0, INSERT_VALUES));
  for (PetscInt k = 0; k < c->nodes.nown; ++k) {
    const PetscInt    rows[2] = {rstart + c->nodes.own_off[k], rstart + c->nodes.own_off[k] + 1};
    const PetscScalar id[4]   = {1.0, 0.0, 0.0, 1.0};

    PetscCall(MatSetValues(pr->Q, 2, rows, 2, rows, id, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(pr->Q, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pr->Q, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscFree2(nnz, on_gamma));
  PetscCall(MatPtAP(c->step.op->A, pr->Q, MAT_INITIAL_MATRIX, 1.0, &pr->Ahat));
  PetscCall(PetscObjectSetName((PetscObject)pr->Ahat, "A_hat"));
  PetscCall(VecDuplicate(ctx->state.cur, &pr->z));
  PetscCall(VecDuplicate(ctx->state.cur, &pr->bhat));
  PetscCall(VecDuplicate(ctx->state.cur, &pr->lower));
  PetscCall(VecDuplicate(ctx->state.cur, &pr->upper));
  PetscCall(VecDuplicate(ctx->state.cur, &pr->r));
  PetscCall(VecDuplicateVecs(ctx->state.cur, 4, &pr->work));
  PetscCall(VecSet(pr->upper, PETSC_INFINITY));
  PetscFunctionReturn(0);
}

/* Q for the candidate set and (t^k, n^k) of the step; A_hat = Q^T A Q (A the step's matrix), b_hat = Q^T b; the bounds; the warm
   start z = max(Q^T xi^{k-1}, lower), feasible; the force scale of the tolerances, max(||b||, ||A|| ||z||):
   ||A||_inf ||z||_2 bounds ||A z||_2 (A symmetric) and sets the round-off floor of the gradient. */
PetscErrorCode RollerContactPrimalSetUpStep(Roller ctx, RollerContact c, RollerContactPrimal *pr, Vec b)
{
  PetscInt     rstart;
  PetscScalar *l;
  PetscReal    nb, nz;

  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(ctx->state.cur, &rstart, NULL));
  for (PetscInt k = 0; k < c->nodes.nown; ++k) {
    const PetscInt    i = c->nodes.own_node[k], rows[2] = {rstart + c->nodes.own_off[k], rstart + c->nodes.own_off[k] + 1};
    const PetscScalar id[4] = {1.0, 0.0, 0.0, 1.0};
    /* row-major [t n]: xi_n = s t^k + q n^k */
    const PetscScalar rot[4] = {c->step.tangent[0], c->step.normal[0], c->step.tangent[1], c->step.normal[1]};

    PetscCall(MatSetValues(pr->Q, 2, rows, 2, rows, c->step.is_cand[i] ? rot : id, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(pr->Q, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pr->Q, MAT_FINAL_ASSEMBLY));
  PetscCall(MatPtAP(c->step.op->A, pr->Q, MAT_REUSE_MATRIX, 1.0, &pr->Ahat));
  PetscCall(MatNorm(c->step.op->A, NORM_INFINITY, &pr->Anorm));
  pr->ksp = c->step.op->ksp;
  PetscCall(MatSetOption(pr->Ahat, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(pr->Ahat, MAT_SPD, PETSC_TRUE));
  PetscCall(MatMultTranspose(pr->Q, b, pr->bhat));
  PetscCall(VecSet(pr->lower, PETSC_NINFINITY));
  PetscCall(VecGetArray(pr->lower, &l));
  for (PetscInt k = 0; k < c->nodes.nown; ++k)
    if (c->step.is_cand[c->nodes.own_node[k]]) l[c->nodes.own_off[k] + 1] = c->step.lower[c->nodes.own_node[k]];
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
PetscErrorCode RollerContactPrimalFinish(Roller ctx, RollerContact c, RollerContactPrimal *pr, Vec xi, RollerContactResult *res)
{
  const PetscReal    tol = RollerContactGapTolerance(ctx);
  const PetscScalar *r, *z;

  PetscFunctionBeginUser;
  PetscCall(MatMult(pr->Q, pr->z, xi));
  PetscCall(MatMult(pr->Ahat, pr->z, pr->r));
  PetscCall(VecAXPY(pr->r, -1.0, pr->bhat));
  PetscCall(RollerContactGather(c, pr->r, c->nodes.red));
  PetscCall(RollerContactGather(c, pr->z, c->nodes.red2));
  PetscCall(VecGetArrayRead(c->nodes.red, &r));
  PetscCall(VecGetArrayRead(c->nodes.red2, &z));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) res->lambda[i] = (c->step.is_cand[i] && PetscRealPart(z[2 * i + 1]) <= c->step.lower[i] + tol) ? PetscRealPart(r[2 * i + 1]) : 0.0;
  PetscCall(VecRestoreArrayRead(c->nodes.red, &r));
  PetscCall(VecRestoreArrayRead(c->nodes.red2, &z));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactPrimalDestroy(RollerContactPrimal *pr)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&pr->Q));
  PetscCall(MatDestroy(&pr->Ahat));
  PetscCall(VecDestroy(&pr->z));
  PetscCall(VecDestroy(&pr->bhat));
  PetscCall(VecDestroy(&pr->lower));
  PetscCall(VecDestroy(&pr->upper));
  PetscCall(VecDestroy(&pr->r));
  if (pr->work) PetscCall(VecDestroyVecs(4, &pr->work));
  PetscFunctionReturn(0);
}
