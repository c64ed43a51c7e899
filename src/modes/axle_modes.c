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
   ramp), the drive's k_d and c_d against the steadily turning motor.

   The steady state: the hub's height Y0 is the one at which the steady contact force is -nip_force (a secant on the
   depth of the clamped-hub steady state, steady.c: a rigid translation of the whole body leaves its strain alone), and
   the hub's mean rotation is the friction torque over k_d (a rigid rotation of the round annulus changes no contact
   force). */
#include "modes/modes.h"
#include "model/axle.h"
#include "model/kernels.h"

/* e2 and J x on the free nodes */
static PetscErrorCode RigidFields(Roller ctx, Vec r[2])
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

/* bd: with the Maxwell branches (NULL otherwise), their K_d bordered the same way (C_D, D_D of model/axle.c: the
   branch energy of the time step, 1/2 g_i (xi - z_i, q - zeta_i) . K_d,aug (xi - z_i, q - zeta_i)), for branches.c to augment the bordered operators with: each branch's field then carries
   its hub part zeta_i = (Y, phi) as the step's */
PetscErrorCode RollerAxleModeOperators(Roller ctx, Mat *M, Mat *C, Mat *K, RollerBranchBorder *bd)
{
  const RollerHubCoupling *hc  = &ctx->axle.hub->c;
  const PetscReal          rho = ctx->material.density, w = ctx->rotation.omega, tau = ctx->material.viscosity, eta = ctx->disc.damping;
  Vec                      r[2], cm[2], ck[2], c[2];
  PetscReal                H[4], DMh[4], DKh[4];
  Border                   bm, bc, bk;
  Mat                      B;

  PetscFunctionBeginUser;
  PetscCall(RigidFields(ctx, r));
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
  if (bd) {
    Border    bb;
    PetscReal DDh[4];
    Vec       cd[2];

    PetscCheck(hc->CD[1], ctx->comm, PETSC_ERR_PLIB, "-axle: the branches' border C_D was not made (no K_d)");
    cd[0] = hc->CD[1], cd[1] = hc->CD[2];
    Sub(hc->DD, DDh);
    PetscCall(BorderCreate(r[0], &bb));
    PetscCall(BorderAdd(&bb, 1.0, cd, 1.0, DDh));
    PetscCall(Bordered(ctx->ops.Kd, &bb, &bd->Kd));
    PetscCall(BorderDestroy(&bb));
    bd->W = *M; /* the bordered mass (a reference the caller's M holds) */
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

/* u += q_0 r_0 + q_1 r_1 on the body's part of u (all of it, or the leading local entries of the Maxwell branches'
   augmented layout: the branches' fields are not read from the steady state) */
static PetscErrorCode AddToBody(Vec u, const PetscReal q[2], Vec r[2])
{
  const PetscScalar *a, *b;
  PetscScalar       *pu;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(r[0], &n));
  PetscCall(VecGetArray(u, &pu));
  PetscCall(VecGetArrayRead(r[0], &a));
  PetscCall(VecGetArrayRead(r[1], &b));
  for (PetscInt i = 0; i < n; ++i) pu[i] += q[0] * a[i] + q[1] * b[i];
  PetscCall(VecRestoreArrayRead(r[1], &b));
  PetscCall(VecRestoreArrayRead(r[0], &a));
  PetscCall(VecRestoreArray(u, &pu));
  PetscFunctionReturn(0);
}

/* The total normal force of a steady state */
static PetscReal NormalForce(const RollerSteady *st)
{
  PetscReal N = 0;

  for (PetscInt j = 0; j < st->n; ++j) N += st->normal[j];
  return N;
}

/* The clamped-hub steady state at depth d (the sheet at d - r_outer) */
static PetscErrorCode SteadyAt(Roller ctx, KSP ksp, PetscReal d, RollerSteady *st, PetscReal *N)
{
  PetscFunctionBeginUser;
  ctx->obstacle.depth = d;
  PetscCall(RollerSteadySolveWith(ctx, ksp, st));
  *N = NormalForce(st);
  PetscFunctionReturn(0);
}

PetscErrorCode RollerAxleSteadySolve(Roller ctx, Mat Klab, RollerSteady *st, PetscReal q[2])
{
  const PetscReal F = ctx->axle.nip_force, depth = ctx->obstacle.depth;
  PetscReal       d0, d1, N0, N1, torque = 0;
  PetscInt        it;
  Vec             r[2];
  KSP             ksp; /* K_lab factored once for every depth */

  PetscFunctionBeginUser;
  PetscCheck(F > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-modes -axle -obstacle: the steady state is pressed by the spring's preload: -nip_force must be > 0, got %g", (double)F);
  /* a secant on the depth d: N(d) rises monotonically; the first two guesses -obstacle_depth and its scaling by F/N */
  d0 = depth > 0 ? depth : 1e-3 * ctx->mesh.r_outer;
  PetscCall(RollerSteadyKSPCreate(ctx, Klab, &ksp));
  PetscCall(SteadyAt(ctx, ksp, d0, st, &N0));
  PetscCheck(N0 > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "-modes -axle: no contact at the first depth %g", (double)d0);
  d1 = d0 * F / N0;
  for (it = 0; it < 40; ++it) {
    PetscReal d2;

    PetscCall(RollerSteadyDestroy(st, PETSC_TRUE));
    PetscCall(SteadyAt(ctx, ksp, d1, st, &N1));
    if (PetscAbsReal(N1 - F) <= 1e-10 * F) break;
    d2 = N1 != N0 ? d1 - (N1 - F) * (d1 - d0) / (N1 - N0) : d1 * F / PetscMax(N1, 1e-300);
    if (d2 <= 0) d2 = 0.5 * d1; /* stay in contact */
    d0 = d1, N0 = N1, d1 = d2;
  }
  PetscCheck(it < 40, ctx->comm, PETSC_ERR_NOT_CONVERGED, "-modes -axle: the hub's height for -nip_force %g did not settle in 40 steady solves (force %g at depth %g)", (double)F, (double)N1, (double)d1);
  ctx->obstacle.depth = depth;
  PetscCall(KSPDestroy(&ksp));
  for (PetscInt j = 0; j < st->n; ++j) torque += st->xy[2 * j] * st->normal[j] - st->xy[2 * j + 1] * st->tangent[j];
  q[0] = -d1;                                /* the hub lowered onto the sheet at -r_outer */
  q[1] = torque / ctx->axle.drive_stiffness; /* the drive's spring holds the friction torque */
  PetscCall(RigidFields(ctx, r));
  PetscCall(AddToBody(st->u, q, r));
  PetscCall(VecDestroy(&r[0]));
  PetscCall(VecDestroy(&r[1]));
  if (!ctx->ts.quiet)
    PetscCall(PetscPrintf(ctx->comm, "roller: -modes -axle: the hub at Y = %.10g (the clamped hub's depth; %" PetscInt_FMT " steady solves) gives the contact force %.10g against -nip_force %g; the drive's mean twist %.6g (friction torque %.6g)\n", (double)q[0], it + 2, (double)NormalForce(st), (double)F, (double)q[1], (double)torque));
  PetscFunctionReturn(0);
}

/* An augmented vector (the body's local rows, then on the last rank Y, phi) into the body's vector and q (on every
   rank) */
PetscErrorCode RollerAxleModeSplit(Vec z, Vec x, PetscReal q[2])
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)z);
  PetscMPIInt        rank, size;
  const PetscScalar *a;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(RollerBranchRestrict(z, x)); /* the body's part: the leading local entries */
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(z, &a));
  if (rank == size - 1) q[0] = PetscRealPart(a[n]), q[1] = PetscRealPart(a[n + 1]);
  PetscCall(VecRestoreArrayRead(z, &a));
  PetscCallMPI(MPI_Bcast(q, 2, MPIU_REAL, size - 1, comm));
  PetscFunctionReturn(0);
}

/* rel = x - Y e2 - phi J x on the free nodes: the body's shape relative to the hub, whose strain is the whole body's
   (K and K_d annihilate the rigid fields; Gamma_D's nodes carry no relative motion), for the clamped body's quadratic
   forms (the rubber's loss factor of a mode, branches.c) */
PetscErrorCode RollerAxleModeRelative(Roller ctx, Vec x, const PetscReal q[2], Vec rel)
{
  const PetscReal mq[2] = {-q[0], -q[1]};
  Vec             r[2];

  PetscFunctionBeginUser;
  PetscCall(RigidFields(ctx, r));
  PetscCall(VecCopy(x, rel));
  PetscCall(AddToBody(rel, mq, r));
  PetscCall(VecDestroy(&r[0]));
  PetscCall(VecDestroy(&r[1]));
  PetscFunctionReturn(0);
}

/* An augmented vector with the body's layout and the hub's two entries on the last rank */
PetscErrorCode RollerAxleModeVec(Vec x, Vec *z)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)x);
  PetscMPIInt rank, size;
  PetscInt    n;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecCreateMPI(comm, n + (rank == size - 1 ? 2 : 0), PETSC_DETERMINE, z));
  PetscFunctionReturn(0);
}
