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
   RollerSkewPart then keeps (A - A^T)/2 of each and reports the defect ||A + A^T||_F / ||A||_F. The pointwise pieces
   the cells and the edges share (the map, the basis derivatives, the stress product) are rotational_element.c's. */
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
