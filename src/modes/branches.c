/* The generalized Maxwell rubber in the eigenproblem (-rubber maxwell, docs/squeal.md section 1.2): the augmented
   state (xi, z_1, ..., z_n), z_i the nodal displacement-like field of branch i, the time step's model
   (integrate/scheme_maxwell.c): branch energy 1/2 g_i (xi - z_i) . K_d (xi - z_i), flow rule tau_i z_i' = xi - z_i
   with z_i' the rate seen in the co-rotating frame (z_i is material). With Q(lambda) = lambda^2 M + lambda C + K the
   frame's operator of xi (operators.c), the rows of xi gain the branch forces, K + sum_i g_i K_d and -g_i K_d z_i, and
   branch i's flow rule is a row block weighted by W_i:

     co-rotating frame  W_i = g_i K_d:   g_i K_d ((1 + tau_i lambda) z_i - xi) = 0
                        (the branch's spring against its dashpot: a symmetric problem, positive definite at lambda = 0)
     lab frame          W_i = g_i M:     g_i (M (1 + tau_i lambda) z_i + tau_i theta' B_L z_i - M xi) = 0
                        (z_i transported with the material at the objective rate u_t + theta' L u, L = d_phi - J, in
                        its L2 (Galerkin) form B_L = (L u, v), the mass damping's of section 1.1: first derivatives;
                        -modes_branch_transport false drops it: the branches frozen in the lab, an approximation whose
                        error is the loss factor's change over the Doppler shift n theta', which leaves out the
                        transported creep spectrum -1/tau_i - i m theta' that crowds shift-and-invert)

   Eliminating z_i = xi/(1 + tau_i lambda) (co-rotating) gives back K + sum_i g_i K_d tau_i lambda/(1 + tau_i lambda),
   the complex modulus G*(lambda)/mu of model/rubber.c. The augmented matrices are one AIJ each, in MatNest's layout:
   each rank's rows are its xi rows, then its z_1 rows, ..., so that the xi part of an augmented vector is the leading
   part of every rank's local array (RollerBranchRestrict, RollerBranchExtend). */
#include "modes/modes.h"

/* The index sets of the nb blocks of the augmented layout, each the layout of A (xi's) */
static PetscErrorCode BlockISs(Mat A, PetscInt nb, IS is[])
{
  PetscInt lo, hi;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(A, &lo, &hi));
  for (PetscInt b = 0; b < nb; ++b) PetscCall(ISCreateStride(PetscObjectComm((PetscObject)A), hi - lo, nb * lo + b * (hi - lo), 1, &is[b]));
  PetscFunctionReturn(0);
}

/* One AIJ matrix of the nb x nb blocks (NULL: zero) in the augmented layout */
static PetscErrorCode Assemble(PetscInt nb, IS is[], Mat blocks[], Mat *A)
{
  Mat nest;

  PetscFunctionBeginUser;
  PetscCall(MatCreateNest(PetscObjectComm((PetscObject)is[0]), nb, is, nb, is, blocks, &nest));
  PetscCall(MatConvert(nest, MATAIJ, MAT_INITIAL_MATRIX, A));
  PetscCall(MatDestroy(&nest));
  PetscFunctionReturn(0);
}

/* a B + b T into a new matrix (T may be NULL) */
static PetscErrorCode Combine(PetscReal a, Mat B, PetscReal b, Mat T, Mat *A)
{
  PetscFunctionBeginUser;
  PetscCall(MatDuplicate(B, MAT_COPY_VALUES, A));
  PetscCall(MatScale(*A, a));
  if (T && b != 0) PetscCall(MatAXPY(*A, b, T, DIFFERENT_NONZERO_PATTERN));
  PetscFunctionReturn(0);
}

/* The augmented (M, C, K) from the frame's; in the lab the branches transported by B_L or frozen. Kdb: the branches'
   stiffness K_d of a bordered body (-axle: the hub's rows, axle_modes.c), whose flow rules are weighted by its bordered
   mass *M (the bordered K_d annihilates the rigid fields; frozen in the lab); NULL: the body's K_d, W = M in the lab,
   K_d co-rotating. */
static PetscErrorCode Augment(Roller ctx, PetscBool transport, Mat Kdb, Mat *M, Mat *C, Mat *K)
{
  const RollerMaterial *mat = &ctx->material;
  const PetscInt        n = mat->nbranch, nb = n + 1;
  const PetscReal       w   = ctx->rotation.omega;
  const PetscBool       lab = ctx->eig.frame == ROLLER_FRAME_LAB ? PETSC_TRUE : PETSC_FALSE;
  const MatStructure    str = Kdb ? DIFFERENT_NONZERO_PATTERN : SUBSET_NONZERO_PATTERN;
  Mat                   Kd, W, B = NULL, *bm, *bc, *bk, Ma, Ca, Ka;
  IS                    is[ROLLER_MAX_BRANCHES + 1];

  PetscFunctionBeginUser;
  if (mat->rubber != ROLLER_RUBBER_MAXWELL || !n) PetscFunctionReturn(0);
  PetscCall(PetscCalloc3(nb * nb, &bm, nb * nb, &bc, nb * nb, &bk));
  PetscCall(BlockISs(*M, nb, is));
  Kd = Kdb ? Kdb : ctx->ops.Kd;
  W  = Kdb ? *M : (lab ? ctx->ops.M : ctx->ops.Kd);
  if (lab && w != 0 && transport) {
    PetscReal defect;

    PetscCheck(!Kdb, ctx->comm, PETSC_ERR_SUP, "the branches' transport B_L has no hub rows (options.c refuses -axle with -modes_branch_transport)");
    PetscCall(RollerAssembleRotationalMass(ctx, &B));
    PetscCall(RollerSkewPart(B, &defect));
  }
  bm[0] = *M;
  bc[0] = *C;
  PetscCall(MatDuplicate(*K, MAT_COPY_VALUES, &bk[0]));
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt  d = (i + 1) * nb + i + 1;
    const PetscReal g = mat->g[i], tau = mat->tau[i];

    PetscCall(MatAXPY(bk[0], g, Kd, str));
    PetscCall(Combine(-g, Kd, 0, NULL, &bk[i + 1]));       /* -g_i K_d z_i in the rows of xi */
    PetscCall(Combine(-g, W, 0, NULL, &bk[(i + 1) * nb])); /* -W_i xi in the rows of z_i */
    PetscCall(Combine(g * tau, W, 0, NULL, &bc[d]));
    PetscCall(Combine(g, W, g * tau * w, B, &bk[d]));
  }
  PetscCall(Assemble(nb, is, bm, &Ma));
  PetscCall(Assemble(nb, is, bc, &Ca));
  PetscCall(Assemble(nb, is, bk, &Ka));
  PetscCall(MatDestroy(&bk[0]));
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt d = (i + 1) * nb + i + 1;

    PetscCall(MatDestroy(&bk[i + 1]));
    PetscCall(MatDestroy(&bk[(i + 1) * nb]));
    PetscCall(MatDestroy(&bc[d]));
    PetscCall(MatDestroy(&bk[d]));
  }
  for (PetscInt b = 0; b < nb; ++b) PetscCall(ISDestroy(&is[b]));
  PetscCall(PetscFree3(bm, bc, bk));
  PetscCall(MatDestroy(&B));
  PetscCall(MatDestroy(M));
  PetscCall(MatDestroy(C));
  PetscCall(MatDestroy(K));
  *M = Ma;
  *C = Ca;
  *K = Ka;
  PetscFunctionReturn(0);
}

/* Kdb: NULL for the body (clamped at the shaft); the bordered K_d with -axle (M, C, K bordered too) */
PetscErrorCode RollerBranchOperators(Roller ctx, Mat Kdb, Mat *M, Mat *C, Mat *K)
{
  PetscFunctionBeginUser;
  PetscCall(Augment(ctx, ctx->eig.branch_transport, Kdb, M, C, K));
  PetscFunctionReturn(0);
}

/*
  RollerBranchSteadyStiffness - the lab K the steady rolling state is solved with: K itself (a new reference) when it
  carries the branches (augmented) as the steady state takes them, else the frame's K augmented anew: with
  -modes_branch_transport false the steady state still takes the transported branches (its z_i != xi: the rubber's
  rolling hysteresis; one linear solve, cheap) and only the eigenproblem freezes them; with -axle K is the body's
  alone (the branches come after the hub's border) and the steady state is the clamped hub's (axle_modes.c).
*/
PetscErrorCode RollerBranchSteadyStiffness(Roller ctx, Mat K, PetscBool augmented, Mat *Ks)
{
  Mat m, c;

  PetscFunctionBeginUser;
  if (ctx->material.rubber != ROLLER_RUBBER_MAXWELL || !ctx->material.nbranch || (augmented && (ctx->eig.branch_transport || ctx->eig.frame != ROLLER_FRAME_LAB || ctx->rotation.omega == 0))) {
    PetscCall(PetscObjectReference((PetscObject)K));
    *Ks = K;
    PetscFunctionReturn(0);
  }
  PetscCall(RollerModeOperators(ctx, &m, &c, Ks));
  PetscCall(Augment(ctx, PETSC_TRUE, NULL, &m, &c, Ks));
  PetscCall(MatDestroy(&m));
  PetscCall(MatDestroy(&c));
  PetscFunctionReturn(0);
}

/* x = the xi part of the augmented vector a (the leading local entries; a copy without branches) */
PetscErrorCode RollerBranchRestrict(Vec a, Vec x)
{
  const PetscScalar *pa;
  PetscScalar       *px;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(a, &pa));
  PetscCall(VecGetArrayWrite(x, &px));
  PetscCall(PetscArraycpy(px, pa, n));
  PetscCall(VecRestoreArrayWrite(x, &px));
  PetscCall(VecRestoreArrayRead(a, &pa));
  PetscFunctionReturn(0);
}

/* a = (x, 0, ..., 0) */
PetscErrorCode RollerBranchExtend(Vec x, Vec a)
{
  const PetscScalar *px;
  PetscScalar       *pa;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecZeroEntries(a));
  PetscCall(VecGetArrayRead(x, &px));
  PetscCall(VecGetArray(a, &pa));
  PetscCall(PetscArraycpy(pa, px, n));
  PetscCall(VecRestoreArray(a, &pa));
  PetscCall(VecRestoreArrayRead(x, &px));
  PetscFunctionReturn(0);
}

/*
  RollerBranchRelaxationBand - the decay rates [r_lo, r_hi] around the branches' relaxation spectrum, or PETSC_FALSE
  without branches. At rest a real eigenvalue -r of the augmented problem (a creep mode: x . K x >= x . K_d x, the bulk
  elastic) has 1/(tau_max (1 + sum g)) <= r <= 1/tau_min (docs/squeal.md 1.2): the band is that widened by 2 on each
  side (the centrifugal softening and the Coriolis coupling of a rotating roller move them a little off the axis).
*/
PetscBool RollerBranchRelaxationBand(Roller ctx, PetscReal band[2])
{
  const RollerMaterial *m   = &ctx->material;
  PetscReal             sum = 0.0, tmin = PETSC_MAX_REAL, tmax = 0.0;

  if (m->rubber != ROLLER_RUBBER_MAXWELL || !m->nbranch) return PETSC_FALSE;
  for (PetscInt i = 0; i < m->nbranch; ++i) {
    sum += m->g[i];
    tmin = PetscMin(tmin, m->tau[i]);
    tmax = PetscMax(tmax, m->tau[i]);
  }
  band[0] = 0.5 / (tmax * (1.0 + sum));
  band[1] = 2.0 / tmin;
  return PETSC_TRUE;
}

/*
  RollerBranchLossFactor - the rubber's loss factor for the displacement shape x = xr + i xi at the angular frequency
  w: Im(x^H K*(i w) x)/Re(x^H K*(i w) x), K*(i w) = K + sum_i g_i K_d i w tau_i/(1 + i w tau_i) the complex stiffness
  (K the relaxed elastic one, K_d the branches'; with Kelvin-Voigt K (1 + i w tau): w tau; -viscosity beside the
  branches adds its i w tau K to K*). The deviatoric share of the
  shape's strain energy sets it: a torsional (isochoric) shape has the shear loss factor G''/G' itself.
*/
PetscErrorCode RollerBranchLossFactor(Roller ctx, Vec xr, Vec xi, PetscReal w, PetscReal *eta)
{
  const RollerMaterial *m = &ctx->material;
  PetscScalar           a[4];
  PetscReal             k, d = 0.0, re, im;
  Vec                   t;

  PetscFunctionBeginUser;
  *eta = 0.0;
  if (m->rubber != ROLLER_RUBBER_MAXWELL) {
    *eta = w * m->viscosity;
    PetscFunctionReturn(0);
  }
  PetscCall(VecDuplicate(xr, &t));
  PetscCall(MatMult(ctx->ops.K, xr, t));
  PetscCall(VecDot(xr, t, &a[0]));
  PetscCall(MatMult(ctx->ops.K, xi, t));
  PetscCall(VecDot(xi, t, &a[1]));
  PetscCall(MatMult(ctx->ops.Kd, xr, t));
  PetscCall(VecDot(xr, t, &a[2]));
  PetscCall(MatMult(ctx->ops.Kd, xi, t));
  PetscCall(VecDot(xi, t, &a[3]));
  PetscCall(VecDestroy(&t));
  k = PetscRealPart(a[0] + a[1]); /* x^H K x of a symmetric K */
  d = PetscRealPart(a[2] + a[3]);
  RollerRubberModulus(m->nbranch, m->tau, m->g, 0.0, w, &re, &im);
  if (k + d * (re - 1.0) > 0) *eta = (d * im + w * m->viscosity * k) / (k + d * (re - 1.0)); /* (with -viscosity: its w tau K) */
  PetscFunctionReturn(0);
}
