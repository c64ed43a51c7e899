/* A direct solve of a symmetric positive definite step matrix on several ranks by substructuring (docs/performance.md,
   "Large meshes on several ranks"): the interface Gamma takes, for each pair of coupled ranks, the smaller of their two
   sets of rows coupled to the other; the rest of rank r's rows are its interior I_r. No interior row couples to
   another rank's interior, so with the interior blocks A_rr = L_r L_r^T factored on their ranks (serial Cholesky, nested dissection),
     G_r = L_r^{-1} A_{I_r,Gamma}     (sparse: the fill of the interface columns in the rank's factor),
     S   = A_{Gamma,Gamma} - sum_r G_r^T G_r   (dense, of the interface's size, Cholesky on every rank),
   and a solve is
     y_r = L_r^{-1} b_r,   x_Gamma = S^{-1} (b_Gamma - sum_r G_r^T y_r),   x_r = L_r^{-T} (y_r - G_r x_Gamma):
   each rank's forward and backward substitution covers its share of the factor only (MUMPS's distributed triangular
   solves cost more than a serial one on this machine), plus one reduction of the interface's size. The same
   factorization as nested dissection with the partition's separator last, exact to round-off. */
#include "model/solver_schur.h"

static PetscErrorCode Forward(const SchurCtx *, Vec, Vec);

/* G_r^T by forward substitutions of the interface columns of A_{I_r,Gamma} (the fill of each kept, exact zeros
   dropped), and this rank's share of S: its interface rows of A_{Gamma,Gamma} minus G_r^T G_r. */
static PetscErrorCode Coupling(Mat A, SchurCtx *sc, PetscInt nI, const PetscInt inv[], const PetscInt gl[], const PetscBool isg[])
{
  Mat             Ad, Ao, C;
  const PetscInt *garray;
  PetscInt        lo, hi, m, ng = sc->ng, *gidx, *cnt, *ptr, *ent, nz = 0, cap, *ja, *ia, *rnnz;
  PetscScalar    *ev, *va, *y;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(A, &lo, &hi));
  PetscCall(MatMPIAIJGetSeqAIJ(A, &Ad, &Ao, &garray));
  m = hi - lo;
  PetscCall(PetscMalloc1(m, &gidx));
  for (PetscInt i = 0, q = 0; i < m; ++i) gidx[i] = isg[i] ? sc->goff + q++ : -1;
  /* the columns of A_{I_r,Gamma}: entries (factor row, value) per interface column, and the rows of A_{Gamma_r,Gamma} */
  PetscCall(PetscCalloc2(ng + 1, &cnt, ng + 1, &ptr));
  for (PetscInt pass = 0; pass < 2; ++pass) {
    if (pass) {
      for (PetscInt j = 0; j < ng; ++j) ptr[j + 1] = ptr[j] + cnt[j];
      PetscCall(PetscMalloc2(ptr[ng], &ent, ptr[ng], &ev));
      PetscCall(PetscArrayzero(cnt, ng));
    }
    for (PetscInt i = 0; i < m; ++i)
      for (PetscInt part = 0; part < 2; ++part) {
        const PetscInt    *cols;
        const PetscScalar *vals;
        PetscInt           nc;

        PetscCall(MatGetRow(part ? Ao : Ad, i, &nc, &cols, &vals));
        for (PetscInt k = 0; k < nc; ++k) {
          const PetscInt j = part ? RollerSchurInInterface(ng, gl, garray[cols[k]]) : gidx[cols[k]];

          PetscCheck(!part || isg[i] || j >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The step matrix couples an interior row to a non-interface row of another rank: its pattern is not symmetric");
          if (j < 0) continue;
          if (isg[i]) {
            if (pass) sc->Sa[gidx[i] + (size_t)j * ng] += vals[k];
          } else if (pass) {
            ent[ptr[j] + cnt[j]]  = inv[i];
            ev[ptr[j] + cnt[j]++] = vals[k];
          } else cnt[j]++;
        }
        PetscCall(MatRestoreRow(part ? Ao : Ad, i, &nc, &cols, &vals));
      }
  }
  /* G_r^T, row j = L_r^{-1} (column j of A_{I_r,Gamma}) */
  cap = 16 * (ptr[ng] + 1);
  PetscCall(PetscMalloc2(cap, &ja, cap, &va));
  PetscCall(PetscMalloc2(ng + 1, &ia, ng, &rnnz));
  ia[0] = 0;
  PetscCall(VecSet(sc->bI, 0.0));
  for (PetscInt j = 0; j < ng; ++j) {
    if (ptr[j + 1] > ptr[j]) {
      PetscCall(VecSetValues(sc->bI, ptr[j + 1] - ptr[j], ent + ptr[j], ev + ptr[j], INSERT_VALUES));
      PetscCall(VecAssemblyBegin(sc->bI));
      PetscCall(VecAssemblyEnd(sc->bI));
      if (sc->rows.on) PetscCall(Forward(sc, sc->bI, sc->yI));
      else PetscCall(MatForwardSolve(sc->F, sc->bI, sc->yI));
      PetscCall(VecSet(sc->bI, 0.0));
      PetscCall(VecGetArray(sc->yI, &y));
      for (PetscInt p = 0; p < nI; ++p) {
        if (y[p] == 0.0) continue;
        if (nz == cap) {
          PetscInt    *nja;
          PetscScalar *nva;

          PetscCall(PetscMalloc2(2 * cap, &nja, 2 * cap, &nva));
          PetscCall(PetscArraycpy(nja, ja, nz));
          PetscCall(PetscArraycpy(nva, va, nz));
          PetscCall(PetscFree2(ja, va));
          ja = nja, va = nva, cap *= 2;
        }
        ja[nz]   = p;
        va[nz++] = y[p];
      }
      PetscCall(VecRestoreArray(sc->yI, &y));
    }
    ia[j + 1] = nz;
    rnnz[j]   = ia[j + 1] - ia[j];
  }
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, ng, nI, 0, rnnz, &sc->Gt));
  for (PetscInt j = 0; j < ng; ++j)
    if (rnnz[j]) PetscCall(MatSetValues(sc->Gt, 1, &j, rnnz[j], ja + ia[j], va + ia[j], INSERT_VALUES));
  PetscCall(MatAssemblyBegin(sc->Gt, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(sc->Gt, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscFree2(ja, va));
  PetscCall(PetscFree2(ia, rnnz));
  /* S -= G_r^T G_r */
  PetscCall(MatMatTransposeMult(sc->Gt, sc->Gt, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &C));
  for (PetscInt r = 0; r < ng; ++r) {
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscInt           nc;

    PetscCall(MatGetRow(C, r, &nc, &cols, &vals));
    for (PetscInt k = 0; k < nc; ++k) sc->Sa[r + (size_t)cols[k] * ng] -= vals[k];
    PetscCall(MatRestoreRow(C, r, &nc, &cols, &vals));
  }
  PetscCall(MatDestroy(&C));
  PetscCall(PetscFree2(ent, ev));
  PetscCall(PetscFree2(cnt, ptr));
  PetscCall(PetscFree(gidx));
  PetscFunctionReturn(0);
}

/* The backward substitution D^{1/2} U x = b (MatBackwardSolve) on the factor's rows. */
static PetscErrorCode Backward(const SchurCtx *sc, Vec b, Vec x)
{
  const PetscInt    *ai = sc->rows.i, *aj = sc->rows.j;
  const PetscScalar *aa = sc->rows.a, *bb;
  PetscScalar       *xx;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetSize(b, &n));
  PetscCall(VecGetArrayRead(b, &bb));
  PetscCall(VecGetArray(x, &xx));
  for (PetscInt k = n - 1; k >= 0; --k) {
    PetscScalar s = PetscSqrtReal(PetscRealPart(aa[ai[k + 1] - 1])) * bb[k];

    for (PetscInt p = ai[k + 1] - 2; p >= ai[k]; --p) s += aa[p] * xx[aj[p]]; /* backwards: one descending stream */
    xx[k] = s;
  }
  PetscCall(VecRestoreArrayRead(b, &bb));
  PetscCall(VecRestoreArray(x, &xx));
  PetscCall(PetscLogFlops(2.0 * ai[n] - n));
  PetscFunctionReturn(0);
}

/* The forward substitution U^T D^{1/2} x = b (MatForwardSolve) on the factor's rows, skipping the rows of zero
   entries: the interface columns' substitutions touch only their reach in the elimination tree. */
static PetscErrorCode Forward(const SchurCtx *sc, Vec b, Vec x)
{
  const PetscInt    *ai = sc->rows.i, *aj = sc->rows.j;
  const PetscScalar *aa = sc->rows.a;
  PetscScalar       *xx;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetSize(b, &n));
  PetscCall(VecCopy(b, x));
  PetscCall(VecGetArray(x, &xx));
  for (PetscInt k = 0; k < n; ++k) {
    const PetscScalar xk = xx[k];

    if (xk == 0.0) continue;
    for (PetscInt p = ai[k]; p < ai[k + 1] - 1; ++p) xx[aj[p]] += aa[p] * xk;
    xx[k] = xk * PetscSqrtReal(PetscRealPart(aa[ai[k + 1] - 1]));
  }
  PetscCall(VecRestoreArray(x, &xx));
  PetscCall(PetscLogFlops(2.0 * ai[n] - n));
  PetscFunctionReturn(0);
}

/* The factor's rows for Forward() and Backward(), kept only if they reproduce MatForwardSolve and MatBackwardSolve
   on a test vector (to 1e-12). */
static PetscErrorCode SubstitutionSetUp(SchurCtx *sc)
{
  PetscInt  n;
  PetscBool done;
  Vec       b, x1, x2;
  PetscReal err, ref;

  PetscFunctionBeginUser;
  PetscCall(MatGetRowIJ(sc->F, 0, PETSC_FALSE, PETSC_FALSE, &n, &sc->rows.i, &sc->rows.j, &done));
  if (!done) PetscFunctionReturn(0);
  PetscCall(MatSeqAIJGetArrayRead(sc->F, &sc->rows.a));
  PetscCall(VecDuplicate(sc->bI, &b));
  PetscCall(VecDuplicate(sc->bI, &x1));
  PetscCall(VecDuplicate(sc->bI, &x2));
  for (PetscInt k = 0; k < n; ++k) PetscCall(VecSetValue(b, k, PetscSinReal(0.37 * k + 0.1), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(b));
  PetscCall(VecAssemblyEnd(b));
  sc->rows.on = PETSC_TRUE;
  for (PetscInt pass = 0; pass < 2; ++pass) {
    PetscCall(pass ? MatBackwardSolve(sc->F, b, x1) : MatForwardSolve(sc->F, b, x1));
    PetscCall(pass ? Backward(sc, b, x2) : Forward(sc, b, x2));
    PetscCall(VecNorm(x1, NORM_INFINITY, &ref));
    PetscCall(VecAXPY(x2, -1.0, x1));
    PetscCall(VecNorm(x2, NORM_INFINITY, &err));
    if (err > 1e-12 * ref) sc->rows.on = PETSC_FALSE;
    PetscCall(PetscInfo(NULL, "Substructured Cholesky: own %s substitution against PETSc's: difference %g of %g\n", pass ? "backward" : "forward", (double)err, (double)ref));
  }
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&x1));
  PetscCall(VecDestroy(&x2));
  PetscFunctionReturn(0);
}

static PetscErrorCode SchurDestroyCtx(SchurCtx *sc)
{
  PetscBool done;
  PetscInt  n;

  PetscFunctionBeginUser;
  if (sc->rows.a) PetscCall(MatSeqAIJRestoreArrayRead(sc->F, &sc->rows.a));
  if (sc->rows.i) PetscCall(MatRestoreRowIJ(sc->F, 0, PETSC_FALSE, PETSC_FALSE, &n, &sc->rows.i, &sc->rows.j, &done));
  PetscCall(MatDestroy(&sc->F));
  PetscCall(MatDestroy(&sc->Gt));
  PetscCall(MatDestroy(&sc->S));
  PetscCall(VecDestroy(&sc->bI));
  PetscCall(VecDestroy(&sc->yI));
  PetscCall(VecDestroy(&sc->xI));
  PetscCall(VecDestroy(&sc->xg));
  PetscCall(VecDestroy(&sc->tg));
  PetscCall(PetscFree(sc->row));
  PetscCall(PetscFree(sc->grow));
  PetscCall(PetscFree(sc->Sa));
  PetscCall(PetscMemzero(sc, sizeof(*sc)));
  PetscFunctionReturn(0);
}

static PetscErrorCode SchurSetUp(PC pc)
{
  SchurCtx     *sc;
  Mat           A;
  PetscInt     *gl, *inv, nI;
  PetscBool    *isg;
  MatFactorInfo info;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &sc));
  PetscCall(SchurDestroyCtx(sc));
  PetscCall(PCGetOperators(pc, &A, NULL));
  PetscCall(RollerSchurInterface(A, sc, &gl, &isg));
  PetscCall(RollerSchurInteriorFactor(A, sc, isg, &nI, &inv));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, nI, &sc->bI));
  PetscCall(VecDuplicate(sc->bI, &sc->yI));
  PetscCall(VecDuplicate(sc->bI, &sc->xI));
  PetscCall(SubstitutionSetUp(sc));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, sc->ng, &sc->xg));
  PetscCall(VecDuplicate(sc->xg, &sc->tg));
  PetscCall(PetscCalloc1((size_t)sc->ng * sc->ng, &sc->Sa));
  PetscCall(Coupling(A, sc, nI, inv, gl, isg));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sc->Sa, (PetscMPIInt)(sc->ng * sc->ng), MPIU_SCALAR, MPIU_SUM, PetscObjectComm((PetscObject)pc)));
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, sc->ng, sc->ng, sc->Sa, &sc->S));
  PetscCall(MatFactorInfoInitialize(&info));
  PetscCall(MatCholeskyFactor(sc->S, NULL, &info));
  {
    MatInfo fi, gi;

    PetscCall(MatGetInfo(sc->F, MAT_LOCAL, &fi));
    PetscCall(MatGetInfo(sc->Gt, MAT_LOCAL, &gi));
    PetscCall(PetscInfo(pc, "Substructured Cholesky: %" PetscInt_FMT " interior unknowns here (factor %g nonzeros, G %g), interface %" PetscInt_FMT "\n", nI, fi.nz_used, gi.nz_used, sc->ng));
  }
  PetscCall(PetscFree(gl));
  PetscCall(PetscFree(isg));
  PetscCall(PetscFree(inv));
  PetscFunctionReturn(0);
}

static PetscErrorCode SchurApply(PC pc, Vec b, Vec x)
{
  SchurCtx          *sc;
  const PetscScalar *bb, *xg;
  PetscScalar       *bi, *g, *xx;
  PetscInt           nI;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &sc));
  PetscCall(VecGetSize(sc->bI, &nI));
  PetscCall(VecGetArrayRead(b, &bb));
  PetscCall(VecGetArray(sc->bI, &bi));
  for (PetscInt p = 0; p < nI; ++p) bi[p] = bb[sc->row[p]];
  PetscCall(VecRestoreArray(sc->bI, &bi));
  if (sc->rows.on) PetscCall(Forward(sc, sc->bI, sc->yI));
  else PetscCall(MatForwardSolve(sc->F, sc->bI, sc->yI));
  PetscCall(MatMult(sc->Gt, sc->yI, sc->tg)); /* G_r^T y_r */
  PetscCall(VecScale(sc->tg, -1.0));
  PetscCall(VecGetArray(sc->tg, &g));
  for (PetscInt q = 0; q < sc->nglocal; ++q) g[sc->goff + q] += bb[sc->grow[q]];
  PetscCall(VecRestoreArrayRead(b, &bb));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, g, (PetscMPIInt)sc->ng, MPIU_SCALAR, MPIU_SUM, PetscObjectComm((PetscObject)pc)));
  PetscCall(VecRestoreArray(sc->tg, &g));
  PetscCall(MatSolve(sc->S, sc->tg, sc->xg));
  PetscCall(MatMultTranspose(sc->Gt, sc->xg, sc->xI)); /* G_r x_Gamma */
  PetscCall(VecAYPX(sc->xI, -1.0, sc->yI));
  if (sc->rows.on) PetscCall(Backward(sc, sc->xI, sc->bI));
  else PetscCall(MatBackwardSolve(sc->F, sc->xI, sc->bI));
  PetscCall(VecGetArray(x, &xx));
  PetscCall(VecGetArrayRead(sc->bI, (const PetscScalar **)&bi));
  for (PetscInt p = 0; p < nI; ++p) xx[sc->row[p]] = bi[p];
  PetscCall(VecRestoreArrayRead(sc->bI, (const PetscScalar **)&bi));
  PetscCall(VecGetArrayRead(sc->xg, &xg));
  for (PetscInt q = 0; q < sc->nglocal; ++q) xx[sc->grow[q]] = xg[sc->goff + q];
  PetscCall(VecRestoreArrayRead(sc->xg, &xg));
  PetscCall(VecRestoreArray(x, &xx));
  PetscFunctionReturn(0);
}

static PetscErrorCode SchurDestroy(PC pc)
{
  SchurCtx *sc;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &sc));
  PetscCall(SchurDestroyCtx(sc));
  PetscCall(PetscFree(sc));
  PetscFunctionReturn(0);
}

static PetscErrorCode SchurView(PC pc, PetscViewer viewer)
{
  SchurCtx *sc;
  PetscInt  nI = 0;
  MatInfo   fi = {0}, gi = {0};
  PetscReal loc[3], mx[3];

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &sc));
  if (!sc->F) PetscFunctionReturn(0);
  PetscCall(VecGetSize(sc->bI, &nI));
  PetscCall(MatGetInfo(sc->F, MAT_LOCAL, &fi));
  PetscCall(MatGetInfo(sc->Gt, MAT_LOCAL, &gi));
  loc[0] = nI, loc[1] = fi.nz_used, loc[2] = gi.nz_used;
  PetscCall(MPIU_Allreduce(loc, mx, 3, MPIU_REAL, MPIU_MAX, PetscObjectComm((PetscObject)pc)));
  PetscCall(PetscViewerASCIIPrintf(viewer, "  interface %" PetscInt_FMT " unknowns (dense Schur complement on every rank); largest interior %g unknowns, its factor %g nonzeros, its G %g\n", sc->ng, mx[0], mx[1], mx[2]));
  PetscFunctionReturn(0);
}

/* The step KSP's PC as the substructured Cholesky (an SPD matrix of type MPIAIJ on several ranks). */
PetscErrorCode RollerSchurPCSet(PC pc)
{
  SchurCtx *sc;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&sc));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, sc));
  PetscCall(PCShellSetSetUp(pc, SchurSetUp));
  PetscCall(PCShellSetApply(pc, SchurApply));
  PetscCall(PCShellSetDestroy(pc, SchurDestroy));
  PetscCall(PCShellSetView(pc, SchurView));
  PetscCall(PCShellSetName(pc, "substructured Cholesky: interiors factored on their ranks, the dense interface Schur complement on every rank"));
  PetscFunctionReturn(0);
}
