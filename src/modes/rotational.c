/* The rotational rate operators of the damped lab frame (docs/squeal.md section 1.1). The damping acts on the
   objective rate, the rate seen in the co-rotating frame, u_t + theta' L u in lab components, with
     L u = d_phi u - J u,   d_phi = x1 d/dx2 - x2 d/dx1 on each component,  J(a, b) = (-b, a) (rotation by +pi/2),
   the generator of the rotation of a displacement field (L of a rigid rotation J x is 0). Its two forms:
     A_L = a(L u, v)  the elastic form of the rotated field. grad(L u) holds second derivatives of the trial functions,
                      so it is assembled here cell by cell (a PetscDS pointwise Jacobian sees only first derivatives),
                      with the physical Hessian of the isoparametric (curved P2) map. a(L u, v) = -a(u, L v) in the
                      continuum, but the broken (cellwise) form is far from skew: A + A^T is a sum of edge integrals
                      of (e . n) times gradient jumps, of the size of A itself (defect ~1.4 in the Frobenius norm,
                      whatever h), and its skew part alone is inconsistent (its eigenvalues drift away as h -> 0).
                      EdgeTerms subtracts the part of those edge integrals that vanishes on smooth fields: the
                      result is skew up to the curved cells' quadrature and consistent to second order;
     B_L = (L u, v)   the mass form, D + G (D = (d_phi u, v), G = (R(-pi/2) u, v) = (-J u, v)), from kernels.h.
   RollerSkewPart then keeps (A - A^T)/2 of each and reports the defect ||A + A^T||_F / ||A||_F. */
#include "modes/rotational_impl.h"
#include "model/kernels.h"

/* grad(L phi)[k][d] at x, from phi's gradient g[k][d] and Hessian h[k][m][d] (physical, component k). */
static void RotatedGradient(const PetscReal x[], const PetscReal g[], const PetscReal h[], PetscReal gl[])
{
  const PetscReal e[2] = {-x[1], x[0]}; /* d_phi = e . grad; d e_m / d x_d: d e_0/d x_1 = -1, d e_1/d x_0 = 1 */

  for (PetscInt k = 0; k < 2; ++k) {
    for (PetscInt d = 0; d < 2; ++d) gl[k * 2 + d] = e[0] * h[(k * 2 + 0) * 2 + d] + e[1] * h[(k * 2 + 1) * 2 + d];
    gl[k * 2 + 0] += g[k * 2 + 1]; /* grad(e . grad phi_k) = e . Hess phi_k + (grad phi_k) (grad e) */
    gl[k * 2 + 1] += -g[k * 2 + 0];
  }
  for (PetscInt d = 0; d < 2; ++d) { /* - J grad phi: row 0 += grad phi_1, row 1 -= grad phi_0 */
    const PetscReal g0 = g[0 * 2 + d], g1 = g[1 * 2 + d];

    gl[0 * 2 + d] += g1;
    gl[1 * 2 + d] -= g0;
  }
}

/* The isoparametric map at tabulation point q of the coordinate element Tx (2 components, the cell's coordinate
   closure coords): x, J[c][a] = d x_c / d xi_a, its inverse Ji[a][c], det J and, if Tx holds second derivatives,
   X2[c][a][b] = d^2 x_c / d xi_a d xi_b (0 on straight cells). */
void RollerRotGeometry(PetscTabulation Tx, PetscInt q, const PetscScalar coords[], PetscReal x[], PetscReal J[], PetscReal Ji[], PetscReal X2[], PetscReal *det)
{
  const PetscInt Nb = Tx->Nb;

  for (PetscInt t = 0; t < 2; ++t) x[t] = 0;
  for (PetscInt t = 0; t < 4; ++t) J[t] = 0;
  for (PetscInt t = 0; t < 8; ++t) X2[t] = 0;
  for (PetscInt b = 0; b < Nb; ++b) {
    const PetscReal X = PetscRealPart(coords[b]);

    for (PetscInt c = 0; c < 2; ++c) {
      x[c] += X * Tx->T[0][(q * Nb + b) * 2 + c];
      for (PetscInt a = 0; a < 2; ++a) {
        J[c * 2 + a] += X * Tx->T[1][((q * Nb + b) * 2 + c) * 2 + a];
        if (Tx->K > 1)
          for (PetscInt bb = 0; bb < 2; ++bb) X2[(c * 2 + a) * 2 + bb] += X * Tx->T[2][(((q * Nb + b) * 2 + c) * 2 + a) * 2 + bb];
      }
    }
  }
  *det  = J[0] * J[3] - J[1] * J[2];
  Ji[0] = J[3] / *det;
  Ji[1] = -J[1] / *det;
  Ji[2] = -J[2] / *det;
  Ji[3] = J[0] / *det;
}

/* The physical gradients g[f][k][c] (and, with h, Hessians h[f][k][c][d]) of the Nb vector basis functions of T
   at point q: grad = J^-T grad_xi; d2 phi/dxi_a dxi_b = (J^T Hess J)_ab + sum_e X2[e][a][b] d phi/dx_e. */
void RollerRotDerivatives(PetscTabulation T, PetscInt q, const PetscReal Ji[], const PetscReal X2[], PetscReal g[], PetscReal h[])
{
  const PetscInt Nb = T->Nb, Nc = T->Nc;

  for (PetscInt f = 0; f < Nb; ++f) {
    for (PetscInt k = 0; k < Nc; ++k) {
      const PetscReal *dk = &T->T[1][((q * Nb + f) * Nc + k) * 2];
      PetscReal       *gk = &g[(f * Nc + k) * 2], r[4];

      for (PetscInt c = 0; c < 2; ++c) gk[c] = dk[0] * Ji[0 * 2 + c] + dk[1] * Ji[1 * 2 + c];
      if (!h) continue;
      for (PetscInt a = 0; a < 4; ++a) r[a] = T->T[2][((q * Nb + f) * Nc + k) * 4 + a] - X2[0 * 4 + a] * gk[0] - X2[1 * 4 + a] * gk[1];
      for (PetscInt c = 0; c < 2; ++c)
        for (PetscInt d = 0; d < 2; ++d) {
          PetscReal s = 0;

          for (PetscInt a = 0; a < 2; ++a)
            for (PetscInt b = 0; b < 2; ++b) s += Ji[a * 2 + c] * r[a * 2 + b] * Ji[b * 2 + d];
          h[((f * Nc + k) * 2 + c) * 2 + d] = s;
        }
    }
  }
}

/* sigma[G] : H for two 2x2 gradients */
PetscReal RollerRotStressProduct(Roller ctx, const PetscReal G[], const PetscReal H[])
{
  PetscScalar gs[4], sigma[4];

  for (PetscInt t = 0; t < 4; ++t) gs[t] = G[t];
  RollerStress(ctx->material.lambda, ctx->material.mu, gs, sigma);
  return PetscRealPart(sigma[0] * H[0] + sigma[1] * H[1] + sigma[2] * H[2] + sigma[3] * H[3]);
}

/* The coordinate element of a cell from its number of coordinates: P1 (straight) or P2 (mesh/geometry.c). */
PetscErrorCode RollerRotCoordinateElement(PetscInt Ncx, PetscFE cfe[2], PetscFE *fe)
{
  PetscFunctionBeginUser;
  PetscCheck(Ncx == 6 || Ncx == 12, PETSC_COMM_SELF, PETSC_ERR_SUP, "A cell with %" PetscInt_FMT " coordinates: expected a P1 or P2 triangle", Ncx);
  *fe = cfe[Ncx == 6 ? 0 : 1];
  PetscFunctionReturn(0);
}

/* The cell integrals sum_K int_K sigma[grad L u] : grad v, cell by cell. */
static PetscErrorCode CellTerms(Roller ctx, DM dm, PetscFE fe, PetscFE cfe[2], Mat A)
{
  PetscQuadrature  quad;
  PetscTabulation  T, Tc[2] = {NULL, NULL};
  const PetscReal *qp, *qw;
  PetscInt         Nq, Nb, cStart, cEnd;
  PetscReal       *g, *h, *gl;
  PetscScalar     *mat;

  PetscFunctionBeginUser;
  PetscCall(PetscFEGetQuadrature(fe, &quad));
  PetscCall(PetscQuadratureGetData(quad, NULL, NULL, &Nq, &qp, &qw));
  PetscCall(PetscFECreateTabulation(fe, 1, Nq, qp, 2, &T));
  Nb = T->Nb;
  for (PetscInt p = 0; p < 2; ++p) PetscCall(PetscFECreateTabulation(cfe[p], 1, Nq, qp, 2, &Tc[p]));
  PetscCall(PetscMalloc4(Nb * 4, &g, Nb * 8, &h, Nb * 4, &gl, Nb * Nb, &mat));
  PetscCall(DMPlexGetSimplexOrBoxCells(dm, 0, &cStart, &cEnd));
  for (PetscInt cell = cStart; cell < cEnd; ++cell) {
    const PetscScalar *array;
    PetscScalar       *coords;
    PetscBool          isDG;
    PetscInt           Ncx;
    PetscFE            cf = NULL;

    PetscCall(DMPlexGetCellCoordinates(dm, cell, &isDG, &Ncx, &array, &coords));
    PetscCall(RollerRotCoordinateElement(Ncx, cfe, &cf));
    PetscCall(PetscArrayzero(mat, Nb * Nb));
    for (PetscInt q = 0; q < Nq; ++q) {
      PetscReal x[2], J[4], Ji[4], X2[8], det, wq;

      RollerRotGeometry(Tc[cf == cfe[0] ? 0 : 1], q, coords, x, J, Ji, X2, &det);
      wq = qw[q] * PetscAbsReal(det);
      RollerRotDerivatives(T, q, Ji, X2, g, h);
      for (PetscInt f = 0; f < Nb; ++f) RotatedGradient(x, &g[f * 4], &h[f * 8], &gl[f * 4]);
      for (PetscInt i = 0; i < Nb; ++i) /* test i, trial j */
        for (PetscInt j = 0; j < Nb; ++j) mat[i * Nb + j] += wq * RollerRotStressProduct(ctx, &gl[j * 4], &g[i * 4]);
    }
    PetscCall(DMPlexRestoreCellCoordinates(dm, cell, &isDG, &Ncx, &array, &coords));
    PetscCall(DMPlexMatSetClosure(dm, NULL, NULL, A, cell, mat, ADD_VALUES));
  }
  PetscCall(PetscFree4(g, h, gl, mat));
  PetscCall(PetscTabulationDestroy(&T));
  for (PetscInt p = 0; p < 2; ++p) PetscCall(PetscTabulationDestroy(&Tc[p]));
  PetscFunctionReturn(0);
}

/* A_L = the cell terms - the edge terms S + B/2, on the free dofs; broken: the skewness defect of the cell terms
   alone, ||A + A^T||_F / ||A||_F. */
static PetscErrorCode AssembleElastic(Roller ctx, Mat *A, PetscReal *broken)
{
  DM      dm;
  PetscFE fe, cfe[2] = {NULL, NULL};

  PetscFunctionBeginUser;
  PetscCall(RollerOperatorDMCreate(ctx, NULL, &dm));
  PetscCall(DMCreateMatrix(dm, A));
  PetscCall(DMGetField(dm, 0, NULL, (PetscObject *)&fe));
  for (PetscInt p = 0; p < 2; ++p) PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 2, 2, PETSC_TRUE, p + 1, PETSC_DETERMINE, &cfe[p]));
  PetscCall(CellTerms(ctx, dm, fe, cfe, *A));
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  {
    Mat       At;
    PetscReal na, ns;

    PetscCall(MatNorm(*A, NORM_FROBENIUS, &na));
    PetscCall(MatTranspose(*A, MAT_INITIAL_MATRIX, &At));
    PetscCall(MatAXPY(At, 1.0, *A, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatNorm(At, NORM_FROBENIUS, &ns));
    *broken = na > 0 ? ns / na : 0.0;
    PetscCall(MatDestroy(&At));
  }
  { /* the edge terms couple the cells' neighbours: a pattern of their own */
    Mat      pre, S;
    PetscInt m, n;

    PetscCall(MatGetLocalSize(*A, &m, &n));
    PetscCall(MatCreate(ctx->comm, &pre));
    PetscCall(MatSetSizes(pre, m, n, PETSC_DETERMINE, PETSC_DETERMINE));
    PetscCall(MatSetType(pre, MATPREALLOCATOR));
    PetscCall(MatSetUp(pre));
    PetscCall(RollerRotEdgeTerms(ctx, dm, fe, cfe, pre));
    PetscCall(MatAssemblyBegin(pre, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(pre, MAT_FINAL_ASSEMBLY));
    PetscCall(MatCreate(ctx->comm, &S));
    PetscCall(MatSetSizes(S, m, n, PETSC_DETERMINE, PETSC_DETERMINE));
    PetscCall(MatSetType(S, MATAIJ));
    PetscCall(MatPreallocatorPreallocate(pre, PETSC_TRUE, S));
    PetscCall(MatDestroy(&pre));
    PetscCall(RollerRotEdgeTerms(ctx, dm, fe, cfe, S));
    PetscCall(MatAssemblyBegin(S, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(S, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAXPY(*A, -1.0, S, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatDestroy(&S));
  }
  PetscCall(PetscObjectSetName((PetscObject)*A, "A_L"));
  for (PetscInt p = 0; p < 2; ++p) PetscCall(PetscFEDestroy(&cfe[p]));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerAssembleRotationalElastic(Roller ctx, Mat *A, PetscReal *broken)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleElastic(ctx, A, broken));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerAssembleRotationalMass(Roller ctx, Mat *B)
{
  Mat G;

  PetscFunctionBeginUser;
  PetscCall(RollerAssembleMatrix(ctx, "B_L", NULL, g1_convective, NULL, B));
  PetscCall(RollerAssembleMatrix(ctx, "G", g0_gyro, NULL, NULL, &G));
  PetscCall(MatAXPY(*B, 1.0, G, DIFFERENT_NONZERO_PATTERN));
  PetscCall(MatDestroy(&G));
  PetscFunctionReturn(0);
}

/* A <- (A - A^T)/2; defect = ||A + A^T||_F / ||A||_F of the A given. */
PetscErrorCode RollerSkewPart(Mat A, PetscReal *defect)
{
  Mat       At;
  PetscReal na, ns;

  PetscFunctionBeginUser;
  PetscCall(MatNorm(A, NORM_FROBENIUS, &na));
  PetscCall(MatTranspose(A, MAT_INITIAL_MATRIX, &At));
  PetscCall(MatAXPY(At, 1.0, A, DIFFERENT_NONZERO_PATTERN)); /* A + A^T */
  PetscCall(MatNorm(At, NORM_FROBENIUS, &ns));
  *defect = na > 0 ? ns / na : 0.0;
  PetscCall(MatAXPY(A, -0.5, At, DIFFERENT_NONZERO_PATTERN)); /* A - (A + A^T)/2 */
  PetscCall(MatDestroy(&At));
  PetscFunctionReturn(0);
}
