/* The Gamma_C nodes: gathered once on every rank in angle order with their dofs and positions, the scatter of
   their dofs into a redundant Vec, and what is computed from it on every rank alike: gaps and nodal forces. */
#include "contact_impl.h"

/* A node outside the candidate set whose gap is below -tol triggers a re-solve with it added. */
PetscReal RollerContactGapTolerance(Roller ctx)
{
  return 1e-12 * ctx->mesh.r_outer;
}

/* The Lagrange nodes of Gamma_C (label "outer": vertices, and edges for P2) with their global dof pairs and
   positions, gathered on every rank and sorted by angle, so every rank numbers them the same way whatever
   the partition; and the scatter of their dofs from a global Vec into a redundant sequential Vec. */
PetscErrorCode RollerContactNodesCreate(Roller ctx, RollerContact c)
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
  c->nodes.nc = 0;
  for (PetscMPIInt r = 0; r < size; ++r) {
    displs[r]  = (PetscMPIInt)c->nodes.nc;
    counts2[r] = 2 * counts[r];
    displs2[r] = 2 * displs[r];
    c->nodes.nc += counts[r];
  }
  PetscCheck(c->nodes.nc > 0, ctx->comm, PETSC_ERR_ARG_WRONG, "Gamma_C (label \"outer\") has no free nodes: the obstacle has nothing to touch");
  PetscCall(PetscMalloc5(c->nodes.nc, &idx, c->nodes.nc, &vert, 2 * c->nodes.nc, &xc, c->nodes.nc, &angle, c->nodes.nc, &perm));
  PetscCallMPI(MPI_Allgatherv(mine_idx, n_mine, MPIU_INT, idx, counts, displs, MPIU_INT, ctx->comm));
  PetscCallMPI(MPI_Allgatherv(mine_vert, n_mine, MPIU_INT, vert, counts, displs, MPIU_INT, ctx->comm));
  PetscCallMPI(MPI_Allgatherv(mine_x, 2 * n_mine, MPIU_REAL, xc, counts2, displs2, MPIU_REAL, ctx->comm));
  PetscCall(PetscFree4(counts, displs, counts2, displs2));
  PetscCall(PetscSortIntWithArray(nown, mine_idx, mine_point)); /* to find the mesh point of an owned node */

  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    angle[i] = PetscAtan2Real(xc[2 * i + 1], xc[2 * i]);
    perm[i]  = i;
  }
  PetscCall(PetscSortRealWithPermutation(c->nodes.nc, angle, perm));
  PetscCall(PetscMalloc3(c->nodes.nc, &c->nodes.gidx, c->nodes.nc, &c->nodes.is_vertex, 2 * c->nodes.nc, &c->nodes.xc));
  PetscCall(PetscMalloc3(nown, &c->nodes.own_node, nown, &c->nodes.own_off, nown, &c->nodes.own_point));
  c->nodes.nown = 0;
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    c->nodes.gidx[i]       = idx[perm[i]];
    c->nodes.is_vertex[i]  = vert[perm[i]] ? PETSC_TRUE : PETSC_FALSE;
    c->nodes.xc[2 * i]     = xc[2 * perm[i]];
    c->nodes.xc[2 * i + 1] = xc[2 * perm[i] + 1];
    if (c->nodes.gidx[i] >= rstart && c->nodes.gidx[i] < rend) {
      PetscInt loc;

      c->nodes.own_node[c->nodes.nown] = i;
      c->nodes.own_off[c->nodes.nown]  = c->nodes.gidx[i] - rstart;
      PetscCall(PetscFindInt(c->nodes.gidx[i], nown, mine_idx, &loc));
      PetscCheck(loc >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Owned Gamma_C dof %" PetscInt_FMT " not found", c->nodes.gidx[i]);
      c->nodes.own_point[c->nodes.nown] = mine_point[loc];
      c->nodes.nown++;
    }
  }
  PetscCheck(c->nodes.nown == nown, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Owned Gamma_C nodes %" PetscInt_FMT " != %" PetscInt_FMT, c->nodes.nown, nown);
  PetscCall(PetscFree5(idx, vert, xc, angle, perm));
  PetscCall(PetscFree4(mine_idx, mine_vert, mine_point, mine_x));

  PetscCall(PetscMalloc1(2 * c->nodes.nc, &idx));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    idx[2 * i]     = c->nodes.gidx[i];
    idx[2 * i + 1] = c->nodes.gidx[i] + 1;
  }
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, 2 * c->nodes.nc, idx, PETSC_OWN_POINTER, &is));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, 2 * c->nodes.nc, 0, 1, &to));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 2 * c->nodes.nc, &c->nodes.red));
  PetscCall(VecDuplicate(c->nodes.red, &c->nodes.red1));
  PetscCall(VecDuplicate(c->nodes.red, &c->nodes.red2));
  PetscCall(VecScatterCreate(ctx->ops.coordinates, is, c->nodes.red, to, &c->nodes.scatter));
  PetscCall(ISDestroy(&is));
  PetscCall(ISDestroy(&to));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactNodesDestroy(RollerContact c)
{
  PetscFunctionBeginUser;
  PetscCall(RollerContactReducedDestroy(c));
  PetscCall(VecScatterDestroy(&c->nodes.scatter));
  PetscCall(VecDestroy(&c->nodes.red));
  PetscCall(VecDestroy(&c->nodes.red1));
  PetscCall(VecDestroy(&c->nodes.red2));
  PetscCall(PetscFree3(c->nodes.gidx, c->nodes.is_vertex, c->nodes.xc));
  PetscCall(PetscFree3(c->nodes.own_node, c->nodes.own_off, c->nodes.own_point));
  PetscFunctionReturn(0);
}

/* Forward scatter of the Gamma_C dofs of a global Vec into a redundant Vec (2 nc entries, node order). */
PetscErrorCode RollerContactGather(RollerContact c, Vec v, Vec red)
{
  PetscFunctionBeginUser;
  if (c->nodes.phi) {
    PetscCall(RollerContactReducedGather(c, v, red)); /* -rom: v is q */
    PetscFunctionReturn(0);
  }
  PetscCall(VecScatterBegin(c->nodes.scatter, v, red, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(c->nodes.scatter, v, red, INSERT_VALUES, SCATTER_FORWARD));
  PetscFunctionReturn(0);
}

/* f = E (N lambda + T lambda_t): the nodal force lambda_n n^k (+ lambda_t,n t^k with friction; lambda_t may be
   NULL) at every owned Gamma_C node, 0 elsewhere. Every rank holds all multipliers and writes its own nodes,
   which is the reverse scatter without communication. */
PetscErrorCode RollerContactForce(RollerContact c, const PetscReal lambda[], const PetscReal lambda_t[], Vec f)
{
  PetscScalar *fa;

  PetscFunctionBeginUser;
  if (c->nodes.phi) {
    PetscCall(RollerContactReducedForce(c, lambda, lambda_t, f)); /* -rom: f is reduced */
    PetscFunctionReturn(0);
  }
  PetscCall(VecZeroEntries(f));
  PetscCall(VecGetArray(f, &fa));
  for (PetscInt k = 0; k < c->nodes.nown; ++k) {
    const PetscInt i = c->nodes.own_node[k], off = c->nodes.own_off[k];

    fa[off]     = lambda[i] * c->step.normal[0];
    fa[off + 1] = lambda[i] * c->step.normal[1];
    if (lambda_t) {
      fa[off] += lambda_t[i] * c->step.tangent[0];
      fa[off + 1] += lambda_t[i] * c->step.tangent[1];
    }
  }
  PetscCall(VecRestoreArray(f, &fa));
  PetscFunctionReturn(0);
}

/* The obstacle at time t in the rotating frame: its normal n(t) = (sin theta, cos theta) and height g(t). */
void RollerContactObstacleAt(Roller ctx, PetscReal t, PetscReal normal[2], PetscReal *g)
{
  PetscReal theta;

  RollerTheta(ctx, t, &theta, NULL, NULL);
  normal[0] = PetscSinReal(theta);
  normal[1] = PetscCosReal(theta);
  *g        = RollerObstacleHeight(ctx, t);
}

/* gap_n = (x_n + xi_n) . n(t) - g(t) at every node from the gathered displacement red, against the obstacle
   of time t (not necessarily the step's): the state of an earlier level (candidates, contact energy). */
PetscErrorCode RollerContactGapsAt(Roller ctx, RollerContact c, Vec red, PetscReal t, PetscReal gap[])
{
  const PetscScalar *u;
  const PetscReal   *xc = c->nodes.xc;
  PetscReal          n[2], g;

  PetscFunctionBeginUser;
  RollerContactObstacleAt(ctx, t, n, &g);
  PetscCall(VecGetArrayRead(red, &u));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) gap[i] = (xc[2 * i] + PetscRealPart(u[2 * i])) * n[0] + (xc[2 * i + 1] + PetscRealPart(u[2 * i + 1])) * n[1] - g;
  PetscCall(VecRestoreArrayRead(red, &u));
  PetscFunctionReturn(0);
}

/* gap_n = (x_n + xi_n) . n^k - g^k at every node from the gathered displacement; returns the least. */
PetscErrorCode RollerContactGaps(RollerContact c, Vec red, PetscReal gap[], PetscReal *gap_min)
{
  const PetscScalar *u;

  PetscFunctionBeginUser;
  *gap_min = PETSC_MAX_REAL;
  PetscCall(VecGetArrayRead(red, &u));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    gap[i]   = PetscRealPart(u[2 * i]) * c->step.normal[0] + PetscRealPart(u[2 * i + 1]) * c->step.normal[1] - c->step.lower[i];
    *gap_min = PetscMin(*gap_min, gap[i]);
  }
  PetscCall(VecRestoreArrayRead(red, &u));
  PetscFunctionReturn(0);
}
