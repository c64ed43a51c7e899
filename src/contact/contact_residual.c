/* -rom_residual (docs/model.md "The reduced model", docs/performance.md "Reduced-order transient"): MacNeal's static
   residual flexibility at Gamma_C. The kept modes (wavelengths of millimetres at the cutoff) cannot take the shape of
   a contact patch a few elements wide; the modes above the cutoff answer a contact force quasi-statically on the
   time scale of the kept ones, with the flexibility the basis misses,

     R = E^T (K^{-1} - V K_r^{-1} V^T) E    (symmetric, positive semi-definite; V^T K V = K_r diagonal),

   so the Gamma_C displacement of a level is u_C = Phi q + R f_C, f_C the nodal force of the solve that made it. The
   condensed operator becomes S + R (the same LCP and Coulomb solves, now on a patch of the full model's width), and
   every gather of a level adds its residual r = R f_C, which travels with the level's Vec (kept by the Vec's id). The
   residual is memoryless: without contact the reduced model and its energy identity are unchanged; in contact its
   static energy is in E and the dissipation of its update in the contact's (RollerContactResidualEnergy), so the
   balance still closes to round-off. */
#include "contact_impl.h"

/* out (2 nc reals) = the Gamma_C rows of a vector of the full layout (the nodes' scatter, whatever -rom has set). */
PetscErrorCode RollerContactResidualGatherFull(RollerContact c, Vec v, PetscReal out[])
{
  const PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(VecScatterBegin(c->nodes.scatter, v, c->nodes.red, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(c->nodes.scatter, v, c->nodes.red, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(c->nodes.red, &a));
  for (PetscInt i = 0; i < 2 * c->nodes.nc; ++i) out[i] = PetscRealPart(a[i]);
  PetscCall(VecRestoreArrayRead(c->nodes.red, &a));
  PetscFunctionReturn(0);
}

/* R's columns: K^{-1} of the unit vectors of the Gamma_C dofs in blocks (KSPMatSolve on K's factorization), their
   Gamma_C rows gathered on every rank (the full layout's scatter), minus Phi K_r^{-1} Phi^T; then symmetrized. */
PetscErrorCode RollerContactSetResidualFlexibility(Roller ctx, RollerContact c, KSP kinv, const PetscReal Kr[])
{
  const PetscInt n = 2 * c->nodes.nc, nq = c->nodes.nq, nb = 64;
  PetscInt       nlocal, rstart, rend;
  PetscReal     *R;

  PetscFunctionBeginUser;
  PetscCheck(c->nodes.phi, ctx->comm, PETSC_ERR_ORDER, "The residual flexibility needs the basis' Gamma_C rows first");
  PetscCall(PetscFree(c->nodes.residual.R)); /* an earlier one (rom.c: R of the storage stiffness, for kappa) */
  {
    Mat K;

    PetscCall(KSPGetOperators(kinv, &K, NULL));
    PetscCall(MatGetLocalSize(K, &nlocal, NULL));
    PetscCall(MatGetOwnershipRange(K, &rstart, &rend));
  }
  PetscCall(PetscCalloc1((size_t)n * n, &R));
  for (PetscInt j0 = 0; j0 < n; j0 += nb) {
    const PetscInt mb = PetscMin(nb, n - j0);
    Mat            B, X;

    PetscCall(MatCreateDense(ctx->comm, nlocal, PETSC_DECIDE, PETSC_DETERMINE, mb, NULL, &B));
    PetscCall(MatZeroEntries(B));
    for (PetscInt jj = 0; jj < mb; ++jj) {
      const PetscInt j = j0 + jj, row = c->nodes.gidx[j / 2] + j % 2;

      if (row >= rstart && row < rend) PetscCall(MatSetValue(B, row, jj, 1.0, INSERT_VALUES));
    }
    PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatDuplicate(B, MAT_DO_NOT_COPY_VALUES, &X));
    PetscCall(KSPMatSolve(kinv, B, X));
    for (PetscInt jj = 0; jj < mb; ++jj) {
      Vec v;

      PetscCall(MatDenseGetColumnVecRead(X, jj, &v));
      PetscCall(RollerContactResidualGatherFull(c, v, R + (size_t)(j0 + jj) * n));
      PetscCall(MatDenseRestoreColumnVecRead(X, jj, &v));
    }
    PetscCall(MatDestroy(&B));
    PetscCall(MatDestroy(&X));
  }
  { /* R -= Phi K_r^{-1} Phi^T: phi row-major (n x nq) is the column-major nq x n P; R -= P^T (K_r^{-1} P), K_r = V^T K V of
       kinv's K (dense nq x nq: diagonal for the relaxed K of the basis' Ritz step) */
    Mat                P, Q, O, F;
    PetscScalar       *f;
    const PetscScalar *o;

    PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, nq, n, c->nodes.phi, &P));
    PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, nq, nq, NULL, &F));
    PetscCall(MatDenseGetArrayWrite(F, &f));
    for (size_t k = 0; k < (size_t)nq * nq; ++k) f[k] = Kr[k];
    PetscCall(MatDenseRestoreArrayWrite(F, &f));
    PetscCall(MatLUFactor(F, NULL, NULL, NULL));
    PetscCall(MatDuplicate(P, MAT_DO_NOT_COPY_VALUES, &Q));
    PetscCall(MatMatSolve(F, P, Q));
    PetscCall(MatDestroy(&F));
    PetscCall(MatTransposeMatMult(P, Q, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &O));
    PetscCall(MatDenseGetArrayRead(O, &o));
    for (size_t k = 0; k < (size_t)n * n; ++k) R[k] -= PetscRealPart(o[k]);
    PetscCall(MatDenseRestoreArrayRead(O, &o));
    PetscCall(MatDestroy(&O));
    PetscCall(MatDestroy(&Q));
    PetscCall(MatDestroy(&P));
  }
  for (PetscInt j = 0; j < n; ++j)
    for (PetscInt i = 0; i < j; ++i) R[i + (size_t)j * n] = R[j + (size_t)i * n] = 0.5 * (R[i + (size_t)j * n] + R[j + (size_t)i * n]);
  c->nodes.residual.R    = R;
  c->nodes.residual.cinv = 1.0;
  PetscFunctionReturn(0);
}

/* tr R */
PetscErrorCode RollerContactResidualTrace(RollerContact c, PetscReal *tr)
{
  const PetscInt n = 2 * c->nodes.nc;

  PetscFunctionBeginUser;
  *tr = 0.0;
  for (PetscInt i = 0; c->nodes.residual.R && i < n; ++i) *tr += c->nodes.residual.R[i + (size_t)i * n];
  PetscFunctionReturn(0);
}

/* Column j of the condensed S (2 nc entries) plus R's (over C with the branches: contact_residual_branches.c). */
void RollerContactReducedAddFlexibility(RollerContact c, PetscInt j, PetscReal col[])
{
  const PetscInt   n = 2 * c->nodes.nc;
  const PetscReal *r = c->nodes.residual.R + (size_t)j * n, ci = c->nodes.residual.cinv;

  if (!c->nodes.residual.R) return;
  for (PetscInt i = 0; i < n; ++i) col[i] += ci * r[i];
}

/* The residual's 2 n reals (r, then f_C) of a level's Vec, found by the Vec's object id (unique in the run, never
   reused; a Vec composed object would be shared by the VecDuplicate copies of it, e.g. a solver's work vectors made
   from a level). Kept: the levels and the stages' vectors, a fixed few. */
PetscErrorCode RollerContactResidualOf(RollerContact c, Vec v, PetscReal **r)
{
  PetscObjectId id;

  PetscFunctionBeginUser;
  *r = NULL;
  PetscCall(PetscObjectGetId((PetscObject)v, &id));
  for (PetscInt k = 0; k < c->nodes.residual.nslot; ++k)
    if (c->nodes.residual.id[k] == id) *r = c->nodes.residual.slot[k];
  PetscFunctionReturn(0);
}

/* ... made if v has none, and zeroed */
PetscErrorCode RollerContactResidualKeep(RollerContact c, Vec v, PetscReal **r)
{
  RollerContactResidual *rs = &c->nodes.residual;
  const PetscInt         n  = RollerContactResidualSize(c);

  PetscFunctionBeginUser;
  PetscCall(RollerContactResidualOf(c, v, r));
  if (!*r) {
    PetscCheck(rs->nslot < ROLLER_RESIDUAL_SLOTS, c->comm, PETSC_ERR_PLIB, "-rom_residual: more than %d vectors carry a residual", ROLLER_RESIDUAL_SLOTS);
    PetscCall(PetscObjectGetId((PetscObject)v, &rs->id[rs->nslot]));
    PetscCall(PetscMalloc1(n, &rs->slot[rs->nslot]));
    *r = rs->slot[rs->nslot++];
  }
  PetscCall(PetscArrayzero(*r, n));
  PetscFunctionReturn(0);
}

/* The residual r = R f_C of the solve's multipliers, kept for its solution xi (the Vec keeps it as it moves
   through the levels; a Vec without one has none); with the branches r = R h/C + R f_C/C and the level's a, b_i, w_i. */
PetscErrorCode RollerContactReducedResidual(RollerContact c, const RollerContactResult *res, Vec xi)
{
  const PetscInt  n  = 2 * c->nodes.nc;
  const PetscReal ci = c->nodes.residual.cinv;
  PetscReal      *r;

  PetscFunctionBeginUser;
  if (!c->nodes.residual.R) PetscFunctionReturn(0);
  PetscCall(RollerContactResidualKeep(c, xi, &r));
  if (c->nodes.residual.nb) PetscCall(PetscArraycpy(r, c->nodes.residual.hist, n));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscReal lt = res->lambda_t ? res->lambda_t[i] : 0.0;
    PetscReal      *f  = r + n + 2 * i;

    f[0] = res->lambda[i] * c->step.normal[0] + lt * c->step.tangent[0];
    f[1] = res->lambda[i] * c->step.normal[1] + lt * c->step.tangent[1];
  }
  RollerDenseMultAdd(n, c->nodes.residual.R, r, ci, r + n, r); /* r += R f_C/C */
  RollerContactResidualBranchesUpdate(c, r);
  PetscFunctionReturn(0);
}

/* red += the residual of q (if any), at the nodes a gather computes (the window's, or all). */
PetscErrorCode RollerContactReducedAddResidual(RollerContact c, Vec q, Vec red)
{
  PetscReal   *r;
  PetscScalar *u;

  PetscFunctionBeginUser;
  if (!c->nodes.residual.R) PetscFunctionReturn(0);
  PetscCall(RollerContactResidualOf(c, q, &r));
  if (!r) PetscFunctionReturn(0);
  PetscCall(VecGetArray(red, &u));
  for (PetscInt k = 0; k < c->nodes.nwin; ++k) {
    const PetscInt i = c->nodes.windowed ? c->nodes.win[k] : k;

    u[2 * i] += r[2 * i];
    u[2 * i + 1] += r[2 * i + 1];
  }
  PetscCall(VecRestoreArray(red, &u));
  PetscFunctionReturn(0);
}

/* The residual's energy in a three-level scheme's balance (section 2: the force f^k of step k works on
   D = u^k - u^{k-2}). With r = R f, E_r^k = 1/4 (f^k . r^k + f^{k-1} . r^{k-1}) and
   D_r^k = 1/4 (f^k - f^{k-2}) . (r^k - r^{k-2}) >= 0 give E_r^k - E_r^{k-1} = 1/2 f^k . (r^k - r^{k-2}) - D_r^k
   exactly: the memoryless residual is the static energy E_r (added to E) and the dissipation D_r (the contact's).
   With the branches E_r^k = (e^k + e^{k-1})/2 and the branches' D_b^k besides (contact_residual_branches.c). */
/* The dots f_u . r_u, f_v . r_v, f_u . r_v, f_v . r_u of the residuals of two levels (0 for a level without one). */
static PetscErrorCode Dots(RollerContact c, Vec u, Vec v, PetscReal d[4])
{
  const PetscInt n = 2 * c->nodes.nc;
  PetscReal     *a, *b;

  PetscFunctionBeginUser;
  PetscCall(RollerContactResidualOf(c, u, &a));
  PetscCall(RollerContactResidualOf(c, v, &b));
  d[0] = d[1] = d[2] = d[3] = 0.0;
  for (PetscInt i = 0; i < n; ++i) {
    if (a) d[0] += a[n + i] * a[i];
    if (b) d[1] += b[n + i] * b[i];
    if (a && b) {
      d[2] += a[n + i] * b[i];
      d[3] += b[n + i] * a[i];
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactResidualEnergy(RollerContact c, Vec cur, Vec prev, PetscReal *energy)
{
  PetscReal *a, *b, e[2];

  PetscFunctionBeginUser;
  if (!c || !c->nodes.residual.R) PetscFunctionReturn(0);
  PetscCall(RollerContactResidualOf(c, cur, &a));
  PetscCall(RollerContactResidualOf(c, prev, &b));
  if (c->nodes.residual.nb) { /* kept in the slot */
    const PetscInt last = RollerContactResidualSize(c) - 1;

    e[0] = a ? a[last] : 0.0;
    e[1] = b ? b[last] : 0.0;
  } else {
    RollerContactResidualLevelEnergy(c, a, &e[0]);
    RollerContactResidualLevelEnergy(c, b, &e[1]);
  }
  *energy += 0.5 * (e[0] + e[1]);
  PetscFunctionReturn(0);
}

/* contact_dissipation += 1/4 (f^k - f^{k-2}) . (r^k - r^{k-2}); viscous_dissipation += the branches' D_b^k */
PetscErrorCode RollerContactResidualDissipation(RollerContact c, Vec cur, Vec prev2, PetscReal *dissipation, PetscReal *viscous)
{
  PetscReal d[4] = {0.0, 0.0, 0.0, 0.0}, *a, *b;

  PetscFunctionBeginUser;
  if (!c || !c->nodes.residual.R) PetscFunctionReturn(0);
  PetscCall(Dots(c, cur, prev2, d));
  *dissipation += 0.25 * (d[0] + d[1] - d[2] - d[3]);
  if (!c->nodes.residual.nb) PetscFunctionReturn(0);
  PetscCall(RollerContactResidualOf(c, cur, &a));
  PetscCall(RollerContactResidualOf(c, prev2, &b));
  RollerContactResidualBranchDissipation(c, a, b, viscous);
  PetscFunctionReturn(0);
}

PetscErrorCode RollerContactResidualDestroy(RollerContact c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(c->nodes.residual.R));
  PetscCall(PetscFree(c->nodes.residual.wc));
  PetscCall(PetscFree(c->nodes.residual.u0));
  PetscCall(PetscFree(c->nodes.residual.hist));
  for (PetscInt k = 0; k < c->nodes.residual.nslot; ++k) PetscCall(PetscFree(c->nodes.residual.slot[k]));
  c->nodes.residual.nslot = 0;
  PetscFunctionReturn(0);
}
