/* -rom_residual (contact_residual.c): the residual seen beyond a step: the fields output (E r), the functionals of R,
   alpha and the surface's orders on it, R in a -rom_output file, and the initial levels of a start held by contact
   forces (their Gamma_C remainder and its force). */
#include "contact_impl.h"

/* x (the full model's layout) += E r, the residual of the level q at the Gamma_C dofs (the fields output of -rom). */
PetscErrorCode RollerContactResidualAddFull(RollerContact c, Vec q, Vec x)
{
  PetscReal   *r;
  PetscScalar *u;
  PetscMPIInt  rank;

  PetscFunctionBeginUser;
  if (!c || !c->nodes.residual.R) PetscFunctionReturn(0);
  PetscCall(RollerContactResidualOf(c, q, &r));
  if (!r) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(c->comm, &rank));
  PetscCall(VecGetArrayWrite(c->nodes.red, &u));
  for (PetscInt i = 0; i < 2 * c->nodes.nc; ++i) u[i] = rank == 0 ? r[i] : 0.0; /* every rank holds all of r: one adds it */
  PetscCall(VecRestoreArrayWrite(c->nodes.red, &u));
  PetscCall(VecScatterBegin(c->nodes.scatter, c->nodes.red, x, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(c->nodes.scatter, c->nodes.red, x, ADD_VALUES, SCATTER_REVERSE));
  PetscFunctionReturn(0);
}

/* The functionals behind R and alpha are integrals over Gamma_C: their Gamma_C rows (before the reduction replaces
   them by V^T w) give the residual's part of the two columns. */
PetscErrorCode RollerContactResidualFunctionals(RollerContact c, Vec wR, Vec walpha)
{
  const PetscInt n    = 2 * c->nodes.nc;
  Vec            w[2] = {wR, walpha};

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(2 * n, &c->nodes.residual.wc));
  for (PetscInt k = 0; k < 2; ++k) PetscCall(RollerContactResidualGatherFull(c, w[k], c->nodes.residual.wc + k * n));
  PetscFunctionReturn(0);
}

/* *wr += w_R . r, *wa += w_alpha . r of the residual of the level q (nothing without one). */
PetscErrorCode RollerContactResidualDots(RollerContact c, Vec q, PetscReal *wr, PetscReal *wa)
{
  PetscFunctionBeginUser;
  if (!c || !c->nodes.residual.wc) PetscFunctionReturn(0);
  PetscCall(RollerContactResidualDot(c, q, c->nodes.residual.wc, wr));
  PetscCall(RollerContactResidualDot(c, q, c->nodes.residual.wc + 2 * c->nodes.nc, wa));
  PetscFunctionReturn(0);
}

/* R in a -rom_output file (a flat dataset of (2 nc)^2 reals, column-major, written by rank 0), or read back from one
   (after RollerContactSetBasis; the file's Gamma_C nodes are this run's: the caller has matched the meshes). */
PetscErrorCode RollerContactResidualView(Roller ctx, RollerContact c, PetscViewer viewer, PetscBool load)
{
  const PetscInt n = 2 * c->nodes.nc;
  PetscMPIInt    rank;
  Vec            v;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  PetscCall(VecCreateMPI(ctx->comm, rank == 0 ? n * n : 0, n * n, &v));
  PetscCall(PetscObjectSetName((PetscObject)v, "residual_flexibility"));
  if (load) {
    const PetscScalar *a;

    PetscCall(VecLoad(v, viewer));
    PetscCall(PetscMalloc1((size_t)n * n, &c->nodes.residual.R));
    if (rank == 0) {
      PetscCall(VecGetArrayRead(v, &a));
      for (size_t k = 0; k < (size_t)n * n; ++k) c->nodes.residual.R[k] = PetscRealPart(a[k]);
      PetscCall(VecRestoreArrayRead(v, &a));
    }
    PetscCallMPI(MPI_Bcast(c->nodes.residual.R, (PetscMPIInt)(n * n), MPIU_REAL, 0, ctx->comm));
    c->nodes.residual.cinv = 1.0;
  } else {
    PetscScalar *a;

    PetscCheck(c->nodes.residual.R, ctx->comm, PETSC_ERR_ORDER, "No residual flexibility to write");
    PetscCall(VecGetArray(v, &a));
    if (rank == 0)
      for (size_t k = 0; k < (size_t)n * n; ++k) a[k] = c->nodes.residual.R[k];
    PetscCall(VecRestoreArray(v, &a));
    PetscCall(VecView(v, viewer));
  }
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

PetscInt RollerContactNodeCount(RollerContact c)
{
  return c ? c->nodes.nc : 0;
}

/* The initial levels (a start from a state held by contact forces: a steady state, a checkpoint-free seeded
   transient): their Gamma_C displacements u_C, gathered before the reduction replaces them ... */
PetscErrorCode RollerContactResidualLevelsBegin(RollerContact c, const Vec lev[3])
{
  const PetscInt n   = 2 * c->nodes.nc;
  PetscReal      big = 0.0;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(3 * n, &c->nodes.residual.u0));
  for (PetscInt l = 0; l < 3; ++l) PetscCall(RollerContactResidualGatherFull(c, lev[l], c->nodes.residual.u0 + l * n));
  for (PetscInt i = 0; i < 3 * n; ++i) big = PetscMax(big, PetscAbsReal(c->nodes.residual.u0[i]));
  if (big == 0.0) PetscCall(PetscFree(c->nodes.residual.u0)); /* from rest: nothing to carry */
  PetscFunctionReturn(0);
}

/* ... and after R (and the branches) are known, each reduced level q (the K-orthogonal projection) carries the remainder
   r = u_C - Phi q with the force f_C = R^{-1} r (a Cholesky factorization of R): for a state held by contact forces,
   r = R f_C exactly and f_C is that force (0 away from the contact, to the basis' truncation). */
PetscErrorCode RollerContactResidualLevelsEnd(RollerContact c, const Vec lev[3])
{
  const PetscInt n = 2 * c->nodes.nc, nq = c->nodes.nq;
  Mat            F;
  Vec            b, x;

  PetscFunctionBeginUser;
  if (!c->nodes.residual.u0 || !c->nodes.residual.R) {
    PetscCall(PetscFree(c->nodes.residual.u0));
    PetscFunctionReturn(0);
  }
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, n, n, NULL, &F));
  {
    PetscScalar *f;

    PetscCall(MatDenseGetArrayWrite(F, &f));
    for (size_t k = 0; k < (size_t)n * n; ++k) f[k] = c->nodes.residual.R[k];
    PetscCall(MatDenseRestoreArrayWrite(F, &f));
  }
  PetscCall(MatCholeskyFactor(F, NULL, NULL));
  PetscCall(MatCreateVecs(F, &x, &b));
  for (PetscInt l = 0; l < 3; ++l) {
    const PetscScalar *qa, *xa;
    PetscScalar       *ba;
    PetscReal         *r;

    PetscCall(VecScatterBegin(c->nodes.gather.qscatter, lev[l], c->nodes.gather.qall, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(c->nodes.gather.qscatter, lev[l], c->nodes.gather.qall, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGetArrayRead(c->nodes.gather.qall, &qa));
    PetscCall(RollerContactResidualKeep(c, lev[l], &r));
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal *p = c->nodes.phi + (size_t)i * nq;
      PetscReal        u = 0.0;

      for (PetscInt j = 0; j < nq; ++j) u += p[j] * PetscRealPart(qa[j]);
      r[i] = c->nodes.residual.u0[l * n + i] - u;
    }
    PetscCall(VecRestoreArrayRead(c->nodes.gather.qall, &qa));
    PetscCall(VecGetArrayWrite(b, &ba));
    for (PetscInt i = 0; i < n; ++i) ba[i] = r[i];
    PetscCall(VecRestoreArrayWrite(b, &ba));
    PetscCall(MatSolve(F, b, x));
    PetscCall(VecGetArrayRead(x, &xa));
    for (PetscInt i = 0; i < n; ++i) r[n + i] = PetscRealPart(xa[i]);
    PetscCall(VecRestoreArrayRead(x, &xa));
    if (c->nodes.residual.nb) { /* the branches start unstretched (b_i = w_i = 0, as the full model's z_i): a = R^{-1} r, f_C = (1 + kappa sum g_i) a */
      PetscReal G = 0.0;

      for (PetscInt i = 0; i < c->nodes.residual.nb; ++i) G += c->nodes.residual.g[i];
      for (PetscInt i = 0; i < n; ++i) {
        r[2 * n + i] = r[n + i];
        r[n + i] *= 1.0 + c->nodes.residual.kappa * G;
      }
      RollerContactResidualLevelEnergy(c, r, &r[RollerContactResidualSize(c) - 1]);
    }
  }
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&F));
  PetscCall(PetscFree(c->nodes.residual.u0));
  PetscFunctionReturn(0);
}

/* A boundary functional's Gamma_C rows (2 nc reals, malloc'ed; NULL without the residual) and, per level, its dot with
   the level's residual: the -monitor_surface_csv orders of a reduced run (integrate/observers_surface.c). */
PetscErrorCode RollerContactResidualRows(RollerContact c, Vec w, PetscReal **rows)
{
  PetscFunctionBeginUser;
  *rows = NULL;
  if (!c || !c->nodes.residual.R) PetscFunctionReturn(0);
  PetscCall(PetscMalloc1(2 * c->nodes.nc, rows));
  PetscCall(RollerContactResidualGatherFull(c, w, *rows));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactResidualDot(RollerContact c, Vec q, const PetscReal rows[], PetscReal *dot)
{
  PetscReal *r;

  PetscFunctionBeginUser;
  if (!c || !c->nodes.residual.R || !rows) PetscFunctionReturn(0);
  PetscCall(RollerContactResidualOf(c, q, &r));
  for (PetscInt i = 0; r && i < 2 * c->nodes.nc; ++i) *dot += rows[i] * r[i];
  PetscFunctionReturn(0);
}
