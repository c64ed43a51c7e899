/* The reduced model put in the context (docs/performance.md "Reduced-order transient"): with the M-orthonormal
   basis V (rom_basis.c) the coordinates q of xi = V q have M_r = I, K_r = diag(lambda) (its Kelvin-Voigt term tau K_r
   with it), the rotating frame's R(-pi/2) M on M products G_r = V^T R(-pi/2) M V (dense, skew), the loads V^T L and the
   functionals V^T w; the levels of the state are projected, q = V^T M xi (with the residual flexibility
   q = K_r^{-1} V^T K xi, contact_residual.c). The schemes (integrate/scheme_newmark.c),
   the driver, the diagnostics and the CSV then step and report the reduced model unchanged; its step matrix
   c_M I + c_K K_r is diagonal (model/solver.c). */
#include "rom/rom.h"
#include "model/axle.h"

/* A diagonal n x n AIJ matrix with the values d[] (every rank holds all of d). */
static PetscErrorCode Diagonal(MPI_Comm comm, PetscInt n, const PetscReal d[], Mat *A)
{
  PetscInt rstart, rend;

  PetscFunctionBeginUser;
  PetscCall(MatCreateAIJ(comm, PETSC_DECIDE, PETSC_DECIDE, n, n, 1, NULL, 0, NULL, A));
  PetscCall(MatGetOwnershipRange(*A, &rstart, &rend));
  for (PetscInt i = rstart; i < rend; ++i) PetscCall(MatSetValue(*A, i, i, d[i], INSERT_VALUES)); /* zeros too: the pattern of the step matrix */
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* V^T A V, or with rotate V^T R(-pi/2) (A V), as a dense-pattern n x n AIJ matrix (n = nq): the rotating frame's
   G_r (A = M), the Maxwell branches' K_d,r (A = K_d). */
static PetscErrorCode Gram(Roller ctx, RollerRom rom, Mat A, PetscBool rotate, PetscInt n, Mat *R)
{
  const PetscInt nq = rom->nq;
  Mat            MV;
  Vec           *cols, w;
  PetscReal     *g;
  PetscScalar   *row;
  PetscInt       rstart, rend, *idx;

  PetscFunctionBeginUser;
  PetscCall(MatMatMult(A, rom->V, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &MV));
  PetscCall(RollerRomColumnsGet(MV, &cols));
  PetscCall(VecDuplicate(cols[0], &w));
  for (PetscInt j = 0; rotate && j < nq; ++j) { /* the nodal R(-pi/2): ops.R90 is not set yet */
    PetscCall(RollerApplyRotate90(ctx, cols[j], w));
    PetscCall(VecCopy(w, cols[j]));
  }
  PetscCall(VecDestroy(&w));
  PetscCall(RollerRomColumnsRestore(MV, &cols));
  PetscCall(PetscMalloc3((size_t)nq * nq, &g, nq, &idx, nq, &row));
  PetscCall(RollerRomGram(rom->V, MV, g));
  for (PetscInt j = 0; j < nq; ++j) idx[j] = j;
  PetscCall(MatCreateAIJ(ctx->comm, PETSC_DECIDE, PETSC_DECIDE, n, n, nq, NULL, nq, NULL, R));
  PetscCall(MatGetOwnershipRange(*R, &rstart, &rend));
  for (PetscInt i = rstart; i < PetscMin(rend, nq); ++i) {
    for (PetscInt j = 0; j < nq; ++j) row[j] = g[i + (size_t)j * nq];
    PetscCall(MatSetValues(*R, 1, &i, nq, idx, row, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*R, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*R, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscFree3(g, idx, row));
  PetscCall(MatDestroy(&MV));
  PetscFunctionReturn(0);
}

typedef enum {
  PROJECT_PLAIN,    /* V^T x: a load or a functional */
  PROJECT_MASS,     /* V^T M x: the M-orthogonal projection of a state */
  PROJECT_STIFFNESS /* K_r^{-1} V^T K x: the K-orthogonal one, whose remainder at Gamma_C is R f_C for a state held by
                       contact forces f_C (-rom_residual: contact_residual.c) */
} Projection;

/* y (reduced, the layout of the reduced matrices) = the projection of x; entries past nq are 0. */
static PetscErrorCode Project(Roller ctx, RollerRom rom, Vec x, Projection how, Vec y)
{
  Vec                p, Mx = NULL, all;
  VecScatter         sc;
  const PetscScalar *a;
  PetscInt           rstart, rend;

  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(rom->V, &p, NULL));
  if (how != PROJECT_PLAIN) {
    PetscCall(VecDuplicate(x, &Mx));
    PetscCall(MatMult(how == PROJECT_MASS ? ctx->ops.M : ctx->ops.K, x, Mx));
  }
  PetscCall(MatMultTranspose(rom->V, Mx ? Mx : x, p));
  PetscCall(VecScatterCreateToAll(p, &sc, &all));
  PetscCall(VecScatterBegin(sc, p, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, p, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecZeroEntries(y));
  PetscCall(VecGetOwnershipRange(y, &rstart, &rend));
  PetscCall(VecGetArrayRead(all, &a));
  for (PetscInt i = rstart; i < PetscMin(rend, rom->nq); ++i) PetscCall(VecSetValue(y, i, how == PROJECT_STIFFNESS ? a[i] / rom->lambda[i] : a[i], INSERT_VALUES));
  PetscCall(VecRestoreArrayRead(all, &a));
  PetscCall(VecAssemblyBegin(y));
  PetscCall(VecAssemblyEnd(y));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecDestroy(&all));
  PetscCall(VecDestroy(&p));
  PetscCall(VecDestroy(&Mx));
  PetscFunctionReturn(0);
}

/* A full-space vector replaced by its reduced image. */
static PetscErrorCode Replace(Roller ctx, RollerRom rom, Vec tmpl, Projection how, Vec *v)
{
  Vec r;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(tmpl, &r));
  PetscCall(Project(ctx, rom, *v, how, r));
  PetscCall(VecDestroy(v));
  *v = r;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerRomReduce(Roller ctx, RollerRom rom)
{
  const PetscInt n  = rom->nq;
  RollerState   *st = &ctx->state;
  PetscReal     *one, *lam;
  Mat            M, K, R;
  Vec            tmpl, *work[] = {&st->next, &st->Kcur, &st->Kprev, &st->Kprev2, &st->Mcur, &st->velocity, &st->rhs, &st->load, &st->work};

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc2(n, &one, n, &lam));
  for (PetscInt i = 0; i < rom->nq; ++i) {
    one[i] = 1.0;
    lam[i] = rom->lambda[i];
  }
  PetscCall(Diagonal(ctx->comm, n, one, &M));
  PetscCall(Diagonal(ctx->comm, n, lam, &K));
  if (ctx->ops.Kd) { /* -rubber maxwell: K_d,r = V^T K_d V (dense; K_r stays diagonal, the step matrix c_D K_d,r + c_K K_r + c_M I) */
    Mat Kd;

    PetscCall(Gram(ctx, rom, ctx->ops.Kd, PETSC_FALSE, n, &Kd));
    PetscCall(MatDestroy(&ctx->ops.Kd));
    ctx->ops.Kd = Kd;
  }
  PetscCall(PetscFree2(one, lam));
  PetscCall(Gram(ctx, rom, ctx->ops.M, PETSC_TRUE, n, &R));
  PetscCall(MatCreateVecs(K, &tmpl, NULL));
  /* the state: the levels projected (M-orthonormal V: q = V^T M xi; with the residual flexibility the K-orthogonal
     projection, whose Gamma_C remainder the residual carries), the rest recomputed */
  for (Vec *lev = &st->cur; lev; lev = lev == &st->cur ? &st->prev : lev == &st->prev ? &st->prev2 : NULL) PetscCall(Replace(ctx, rom, tmpl, ctx->contact && rom->residual ? PROJECT_STIFFNESS : PROJECT_MASS, lev));
  for (size_t k = 0; k < sizeof(work) / sizeof(work[0]); ++k) {
    PetscCall(VecDestroy(work[k]));
    PetscCall(VecDuplicate(tmpl, work[k]));
  }
  /* the operators */
  PetscCall(Replace(ctx, rom, tmpl, PROJECT_PLAIN, &ctx->ops.L_euler));
  PetscCall(Replace(ctx, rom, tmpl, PROJECT_PLAIN, &ctx->ops.L_centrifugal));
  PetscCall(Replace(ctx, rom, tmpl, PROJECT_PLAIN, &ctx->ops.w_R));
  PetscCall(Replace(ctx, rom, tmpl, PROJECT_PLAIN, &ctx->ops.w_alpha));
  if (ctx->axle.on) { /* the hub's couplings: forces V^T c; the rigid fields r_f (in span V: the constraint modes) by
                         their coordinates V^T M r_f, so that r_f . K_d z = RF_r . K_d,r zeta */
    RollerHubCoupling *hc = &ctx->axle.hub->c;

    for (PetscInt j = 0; j < 3; ++j) {
      PetscCall(Replace(ctx, rom, tmpl, PROJECT_PLAIN, &hc->CM[j]));
      PetscCall(Replace(ctx, rom, tmpl, PROJECT_PLAIN, &hc->CK[j]));
      PetscCall(Replace(ctx, rom, tmpl, PROJECT_PLAIN, &hc->RCM[j]));
      if (hc->CD[j]) PetscCall(Replace(ctx, rom, tmpl, PROJECT_PLAIN, &hc->CD[j]));
      if (hc->RF[j]) PetscCall(Replace(ctx, rom, tmpl, PROJECT_MASS, &hc->RF[j]));
    }
    PetscCall(Replace(ctx, rom, tmpl, PROJECT_PLAIN, &hc->cx));
  }
  ctx->ops.M_full = ctx->ops.M;
  PetscCall(MatDestroy(&ctx->ops.K));
  ctx->ops.M   = M;
  ctx->ops.K   = K;
  ctx->ops.R90 = R;
  PetscCall(PetscObjectReference((PetscObject)rom->V));
  ctx->ops.V       = rom->V;
  ctx->ops.reduced = PETSC_TRUE;
  PetscCall(MatMult(K, st->cur, st->Kcur));
  PetscCall(MatMult(K, st->prev, st->Kprev));
  PetscCall(MatMult(K, st->prev2, st->Kprev2));
  PetscCall(VecDestroy(&tmpl));
  PetscFunctionReturn(0);
}
