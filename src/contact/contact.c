/* The obstacle QP of one DMF step (docs/model.md section 2): the Gamma_C nodes, the candidate set, the dispatch to
   the solver chosen by -contact_solver with the penetration check, the KKT residual and the per-step contact
   diagnostics (docs/model.md section 6). The solvers live in contact_condensed.c, contact_primal.c, contact_pcg.c. */
#include "contact_impl.h"

const char *const RollerContactSolverTypes[] = {"condensed", "vi", "tao", "pcg", "RollerContactSolverType", "CONTACT_", NULL};
const char *const RollerContactQPTypes[]     = {"activeset", "tao", "RollerContactQPType", "CONTACT_QP_", NULL};

/* A node outside the candidate set whose gap is below -tol triggers a re-solve with it added. */
PetscReal RollerContactGapTolerance(Roller ctx)
{
  return 1e-12 * ctx->mesh.r_outer;
}

static PetscErrorCode ContactSetFromOptions(Roller ctx, RollerContact c)
{
  PetscFunctionBeginUser;
  c->solver       = CONTACT_CONDENSED;
  c->qp           = CONTACT_QP_ACTIVESET;
  c->margin       = 2e-3 * ctx->mesh.r_outer;
  c->rtol         = 1e-12;
  c->pcg_rtol     = 1e-12;
  c->pcg_max_it   = 100000;
  c->max_resolves = 20;
  c->tao_j0       = PETSC_TRUE;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: contact QP (docs/contact.md)", NULL);
  PetscCall(PetscOptionsEnum("-contact_solver", "Per-step QP solver: condensed (Schur complement on Gamma_C, fast), vi (SNES VI), tao (TAO), pcg (the paper's projected CG)", NULL, RollerContactSolverTypes, (PetscEnum)c->solver, (PetscEnum *)&c->solver, NULL));
  PetscCall(PetscOptionsEnum("-contact_condensed_qp", "Solver of the condensed multiplier QP: activeset (exact) or tao (type -contact_condensed_tao_type)", NULL, RollerContactQPTypes, (PetscEnum)c->qp, (PetscEnum *)&c->qp, NULL));
  PetscCall(PetscOptionsBool("-contact_check", "Each step also solve with every other solver; print the differences and KKT residuals", NULL, c->check, &c->check, NULL));
  PetscCall(PetscOptionsBool("-contact_monitor", "Print the contact set of every step: nodes, force, extent and centroid along t^k", NULL, c->monitor, &c->monitor, NULL));
  PetscCall(PetscOptionsReal("-contact_margin", "Reach of the candidate set beyond the predicted gap (length; < 0 shrinks it, to test the penetration check)", NULL, c->margin, &c->margin, NULL));
  PetscCall(PetscOptionsReal("-contact_rtol", "Relative tolerance of vi, tao (-contact_tao_type, default tron) and the condensed TAO", NULL, c->rtol, &c->rtol, NULL));
  PetscCall(PetscOptionsBool("-contact_tao_j0", "Quasi-Newton TAO types (bqnls, bqnk*): the exact inverse Hessian Q^T A^{-1} Q as J0", NULL, c->tao_j0, &c->tao_j0, NULL));
  PetscCall(PetscOptionsReal("-contact_pcg_rtol", "Projected CG stops when ||T(-grad J)|| <= rtol max(||b||, ||A|| ||xi_0||)", NULL, c->pcg_rtol, &c->pcg_rtol, NULL));
  PetscCall(PetscOptionsInt("-contact_pcg_max_it", "Iteration cap of the projected CG", NULL, c->pcg_max_it, &c->pcg_max_it, NULL));
  PetscCall(PetscOptionsInt("-contact_max_resolves", "Re-solves allowed per step when a node outside the candidate set penetrates", NULL, c->max_resolves, &c->max_resolves, NULL));
  PetscOptionsEnd();
  PetscCheck(c->margin > -ctx->mesh.r_outer, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_margin %g must be > -r_outer", (double)c->margin);
  PetscCheck(c->rtol > 0 && c->rtol < 1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_rtol %g must lie in (0, 1)", (double)c->rtol);
  PetscCheck(c->pcg_rtol > 0 && c->pcg_rtol < 1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_pcg_rtol %g must lie in (0, 1)", (double)c->pcg_rtol);
  PetscCheck(c->pcg_max_it > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_pcg_max_it %" PetscInt_FMT " must be > 0", c->pcg_max_it);
  PetscCheck(c->max_resolves >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_max_resolves %" PetscInt_FMT " must be >= 0", c->max_resolves);
  PetscFunctionReturn(0);
}

/* The Lagrange nodes of Gamma_C (label "outer": vertices, and edges for P2) with their global dof pairs and
   positions, gathered on every rank and sorted by angle, so every rank numbers them the same way whatever
   the partition; and the scatter of their dofs from a global Vec into a redundant sequential Vec. */
static PetscErrorCode ContactGatherNodes(Roller ctx, RollerContact c)
{
  DMLabel            label;
  PetscSection       gsection;
  IS                 is, to;
  const PetscInt    *points;
  const PetscScalar *x;
  PetscInt           npoints = 0, nown = 0, rstart, rend, *mine_idx, *mine_vert, *mine_point, *idx, *vert, *perm;
  PetscReal         *mine_x, *angle, *xc;
  PetscMPIInt        size, n_mine, *counts, *displs, *counts2, *displs2;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCall(DMGetLabel(ctx->mesh.dm, "outer", &label));
  PetscCheck(label, ctx->comm, PETSC_ERR_ARG_WRONG, "The mesh has no label \"outer\" (Gamma_C)");
  PetscCall(DMGetGlobalSection(ctx->mesh.dm, &gsection));
  PetscCall(VecGetOwnershipRange(ctx->ops.coordinates, &rstart, &rend));
  PetscCall(DMLabelGetStratumIS(label, 1, &is));
  if (is) PetscCall(ISGetLocalSize(is, &npoints));
  if (is) PetscCall(ISGetIndices(is, &points));
  /* every owned point of the label carries gdof/2 nodes (P1 vertex 1, P2 vertex or edge 1) */
  PetscCall(PetscMalloc4(2 * npoints * ctx->disc.degree, &mine_idx, 2 * npoints * ctx->disc.degree, &mine_vert, 2 * npoints * ctx->disc.degree, &mine_point, 4 * npoints * ctx->disc.degree, &mine_x));
  PetscCall(VecGetArrayRead(ctx->ops.coordinates, &x));
  for (PetscInt p = 0; p < npoints; ++p) {
    PetscInt gdof, gcdof, goff, depth;

    PetscCall(PetscSectionGetDof(gsection, points[p], &gdof));
    PetscCall(PetscSectionGetConstraintDof(gsection, points[p], &gcdof));
    PetscCall(PetscSectionGetOffset(gsection, points[p], &goff));
    if (gdof <= 0 || goff < 0) continue; /* not owned here */
    PetscCheck(gcdof == 0 && gdof % 2 == 0, ctx->comm, PETSC_ERR_PLIB, "Gamma_C point %" PetscInt_FMT " has %" PetscInt_FMT " dofs, %" PetscInt_FMT " constrained", points[p], gdof, gcdof);
    PetscCall(DMPlexGetPointDepth(ctx->mesh.dm, points[p], &depth));
    for (PetscInt j = 0; j < gdof; j += 2) {
      mine_idx[nown]       = goff + j;
      mine_vert[nown]      = depth == 0 ? 1 : 0;
      mine_point[nown]     = points[p];
      mine_x[2 * nown]     = PetscRealPart(x[goff + j - rstart]);
      mine_x[2 * nown + 1] = PetscRealPart(x[goff + j + 1 - rstart]);
      nown++;
    }
  }
  PetscCall(VecRestoreArrayRead(ctx->ops.coordinates, &x));
  if (is) PetscCall(ISRestoreIndices(is, &points));
  PetscCall(ISDestroy(&is));

  /* gather (index, position) of all nodes on every rank */
  PetscCall(PetscMalloc4(size, &counts, size, &displs, size, &counts2, size, &displs2));
  PetscCall(PetscMPIIntCast(nown, &n_mine));
  PetscCallMPI(MPI_Allgather(&n_mine, 1, MPI_INT, counts, 1, MPI_INT, ctx->comm));
  c->nc = 0;
  for (PetscMPIInt r = 0; r < size; ++r) {
    displs[r]  = (PetscMPIInt)c->nc;
    counts2[r] = 2 * counts[r];
    displs2[r] = 2 * displs[r];
    c->nc += counts[r];
  }
  PetscCheck(c->nc > 0, ctx->comm, PETSC_ERR_ARG_WRONG, "Gamma_C (label \"outer\") has no free nodes: the obstacle has nothing to touch");
  PetscCall(PetscMalloc5(c->nc, &idx, c->nc, &vert, 2 * c->nc, &xc, c->nc, &angle, c->nc, &perm));
  PetscCallMPI(MPI_Allgatherv(mine_idx, n_mine, MPIU_INT, idx, counts, displs, MPIU_INT, ctx->comm));
  PetscCallMPI(MPI_Allgatherv(mine_vert, n_mine, MPIU_INT, vert, counts, displs, MPIU_INT, ctx->comm));
  PetscCallMPI(MPI_Allgatherv(mine_x, 2 * n_mine, MPIU_REAL, xc, counts2, displs2, MPIU_REAL, ctx->comm));
  PetscCall(PetscFree4(counts, displs, counts2, displs2));
  PetscCall(PetscSortIntWithArray(nown, mine_idx, mine_point)); /* to find the mesh point of an owned node */

  for (PetscInt i = 0; i < c->nc; ++i) {
    angle[i] = PetscAtan2Real(xc[2 * i + 1], xc[2 * i]);
    perm[i]  = i;
  }
  PetscCall(PetscSortRealWithPermutation(c->nc, angle, perm));
  PetscCall(PetscMalloc3(c->nc, &c->gidx, c->nc, &c->is_vertex, 2 * c->nc, &c->xc));
  PetscCall(PetscMalloc3(nown, &c->own_node, nown, &c->own_off, nown, &c->own_point));
  c->nown = 0;
  for (PetscInt i = 0; i < c->nc; ++i) {
    c->gidx[i]       = idx[perm[i]];
    c->is_vertex[i]  = vert[perm[i]] ? PETSC_TRUE : PETSC_FALSE;
    c->xc[2 * i]     = xc[2 * perm[i]];
    c->xc[2 * i + 1] = xc[2 * perm[i] + 1];
    if (c->gidx[i] >= rstart && c->gidx[i] < rend) {
      PetscInt loc;

      c->own_node[c->nown] = i;
      c->own_off[c->nown]  = c->gidx[i] - rstart;
      PetscCall(PetscFindInt(c->gidx[i], nown, mine_idx, &loc));
      PetscCheck(loc >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Owned Gamma_C dof %" PetscInt_FMT " not found", c->gidx[i]);
      c->own_point[c->nown] = mine_point[loc];
      c->nown++;
    }
  }
  PetscCheck(c->nown == nown, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Owned Gamma_C nodes %" PetscInt_FMT " != %" PetscInt_FMT, c->nown, nown);
  PetscCall(PetscFree5(idx, vert, xc, angle, perm));
  PetscCall(PetscFree4(mine_idx, mine_vert, mine_point, mine_x));

  PetscCall(PetscMalloc1(2 * c->nc, &idx));
  for (PetscInt i = 0; i < c->nc; ++i) {
    idx[2 * i]     = c->gidx[i];
    idx[2 * i + 1] = c->gidx[i] + 1;
  }
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, 2 * c->nc, idx, PETSC_OWN_POINTER, &is));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, 2 * c->nc, 0, 1, &to));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 2 * c->nc, &c->red));
  PetscCall(VecDuplicate(c->red, &c->red1));
  PetscCall(VecDuplicate(c->red, &c->red2));
  PetscCall(VecScatterCreate(ctx->ops.coordinates, is, c->red, to, &c->scatter));
  PetscCall(ISDestroy(&is));
  PetscCall(ISDestroy(&to));
  PetscFunctionReturn(0);
}

/* -help without -obstacle: list the contact options and their defaults too (the same block as a run with
   the obstacle reads), without building any of the machinery. */
PetscErrorCode RollerContactHelp(Roller ctx)
{
  struct _n_RollerContact c;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&c, sizeof(c)));
  PetscCall(ContactSetFromOptions(ctx, &c));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactCreate(Roller ctx, RollerContact *contact)
{
  RollerContact c;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&c));
  c->comm = ctx->comm;
  PetscCall(ContactSetFromOptions(ctx, c));
  PetscCall(ContactGatherNodes(ctx, c));
  PetscCall(PetscMalloc7(c->nc, &c->cand, c->nc, &c->is_cand, c->nc, &c->on_obstacle, c->nc, &c->lower, c->nc, &c->gap, c->nc, &c->result.lambda, c->nc, &c->check_result.lambda));
  PetscCall(PetscArrayzero(c->result.lambda, c->nc));
  PetscCall(PetscArrayzero(c->is_cand, c->nc));
  PetscCall(VecDuplicate(ctx->state.cur, &c->b));
  PetscCall(VecDuplicate(ctx->state.cur, &c->force));
  PetscCall(VecDuplicate(ctx->state.cur, &c->work));
  if (c->check) PetscCall(VecDuplicate(ctx->state.cur, &c->xi_check));
  /* S is computed once (2 N_C solves): only when the condensed solver will be used */
  if (c->solver == CONTACT_CONDENSED || c->check) PetscCall(RollerContactCondensedCreate(ctx, c));
  PetscCall(PetscInfo(NULL, "Contact: %" PetscInt_FMT " Gamma_C nodes (%" PetscInt_FMT " on this rank), solver %s\n", c->nc, c->nown, RollerContactSolverTypes[c->solver]));
  *contact = c;
  PetscFunctionReturn(0);
}

/* Forward scatter of the Gamma_C dofs of a global Vec into a redundant Vec (2 nc entries, node order). */
PetscErrorCode RollerContactGather(RollerContact c, Vec v, Vec red)
{
  PetscFunctionBeginUser;
  PetscCall(VecScatterBegin(c->scatter, v, red, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(c->scatter, v, red, INSERT_VALUES, SCATTER_FORWARD));
  PetscFunctionReturn(0);
}

/* f = E N lambda: the nodal force lambda_n n^k at every owned Gamma_C node, 0 elsewhere. Every rank holds
   all multipliers and writes its own nodes, which is the reverse scatter without communication. */
PetscErrorCode RollerContactForce(RollerContact c, const PetscReal lambda[], Vec f)
{
  PetscScalar *fa;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(f));
  PetscCall(VecGetArray(f, &fa));
  for (PetscInt k = 0; k < c->nown; ++k) {
    const PetscInt i = c->own_node[k], off = c->own_off[k];

    fa[off]     = lambda[i] * c->normal[0];
    fa[off + 1] = lambda[i] * c->normal[1];
  }
  PetscCall(VecRestoreArray(f, &fa));
  PetscFunctionReturn(0);
}

/* theta^k, n^k = (sin theta, cos theta), t^k = (cos theta, -sin theta), g^k and the bounds
   q_n >= g^k - x_n . n^k of every node (docs/model.md sections 1-2). */
static PetscErrorCode ContactSetTime(Roller ctx, RollerContact c, PetscReal t)
{
  PetscFunctionBeginUser;
  c->t = t;
  RollerTheta(ctx, t, &c->theta, NULL, NULL);
  c->normal[0]  = PetscSinReal(c->theta);
  c->normal[1]  = PetscCosReal(c->theta);
  c->tangent[0] = PetscCosReal(c->theta);
  c->tangent[1] = -PetscSinReal(c->theta);
  c->g          = RollerObstacleHeight(ctx, t);
  for (PetscInt i = 0; i < c->nc; ++i) c->lower[i] = c->g - (c->xc[2 * i] * c->normal[0] + c->xc[2 * i + 1] * c->normal[1]);
  PetscFunctionReturn(0);
}

/* gap_n = (x_n + xi_n) . n^k - g^k at every node from the gathered displacement; returns the least. */
static PetscErrorCode ContactGaps(RollerContact c, Vec red, PetscReal gap[], PetscReal *gap_min)
{
  const PetscScalar *u;

  PetscFunctionBeginUser;
  *gap_min = PETSC_MAX_REAL;
  PetscCall(VecGetArrayRead(red, &u));
  for (PetscInt i = 0; i < c->nc; ++i) {
    gap[i]   = PetscRealPart(u[2 * i]) * c->normal[0] + PetscRealPart(u[2 * i + 1]) * c->normal[1] - c->lower[i];
    *gap_min = PetscMin(*gap_min, gap[i]);
  }
  PetscCall(VecRestoreArrayRead(red, &u));
  PetscFunctionReturn(0);
}

static void ContactCandidateList(RollerContact c)
{
  c->ncand = 0;
  for (PetscInt i = 0; i < c->nc; ++i)
    if (c->is_cand[i]) c->cand[c->ncand++] = i;
}

/* The nodes the obstacle can reach in this step: the gap of the extrapolated position
   x_n + 2 xi^{k-1}_n - xi^{k-2}_n against the obstacle at t_k (its motion and the rotation of n^k are exact
   in this prediction) is below the reach: -contact_margin, plus the obstacle's advance in one step, plus
   twice the largest displacement increment of a Gamma_C node in the last step (a bound on the change of
   velocity a contact shock can bring). A node that still penetrates is added after the solve.
   Also the nodes on the obstacle at the previous level t_{k-1} (gap^{k-1} <= tol with n^{k-1}, g^{k-1}): the
   initial active set of the condensed solver. It is derived from xi^{k-1}, not remembered from the last
   solve, so that the step is a function of the checkpointed state only and a restart repeats it exactly. */
static PetscErrorCode ContactCandidates(Roller ctx, RollerContact c)
{
  const PetscScalar *u1, *u2;
  const PetscReal    tol  = RollerContactGapTolerance(ctx);
  PetscReal          dmax = 0.0, reach, theta1, n1[2], g1;

  PetscFunctionBeginUser;
  PetscCall(RollerContactGather(c, ctx->state.cur, c->red1));
  PetscCall(RollerContactGather(c, ctx->state.prev, c->red2));
  PetscCall(VecGetArrayRead(c->red1, &u1));
  PetscCall(VecGetArrayRead(c->red2, &u2));
  for (PetscInt i = 0; i < c->nc; ++i) dmax = PetscMax(dmax, PetscSqrtReal(PetscSqr(PetscRealPart(u1[2 * i] - u2[2 * i])) + PetscSqr(PetscRealPart(u1[2 * i + 1] - u2[2 * i + 1]))));
  reach = c->margin + PetscAbsReal(c->g - RollerObstacleHeight(ctx, c->t - ctx->ts.dt)) + 2.0 * dmax;
  RollerTheta(ctx, ctx->state.time, &theta1, NULL, NULL);
  n1[0] = PetscSinReal(theta1);
  n1[1] = PetscCosReal(theta1);
  g1    = RollerObstacleHeight(ctx, ctx->state.time);
  for (PetscInt i = 0; i < c->nc; ++i) {
    const PetscReal p0 = PetscRealPart(2.0 * u1[2 * i] - u2[2 * i]), p1 = PetscRealPart(2.0 * u1[2 * i + 1] - u2[2 * i + 1]);
    const PetscReal gap1 = (c->xc[2 * i] + PetscRealPart(u1[2 * i])) * n1[0] + (c->xc[2 * i + 1] + PetscRealPart(u1[2 * i + 1])) * n1[1] - g1;

    c->is_cand[i]     = (p0 * c->normal[0] + p1 * c->normal[1] - c->lower[i] <= reach) ? PETSC_TRUE : PETSC_FALSE;
    c->on_obstacle[i] = gap1 <= tol ? PETSC_TRUE : PETSC_FALSE;
  }
  PetscCall(VecRestoreArrayRead(c->red1, &u1));
  PetscCall(VecRestoreArrayRead(c->red2, &u2));
  ContactCandidateList(c);
  PetscFunctionReturn(0);
}

/* Solve with one solver; then check ALL Gamma_C nodes, add every non-candidate that penetrates, re-solve. */
static PetscErrorCode ContactSolveWith(Roller ctx, RollerContact c, RollerContactSolverType solver, Vec b, Vec xi, RollerContactResult *res)
{
  const PetscReal tol = RollerContactGapTolerance(ctx);
  PetscInt        its = 0;

  PetscFunctionBeginUser;
  for (PetscInt pass = 0;; ++pass) {
    PetscInt  added = 0;
    PetscReal gap_min;

    switch (solver) {
    case CONTACT_CONDENSED:
      PetscCall(RollerContactCondensedSolve(ctx, c, b, xi, res));
      break;
    case CONTACT_VI:
      PetscCall(RollerContactVISolve(ctx, c, b, xi, res));
      break;
    case CONTACT_TAO:
      PetscCall(RollerContactTaoSolve(ctx, c, b, xi, res));
      break;
    case CONTACT_PCG:
      PetscCall(RollerContactPCGSolve(ctx, c, b, xi, res));
      break;
    default:
      SETERRQ(ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "Unknown contact solver %d", (int)solver);
    }
    its += res->its;
    PetscCall(RollerContactGather(c, xi, c->red));
    PetscCall(ContactGaps(c, c->red, c->gap, &gap_min));
    for (PetscInt i = 0; i < c->nc; ++i)
      if (!c->is_cand[i] && c->gap[i] < -tol) {
        c->is_cand[i] = PETSC_TRUE;
        added++;
      }
    if (!added) break;
    ContactCandidateList(c);
    c->resolves++;
    PetscCall(PetscInfo(NULL, "Contact %s: %" PetscInt_FMT " nodes outside the candidate set penetrate (gap %g), re-solving with %" PetscInt_FMT " candidates\n", RollerContactSolverTypes[solver], added, (double)gap_min, c->ncand));
    PetscCheck(pass < c->max_resolves, ctx->comm, PETSC_ERR_CONV_FAILED, "Contact at t = %g: nodes outside the candidate set still penetrate after %" PetscInt_FMT " re-solves (-contact_max_resolves)", (double)c->t, c->max_resolves);
  }
  res->its = its;
  PetscFunctionReturn(0);
}

/* The KKT residual of (xi, lambda) for the step's QP (docs/contact.md), with F = max(||b||, ||E N lambda||):
   max of  max(0, -min gap)/r_C,  max(0, -min lambda)/F,  max |lambda_n gap_n|/(F r_C),
   ||A xi - b - E N lambda||/F. Also returns the least gap over all Gamma_C nodes. */
static PetscErrorCode ContactKKT(Roller ctx, RollerContact c, Vec xi, const PetscReal lambda[], PetscReal *gap_min, PetscReal *kkt)
{
  PetscReal nb, nf, nr, fs, lmin = 0.0, comp = 0.0;

  PetscFunctionBeginUser;
  PetscCall(RollerContactGather(c, xi, c->red));
  PetscCall(ContactGaps(c, c->red, c->gap, gap_min));
  PetscCall(RollerContactForce(c, lambda, c->force));
  PetscCall(MatMult(ctx->ops.A, xi, c->work));
  PetscCall(VecAXPBYPCZ(c->work, -1.0, -1.0, 1.0, c->b, c->force));
  PetscCall(VecNorm(c->work, NORM_2, &nr));
  PetscCall(VecNorm(c->b, NORM_2, &nb));
  PetscCall(VecNorm(c->force, NORM_2, &nf));
  fs = PetscMax(nb, nf);
  if (fs == 0.0) fs = 1.0;
  for (PetscInt i = 0; i < c->nc; ++i) {
    lmin = PetscMin(lmin, lambda[i]);
    comp = PetscMax(comp, PetscAbsReal(lambda[i] * c->gap[i]));
  }
  *kkt = PetscMax(PetscMax(PetscMax(0.0, -*gap_min) / ctx->mesh.r_outer, -lmin / fs), PetscMax(comp / (fs * ctx->mesh.r_outer), nr / fs));
  PetscFunctionReturn(0);
}

/* -contact_check: the same step with every other solver, from the same data and candidate set. */
static PetscErrorCode ContactCheck(Roller ctx, RollerContact c, Vec b, Vec xi)
{
  PetscReal xmax, gap_min, kkt;

  PetscFunctionBeginUser;
  PetscCall(VecNorm(xi, NORM_INFINITY, &xmax));
  if (xmax == 0.0) xmax = 1.0;
  PetscCall(ContactKKT(ctx, c, xi, c->result.lambda, &gap_min, &kkt));
  c->check_max_kkt[c->solver] = PetscMax(c->check_max_kkt[c->solver], kkt);
  PetscCall(PetscPrintf(ctx->comm, "contact_check: step %" PetscInt_FMT " t %.6g solver %s its %" PetscInt_FMT " diff %.3e kkt %.3e gap_min %+.3e\n", ctx->state.step + 1, (double)c->t, RollerContactSolverTypes[c->solver], c->result.its, 0.0, (double)kkt, (double)gap_min));
  for (PetscInt s = 0; s < CONTACT_NUM_SOLVERS; ++s) {
    PetscReal diff;

    if (s == (PetscInt)c->solver) continue;
    PetscCall(ContactSolveWith(ctx, c, (RollerContactSolverType)s, b, c->xi_check, &c->check_result));
    PetscCall(ContactKKT(ctx, c, c->xi_check, c->check_result.lambda, &gap_min, &kkt));
    PetscCall(VecAXPY(c->xi_check, -1.0, xi));
    PetscCall(VecNorm(c->xi_check, NORM_INFINITY, &diff));
    diff /= xmax;
    c->check_max_diff[s] = PetscMax(c->check_max_diff[s], diff);
    c->check_max_kkt[s]  = PetscMax(c->check_max_kkt[s], kkt);
    PetscCall(PetscPrintf(ctx->comm, "contact_check: step %" PetscInt_FMT " t %.6g solver %s its %" PetscInt_FMT " diff %.3e kkt %.3e gap_min %+.3e\n", ctx->state.step + 1, (double)c->t, RollerContactSolverTypes[s], c->check_result.its, (double)diff, (double)kkt, (double)gap_min));
  }
  c->check_steps++;
  PetscFunctionReturn(0);
}

/* xi = argmin 1/2 xi^T A xi - b^T xi over the admissible set at t = t_k (docs/model.md section 2). */
PetscErrorCode RollerContactSolve(Roller ctx, RollerContact c, PetscReal t, Vec b, Vec xi)
{
  PetscFunctionBeginUser;
  PetscCall(ContactSetTime(ctx, c, t));
  PetscCall(VecCopy(b, c->b));
  PetscCall(ContactCandidates(ctx, c));
  c->resolves = 0;
  PetscCall(ContactSolveWith(ctx, c, c->solver, b, xi, &c->result));
  c->solved = PETSC_TRUE;
  if (c->check) PetscCall(ContactCheck(ctx, c, b, xi));
  PetscFunctionReturn(0);
}

/* -contact_monitor: the contact set along the tangent t^k, s_n = (x_n + xi_n) . t^k: its extent, the
   force-weighted centroid (0 for a contact symmetric about the line through the centre along n^k) and the
   force-weighted RMS distance from it (a Hertz pressure p0 sqrt(1 - s^2/a^2) has s_rms = a/2). */
static PetscErrorCode ContactMonitor(Roller ctx, RollerContact c, const RollerStepInfo *info)
{
  const PetscScalar *u;
  PetscReal          smin = 0.0, smax = 0.0, sbar = 0.0, s2 = 0.0;
  PetscBool          first = PETSC_TRUE;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(c->red, &u));
  for (PetscInt i = 0; i < c->nc; ++i) {
    const PetscReal s = (c->xc[2 * i] + PetscRealPart(u[2 * i])) * c->tangent[0] + (c->xc[2 * i + 1] + PetscRealPart(u[2 * i + 1])) * c->tangent[1];

    if (c->result.lambda[i] <= 0.0) continue;
    smin = first ? s : PetscMin(smin, s);
    smax = first ? s : PetscMax(smax, s);
    sbar += c->result.lambda[i] * s;
    first = PETSC_FALSE;
  }
  if (info->contact_force > 0) sbar /= info->contact_force;
  for (PetscInt i = 0; i < c->nc; ++i) {
    const PetscReal s = (c->xc[2 * i] + PetscRealPart(u[2 * i])) * c->tangent[0] + (c->xc[2 * i + 1] + PetscRealPart(u[2 * i + 1])) * c->tangent[1];

    if (c->result.lambda[i] > 0.0) s2 += c->result.lambda[i] * PetscSqr(s - sbar);
  }
  PetscCall(VecRestoreArrayRead(c->red, &u));
  if (info->contact_force > 0) s2 /= info->contact_force;
  PetscCall(PetscPrintf(ctx->comm, "contact_monitor: step %" PetscInt_FMT " t %.6g nodes %" PetscInt_FMT " force %.10e s_min %+.10e s_max %+.10e s_centroid %+.10e s_rms %.10e candidates %" PetscInt_FMT " resolves %" PetscInt_FMT "\n", ctx->state.step,
                        (double)c->t, info->contact_nodes, (double)info->contact_force, (double)smin, (double)smax, (double)sbar, (double)PetscSqrtReal(s2), c->ncand, c->resolves));
  PetscFunctionReturn(0);
}

/* The contact columns of the CSV (docs/model.md section 6) for the solution xi at t. */
PetscErrorCode RollerContactInfo(Roller ctx, RollerContact c, Vec xi, PetscReal t, RollerStepInfo *info)
{
  PetscReal gap_min, kkt;

  PetscFunctionBeginUser;
  if (!c->solved || t != c->t) { /* before the first step: no multipliers yet */
    PetscCall(ContactSetTime(ctx, c, t));
    PetscCall(PetscArrayzero(c->result.lambda, c->nc));
    c->result.its = 0;
    PetscCall(RollerContactGather(c, xi, c->red));
    PetscCall(ContactGaps(c, c->red, c->gap, &gap_min));
    kkt = PetscMax(0.0, -gap_min) / ctx->mesh.r_outer;
  } else PetscCall(ContactKKT(ctx, c, xi, c->result.lambda, &gap_min, &kkt));
  info->contact_nodes = 0;
  info->contact_force = 0.0;
  for (PetscInt i = 0; i < c->nc; ++i) {
    if (c->result.lambda[i] > 0.0) info->contact_nodes++;
    info->contact_force += c->result.lambda[i];
  }
  info->gap_min       = gap_min;
  info->qp_iterations = c->result.its;
  info->kkt_residual  = kkt;
  if (c->monitor) PetscCall(ContactMonitor(ctx, c, info));
  PetscFunctionReturn(0);
}

/* The contact pressure at the Gamma_C vertices (output field contact_pressure, docs/contact.md). The multipliers
   are nodal forces, lambda_n = int_{Gamma_C} p phi_n ds for a normal traction p. With h_v the P1 hat function
   of vertex v on the polygon of the Gamma_C vertices, the lumped L2 projection of the traction onto P1 is
     p_v = sum_n lambda_n h_v(x_n) / int h_v ds,   int h_v ds = half the lengths of the two polygon edges at v:
   for P1 the nodal force over its tributary length; for P2 an edge midpoint gives half its force to each end
   of its edge. The trapezoidal integral of p over the polygon, sum_v p_v int h_v ds, is then exactly
   sum_n lambda_n, the contact force. p is a global Vec of a P1 scalar space on (a clone of) the mesh; on return
   it holds p_v at every Gamma_C vertex and 0 everywhere else. */
PetscErrorCode RollerContactPressure(Roller ctx, RollerContact c, Vec p)
{
  const PetscReal *lambda = c->result.lambda;
  PetscReal       *force, *trib;
  PetscScalar     *pa;
  PetscInt         first = -1, rstart;
  DM               dm;
  PetscSection     gsection;

  PetscFunctionBeginUser;
  PetscCall(VecGetDM(p, &dm));
  PetscCheck(dm, ctx->comm, PETSC_ERR_ARG_WRONG, "The contact pressure Vec needs a DM (a P1 scalar space on the mesh)");
  PetscCall(DMGetGlobalSection(dm, &gsection));
  PetscCall(VecGetOwnershipRange(p, &rstart, NULL));
  PetscCall(PetscCalloc2(c->nc, &force, c->nc, &trib));
  for (PetscInt i = 0; i < c->nc && first < 0; ++i)
    if (c->is_vertex[i]) first = i;
  PetscCheck(first >= 0, ctx->comm, PETSC_ERR_PLIB, "Gamma_C has no vertex");
  /* walk the polygon edge by edge: from vertex v to the next vertex w (cyclic, angle order), the nodes between */
  for (PetscInt v = first, walked = 0; walked < c->nc;) {
    PetscInt  w = (v + 1) % c->nc, len;
    PetscReal L;

    while (!c->is_vertex[w]) w = (w + 1) % c->nc;
    len = w > v ? w - v : w + c->nc - v;
    L   = PetscSqrtReal(PetscSqr(c->xc[2 * w] - c->xc[2 * v]) + PetscSqr(c->xc[2 * w + 1] - c->xc[2 * v + 1]));
    PetscCheck(L > 0.0, ctx->comm, PETSC_ERR_PLIB, "Gamma_C edge of zero length");
    force[v] += lambda[v];
    trib[v] += 0.5 * L;
    trib[w] += 0.5 * L;
    for (PetscInt j = 1; j < len; ++j) { /* P2: the edge midpoint */
      const PetscInt  m  = (v + j) % c->nc;
      const PetscReal hv = PetscSqrtReal(PetscSqr(c->xc[2 * w] - c->xc[2 * m]) + PetscSqr(c->xc[2 * w + 1] - c->xc[2 * m + 1])) / L;

      force[v] += hv * lambda[m];
      force[w] += (1.0 - hv) * lambda[m];
    }
    walked += len;
    v = w;
  }
  PetscCall(VecZeroEntries(p));
  PetscCall(VecGetArray(p, &pa));
  for (PetscInt k = 0; k < c->nown; ++k) {
    const PetscInt i = c->own_node[k];
    PetscInt       dof, off;

    if (!c->is_vertex[i]) continue;
    PetscCall(PetscSectionGetDof(gsection, c->own_point[k], &dof));
    PetscCall(PetscSectionGetOffset(gsection, c->own_point[k], &off));
    PetscCheck(dof == 1 && off >= rstart, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "The contact pressure Vec is not a P1 scalar space with the mesh's partition (vertex %" PetscInt_FMT ": %" PetscInt_FMT " dofs at %" PetscInt_FMT ")", c->own_point[k], dof, off);
    pa[off - rstart] = force[i] / trib[i];
  }
  PetscCall(VecRestoreArray(p, &pa));
  PetscCall(PetscFree2(force, trib));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactDestroy(RollerContact *contact)
{
  RollerContact c = *contact;

  PetscFunctionBeginUser;
  if (!c) PetscFunctionReturn(0);
  if (c->check && c->check_steps) {
    for (PetscInt s = 0; s < CONTACT_NUM_SOLVERS; ++s)
      PetscCall(PetscPrintf(c->comm, "contact_check: summary over %" PetscInt_FMT " steps: solver %s max diff %.3e max kkt %.3e\n", c->check_steps, RollerContactSolverTypes[s], (double)c->check_max_diff[s], (double)c->check_max_kkt[s]));
  }
  PetscCall(RollerContactCondensedDestroy(c));
  PetscCall(RollerContactPrimalDestroy(c));
  PetscCall(VecScatterDestroy(&c->scatter));
  PetscCall(VecDestroy(&c->red));
  PetscCall(VecDestroy(&c->red1));
  PetscCall(VecDestroy(&c->red2));
  PetscCall(VecDestroy(&c->b));
  PetscCall(VecDestroy(&c->force));
  PetscCall(VecDestroy(&c->work));
  PetscCall(VecDestroy(&c->xi_check));
  PetscCall(PetscFree3(c->gidx, c->is_vertex, c->xc));
  PetscCall(PetscFree3(c->own_node, c->own_off, c->own_point));
  PetscCall(PetscFree7(c->cand, c->is_cand, c->on_obstacle, c->lower, c->gap, c->result.lambda, c->check_result.lambda));
  PetscCall(PetscFree(c));
  *contact = NULL;
  PetscFunctionReturn(0);
}
