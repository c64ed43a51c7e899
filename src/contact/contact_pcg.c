/* -contact_solver pcg: the paper's projected Polak-Ribiere nonlinear CG (Akagawa, Morikawa, Omata 2019,
   section 3.3), the historical baseline, on the rotated primal problem of contact_primal.c:

     (1) z_0 = Proj(Q^T xi^{k-1})   (2) g_1 = -grad J(z_0)   (3) p_1 = T_{z_0}(g_1)   (4) stop if ||p_1|| <= eps
     (5) for m = 1, 2, ...: alpha_m = argmin_alpha J(z_{m-1} + alpha p_m) (exact: J is quadratic);
         z_m = Proj(z_{m-1} + alpha_m p_m); g_{m+1} = -grad J(z_m);
         beta_m = max(0, (g_{m+1} - g_m) . g_{m+1} / |g_m|^2); p_{m+1} = T_{z_m}(g_{m+1} + beta_m p_m);
         stop if ||T_{z_m}(g_{m+1})|| <= eps

   In rotated coordinates the admissible set is the box q_n >= g^k - x_n . n^k, so Proj is a max with the
   bound and T_z zeroes the negative normal component of a direction at nodes on the obstacle
   (z_q <= bound): the paper's formulas with n^k = R^T(theta^k) e_2. Correction: the paper prints Proj with
   min{0, g - (x + xi) . n}, which would pull feasible nodes onto the obstacle; the orthogonal projection it
   describes adds max{0, g - (x + xi) . n} n (docs/model.md sections 2 and 9).
   Q is orthogonal, so the Euclidean gradient, the norms and the line search are those of the paper's
   unknowns. eps = -contact_pcg_rtol times the force scale max(||b||_2, ||A||_inf ||z_0||_2). */
#include "contact_impl.h"

typedef struct {
  RollerContactPrimal pr;
  PetscReal           rtol; /* -contact_pcg_rtol, relative to the force scale */
  PetscInt            max_it;
} PCG;

static PetscErrorCode PCGSetFromOptions(RollerContactSolver s, PetscOptionItems *PetscOptionsObject)
{
  PCG *pcg = (PCG *)s->data;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsReal("-contact_pcg_rtol", "Projected CG stops when ||T(-grad J)|| <= rtol max(||b||, ||A|| ||xi_0||)", NULL, pcg->rtol, &pcg->rtol, NULL));
  PetscCall(PetscOptionsInt("-contact_pcg_max_it", "Iteration cap of the projected CG", NULL, pcg->max_it, &pcg->max_it, NULL));
  RollerCheckOption(PetscOptionsObject->comm, "-contact_pcg_rtol", pcg->rtol, pcg->rtol > 0 && pcg->rtol < 1, "in (0, 1)");
  PetscCheck(pcg->max_it > 0, PetscOptionsObject->comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_pcg_max_it %" PetscInt_FMT " must be > 0", pcg->max_it);
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGSetUp(RollerContactSolver s, Roller ctx, RollerContact c)
{
  PetscFunctionBeginUser;
  PetscCall(RollerContactPrimalSetUp(ctx, c, &((PCG *)s->data)->pr));
  PetscFunctionReturn(0);
}

/* p = T_z(v): zero the components that point below an active bound. */
static PetscErrorCode Restrict(Vec z, Vec lower, Vec v, Vec p)
{
  const PetscScalar *za, *la, *va;
  PetscScalar       *pa;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(z, &n));
  PetscCall(VecGetArrayRead(z, &za));
  PetscCall(VecGetArrayRead(lower, &la));
  PetscCall(VecGetArrayRead(v, &va));
  PetscCall(VecGetArray(p, &pa));
  for (PetscInt i = 0; i < n; ++i) pa[i] = (PetscRealPart(za[i]) <= PetscRealPart(la[i]) && PetscRealPart(va[i]) < 0.0) ? 0.0 : va[i];
  PetscCall(VecRestoreArrayRead(z, &za));
  PetscCall(VecRestoreArrayRead(lower, &la));
  PetscCall(VecRestoreArrayRead(v, &va));
  PetscCall(VecRestoreArray(p, &pa));
  PetscFunctionReturn(0);
}

/* z <- max(z + alpha p, lower); clipped = whether any component was projected. */
static PetscErrorCode StepAndProject(Vec z, Vec lower, PetscReal alpha, Vec p, PetscBool *clipped)
{
  const PetscScalar *la, *pa;
  PetscScalar       *za;
  PetscInt           n, nclip = 0;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(z, &n));
  PetscCall(VecGetArray(z, &za));
  PetscCall(VecGetArrayRead(lower, &la));
  PetscCall(VecGetArrayRead(p, &pa));
  for (PetscInt i = 0; i < n; ++i) {
    za[i] += alpha * pa[i];
    if (PetscRealPart(za[i]) < PetscRealPart(la[i])) {
      za[i] = la[i];
      nclip++;
    }
  }
  PetscCall(VecRestoreArray(z, &za));
  PetscCall(VecRestoreArrayRead(lower, &la));
  PetscCall(VecRestoreArrayRead(p, &pa));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &nclip, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)z)));
  *clipped = nclip ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* g = b_hat - A_hat z */
static PetscErrorCode NegativeGradient(RollerContactPrimal *pr, Vec g)
{
  PetscFunctionBeginUser;
  PetscCall(MatMult(pr->Ahat, pr->z, g));
  PetscCall(VecAYPX(g, -1.0, pr->bhat));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGSolve(RollerContactSolver s, Roller ctx, RollerContact c, Vec b, Vec xi, RollerContactResult *res)
{
  PCG                 *pcg = (PCG *)s->data;
  RollerContactPrimal *pr  = &pcg->pr;
  Vec                  g, gnew, p, Ap;
  PetscReal            eps, e, gg;
  PetscInt             m;

  PetscFunctionBeginUser;
  PetscCall(RollerContactPrimalSetUpStep(ctx, c, pr, b));
  g    = pr->work[0];
  gnew = pr->work[1];
  p    = pr->work[2];
  Ap   = pr->work[3];
  eps  = pcg->rtol * pr->fscale;
  PetscCall(NegativeGradient(pr, g));
  PetscCall(Restrict(pr->z, pr->lower, g, p));
  PetscCall(VecNorm(p, NORM_2, &e));
  PetscCall(VecDot(g, g, &gg));
  for (m = 1; e > eps && m <= pcg->max_it; ++m) {
    PetscScalar gp, pAp, gnew_g, gnew_gnew;
    PetscReal   alpha, beta;
    PetscBool   clipped;

    PetscCall(MatMult(pr->Ahat, p, Ap));
    PetscCall(VecDot(g, p, &gp));
    PetscCall(VecDot(p, Ap, &pAp));
    if (PetscRealPart(gp) <= 0.0) { /* not a descent direction after the restriction: restart along T(g) */
      PetscCall(Restrict(pr->z, pr->lower, g, p));
      PetscCall(MatMult(pr->Ahat, p, Ap));
      PetscCall(VecDot(g, p, &gp));
      PetscCall(VecDot(p, Ap, &pAp));
    }
    alpha = PetscRealPart(gp) / PetscRealPart(pAp);
    PetscCall(StepAndProject(pr->z, pr->lower, alpha, p, &clipped));
    if (clipped) PetscCall(NegativeGradient(pr, gnew));
    else PetscCall(VecWAXPY(gnew, -alpha, Ap, g));
    /* beta_m = max(0, (g_{m+1} - g_m) . g_{m+1} / |g_m|^2) */
    PetscCall(VecDotBegin(gnew, g, &gnew_g));
    PetscCall(VecDotBegin(gnew, gnew, &gnew_gnew));
    PetscCall(VecDotEnd(gnew, g, &gnew_g));
    PetscCall(VecDotEnd(gnew, gnew, &gnew_gnew));
    beta = PetscMax(0.0, PetscRealPart(gnew_gnew - gnew_g) / gg);
    PetscCall(VecAYPX(p, beta, gnew));
    PetscCall(Restrict(pr->z, pr->lower, p, p));
    PetscCall(VecCopy(gnew, g));
    gg = PetscRealPart(gnew_gnew);
    PetscCall(Restrict(pr->z, pr->lower, g, gnew));
    PetscCall(VecNorm(gnew, NORM_2, &e));
    if (e <= eps) { /* confirm with the true gradient (the update g - alpha A p drifts by round-off) */
      PetscCall(NegativeGradient(pr, g));
      PetscCall(Restrict(pr->z, pr->lower, g, gnew));
      PetscCall(VecNorm(gnew, NORM_2, &e));
    }
  }
  PetscCheck(e <= eps, ctx->comm, PETSC_ERR_NOT_CONVERGED, "Contact QP at t = %g: the projected CG did not reach ||T(-grad)|| <= %g in %" PetscInt_FMT " iterations (-contact_pcg_max_it) : %g", (double)c->step.t, (double)eps, pcg->max_it, (double)e);
  res->its = m - 1;
  PetscCall(RollerContactPrimalFinish(ctx, c, pr, xi, res));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDestroy(RollerContactSolver s)
{
  PetscFunctionBeginUser;
  PetscCall(RollerContactPrimalDestroy(&((PCG *)s->data)->pr));
  PetscFunctionReturn(0);
}

static const RollerContactSolverOps ops = {.setfromoptions = PCGSetFromOptions, .setup = PCGSetUp, .solve = PCGSolve, .destroy = PCGDestroy};

PetscErrorCode RollerContactSolverCreate_PCG(RollerContactSolver s)
{
  PCG *pcg;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&pcg));
  pcg->rtol   = 1e-12;
  pcg->max_it = 100000;
  s->data     = pcg;
  *s->ops     = ops;
  PetscFunctionReturn(0);
}
