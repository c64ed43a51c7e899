/* The steady rolling/sliding state of the roller pressed by the sheet, in the lab (Eulerian) description
   (docs/squeal.md section 3): the obstacle and the contact patch stand still while the material flows through
   them, so the state solves one static problem with the constant matrix K_lab = K - rho theta'^2 P,

     K_lab u = rho theta'^2 L_centrifugal + sum_j (N_j e_y + T_j e_x)            (forces at the Gamma_C nodes j)
     gap_j = y_j,2 + u_j,2 - g >= 0,  N_j >= 0,  N_j gap_j = 0,                   (the sheet at height g = depth - r_outer)
     v_j = theta'(-y_j,2 + d_phi u_j,1) - V,  |T_j| <= mu_j N_j,  T_j = -mu_j N_j sign(v_j) where v_j != 0,

   on the Gamma_C nodes within reach of the sheet: v_j is the speed of the material over the sheet (the rigid
   rotation's plus the convective rate of the displacement, d_phi along Gamma_C by differences, upwind: three
   points at j, or two with the slip taken midway, -modes_slip_difference), so a node sticks
   (v_j = 0) or slips against its force: Carter's rolling with stick and slip zones, full sliding when the sheet
   is held, frictionless rolling at mu = 0. K_lab is factored once; its inverse applied to the unit forces gives
   the dense dual data (gaps and slips of the candidates), and Coulomb's law on it is one LCP solved by Lemke's
   method (RollerContactCoulombLemke; without friction the normal LCP alone). mu_j = mu(|v_j|) (velocity
   weakening; mu_s where a node sticks) is repeated until it settles. */
#include "modes/modes.h"

/* mu(|v|) and its derivative: the law of the step (friction/law.c) */
static void FrictionLaw(Roller ctx, PetscReal v, PetscReal *mu, PetscReal *dmu)
{
  *mu = RollerFrictionMu(&ctx->obstacle, v, dmu);
}

/* A node on Gamma_C: |x| = r_outer (vertices, and the curved P2 boundary's edge nodes) */
static PetscBool OnOuterCircle(Roller ctx, PetscReal x0, PetscReal x1)
{
  return PetscAbsReal(PetscSqrtReal(x0 * x0 + x1 * x1) - ctx->mesh.r_outer) <= 1e-8 * ctx->mesh.r_outer ? PETSC_TRUE : PETSC_FALSE;
}

/* The Gamma_C nodes (|x| = r_outer) with rigid gap y_2 - g below reach, gathered on every rank, sorted by angle; their
   dofs in the operator K (with Maxwell branches the augmented one, whose every rank's rows start with its xi rows). */
static PetscErrorCode Candidates(Roller ctx, Mat K, PetscReal g, PetscReal reach, RollerSteady *st)
{
  const PetscScalar *x;
  PetscInt           n, lo, nloc = 0, *dof;
  PetscReal         *xy;
  PetscMPIInt        size, cnt, *counts, *displs;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(ctx->ops.coordinates, &n));
  PetscCall(MatGetOwnershipRange(K, &lo, NULL));
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

/* The slip speed of candidate j: d_phi of the x displacement, coefficients c[3] on the candidates nb[3] (sorted by
   angle), and the weights a[3] of the point values (the rigid rotation's speed, the perturbation's rate) at the point
   where the slip is taken. Upwind: the material flows through Gamma_C in the direction of the rotation, and the slip
   speed's d_phi is the transport of the displacement by that flow, so the difference looks upstream:
   - box: two points, j and its upstream neighbour j -+ 1, the slip at their midpoint (the point values averaged,
     a = 1/2, 1/2): second order there, and j's stick or slip is that of the segment it closes; the stick CEA
     converges with it (docs/squeal.md 4.4.4);
   - upwind: the same difference taken at j (a = 1, 0): first order; its error, half a spacing of numerical
     diffusion, shortens the stick zone on coarse meshes (docs/squeal.md 4.4.4);
   - upwind2: three points j, j -+ 1, j -+ 2, the parabola's derivative at j: second order but not monotone (the
     third point's weight has the other sign): at the stick/slip boundary, where the slip's derivative jumps, it
     leaves fragmented stick zones (stick, slip, stick, ..., differently on every mesh), and the CEA about them does
     not converge with the contact mesh (docs/squeal.md 4.4.2, 4.4.4); the default before box.
   The upstream end uses its downstream neighbour (and upwind2 the two points next to it). A central difference
   would leave the stick condition v_j = 0 blind to every other node (odd-even decoupling: the dual matrix of the
   stick zone singular). */
PetscErrorCode RollerSteadyAngularDerivative(const RollerSteady *st, PetscReal omega, PetscInt j, PetscInt nb[3], PetscReal c[3], PetscReal a[3])
{
  const PetscInt up = omega >= 0 ? -1 : 1, end = omega >= 0 ? 0 : st->n - 1;
  PetscReal      t[3];
  PetscInt       k = st->difference == ROLLER_SLIP_UPWIND2 ? 3 : 2;

  PetscFunctionBeginUser;
  PetscCheck(st->n > 2, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%" PetscInt_FMT " contact candidates: too few for a derivative along Gamma_C", st->n);
  nb[0] = j;
  if (j == end) { /* nothing upstream: the downstream difference */
    nb[1] = j - up;
    nb[2] = j - 2 * up;
  } else if (j == end - up) {
    nb[1] = j + up;
    nb[2] = j;
    k     = 2;
  } else {
    nb[1] = j + up;
    nb[2] = j + 2 * up;
  }
  for (PetscInt i = 0; i < 3; ++i) t[i] = PetscAtan2Real(st->xy[2 * nb[i] + 1], st->xy[2 * nb[i]]);
  a[0] = 1.0;
  a[1] = a[2] = 0.0;
  /* box: the slip at the midpoint of j and nb[1] */
  if (st->difference == ROLLER_SLIP_BOX) a[0] = a[1] = 0.5;
  if (k == 2) { /* two points */
    c[0] = 1.0 / (t[0] - t[1]);
    c[1] = -c[0];
    c[2] = 0.0;
  } else { /* the derivative at t0 of the parabola through t0, t1, t2 */
    c[0] = 1.0 / (t[0] - t[1]) + 1.0 / (t[0] - t[2]);
    c[1] = (t[0] - t[2]) / ((t[1] - t[0]) * (t[1] - t[2]));
    c[2] = (t[0] - t[1]) / ((t[2] - t[0]) * (t[2] - t[1]));
  }
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

/* K_lab^-1 of the unit force at candidate k along e_{1+c} (c = 0: x, 1: y) into w */
static PetscErrorCode UnitResponse(KSP ksp, const RollerSteady *st, PetscInt k, PetscInt c, Vec f, Vec w)
{
  PetscInt lo, hi;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(f));
  PetscCall(VecGetOwnershipRange(f, &lo, &hi));
  if (st->dof[k] >= lo && st->dof[k] < hi) PetscCall(VecSetValue(f, st->dof[k] + c, 1.0, INSERT_VALUES));
  PetscCall(VecAssemblyBegin(f));
  PetscCall(VecAssemblyEnd(f));
  PetscCall(KSPSolve(ksp, f, w));
  PetscFunctionReturn(0);
}

/* The gaps and the slip speeds (over vs) of the candidates for the candidate values xs of a state, or (affine
   false) of a response: gap_j = y_j,2 + u_j,2 - g, v_j = theta'(-y_j,2 + d_phi u_j,1) - V. */
static PetscErrorCode GapSlip(Roller ctx, const RollerSteady *st, const PetscReal xs[], PetscBool affine, PetscReal g, PetscReal vs, PetscReal gap[], PetscReal slip[])
{
  const PetscReal w = ctx->rotation.omega;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < st->n; ++j) {
    PetscInt  nb[3];
    PetscReal c[3], a[3], du = 0, y = 0;

    PetscCall(RollerSteadyAngularDerivative(st, w, j, nb, c, a));
    for (PetscInt k = 0; k < 3; ++k) du += c[k] * xs[2 * nb[k]], y += a[k] * st->xy[2 * nb[k] + 1];
    gap[j]  = xs[2 * j + 1] + (affine ? st->xy[2 * j + 1] - g : 0.0);
    slip[j] = (w * du + (affine ? -w * y - ctx->obstacle.sheet_speed : 0.0)) / vs;
  }
  PetscFunctionReturn(0);
}

/* The dual data of the candidates: G = [gap; slip/vs] of the unit forces (column k < n: normal force at candidate
   k, k >= n: tangential force at k - n; only the normal ones without friction) into w[k], and d of the state uf
   without contact forces. */
static PetscErrorCode Responses(Roller ctx, KSP ksp, Vec uf, PetscReal g, PetscReal vs, PetscBool friction, RollerSteady *st, Vec *w, PetscReal G[], PetscReal d[])
{
  const PetscInt n = st->n, m = friction ? 2 * n : n;
  PetscReal     *xs, *scratch;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(2 * n, &xs, n, &scratch));
  for (PetscInt k = 0; k < m; ++k) {
    PetscCall(UnitResponse(ksp, st, k % n, k < n ? 1 : 0, st->u, w[k]));
    PetscCall(CandidateValues(st, w[k], xs));
    PetscCall(GapSlip(ctx, st, xs, PETSC_FALSE, g, vs, G + (size_t)k * m, friction ? G + (size_t)k * m + n : scratch));
  }
  PetscCall(CandidateValues(st, uf, xs));
  PetscCall(GapSlip(ctx, st, xs, PETSC_TRUE, g, vs, d, friction ? d + n : scratch));
  PetscCall(PetscFree2(xs, scratch));
  PetscFunctionReturn(0);
}

/* The contact forces at fixed mu_j (RollerSteadyCoulomb), the state u, the candidates' gaps, slips and states. */
static PetscErrorCode SolveContact(Roller ctx, Vec uf, PetscReal g, PetscBool friction, const PetscReal G[], const PetscReal d[], Vec *w, RollerSteady *st)
{
  const PetscInt n = st->n;
  PetscReal     *xs, nmax = 0;

  PetscFunctionBeginUser;
  PetscCall(RollerSteadyCoulomb(ctx->comm, n, G, d, friction, st->mu, st->normal, st->tangent, st->state, &st->alternations, &st->active_set));
  PetscCall(VecCopy(uf, st->u));
  for (PetscInt j = 0; j < n; ++j) {
    if (st->normal[j] != 0) PetscCall(VecAXPY(st->u, st->normal[j], w[j]));
    if (friction && st->tangent[j] != 0) PetscCall(VecAXPY(st->u, st->tangent[j], w[n + j]));
    nmax = PetscMax(nmax, st->normal[j]);
  }
  PetscCall(PetscMalloc1(2 * n, &xs));
  PetscCall(CandidateValues(st, st->u, xs));
  PetscCall(GapSlip(ctx, st, xs, PETSC_TRUE, g, 1.0, st->gap, st->slip));
  for (PetscInt j = 0; j < n; ++j) { /* 0 off the sheet, 1 stick (inside the cone), 2 slip (on it) */
    if (st->normal[j] <= 1e-12 * nmax) st->state[j] = 0;
    else st->state[j] = friction && PetscAbsReal(st->tangent[j]) < (1.0 - 1e-9) * st->mu[j] * st->normal[j] ? 1 : 2;
  }
  PetscCall(PetscFree(xs));
  PetscFunctionReturn(0);
}

/* The direct solver of K_lab (-modes_steady_ksp_*), factored at its first solve */
PetscErrorCode RollerSteadyKSPCreate(Roller ctx, Mat Klab, KSP *ksp)
{
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(ctx->comm, ksp));
  PetscCall(KSPSetOperators(*ksp, Klab, Klab));
  PetscCall(RollerDirectSolverDefaults(*ksp, PCLU));
  PetscCall(KSPSetOptionsPrefix(*ksp, "modes_steady_"));
  PetscCall(KSPSetFromOptions(*ksp));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSteadySolve(Roller ctx, Mat Klab, RollerSteady *st)
{
  KSP ksp;

  PetscFunctionBeginUser;
  PetscCall(RollerSteadyKSPCreate(ctx, Klab, &ksp));
  PetscCall(RollerSteadySolveWith(ctx, ksp, st));
  PetscCall(KSPDestroy(&ksp));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSteadySolveWith(Roller ctx, KSP ksp, RollerSteady *st)
{
  const PetscReal g = ctx->obstacle.depth - ctx->mesh.r_outer, w = ctx->rotation.omega, rho = ctx->material.density;
  const PetscBool friction = ctx->obstacle.friction > 0 || ctx->obstacle.friction_static > 0 ? PETSC_TRUE : PETSC_FALSE;
  const PetscReal vs       = PetscMax(PetscAbsReal(w) * ctx->mesh.r_outer, PetscAbsReal(ctx->obstacle.sheet_speed)) / ctx->mesh.r_outer > 0 ? PetscMax(PetscAbsReal(w) * ctx->mesh.r_outer, PetscAbsReal(ctx->obstacle.sheet_speed)) / ctx->mesh.r_outer : 1.0; /* slips over vs: lengths */
  PetscReal       reach = PetscMax(ctx->obstacle.depth, 1e-3 * ctx->mesh.r_outer), v0 = w * ctx->mesh.r_outer - ctx->obstacle.sheet_speed;
  PetscReal       range[2]; /* of mu(v): its largest the scale of mu's change */
  Mat             Klab;
  Vec             uf;

  PetscFunctionBeginUser;
  RollerFrictionRange(&ctx->obstacle, range);
  PetscCall(PetscMemzero(st, sizeof(*st)));
  st->difference = ctx->eig.slip_difference;
  PetscCall(KSPGetOperators(ksp, &Klab, NULL));
  PetscCall(MatCreateVecs(Klab, &uf, &st->u));
  PetscCall(RollerBranchExtend(ctx->ops.L_centrifugal, st->u));
  PetscCall(VecScale(st->u, rho * w * w));
  PetscCall(KSPSolve(ksp, st->u, uf));
  for (PetscInt attempt = 0;; ++attempt) { /* widen the candidate zone until no node outside it penetrates */
    Vec      *wk;
    PetscReal gmin, *G, *d;
    PetscInt  n, m;

    PetscCall(Candidates(ctx, Klab, g, reach, st));
    PetscCheck(st->n > 2, ctx->comm, PETSC_ERR_ARG_WRONG, "-obstacle_depth %g: fewer than three Gamma_C nodes within reach of the sheet; press deeper or refine the mesh", (double)ctx->obstacle.depth);
    PetscCall(PetscCalloc7(st->n, &st->normal, st->n, &st->tangent, st->n, &st->mu, st->n, &st->dmu, st->n, &st->slip, st->n, &st->gap, st->n, &st->state));
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
    m = friction ? 2 * st->n : st->n;
    PetscCall(VecDuplicateVecs(uf, m, &wk));
    PetscCall(PetscMalloc2((size_t)m * m, &G, m, &d));
    PetscCall(Responses(ctx, ksp, uf, g, vs, friction, st, wk, G, d));
    for (st->iterations = 1;; ++st->iterations) { /* mu_j = mu(|v_j|) at the state's slips */
      PetscReal change = 0;

      PetscCall(SolveContact(ctx, uf, g, friction, G, d, wk, st));
      for (PetscInt j = 0; j < st->n; ++j) {
        PetscReal mu, dmu;

        FrictionLaw(ctx, st->slip[j], &mu, &dmu);
        change     = PetscMax(change, PetscAbsReal(mu - st->mu[j]));
        st->mu[j]  = mu;
        st->dmu[j] = dmu;
      }
      if (change <= 1e-12 * PetscMax(range[1], 1e-300) || !friction) break;
      PetscCheck(st->iterations < 50, ctx->comm, PETSC_ERR_NOT_CONVERGED, "The steady state's mu(v) did not settle in 50 passes (last change %g)", (double)change);
    }
    PetscCall(VecDestroyVecs(m, &wk));
    PetscCall(PetscFree2(G, d));
    /* every Gamma_C node outside the candidates above the sheet? */
    gmin = PETSC_MAX_REAL;
    PetscCall(VecGetLocalSize(ctx->ops.coordinates, &n)); /* the xi part of u leads its local array */
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
    if (gmin >= 0) break;
    PetscCheck(attempt < 8, ctx->comm, PETSC_ERR_PLIB, "The steady state penetrates the sheet outside every candidate zone tried");
    reach *= 2;
    PetscCall(RollerSteadyDestroy(st, PETSC_FALSE));
  }
  PetscCall(VecDestroy(&uf));
  PetscFunctionReturn(0);
}

/* Frees the candidates' arrays (and the state u with all) */
PetscErrorCode RollerSteadyDestroy(RollerSteady *st, PetscBool all)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(st->dof, st->xy));
  PetscCall(PetscFree7(st->normal, st->tangent, st->mu, st->dmu, st->slip, st->gap, st->state));
  PetscCall(VecScatterDestroy(&st->scatter));
  PetscCall(VecDestroy(&st->red));
  if (all) PetscCall(VecDestroy(&st->u));
  PetscFunctionReturn(0);
}

/* The steady state in numbers: printed, and with -modes_steady_csv F one row per candidate node
   x,y,normal_force,tangential_force,gap,slip_velocity,mu,state (state 0 off the sheet, 1 stick, 2 slip;
   rank 0 writes F.part, renamed when complete). */
PetscErrorCode RollerSteadyReport(Roller ctx, const RollerSteady *st)
{
  PetscReal N = 0, T = 0, a0 = PETSC_MAX_REAL, a1 = -PETSC_MAX_REAL;
  PetscInt  count[3] = {0, 0, 0};
  char      part[PETSC_MAX_PATH_LEN];
  FILE     *fp;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < st->n; ++j) {
    ++count[st->state[j]];
    if (!st->state[j]) continue;
    N += st->normal[j];
    T += st->tangent[j];
    a0 = PetscMin(a0, st->xy[2 * j]);
    a1 = PetscMax(a1, st->xy[2 * j]);
  }
  if (!ctx->ts.quiet)
    PetscCall(PetscPrintf(ctx->comm, "roller: steady %s state (lab frame): %" PetscInt_FMT " of %" PetscInt_FMT " candidate nodes in contact over x in [%g, %g] (%" PetscInt_FMT " stick, %" PetscInt_FMT " slip), normal force %.6g, friction force %.6g, nominal slip speed %g, %" PetscInt_FMT " mu(v) passes (the last: %" PetscInt_FMT " normal/tangential alternations, at most %" PetscInt_FMT " stick/slip active-set iterations each)\n", T == 0 ? "frictionless rolling" : (count[1] ? "rolling" : "sliding"), count[1] + count[2], st->n, (double)a0, (double)a1, count[1], count[2], (double)N, (double)T,
                          (double)(ctx->rotation.omega * ctx->mesh.r_outer - ctx->obstacle.sheet_speed), st->iterations, st->alternations, st->active_set));
  if (!ctx->eig.steady_csv[0]) PetscFunctionReturn(0);
  PetscCall(RollerPartFileOpen(ctx->comm, ctx->eig.steady_csv, "-modes_steady_csv", part, sizeof(part), &fp));
  if (fp) {
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "x,y,normal_force,tangential_force,gap,slip_velocity,mu,state\n"));
    for (PetscInt j = 0; j < st->n; ++j)
      PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT "\n", (double)st->xy[2 * j], (double)st->xy[2 * j + 1], (double)st->normal[j], (double)st->tangent[j], (double)st->gap[j], (double)st->slip[j],
                             (double)st->mu[j], st->state[j]));
  }
  PetscCall(RollerPartFileClose(ctx->comm, &fp, part, ctx->eig.steady_csv));
  PetscFunctionReturn(0);
}
