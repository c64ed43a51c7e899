/* The linearization about the steady rolling or sliding state (docs/squeal.md section 3), the complex eigenvalue analysis of
   the brake industry: a perturbation keeps the active contact nodes a (normal force N_a > 0) on the flat sheet
   (du_a,y = 0, the sheet is rigid), its normal force perturbation dN_a is the reaction of row a,y, and Coulomb's
   sliding force -s mu(v) N along e1 perturbs as

     dT_a = -s mu_a dN_a - N_a mu'_a dv_a,   dv_a = (lambda + theta' d_phi) du_a,x   (the slip speed's change)

   (d_phi and the point where the slip is taken as in the steady state, RollerSteadyAngularDerivative: with box
   midway between a and its upstream neighbour, lambda du_a,x then the mean of the two)

   so that, with Q(lambda) = lambda^2 M + lambda C + K the lab-frame operator of the free annulus:
     row a,x  +=  s mu_a row a,y          (friction follows the normal force: a non-symmetric stiffness,
                                             mass and gyroscopic coupling: mode coupling, flutter)
     C(a,x; a,x) += N_a mu'_a,  K(a,x; .) += N_a mu'_a theta' d_phi   (velocity weakening mu' < 0: negative damping)
     rows and columns a,y removed.
   A node that sticks (the rolling state's stick zone) instead moves with the sheet: its slip speed's perturbation
   vanishes, (lambda + theta' d_phi) du_a,x = 0, with its own tangential force perturbation dT_a as the multiplier:
     row a,x  -=  dT_a  (K),     constraint row of dT_a:  lambda du_a,x (C) + theta' d_phi du_a,x (K) = 0,
   appended after the kept dofs (on the last rank; zero mass: the pencil is singular at infinity, harmless to
   shift-and-invert, whose LU then needs pivoting: MUMPS).
   With -modes_stick_eps eps > 0 a stick node instead obeys the regularized cone T = -mu N v/sqrt(v^2 + eps^2): at
   its ratio r = |T|/(mu N) < 1 it slips at v0 = eps r/sqrt(1 - r^2), and dT = (T/N) dN - c dv,
   c = mu N (1 - r^2)^{3/2}/eps: a sliding node's rows with s mu -> -T/N and N mu' -> c (docs/squeal.md 4.4).
   With -modes_stick_margin m > 0 a stick node within m of the cone, |T| > (1 - m) mu N, is linearized as sliding
   against its force (-sign(T) mu in its friction row): the stick nodes a perturbation of finite amplitude unsticks
   first, the leading edge's marginal nodes on which the rigid linearization hinges (docs/squeal.md 4.4.2).
   A sliding node whose force points against the patch's (the upwind slip's artifact at the leading edge) is left
   out: its dofs stay free.
   The same operations on M, C and K give the reduced quadratic eigenproblem on the kept dofs (and the stick
   nodes' multipliers). */
#include "modes/modes.h"

/* How a stick node is linearized: eps, the regularized cone's slip speed (0: rigid); margin, the fraction of the cone
   within which it is linearized as sliding (0: none). */
typedef struct {
  PetscReal eps, margin;
} StickLaw;

/* A stick node within the margin of the cone: linearized as sliding against its force. */
static PetscBool Marginal(const RollerSteady *st, PetscInt j, StickLaw law)
{
  return st->state[j] == 1 && law.margin > 0 && PetscAbsReal(st->tangent[j]) > (1 - law.margin) * st->mu[j] * st->normal[j] ? PETSC_TRUE : PETSC_FALSE;
}

/* A stick node is rigid (a multiplier) at eps = 0, else in the regularized cone; a marginal one slides. */
static PetscBool RigidStick(const RollerSteady *st, PetscInt j, StickLaw law)
{
  return st->state[j] == 1 && law.eps == 0 && !Marginal(st, j, law) ? PETSC_TRUE : PETSC_FALSE;
}

/* s mu_a, the friction row's factor on the normal force: -T/N (sliding, or a stick node in the regularized cone),
   -sign(T) mu for a marginal stick node. */
static PetscReal FrictionRatio(const RollerSteady *st, PetscInt j, StickLaw law)
{
  if (Marginal(st, j, law)) return st->tangent[j] > 0 ? -st->mu[j] : st->mu[j];
  return -st->tangent[j] / st->normal[j];
}

/* A sliding node whose force points against the patch's total tangential force Tsum: the upwind slip's artifact at
   the leading edge (docs/squeal.md section 3: its stencil reaches the free surface, its normal force the
   smallest); left out of the linearization (docs/squeal.md 4.4). */
static PetscBool Reversed(const RollerSteady *st, PetscInt j, PetscReal Tsum)
{
  return st->state[j] == 2 && st->tangent[j] * Tsum < 0 ? PETSC_TRUE : PETSC_FALSE;
}

/* The coefficient of the slip speed's change dv on row a,x: N mu' sliding or marginal (velocity weakening),
   mu N (1 - r^2)^{3/2}/eps for a stick node in the regularized cone. */
static PetscReal SlipCoefficient(const RollerSteady *st, PetscInt j, StickLaw law)
{
  PetscReal r;

  if (st->state[j] == 2 || Marginal(st, j, law)) return st->normal[j] * st->dmu[j];
  if (st->state[j] != 1 || law.eps == 0) return 0;
  r = PetscMin(PetscAbsReal(st->tangent[j]) / (st->mu[j] * st->normal[j]), 1.0);
  return st->mu[j] * st->normal[j] * PetscPowReal(1 - r * r, 1.5) / law.eps;
}

/* B = [A 0; 0 0] with ns rows and columns appended on the last rank, plus the entries (rows[k], cols[k], vals[k])
   (global indices of B; set by any rank). */
static PetscErrorCode Augment(Mat A, PetscInt ns, PetscInt ne, const PetscInt rows[], const PetscInt cols[], const PetscScalar vals[], Mat *B)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)A);
  PetscMPIInt rank, size;
  PetscInt    lo, hi, m, N, *nnz;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(MatGetOwnershipRange(A, &lo, &hi));
  PetscCall(MatGetSize(A, &N, NULL));
  m = hi - lo + (rank == size - 1 ? ns : 0);
  PetscCall(PetscMalloc1(m, &nnz));
  for (PetscInt i = 0; i < m; ++i) {
    PetscInt ncols = 0;

    if (lo + i < hi) PetscCall(MatGetRow(A, lo + i, &ncols, NULL, NULL));
    nnz[i] = PetscMin(ncols + 1 + (i >= hi - lo ? 8 : 0), N + ns);
    if (lo + i < hi) PetscCall(MatRestoreRow(A, lo + i, &ncols, NULL, NULL));
  }
  PetscCall(MatCreateAIJ(comm, m, m, N + ns, N + ns, 0, nnz, 0, nnz, B));
  PetscCall(MatSetOption(*B, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(PetscFree(nnz));
  for (PetscInt i = lo; i < hi; ++i) {
    const PetscInt    *c;
    const PetscScalar *v;
    PetscInt           ncols;

    PetscCall(MatGetRow(A, i, &ncols, &c, &v));
    PetscCall(MatSetValues(*B, 1, &i, ncols, c, v, INSERT_VALUES));
    PetscCall(MatRestoreRow(A, i, &ncols, &c, &v));
  }
  PetscCall(MatAssemblyBegin(*B, MAT_FLUSH_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*B, MAT_FLUSH_ASSEMBLY));
  for (PetscInt k = 0; k < ne; ++k) PetscCall(MatSetValue(*B, rows[k], cols[k], vals[k], ADD_VALUES));
  PetscCall(MatAssemblyBegin(*B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*B, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* The stick nodes' multipliers: their entries in K (the force, the transport's d_phi part) and C (its lambda part). */
static PetscErrorCode StickMultipliers(Roller ctx, const RollerSteady *st, StickLaw law, IS kept, PetscInt nk, PetscInt *ns, PetscInt *nek, PetscInt **rk, PetscInt **ck, PetscScalar **vk, PetscInt *nec, PetscInt **rc, PetscInt **cc, PetscScalar **vc)
{
  PetscInt    nloc, kstart, *red, js = 0;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  /* the reduced index of every candidate's x dof (-1 where not kept), known on every rank */
  PetscCall(PetscMalloc1(st->n, &red));
  PetscCall(ISGetLocalSize(kept, &nloc));
  PetscCallMPI(MPI_Scan(&nloc, &kstart, 1, MPIU_INT, MPI_SUM, ctx->comm));
  kstart -= nloc;
  for (PetscInt j = 0; j < st->n; ++j) {
    PetscInt p;

    PetscCall(ISLocate(kept, st->dof[j], &p)); /* its local position, negative where not here */
    red[j] = p >= 0 ? kstart + p : -1;
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, red, st->n, MPIU_INT, MPI_MAX, ctx->comm));
  *ns = 0;
  for (PetscInt j = 0; j < st->n; ++j)
    if (RigidStick(st, j, law)) ++*ns;
  PetscCall(PetscMalloc3(4 * *ns, rk, 4 * *ns, ck, 4 * *ns, vk));
  PetscCall(PetscMalloc3(3 * *ns, rc, 3 * *ns, cc, 3 * *ns, vc));
  *nek = *nec = 0;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  for (PetscInt j = 0; j < st->n; ++j) {
    PetscInt  nb[3];
    PetscReal c[3], a[3];

    if (!RigidStick(st, j, law)) continue;
    if (!rank) { /* one rank adds each multiplier's entries */
      PetscCall(RollerSteadyAngularDerivative(st, ctx->rotation.omega, j, nb, c, a));
      (*rk)[*nek]     = red[j];
      (*ck)[*nek]     = nk + js;
      (*vk)[(*nek)++] = -1.0;
      for (PetscInt k = 0; k < 3; ++k) {
        if (c[k] == 0) continue;
        PetscCheck(red[nb[k]] >= 0, ctx->comm, PETSC_ERR_PLIB, "A stick node's neighbour on Gamma_C is not kept");
        (*rk)[*nek]     = nk + js;
        (*ck)[*nek]     = red[nb[k]];
        (*vk)[(*nek)++] = ctx->rotation.omega * c[k];
      }
      for (PetscInt k = 0; k < 3; ++k) {
        if (a[k] == 0) continue;
        (*rc)[*nec]     = nk + js;
        (*cc)[*nec]     = red[nb[k]];
        (*vc)[(*nec)++] = a[k];
      }
    }
    ++js;
  }
  PetscCall(PetscFree(red));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSquealOperators(Roller ctx, const RollerSteady *st, Mat M, Mat C, Mat K, Mat *Mr, Mat *Cr, Mat *Kr, IS *kept, PetscInt *nstick)
{
  const PetscReal tol  = 1e-12;
  const StickLaw  law  = {ctx->eig.stick_eps, ctx->eig.stick_margin};
  PetscReal       nmax = 0, Tsum = 0;
  Mat             R, RM, RC, RK;
  PetscInt        lo, hi, m, nk = 0, *idx;
  PetscBool      *drop;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < st->n; ++j) nmax = PetscMax(nmax, st->normal[j]), Tsum += st->tangent[j];
  PetscCall(MatGetOwnershipRange(M, &lo, &hi));
  m = hi - lo;
  /* R = I + sum_a s mu_a e_{a,x} e_{a,y}^T: the friction rows */
  PetscCall(MatCreateAIJ(ctx->comm, m, m, PETSC_DETERMINE, PETSC_DETERMINE, 2, NULL, 1, NULL, &R));
  for (PetscInt i = lo; i < hi; ++i) PetscCall(MatSetValue(R, i, i, 1.0, INSERT_VALUES));
  PetscCall(PetscCalloc1(m, &drop));
  for (PetscInt j = 0; j < st->n; ++j) {
    const PetscInt a = st->dof[j];

    if (st->normal[j] <= tol * nmax || a < lo || a >= hi) continue;
    if (Reversed(st, j, Tsum)) continue;
    if (!RigidStick(st, j, law) && st->tangent[j] != 0) PetscCall(MatSetValue(R, a, a + 1, FrictionRatio(st, j, law), INSERT_VALUES)); /* s mu_a */
    drop[a + 1 - lo] = PETSC_TRUE;
  }
  PetscCall(MatAssemblyBegin(R, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(R, MAT_FINAL_ASSEMBLY));
  PetscCall(MatMatMult(R, M, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &RM));
  PetscCall(MatMatMult(R, C, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &RC));
  PetscCall(MatMatMult(R, K, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &RK));
  /* the slip speed's coefficient on the rows a,x: velocity weakening, the regularized cone */
  PetscCall(MatSetOption(RC, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(MatSetOption(RK, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  for (PetscInt j = 0; j < st->n; ++j) {
    const PetscInt a = st->dof[j];
    PetscInt       nb[3], cols[3];
    PetscReal      c[3], w[3], vals[3], cv;

    if (st->normal[j] <= tol * nmax || a < lo || a >= hi || Reversed(st, j, Tsum) || (cv = SlipCoefficient(st, j, law)) == 0) continue;
    PetscCall(RollerSteadyAngularDerivative(st, ctx->rotation.omega, j, nb, c, w));
    for (PetscInt k = 0; k < 3; ++k) {
      cols[k] = st->dof[nb[k]];
      if (w[k] != 0) PetscCall(MatSetValue(RC, a, cols[k], cv * w[k], ADD_VALUES));
      vals[k] = cv * ctx->rotation.omega * c[k];
    }
    PetscCall(MatSetValues(RK, 1, &a, 3, cols, vals, ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(RC, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(RC, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyBegin(RK, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(RK, MAT_FINAL_ASSEMBLY));
  /* the kept dofs: all but the active nodes' normal ones */
  PetscCall(PetscMalloc1(m, &idx));
  for (PetscInt i = 0; i < m; ++i)
    if (!drop[i]) idx[nk++] = lo + i;
  PetscCall(ISCreateGeneral(ctx->comm, nk, idx, PETSC_OWN_POINTER, kept));
  PetscCall(MatCreateSubMatrix(RM, *kept, *kept, MAT_INITIAL_MATRIX, Mr));
  PetscCall(MatCreateSubMatrix(RC, *kept, *kept, MAT_INITIAL_MATRIX, Cr));
  PetscCall(MatCreateSubMatrix(RK, *kept, *kept, MAT_INITIAL_MATRIX, Kr));
  {
    PetscInt     nk, ns = 0, nek = 0, nec = 0, *rk, *ck, *rc, *cc;
    PetscScalar *vk, *vc;
    Mat          A;

    PetscCall(ISGetSize(*kept, &nk));
    PetscCall(StickMultipliers(ctx, st, law, *kept, nk, &ns, &nek, &rk, &ck, &vk, &nec, &rc, &cc, &vc));
    *nstick = ns;
    if (ns) {
      PetscCall(Augment(*Mr, ns, 0, NULL, NULL, NULL, &A));
      PetscCall(MatDestroy(Mr));
      *Mr = A;
      PetscCall(Augment(*Cr, ns, nec, rc, cc, vc, &A));
      PetscCall(MatDestroy(Cr));
      *Cr = A;
      PetscCall(Augment(*Kr, ns, nek, rk, ck, vk, &A));
      PetscCall(MatDestroy(Kr));
      *Kr = A;
    }
    PetscCall(PetscFree3(rk, ck, vk));
    PetscCall(PetscFree3(rc, cc, vc));
  }
  PetscCall(PetscFree(drop));
  PetscCall(MatDestroy(&R));
  PetscCall(MatDestroy(&RM));
  PetscCall(MatDestroy(&RC));
  PetscCall(MatDestroy(&RK));
  PetscFunctionReturn(0);
}
