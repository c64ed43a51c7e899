/* The reduced basis (docs/performance.md "Reduced-order transient"): the modes of the roller clamped at the shaft,
   K phi = w^2 M phi (free dofs: Gamma_D removed), below the cutoff w_cut (or the -rom_modes lowest), by SLEPc's
   Krylov-Schur with shift-and-invert about 0 (one Cholesky factorization of K, the ranks the run is given); then the
   static responses to the rigid-body loads, K s = L_centrifugal and K s = L_euler, and with -axle the hub's three
   constraint modes (the rigid fields), M-orthogonalized against the modes (which makes them K-orthogonal to the modes
   too: phi^T K s = w^2 phi^T M s) and against each other, and rotated to diagonalize their own block of K.
   V = [phi, s] is M-orthonormal and V^T K V diagonal. */
#include "rom/rom.h"
#include "model/axle.h"

/* The first guess of the number of modes below w: the two-dimensional Weyl law of the elastic body,
   N(w) = A w^2 / (4 pi) (1/c_s^2 + 1/c_p^2) (A the area = 1^T M 1 / 2 of the unit-density mass: the free dofs'),
   raised by 15 % and 10 modes for its boundary terms (the free rim adds more modes than the clamped shaft removes; the
   printer: about 230 by the law, 243 found). */
static PetscErrorCode WeylCount(Roller ctx, PetscReal w, PetscInt *nev)
{
  const PetscReal mu = ctx->material.mu, lp2 = ctx->material.lambda + 2.0 * mu, rho = ctx->material.density;
  Vec             one, Mone;
  PetscScalar     area;

  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(ctx->ops.M, &one, &Mone));
  PetscCall(VecSet(one, 1.0));
  PetscCall(MatMult(ctx->ops.M, one, Mone));
  PetscCall(VecSum(Mone, &area));
  PetscCall(VecDestroy(&one));
  PetscCall(VecDestroy(&Mone));
  area *= 0.5;
  *nev = (PetscInt)PetscCeilReal(1.15 * PetscRealPart(area) * w * w / (4.0 * PETSC_PI) * (rho / mu + rho / lp2)) + 10;
  PetscFunctionReturn(0);
}

/* The modes: nev from -rom_modes, or from the cutoff by the Weyl law (WeylCount), repeated with the law fitted to the
   last solve (N(w) ~ w^2) until the last converged eigenvalue passes w_cut^2. Krylov-Schur's projected dimension is
   at most 120 (-rom_eps_mpd to change): with hundreds of modes the default (ncv = 2 nev, mpd = ncv) spends most of the
   solve orthogonalizing against the whole basis (the printer's 243 modes with this first guess: the set-up's CPU 66 s
   -> 38 s, docs/performance.md). */
static PetscErrorCode ModesSolve(Roller ctx, RollerRom rom, EPS *eps, PetscInt *nkeep)
{
  ST              st;
  KSP             ksp;
  PetscInt        nev = rom->modes_req, nconv, N, mpd = PETSC_DEFAULT;
  PetscBool       mpd_set;
  PetscReal       lam_last;
  const PetscReal lam_cut = ctx->material.density * rom->w_cut * rom->w_cut; /* ops.M is the unit density's: lambda = rho w^2 */

  PetscFunctionBeginUser;
  PetscCall(MatGetSize(ctx->ops.K, &N, NULL));
  PetscCall(EPSCreate(ctx->comm, eps));
  PetscCall(EPSSetOptionsPrefix(*eps, "rom_"));
  PetscCall(EPSSetOperators(*eps, ctx->ops.K, ctx->ops.M));
  PetscCall(EPSSetProblemType(*eps, EPS_GHEP));
  PetscCall(EPSSetType(*eps, EPSKRYLOVSCHUR));
  PetscCall(EPSSetTarget(*eps, 0.0));
  PetscCall(EPSSetWhichEigenpairs(*eps, EPS_TARGET_MAGNITUDE));
  PetscCall(EPSSetTolerances(*eps, 1e-12, PETSC_DEFAULT));
  PetscCall(EPSGetST(*eps, &st));
  PetscCall(STSetType(st, STSINVERT));
  PetscCall(STGetKSP(st, &ksp));
  PetscCall(RollerDirectSolverDefaults(ksp, PCCHOLESKY));
  PetscCall(EPSSetFromOptions(*eps));
  PetscCall(PetscOptionsGetInt(NULL, "rom_", "-eps_mpd", &mpd, &mpd_set));
  if (nev <= 0) PetscCall(WeylCount(ctx, rom->w_cut, &nev));
  for (PetscInt pass = 0;; ++pass) {
    nev = PetscMin(nev, N - 1);
    PetscCall(EPSSetDimensions(*eps, nev, PETSC_DEFAULT, mpd_set ? mpd : nev > 120 ? 120 : PETSC_DEFAULT));
    PetscCall(EPSSolve(*eps));
    PetscCall(EPSGetConverged(*eps, &nconv));
    PetscCheck(nconv > 0, ctx->comm, PETSC_ERR_CONV_FAILED, "-rom: no mode of the clamped roller converged (asked for %" PetscInt_FMT ")", nev);
    PetscCall(EPSGetEigenvalue(*eps, nconv - 1, &lam_last, NULL));
    if (rom->modes_req > 0) {
      *nkeep = PetscMin(nconv, rom->modes_req);
      break;
    }
    if (lam_last >= lam_cut || nev == N - 1) { /* every mode below the cutoff has converged */
      *nkeep = 0;
      for (PetscInt i = 0; i < nconv; ++i) {
        PetscReal lam;

        PetscCall(EPSGetEigenvalue(*eps, i, &lam, NULL));
        if (lam < lam_cut) *nkeep = i + 1;
      }
      break;
    }
    PetscCheck(pass < 8, ctx->comm, PETSC_ERR_CONV_FAILED, "-rom_cutoff: %" PetscInt_FMT " modes did not reach the cutoff %g (last w %g)", nconv, (double)(rom->w_cut / (2 * PETSC_PI)), (double)PetscSqrtReal(lam_last / ctx->material.density));
    nev = (PetscInt)PetscCeilReal(1.2 * nconv * lam_cut / lam_last) + 10;
  }
  PetscFunctionReturn(0);
}

/* x <- x / |x|_M */
static PetscErrorCode MNormalize(Mat M, Vec x, Vec w)
{
  PetscScalar n2;

  PetscFunctionBeginUser;
  PetscCall(MatMult(M, x, w));
  PetscCall(VecDot(x, w, &n2));
  PetscCall(VecScale(x, 1.0 / PetscSqrtReal(PetscRealPart(n2))));
  PetscFunctionReturn(0);
}

/* s <- s - V_k (V_k^T M s) over the first k columns of V, twice (classical Gram-Schmidt, repeated). */
static PetscErrorCode MOrthogonalize(Roller ctx, Mat V, PetscInt k, Vec s, Vec w)
{
  PetscFunctionBeginUser;
  for (PetscInt pass = 0; pass < 2; ++pass) {
    PetscCall(MatMult(ctx->ops.M, s, w));
    for (PetscInt j = 0; j < k; ++j) {
      Vec         v;
      PetscScalar c;

      PetscCall(MatDenseGetColumnVecRead(V, j, &v));
      PetscCall(VecDot(v, w, &c));
      PetscCall(VecAXPY(s, -c, v));
      PetscCall(MatDenseRestoreColumnVecRead(V, j, &v));
    }
  }
  PetscFunctionReturn(0);
}

/* The columns of a dense N x n matrix as Vecs sharing its storage, to read (the array stays where it is; *cols
   freed by RollerRomColumnsRestore). */
PetscErrorCode RollerRomColumnsGet(Mat A, Vec **cols)
{
  PetscScalar *a;
  PetscInt     nloc, n, lda;

  PetscFunctionBeginUser;
  PetscCall(MatGetLocalSize(A, &nloc, NULL));
  PetscCall(MatGetSize(A, NULL, &n));
  PetscCall(MatDenseGetLDA(A, &lda));
  PetscCall(MatDenseGetArray(A, &a));
  PetscCall(PetscMalloc1(n, cols));
  for (PetscInt j = 0; j < n; ++j) PetscCall(VecCreateMPIWithArray(PetscObjectComm((PetscObject)A), 1, nloc, PETSC_DECIDE, a + (size_t)j * lda, &(*cols)[j]));
  PetscCall(MatDenseRestoreArray(A, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerRomColumnsRestore(Mat A, Vec **cols)
{
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(MatGetSize(A, NULL, &n));
  for (PetscInt j = 0; j < n; ++j) PetscCall(VecDestroy(&(*cols)[j]));
  PetscCall(PetscFree(*cols));
  PetscFunctionReturn(0);
}

/* C = A^T B (n x n, column-major, the same on every rank) of two dense N x n matrices, by n VecMDot. */
PetscErrorCode RollerRomGram(Mat A, Mat B, PetscReal C[])
{
  Vec         *a, *b;
  PetscInt     n;
  PetscScalar *c;

  PetscFunctionBeginUser;
  PetscCall(MatGetSize(A, NULL, &n));
  PetscCall(PetscMalloc1(n, &c));
  PetscCall(RollerRomColumnsGet(A, &a));
  PetscCall(RollerRomColumnsGet(B, &b));
  for (PetscInt j = 0; j < n; ++j) {
    PetscCall(VecMDot(b[j], n, a, c));
    for (PetscInt i = 0; i < n; ++i) C[i + (size_t)j * n] = PetscRealPart(c[i]);
  }
  PetscCall(RollerRomColumnsRestore(B, &b));
  PetscCall(RollerRomColumnsRestore(A, &a));
  PetscCall(PetscFree(c));
  PetscFunctionReturn(0);
}

/* The eigenvectors of a small symmetric k x k matrix A (column-major, overwritten) into Q by cyclic Jacobi rotations
   (k <= 5 here: no LAPACK call needed). */
static void SymmetricEigen(PetscInt k, PetscReal A[], PetscReal Q[])
{
  for (PetscInt i = 0; i < k * k; ++i) Q[i] = (i % (k + 1) == 0) ? 1.0 : 0.0;
  for (PetscInt sweep = 0; sweep < 50; ++sweep) {
    PetscReal off = 0.0, diag = 0.0;

    for (PetscInt p = 0; p < k; ++p)
      for (PetscInt q = 0; q < k; ++q) {
        if (p == q) diag += A[p + p * k] * A[p + p * k];
        else off += A[p + q * k] * A[p + q * k];
      }
    if (off <= 1e-32 * diag) break;
    for (PetscInt p = 0; p < k; ++p)
      for (PetscInt q = p + 1; q < k; ++q) {
        const PetscReal apq = A[p + q * k], th = 0.5 * PetscAtan2Real(2.0 * apq, A[q + q * k] - A[p + p * k]), c = PetscCosReal(th), sn = PetscSinReal(th);

        if (apq == 0.0) continue;
        for (PetscInt r = 0; r < k; ++r) { /* A <- A J (columns p, q) */
          const PetscReal arp = A[r + p * k], arq = A[r + q * k];

          A[r + p * k] = c * arp - sn * arq;
          A[r + q * k] = sn * arp + c * arq;
        }
        for (PetscInt r = 0; r < k; ++r) { /* A <- J^T A (rows p, q) */
          const PetscReal apr = A[p + r * k], aqr = A[q + r * k];

          A[p + r * k] = c * apr - sn * aqr;
          A[q + r * k] = sn * apr + c * aqr;
        }
        for (PetscInt r = 0; r < k; ++r) { /* Q <- Q J */
          const PetscReal qrp = Q[r + p * k], qrq = Q[r + q * k];

          Q[r + p * k] = c * qrp - sn * qrq;
          Q[r + q * k] = sn * qrp + c * qrq;
        }
      }
  }
}

/* The static vectors in columns nm .. nq-1 of V: the responses to the rigid-body loads K^{-1} L_centrifugal,
   K^{-1} L_euler (the factorization of K is the eigensolver's, shift 0) and, with -axle, the hub's constraint modes
   (the body's static response to a unit hub motion, K_aug [r_f; e_j] = 0: the rigid fields r_f themselves); made
   M-orthonormal against everything before them (which makes them K-orthogonal to the exact modes too:
   phi^T K s = w^2 phi^T M s), then rotated by the eigenvectors of their own k x k block of K (a Ritz step). */
static PetscErrorCode StaticResponses(Roller ctx, RollerRom rom, EPS eps, Vec w)
{
  const PetscInt nm = rom->nmodes, k = rom->nq - nm;
  Vec            L[2] = {ctx->ops.L_centrifugal, ctx->ops.L_euler}, s[5], Ks, col;
  ST             st;
  KSP            ksp;
  PetscScalar    d;
  PetscReal     *A, *Q;

  PetscFunctionBeginUser;
  PetscCall(EPSGetST(eps, &st));
  PetscCall(STGetKSP(st, &ksp));
  if (k > 2) PetscCall(RollerRigidFields(ctx, s + 2)); /* -axle */
  for (PetscInt j = 0; j < k; ++j) {
    if (j < 2) {
      PetscCall(VecDuplicate(w, &s[j]));
      PetscCall(KSPSolve(ksp, L[j], s[j]));
    }
    for (PetscInt pass = 0; pass < 2; ++pass) {
      PetscCall(MOrthogonalize(ctx, rom->V, nm, s[j], w));
      for (PetscInt i = 0; i < j; ++i) { /* against the earlier static vectors */
        PetscCall(MatMult(ctx->ops.M, s[i], w));
        PetscCall(VecDot(s[j], w, &d));
        PetscCall(VecAXPY(s[j], -d, s[i]));
      }
    }
    PetscCall(MNormalize(ctx->ops.M, s[j], w));
  }
  PetscCall(PetscMalloc2(k * k, &A, k * k, &Q));
  PetscCall(VecDuplicate(w, &Ks));
  for (PetscInt j = 0; j < k; ++j) { /* the k x k block S^T K S */
    PetscCall(MatMult(ctx->ops.K, s[j], Ks));
    for (PetscInt i = 0; i < k; ++i) {
      PetscCall(VecDot(s[i], Ks, &d));
      A[i + j * k] = PetscRealPart(d);
    }
  }
  for (PetscInt j = 0; j < k; ++j)
    for (PetscInt i = 0; i < j; ++i) A[i + j * k] = A[j + i * k] = 0.5 * (A[i + j * k] + A[j + i * k]);
  SymmetricEigen(k, A, Q);
  for (PetscInt j = 0; j < k; ++j) { /* column nm + j = sum_i s_i Q_ij */
    PetscCall(MatDenseGetColumnVecWrite(rom->V, nm + j, &col));
    PetscCall(VecZeroEntries(col));
    for (PetscInt i = 0; i < k; ++i) PetscCall(VecAXPY(col, Q[i + j * k], s[i]));
    PetscCall(MatDenseRestoreColumnVecWrite(rom->V, nm + j, &col));
  }
  for (PetscInt j = 0; j < k; ++j) PetscCall(VecDestroy(&s[j]));
  PetscCall(VecDestroy(&Ks));
  PetscCall(PetscFree2(A, Q));
  PetscFunctionReturn(0);
}

/* The round-off of the basis: V^T M V - I and the off-diagonal of V^T K V (relative to its largest entry); the
   diagonal of V^T K V is the reduced stiffness. */
static PetscErrorCode Check(Roller ctx, RollerRom rom)
{
  Mat            MV, KV;
  PetscReal     *g, big = 0.0, off_k = 0.0, off_m = 0.0;
  const PetscInt n = rom->nq;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1((size_t)n * n, &g));
  PetscCall(MatMatMult(ctx->ops.M, rom->V, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &MV));
  PetscCall(MatMatMult(ctx->ops.K, rom->V, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &KV));
  PetscCall(RollerRomGram(rom->V, KV, g));
  for (PetscInt i = 0; i < n; ++i) {
    rom->lambda[i] = g[i + i * n];
    big            = PetscMax(big, PetscAbsReal(rom->lambda[i]));
  }
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt j = 0; j < n; ++j)
      if (i != j) off_k = PetscMax(off_k, PetscAbsReal(g[i + j * n]) / big);
  PetscCall(RollerRomGram(rom->V, MV, g));
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt j = 0; j < n; ++j) off_m = PetscMax(off_m, PetscAbsReal(g[i + j * n] - (i == j ? 1.0 : 0.0)));
  PetscCall(MatDestroy(&MV));
  PetscCall(MatDestroy(&KV));
  PetscCall(PetscFree(g));
  rom->offdiag = PetscMax(off_k, off_m);
  PetscFunctionReturn(0);
}

PetscErrorCode RollerRomBasis(Roller ctx, RollerRom rom)
{
  EPS      eps;
  PetscInt nloc, N, nkeep = 0;
  Vec      w;

  PetscFunctionBeginUser;
  PetscCall(ModesSolve(ctx, rom, &eps, &nkeep));
  rom->nmodes = nkeep;
  rom->nq     = nkeep + 2 + (ctx->axle.on ? 3 : 0); /* + the load responses, + the hub's constraint modes */
  PetscCall(VecGetLocalSize(ctx->state.cur, &nloc));
  PetscCall(VecGetSize(ctx->state.cur, &N));
  PetscCall(MatCreateDense(ctx->comm, nloc, PETSC_DECIDE, N, rom->nq, NULL, &rom->V));
  PetscCall(PetscMalloc1(rom->nq, &rom->lambda));
  PetscCall(VecDuplicate(ctx->state.cur, &w));
  for (PetscInt i = 0; i < nkeep; ++i) {
    Vec v;

    PetscCall(MatDenseGetColumnVecWrite(rom->V, i, &v));
    PetscCall(EPSGetEigenvector(eps, i, v, NULL));
    PetscCall(MNormalize(ctx->ops.M, v, w));
    PetscCall(MatDenseRestoreColumnVecWrite(rom->V, i, &v));
  }
  PetscCall(StaticResponses(ctx, rom, eps, w));
  PetscCall(VecDestroy(&w));
  rom->eps = eps; /* K's factorization for the residual flexibility (rom.c destroys it) */
  PetscCall(Check(ctx, rom));
  PetscFunctionReturn(0);
}
