/* The steady rolling/sliding state of the roller pressed by the sheet, in the lab (Eulerian) description
   (docs/squeal.md section 3): the obstacle and the contact patch stand still while the material flows through
   them, so the state solves one static problem with the constant matrix K_lab = K - rho theta'^2 P,

     K_lab u = rho theta'^2 L_centrifugal + sum_j lambda_j (e_j,y - s mu_j e_j,x),
     gap_j = y_j,2 + u_j,2 - g >= 0,  lambda_j >= 0,  lambda_j gap_j = 0,

   on the Gamma_C nodes j within reach of the sheet at height g = depth - r_outer: the normal force lambda_j
   pushes up (e2), the Coulomb force -s mu_j lambda_j acts along e1 against the slip, whose sign s is that of
   the material's speed over the sheet's, omega r_outer - V (steady sliding; 0 without friction). K_lab is
   factored once; its inverse applied to each candidate's force direction gives the dense matrix G of the
   LCP w = G lambda + q in the multipliers (symmetric without friction, non-symmetric with), solved by
   Lemke's method. The slip speed at node j, v_j = theta'(-y_j,2 + d_phi u_j,1) - V (d_phi along Gamma_C by
   differences), sets mu_j = mu(|v_j|) (velocity weakening): repeated until mu settles. A node that would
   stick (v_j of the other sign) is reported as an error: the rolling state with stick zones is not built. */
#include "modes/modes.h"

/* mu(v) = mu + (mu_s - mu) exp(-v / v_c) and its derivative (model as contact/contact_friction.c) */
static void FrictionLaw(Roller ctx, PetscReal v, PetscReal *mu, PetscReal *dmu)
{
  const RollerObstacle *o = &ctx->obstacle;
  const PetscReal       e = o->friction_decay > 0 ? PetscExpReal(-PetscAbsReal(v) / o->friction_decay) : 0.0;

  *mu  = o->friction + (o->friction_static - o->friction) * e;
  *dmu = o->friction_decay > 0 ? -(o->friction_static - o->friction) / o->friction_decay * e : 0.0;
}

/* A node on Gamma_C: |x| = r_outer (vertices, and the curved P2 boundary's edge nodes) */
static PetscBool OnOuterCircle(Roller ctx, PetscReal x0, PetscReal x1)
{
  return PetscAbsReal(PetscSqrtReal(x0 * x0 + x1 * x1) - ctx->mesh.r_outer) <= 1e-8 * ctx->mesh.r_outer ? PETSC_TRUE : PETSC_FALSE;
}

/* The Gamma_C nodes (|x| = r_outer) with rigid gap y_2 - g below reach, gathered on every rank, sorted by angle. */
static PetscErrorCode Candidates(Roller ctx, PetscReal g, PetscReal reach, RollerSteady *st)
{
  const PetscScalar *x;
  PetscInt           n, lo, nloc = 0, *dof;
  PetscReal         *xy;
  PetscMPIInt        size, cnt, *counts, *displs;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(ctx->ops.coordinates, &n));
  PetscCall(VecGetOwnershipRange(ctx->ops.coordinates, &lo, NULL));
  PetscCall(PetscMalloc2(n / 2, &dof, n, &xy));
  PetscCall(VecGetArrayRead(ctx->ops.coordinates, &x));
  for (PetscInt j = 0; j < n; j += 2) {
    const PetscReal x0 = PetscRealPart(x[j]), x1 = PetscRealPart(x[j + 1]);

    if (!OnOuterCircle(ctx, x0, x1) || x1 - g > reach) continue;
    dof[nloc]        = lo + j;
    xy[2 * nloc]     = x0;
    xy[2 * nloc + 1] = x1;
    ++nloc;
  }
  PetscCall(VecRestoreArrayRead(ctx->ops.coordinates, &x));
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCall(PetscMalloc2(size, &counts, size, &displs));
  PetscCall(PetscMPIIntCast(nloc, &cnt));
  PetscCallMPI(MPI_Allgather(&cnt, 1, MPI_INT, counts, 1, MPI_INT, ctx->comm));
  st->n = 0;
  for (PetscMPIInt r = 0; r < size; ++r) {
    displs[r] = (PetscMPIInt)st->n;
    st->n += counts[r];
  }
  PetscCall(PetscMalloc2(st->n, &st->dof, 2 * st->n, &st->xy));
  PetscCallMPI(MPI_Allgatherv(dof, cnt, MPIU_INT, st->dof, counts, displs, MPIU_INT, ctx->comm));
  for (PetscMPIInt r = 0; r < size; ++r) {
    counts[r] *= 2;
    displs[r] *= 2;
  }
  PetscCallMPI(MPI_Allgatherv(xy, 2 * cnt, MPIU_REAL, st->xy, counts, displs, MPIU_REAL, ctx->comm));
  PetscCall(PetscFree2(counts, displs));
  PetscCall(PetscFree2(dof, xy));
  for (PetscInt i = 1; i < st->n; ++i) { /* by angle (the patch is at the bottom: no wrap-around) */
    const PetscInt  d = st->dof[i];
    const PetscReal a = st->xy[2 * i], b = st->xy[2 * i + 1], t = PetscAtan2Real(b, a);
    PetscInt        k = i - 1;

    for (; k >= 0 && PetscAtan2Real(st->xy[2 * k + 1], st->xy[2 * k]) > t; --k) {
      st->dof[k + 1]          = st->dof[k];
      st->xy[2 * (k + 1)]     = st->xy[2 * k];
      st->xy[2 * (k + 1) + 1] = st->xy[2 * k + 1];
    }
    st->dof[k + 1]          = d;
    st->xy[2 * (k + 1)]     = a;
    st->xy[2 * (k + 1) + 1] = b;
  }
  PetscFunctionReturn(0);
}

/* d_phi of the x displacement at candidate j, from the redundant values ux[] of all candidates (sorted by angle):
   coefficients c[3] on the candidates j-1, j, j+1 (central differences in the angle, one-sided at the ends). */
PetscErrorCode RollerSteadyAngularDerivative(const RollerSteady *st, PetscInt j, PetscInt nb[3], PetscReal c[3])
{
  PetscReal t[3];
  PetscInt  a = PetscMax(j - 1, 0), b = PetscMin(j + 1, st->n - 1);

  PetscFunctionBeginUser;
  PetscCheck(st->n > 1, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "One contact candidate: no derivative along Gamma_C");
  nb[0] = a;
  nb[1] = j;
  nb[2] = b;
  for (PetscInt k = 0; k < 3; ++k) t[k] = PetscAtan2Real(st->xy[2 * nb[k] + 1], st->xy[2 * nb[k]]);
  c[0] = -1.0 / (t[2] - t[0]);
  c[1] = 0.0;
  c[2] = 1.0 / (t[2] - t[0]);
  PetscFunctionReturn(0);
}

/* The redundant y and x values of every candidate of a global Vec (xs[2j] = x dof, xs[2j+1] = y dof). */
static PetscErrorCode CandidateValues(RollerSteady *st, Vec v, PetscReal xs[])
{
  const PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(VecScatterBegin(st->scatter, v, st->red, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(st->scatter, v, st->red, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(st->red, &a));
  for (PetscInt j = 0; j < 2 * st->n; ++j) xs[j] = PetscRealPart(a[j]);
  PetscCall(VecRestoreArrayRead(st->red, &a));
  PetscFunctionReturn(0);
}

/* One LCP at fixed mu_j: the multipliers, the state u, the gaps and slips of the candidates. */
static PetscErrorCode SolveLCP(Roller ctx, KSP ksp, Vec uf, PetscReal g, RollerSteady *st, Vec *w)
{
  const PetscInt n = st->n;
  PetscReal     *G, *q, *xs;
  PetscInt       pivots;
  PetscBool      solved;
  PetscInt       lo, hi;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc3(n * n, &G, n, &q, 2 * n, &xs));
  PetscCall(VecGetOwnershipRange(uf, &lo, &hi));
  for (PetscInt k = 0; k < n; ++k) { /* w_k = K_lab^-1 (e_k,y - s mu_k e_k,x) */
    Vec f = st->u;

    PetscCall(VecZeroEntries(f));
    if (st->dof[k] >= lo && st->dof[k] < hi) {
      PetscCall(VecSetValue(f, st->dof[k] + 1, 1.0, INSERT_VALUES));
      PetscCall(VecSetValue(f, st->dof[k], -st->sign * st->mu[k], INSERT_VALUES));
    }
    PetscCall(VecAssemblyBegin(f));
    PetscCall(VecAssemblyEnd(f));
    PetscCall(KSPSolve(ksp, f, w[k]));
    PetscCall(CandidateValues(st, w[k], xs));
    for (PetscInt j = 0; j < n; ++j) G[j + k * n] = xs[2 * j + 1];
  }
  PetscCall(CandidateValues(st, uf, xs));
  for (PetscInt j = 0; j < n; ++j) q[j] = st->xy[2 * j + 1] + xs[2 * j + 1] - g;
  PetscCall(RollerContactLemke(n, G, q, st->normal, &pivots, &solved));
  PetscCheck(solved, ctx->comm, PETSC_ERR_NOT_CONVERGED, "The steady state's contact LCP (%" PetscInt_FMT " nodes, -friction %g) has no solution by Lemke's method (a secondary ray after %" PetscInt_FMT " pivots)", n, (double)ctx->obstacle.friction, pivots);
  PetscCall(VecCopy(uf, st->u));
  for (PetscInt k = 0; k < n; ++k)
    if (st->normal[k] != 0) PetscCall(VecAXPY(st->u, st->normal[k], w[k]));
  PetscCall(CandidateValues(st, st->u, xs));
  for (PetscInt j = 0; j < n; ++j) {
    PetscInt  nb[3];
    PetscReal c[3], du = 0;

    PetscCall(RollerSteadyAngularDerivative(st, j, nb, c));
    for (PetscInt k = 0; k < 3; ++k) du += c[k] * xs[2 * nb[k]];
    st->gap[j]  = st->xy[2 * j + 1] + xs[2 * j + 1] - g;
    st->slip[j] = ctx->rotation.omega * (-st->xy[2 * j + 1] + du) - ctx->obstacle.sheet_speed;
  }
  PetscCall(PetscFree3(G, q, xs));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSteadySolve(Roller ctx, Mat Klab, RollerSteady *st)
{
  const PetscReal g = ctx->obstacle.depth - ctx->mesh.r_outer, w = ctx->rotation.omega, rho = ctx->material.density;
  PetscReal       reach = PetscMax(ctx->obstacle.depth, 1e-3 * ctx->mesh.r_outer), v0 = w * ctx->mesh.r_outer - ctx->obstacle.sheet_speed;
  KSP             ksp;
  Vec             uf;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(st, sizeof(*st)));
  PetscCall(KSPCreate(ctx->comm, &ksp));
  PetscCall(KSPSetOperators(ksp, Klab, Klab));
  PetscCall(RollerDirectSolverDefaults(ksp, PCLU));
  PetscCall(KSPSetOptionsPrefix(ksp, "modes_steady_"));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(MatCreateVecs(Klab, &uf, &st->u));
  PetscCall(VecCopy(ctx->ops.L_centrifugal, st->u));
  PetscCall(VecScale(st->u, rho * w * w));
  PetscCall(KSPSolve(ksp, st->u, uf));
  st->sign = ctx->obstacle.friction > 0 ? (v0 > 0 ? 1.0 : -1.0) : 0.0;
  PetscCheck(st->sign == 0 || v0 != 0, ctx->comm, PETSC_ERR_SUP, "-modes with -friction: the sheet moves with the surface (-sheet_speed %g = omega r_outer): steady rolling with stick zones is not built, only steady sliding", (double)ctx->obstacle.sheet_speed);
  for (PetscInt attempt = 0;; ++attempt) { /* widen the candidate zone until no node outside it penetrates */
    Vec      *wk;
    PetscReal gmin, vmin;
    PetscInt  lo, hi, n;

    PetscCall(Candidates(ctx, g, reach, st));
    PetscCheck(st->n > 1, ctx->comm, PETSC_ERR_ARG_WRONG, "-obstacle_depth %g: fewer than two Gamma_C nodes within reach of the sheet; press deeper or refine the mesh", (double)ctx->obstacle.depth);
    PetscCall(PetscMalloc5(st->n, &st->normal, st->n, &st->mu, st->n, &st->dmu, st->n, &st->slip, st->n, &st->gap));
    {
      IS        is;
      PetscInt *idx;

      PetscCall(PetscMalloc1(2 * st->n, &idx));
      for (PetscInt j = 0; j < st->n; ++j) {
        idx[2 * j]     = st->dof[j];
        idx[2 * j + 1] = st->dof[j] + 1;
      }
      PetscCall(ISCreateGeneral(PETSC_COMM_SELF, 2 * st->n, idx, PETSC_OWN_POINTER, &is));
      PetscCall(VecCreateSeq(PETSC_COMM_SELF, 2 * st->n, &st->red));
      PetscCall(VecScatterCreate(uf, is, st->red, NULL, &st->scatter));
      PetscCall(ISDestroy(&is));
    }
    for (PetscInt j = 0; j < st->n; ++j) FrictionLaw(ctx, v0, &st->mu[j], &st->dmu[j]);
    PetscCall(VecDuplicateVecs(uf, st->n, &wk));
    for (st->iterations = 1;; ++st->iterations) { /* mu_j = mu(|v_j|) at the state's slips */
      PetscReal change = 0;

      PetscCall(SolveLCP(ctx, ksp, uf, g, st, wk));
      for (PetscInt j = 0; j < st->n; ++j) {
        PetscReal mu, dmu;

        FrictionLaw(ctx, st->slip[j], &mu, &dmu);
        change     = PetscMax(change, PetscAbsReal(mu - st->mu[j]));
        st->mu[j]  = mu;
        st->dmu[j] = dmu;
      }
      if (change <= 1e-12 * PetscMax(ctx->obstacle.friction_static, 1e-300) || st->sign == 0) break;
      PetscCheck(st->iterations < 50, ctx->comm, PETSC_ERR_NOT_CONVERGED, "The steady state's mu(v) did not settle in 50 passes (last change %g)", (double)change);
    }
    PetscCall(VecDestroyVecs(st->n, &wk));
    /* every Gamma_C node outside the candidates above the sheet? */
    gmin = PETSC_MAX_REAL;
    PetscCall(VecGetLocalSize(uf, &n));
    PetscCall(VecGetOwnershipRange(uf, &lo, &hi));
    {
      const PetscScalar *x, *u;

      PetscCall(VecGetArrayRead(ctx->ops.coordinates, &x));
      PetscCall(VecGetArrayRead(st->u, &u));
      for (PetscInt j = 0; j < n; j += 2) {
        const PetscReal x0 = PetscRealPart(x[j]), x1 = PetscRealPart(x[j + 1]);

        if (!OnOuterCircle(ctx, x0, x1) || x1 - g <= reach) continue;
        gmin = PetscMin(gmin, x1 + PetscRealPart(u[j + 1]) - g);
      }
      PetscCall(VecRestoreArrayRead(ctx->ops.coordinates, &x));
      PetscCall(VecRestoreArrayRead(st->u, &u));
    }
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &gmin, 1, MPIU_REAL, MPIU_MIN, ctx->comm));
    if (gmin >= 0) {
      vmin = PETSC_MAX_REAL;
      for (PetscInt j = 0; j < st->n; ++j)
        if (st->normal[j] > 0) vmin = PetscMin(vmin, st->sign * st->slip[j]);
      PetscCheck(st->sign == 0 || vmin > 0, ctx->comm, PETSC_ERR_SUP, "-modes with -friction: the steady state would stick at some contact node (slip speed %g against the sliding direction): steady rolling with stick zones is not built, only full sliding (choose -sheet_speed further from omega r_outer)", (double)(st->sign * vmin));
      break;
    }
    PetscCheck(attempt < 8, ctx->comm, PETSC_ERR_PLIB, "The steady state penetrates the sheet outside every candidate zone tried");
    reach *= 2;
    PetscCall(RollerSteadyDestroy(st, PETSC_FALSE));
  }
  PetscCall(VecDestroy(&uf));
  PetscCall(KSPDestroy(&ksp));
  PetscFunctionReturn(0);
}

/* Frees the candidates' arrays (and the state u with all) */
PetscErrorCode RollerSteadyDestroy(RollerSteady *st, PetscBool all)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(st->dof, st->xy));
  PetscCall(PetscFree5(st->normal, st->mu, st->dmu, st->slip, st->gap));
  PetscCall(VecScatterDestroy(&st->scatter));
  PetscCall(VecDestroy(&st->red));
  if (all) PetscCall(VecDestroy(&st->u));
  PetscFunctionReturn(0);
}

/* The steady state in numbers: printed, and with -modes_steady_csv F one row per candidate node
   x,y,normal_force,tangential_force,gap,slip_velocity,mu (rank 0 writes F.part, renamed when complete). */
PetscErrorCode RollerSteadyReport(Roller ctx, const RollerSteady *st)
{
  PetscReal N = 0, T = 0, a0 = PETSC_MAX_REAL, a1 = -PETSC_MAX_REAL;
  PetscInt  active = 0;
  char      part[PETSC_MAX_PATH_LEN];
  FILE     *fp;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < st->n; ++j) {
    if (st->normal[j] <= 0) continue;
    N += st->normal[j];
    T += -st->sign * st->mu[j] * st->normal[j];
    a0 = PetscMin(a0, st->xy[2 * j]);
    a1 = PetscMax(a1, st->xy[2 * j]);
    ++active;
  }
  if (!ctx->ts.quiet)
    PetscCall(PetscPrintf(ctx->comm, "roller: steady %s state (lab frame): %" PetscInt_FMT " of %" PetscInt_FMT " candidate nodes in contact over x in [%g, %g], normal force %.6g, friction force %.6g, slip speed %g, %" PetscInt_FMT " mu(v) passes\n", st->sign != 0 ? "sliding" : "frictionless rolling", active, st->n, (double)a0, (double)a1, (double)N, (double)T,
                          (double)(ctx->rotation.omega * ctx->mesh.r_outer - ctx->obstacle.sheet_speed), st->iterations));
  if (!ctx->eig.steady_csv[0]) PetscFunctionReturn(0);
  PetscCall(RollerPartFileOpen(ctx->comm, ctx->eig.steady_csv, "-modes_steady_csv", part, sizeof(part), &fp));
  if (fp) {
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "x,y,normal_force,tangential_force,gap,slip_velocity,mu\n"));
    for (PetscInt j = 0; j < st->n; ++j)
      PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", (double)st->xy[2 * j], (double)st->xy[2 * j + 1], (double)st->normal[j], (double)(-st->sign * st->mu[j] * st->normal[j]), (double)st->gap[j], (double)st->slip[j],
                             (double)st->mu[j]));
  }
  PetscCall(RollerPartFileClose(ctx->comm, &fp, part, ctx->eig.steady_csv));
  PetscFunctionReturn(0);
}
