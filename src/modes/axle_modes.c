/* -modes with -axle (docs/squeal.md section 3.1, docs/model.md section 10): the hub's unknowns in the eigenproblem and
   the steady state set by the nip force.

   The lab frame (the guide is the lab's vertical): the hub's perturbation q = (Y, phi), Y along the lab's e2, phi its
   rotation (the motor turns steadily: against the motor as in the step). The body's unknowns are the free nodes' whole
   displacement, Gamma_D moving with the rigid fields r = e2, J x of q (model/axle.h). Every operator X of the free
   annulus (operators.c) is bordered by its columns X_fG r_G and rows r_G^T X_Gf and the hub block r_G^T X_GG r_G:

     M:  rho C_M,  rho D_M + diag(m, I)
     C:  2 theta' rho C_D + tau C_K + eta C_M (rows: the skew D's -C_D^T),  2 theta' rho D_hub + tau D_K + eta D_M + diag(0, c_d)
     K:  C_K - theta'^2 rho C_P + theta' tau C_A (rows: -C_A^T),  D_K - theta'^2 rho P_hub + diag(k, k_d)

   with C_M, C_K, D_M, D_K of model/axle.c, and from the identities of the whole body's forms on the rigid fields
   (d_phi e2 = 0, d_phi J x = -x, and (f, d_phi v) = -(d_phi f, v) on the annulus):
     D e2 = 0, D J x = -(x, v):        C_D e2 = -D e2_f,  C_D J x = -L_c - D Jx_f,
     P e2 = 0, P J x = (J x, v) = L_Jx: C_P e2 = -P e2_f,  C_P J x = L_Jx - P Jx_f,
   the hub blocks r_G^T X_GG r'_G = r^T X r' - r_f . (X r')_f -+ r'_f . C_X r (symmetric: -, skew: +), and the damped
   lab frame's A_L (skew part), which annihilates the rigid fields on both sides (L r is rigid, and a rigid test field
   has no strain): C_A r = -A r_f, its hub block 0. The mass damping's B_L with theta' != 0 is not carried (refused).
   The vertical spring k acts about the steady state (it is anchored there, as the step anchors it at the end of the nip
   ramp), the drive's k_d and c_d against the steadily turning motor. The steady state
   and the vectors of the bordered layout: axle_steady.c. */
#include "modes/modes.h"
#include "model/axle.h"
#include "model/kernels.h"

/* e2 and J x on the free nodes (axle_steady.c too) */
PetscErrorCode RollerAxleRigidFields(Roller ctx, Vec r[2])
{
  const PetscScalar *x;
  PetscScalar       *a, *b;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(ctx->ops.coordinates, &r[0]));
  PetscCall(VecDuplicate(ctx->ops.coordinates, &r[1]));
  PetscCall(VecGetLocalSize(ctx->ops.coordinates, &n));
  PetscCall(VecGetArrayRead(ctx->ops.coordinates, &x));
  PetscCall(VecGetArrayWrite(r[0], &a));
  PetscCall(VecGetArrayWrite(r[1], &b));
  for (PetscInt i = 0; i < n; i += 2) {
    a[i] = 0.0, a[i + 1] = 1.0;
    b[i] = -x[i + 1], b[i + 1] = x[i];
  }
  PetscCall(VecRestoreArrayWrite(r[0], &a));
  PetscCall(VecRestoreArrayWrite(r[1], &b));
  PetscCall(VecRestoreArrayRead(ctx->ops.coordinates, &x));
  PetscFunctionReturn(0);
}

static PetscReal Dot(Vec a, Vec b)
{
  PetscScalar d = 0.0;

  PetscCallAbort(PETSC_COMM_SELF, VecDot(a, b, &d));
  return PetscRealPart(d);
}

/* The border of one operator: columns col[j] (free rows of X_fG r_j), rows row[j] (r_j^T X_Gf as a vector) and the
   hub block H (row-major 2 x 2). */
typedef struct {
  Vec       col[2], row[2];
  PetscReal H[4];
} Border;

static PetscErrorCode BorderCreate(Vec like, Border *b)
{
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < 2; ++j) {
    PetscCall(VecDuplicate(like, &b->col[j]));
    PetscCall(VecDuplicate(like, &b->row[j]));
  }
  for (PetscInt k = 0; k < 4; ++k) b->H[k] = 0.0;
  PetscFunctionReturn(0);
}

static PetscErrorCode BorderDestroy(Border *b)
{
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < 2; ++j) {
    PetscCall(VecDestroy(&b->col[j]));
    PetscCall(VecDestroy(&b->row[j]));
  }
  PetscFunctionReturn(0);
}

/* b += s (col, row^T, H): col = c, row = sign c (symmetric 1, skew -1) */
static PetscErrorCode BorderAdd(Border *b, PetscReal s, Vec c[2], PetscReal sign, const PetscReal H[4])
{
  PetscFunctionBeginUser;
  if (s == 0) PetscFunctionReturn(0);
  for (PetscInt j = 0; j < 2; ++j) {
    PetscCall(VecAXPY(b->col[j], s, c[j]));
    PetscCall(VecAXPY(b->row[j], s * sign, c[j]));
  }
  for (PetscInt k = 0; k < 4; ++k) b->H[k] += s * H[k];
  PetscFunctionReturn(0);
}

/* The 2 x 2 (e2, J x) part of a 3 x 3 (e1, e2, J x) block */
static void Sub(const PetscReal A[9], PetscReal H[4])
{
  H[0] = A[4], H[1] = A[5], H[2] = A[7], H[3] = A[8];
}

/* B = [[A, col], [row^T, H]]: the hub's two unknowns appended on the last rank (the body's indices unchanged); the
   border's entries below 1e-13 of its largest left out (the columns are nonzero near Gamma_D only, the identities'
   differences leave round-off elsewhere). */
static PetscErrorCode Bordered(Mat A, const Border *b, Mat *B)
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)A);
  PetscMPIInt        rank, size;
  PetscInt           lo, hi, m, N, *nnz;
  PetscReal          big = 0, v;
  const PetscScalar *c[2], *r[2];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(MatGetOwnershipRange(A, &lo, &hi));
  PetscCall(MatGetSize(A, &N, NULL));
  m = hi - lo + (rank == size - 1 ? 2 : 0);
  PetscCall(PetscMalloc1(m, &nnz));
  for (PetscInt i = 0; i < m; ++i) {
    PetscInt ncols = 0;

    if (lo + i < hi) PetscCall(MatGetRow(A, lo + i, &ncols, NULL, NULL));
    nnz[i] = lo + i < hi ? PetscMin(ncols + 3, N + 2) : N + 2;
    if (lo + i < hi) PetscCall(MatRestoreRow(A, lo + i, &ncols, NULL, NULL));
  }
  PetscCall(MatCreateAIJ(comm, m, m, N + 2, N + 2, 0, nnz, 0, nnz, B));
  PetscCall(MatSetOption(*B, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(PetscFree(nnz));
  for (PetscInt j = 0; j < 2; ++j) {
    PetscCall(VecNorm(b->col[j], NORM_INFINITY, &v));
    big = PetscMax(big, v);
    PetscCall(VecNorm(b->row[j], NORM_INFINITY, &v));
    big = PetscMax(big, v);
  }
  for (PetscInt j = 0; j < 2; ++j) {
    PetscCall(VecGetArrayRead(b->col[j], &c[j]));
    PetscCall(VecGetArrayRead(b->row[j], &r[j]));
  }
  for (PetscInt i = lo; i < hi; ++i) {
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscInt           ncols;

    PetscCall(MatGetRow(A, i, &ncols, &cols, &vals));
    PetscCall(MatSetValues(*B, 1, &i, ncols, cols, vals, INSERT_VALUES));
    PetscCall(MatRestoreRow(A, i, &ncols, &cols, &vals));
    for (PetscInt j = 0; j < 2; ++j) {
      const PetscInt h = N + j;

      if (PetscAbsScalar(c[j][i - lo]) > 1e-13 * big) PetscCall(MatSetValue(*B, i, h, c[j][i - lo], INSERT_VALUES));
      if (PetscAbsScalar(r[j][i - lo]) > 1e-13 * big) PetscCall(MatSetValue(*B, h, i, r[j][i - lo], INSERT_VALUES));
    }
  }
  for (PetscInt j = 0; j < 2; ++j) {
    PetscCall(VecRestoreArrayRead(b->col[j], &c[j]));
    PetscCall(VecRestoreArrayRead(b->row[j], &r[j]));
  }
  if (rank == size - 1)
    for (PetscInt i = 0; i < 2; ++i)
      for (PetscInt j = 0; j < 2; ++j) PetscCall(MatSetValue(*B, N + i, N + j, b->H[2 * i + j], INSERT_VALUES));
  PetscCall(MatAssemblyBegin(*B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*B, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* Kd: with the Maxwell branches (NULL otherwise), their K_d bordered the same way (C_D, D_D of model/axle.c: the branch
   energy of the time step, 1/2 g_i (xi - z_i, q - zeta_i) . K_d,aug (xi - z_i, q - zeta_i)), for branches.c to augment
   the bordered operators with: each branch's field then carries its hub part zeta_i = (Y, phi) as the step's */
PetscErrorCode RollerAxleModeOperators(Roller ctx, Mat *M, Mat *C, Mat *K, Mat *Kd)
{
  const RollerHubCoupling *hc  = &ctx->axle.hub->c;
  const PetscReal          rho = ctx->material.density, w = ctx->rotation.omega, tau = ctx->material.viscosity, eta = ctx->disc.damping;
  Vec                      r[2], cm[2], ck[2], c[2];
  PetscReal                H[4], DMh[4], DKh[4];
  Border                   bm, bc, bk;
  Mat                      B;

  PetscFunctionBeginUser;
  PetscCall(RollerAxleRigidFields(ctx, r));
  PetscCall(VecDuplicate(r[0], &c[0]));
  PetscCall(VecDuplicate(r[0], &c[1]));
  cm[0] = hc->CM[1], cm[1] = hc->CM[2];
  ck[0] = hc->CK[1], ck[1] = hc->CK[2];
  Sub(hc->DM, DMh);
  Sub(hc->DK, DKh);
  PetscCall(BorderCreate(r[0], &bm));
  PetscCall(BorderCreate(r[0], &bc));
  PetscCall(BorderCreate(r[0], &bk));
  /* mass */
  PetscCall(BorderAdd(&bm, rho, cm, 1.0, DMh));
  bm.H[0] += ctx->axle.mass;
  bm.H[3] += ctx->axle.inertia;
  /* damping: Kelvin-Voigt, mass damping, the drive's damper */
  PetscCall(BorderAdd(&bc, tau, ck, 1.0, DKh));
  PetscCall(BorderAdd(&bc, eta, cm, 1.0, DMh));
  bc.H[3] += ctx->axle.drive_damping;
  /* stiffness: the elastic border, the springs */
  PetscCall(BorderAdd(&bk, 1.0, ck, 1.0, DKh));
  bk.H[0] += ctx->axle.stiffness;
  bk.H[3] += ctx->axle.drive_stiffness;
  if (ctx->eig.frame == ROLLER_FRAME_LAB && w != 0) {
    Mat D, P;

    /* the convective D (skew): C_D e2 = -D e2_f, C_D Jx = -L_c - D Jx_f; its hub block's (e2, Jx) entry
       e2^T D Jx - e2_f . (D Jx)_f + Jx_f . C_D e2 = -lc[1] + Jx_f . C_D e2 (lc: model/axle.c) */
    PetscCall(RollerAssembleMatrix(ctx, "D", NULL, g1_convective, NULL, &D));
    PetscCall(MatMult(D, r[0], c[0]));
    PetscCall(VecScale(c[0], -1.0));
    PetscCall(MatMult(D, r[1], c[1]));
    PetscCall(VecAXPBY(c[1], -1.0, -1.0, ctx->ops.L_centrifugal));
    H[0] = H[3] = 0.0;
    H[1]        = -hc->lc[1] + Dot(r[1], c[0]);
    H[2]        = -H[1];
    PetscCall(BorderAdd(&bc, 2.0 * w * rho, c, -1.0, H));
    /* the centrifugal P (symmetric): C_P e2 = -P e2_f, C_P Jx = L_Jx - P Jx_f, L_Jx = -L_euler; the hub block
       r^T P r' - r_f . (P r')_f - r'_f . C_P r, r^T P r' nonzero for Jx, Jx only: (x, x) = the polar moment */
    PetscCall(RollerAssembleMatrix(ctx, "P", NULL, NULL, g3_convective, &P));
    PetscCall(MatMult(P, r[0], c[0]));
    PetscCall(VecScale(c[0], -1.0));
    PetscCall(MatMult(P, r[1], c[1]));
    PetscCall(VecAXPBY(c[1], -1.0, -1.0, ctx->ops.L_euler)); /* -L_euler - P Jx_f */
    H[0] = -Dot(r[0], c[0]);
    H[1] = Dot(r[0], ctx->ops.L_euler) - Dot(r[1], c[0]);
    H[2] = H[1];
    H[3] = hc->inertia + Dot(r[1], ctx->ops.L_euler) - Dot(r[1], c[1]);
    PetscCall(BorderAdd(&bk, -w * w * rho, c, 1.0, H));
    PetscCall(MatDestroy(&D));
    PetscCall(MatDestroy(&P));
    if (tau != 0) { /* the damped lab frame's theta' tau A_L (its skew part, operators.c) */
      Mat       A;
      PetscReal broken, defect;

      PetscCall(RollerAssembleRotationalElastic(ctx, &A, &broken));
      PetscCall(RollerSkewPart(A, &defect));
      for (PetscInt j = 0; j < 2; ++j) {
        PetscCall(MatMult(A, r[j], c[j]));
        PetscCall(VecScale(c[j], -1.0));
      }
      H[0] = H[1] = H[2] = H[3] = 0.0;
      PetscCall(BorderAdd(&bk, w * tau, c, -1.0, H));
      PetscCall(MatDestroy(&A));
    }
  }
  PetscCall(Bordered(*M, &bm, &B));
  PetscCall(MatDestroy(M));
  *M = B;
  PetscCall(Bordered(*C, &bc, &B));
  PetscCall(MatDestroy(C));
  *C = B;
  PetscCall(Bordered(*K, &bk, &B));
  PetscCall(MatDestroy(K));
  *K = B;
  if (Kd) {
    Border    bb;
    PetscReal DDh[4];
    Vec       cd[2];

    PetscCheck(hc->CD[1], ctx->comm, PETSC_ERR_PLIB, "-axle: the branches' border C_D was not made (no K_d)");
    cd[0] = hc->CD[1], cd[1] = hc->CD[2];
    Sub(hc->DD, DDh);
    PetscCall(BorderCreate(r[0], &bb));
    PetscCall(BorderAdd(&bb, 1.0, cd, 1.0, DDh));
    PetscCall(Bordered(ctx->ops.Kd, &bb, Kd));
    PetscCall(BorderDestroy(&bb));
  }
  PetscCall(BorderDestroy(&bm));
  PetscCall(BorderDestroy(&bc));
  PetscCall(BorderDestroy(&bk));
  for (PetscInt j = 0; j < 2; ++j) {
    PetscCall(VecDestroy(&r[j]));
    PetscCall(VecDestroy(&c[j]));
  }
  if (!ctx->ts.quiet)
    PetscCall(PetscPrintf(ctx->comm, "roller: -modes -axle: the hub's (Y, phi) appended (mass %g, inertia %g, axle spring %g, drive %g, damper %g): free torsion sqrt(k_d/(I + I_rubber)) = %g, bounce sqrt(k/(m + m_rubber)) = %g\n", (double)ctx->axle.mass,
                          (double)ctx->axle.inertia, (double)ctx->axle.stiffness, (double)ctx->axle.drive_stiffness, (double)ctx->axle.drive_damping, (double)PetscSqrtReal(ctx->axle.drive_stiffness / (ctx->axle.inertia + rho * hc->inertia)),
                          (double)PetscSqrtReal(ctx->axle.stiffness / (ctx->axle.mass + rho * hc->mass))));
  PetscFunctionReturn(0);
}
