/* The pointwise pieces of the rotational elastic form A_L (docs/squeal.md section 1.1) that its cell terms
   (rotational.c) and its edge terms (rotational_edges.c) share: the isoparametric map of a cell, the physical
   derivatives of the basis functions, the stress product and the coordinate element of a cell. */
#include "modes/rotational_impl.h"
#include "model/kernels.h"

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
