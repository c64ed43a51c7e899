/* -rom_residual with the Maxwell rubber (docs/model.md section 11, "The viscoelastic residual"): the residual's modes
   above the cutoff are quasi-static but not elastic. The branches' deviatoric stiffness K_d is nearly K itself on the
   residual's fields (their volumetric energy is small for the nearly incompressible rubber): the storage stiffness
   K + c K_d gives the residual R(c) ~ R/(1 + kappa c) with one scalar kappa (measured on the printer: R(0.28) fits
   R/(1 + 0.968 c) to 2 % in Frobenius norm), so each branch acts on the residual as on a standard linear solid,

     f_C = a + kappa sum_i g_i (a - b_i),   tau_i b_i' = a - b_i,   r = R a,   w_i = R b_i,

   with a level's coefficients a, b_i (Gamma_C vectors) and its displacements r, w_i. The flow rule by the midpoint
   rule over the two steps from the level k-2 (the chain of the three-level schemes' force pairing, as the DMF's
   branches), rho_i = dt/tau_i:

     b_i^k (1 + rho_i) = (1 - rho_i) b_i^{k-2} + rho_i (a^k + a^{k-2}),
     a^k = (f^k + h^k)/C,  C = 1 + kappa sum_i g_i/(1 + rho_i),  h^k = kappa sum_i g_i ((1 - rho_i) b_i^{k-2} + rho_i a^{k-2})/(1 + rho_i),

   so a step's force sees the flexibility R/C (the condensed S + R/C) and the history displacement R h^k/C, which is
   kappa/C sum_i g_i ((1 - rho_i) w_i^{k-2} + rho_i r^{k-2})/(1 + rho_i): no product with R but R f^k's sparse one.
   Energy of a level e = 1/2 a . r + kappa/2 sum_i g_i (a - b_i) . (r - w_i) (E_r^k = (e^k + e^{k-1})/2); the balance
   E_r^k - E_r^{k-1} = 1/2 f^k . (r^k - r^{k-2}) - 1/4 (f^k - f^{k-2}) . (r^k - r^{k-2}) - D_b^k with the branches'
   D_b^k = kappa sum_i g_i rho_i (abar - bbar_i) . (rbar - wbar_i) >= 0 (bars: the mean of the levels k and k-2; added
   to viscous_dissipation) holds exactly. kappa = 0 (or -rom_residual_branches false) is the elastic residual. */
#include "contact_impl.h"

/* The branches (g_i, tau_i) seen by the residual, with kappa; dt the run's step. */
PetscErrorCode RollerContactSetResidualBranches(RollerContact c, PetscInt nb, const PetscReal g[], const PetscReal tau[], PetscReal kappa, PetscReal dt)
{
  RollerContactResidual *rs = &c->nodes.residual;
  PetscReal              C  = 1.0;

  PetscFunctionBeginUser;
  PetscCheck(rs->R && rs->nslot == 0, c->comm, PETSC_ERR_ORDER, "The residual's branches are set after R and before any level carries a residual");
  rs->nb    = nb;
  rs->kappa = kappa;
  for (PetscInt i = 0; i < nb; ++i) {
    rs->g[i]   = g[i];
    rs->rho[i] = dt / tau[i];
    C += kappa * g[i] / (1.0 + rs->rho[i]);
  }
  rs->cinv = 1.0 / C;
  PetscCall(PetscCalloc1(2 * c->nodes.nc, &rs->hist));
  PetscFunctionReturn(0);
}

PetscInt RollerContactResidualSize(RollerContact c)
{
  const PetscInt n = 2 * c->nodes.nc, nb = c->nodes.residual.nb;

  return nb ? (3 + 2 * nb) * n + 1 : 2 * n; /* with the branches the level's energy e last */
}

/* Before a step's solve: the slot s of the level two back (x_aux of the three-level schemes; NULL at rest) and the
   history displacement R h/C. */
PetscErrorCode RollerContactResidualBegin(RollerContact c, const PetscReal s[])
{
  RollerContactResidual *rs = &c->nodes.residual;
  const PetscInt         n  = 2 * c->nodes.nc;

  PetscFunctionBeginUser;
  if (!rs->R || !rs->nb) PetscFunctionReturn(0);
  rs->from = s;
  PetscCall(PetscArrayzero(rs->hist, n));
  for (PetscInt i = 0; s && i < rs->nb; ++i) {
    const PetscReal  rho = rs->rho[i], cw = rs->kappa * rs->cinv * rs->g[i] * (1.0 - rho) / (1.0 + rho), cr = rs->kappa * rs->cinv * rs->g[i] * rho / (1.0 + rho);
    const PetscReal *w = s + (3 + rs->nb + i) * n;

    for (PetscInt k = 0; k < n; ++k) rs->hist[k] += cw * w[k] + cr * s[k];
  }
  PetscFunctionReturn(0);
}

/* red += R h/C at the nodes a gather computes: the free solution's Gamma_C displacement. */
PetscErrorCode RollerContactResidualAddHistory(RollerContact c, Vec red)
{
  RollerContactResidual *rs = &c->nodes.residual;
  PetscScalar           *u;

  PetscFunctionBeginUser;
  if (!rs->R || !rs->nb) PetscFunctionReturn(0);
  PetscCall(VecGetArray(red, &u));
  for (PetscInt k = 0; k < c->nodes.nwin; ++k) {
    const PetscInt i = c->nodes.windowed ? c->nodes.win[k] : k;

    u[2 * i] += rs->hist[2 * i];
    u[2 * i + 1] += rs->hist[2 * i + 1];
  }
  PetscCall(VecRestoreArray(red, &u));
  PetscFunctionReturn(0);
}

/* A new level's a, b_i, w_i (its slot s holds r = R h/C + R f/C and f): from the level two back (rs->from; at rest
   without one). */
void RollerContactResidualBranchesUpdate(RollerContact c, PetscReal s[])
{
  const RollerContactResidual *rs = &c->nodes.residual;
  const PetscInt               n = 2 * c->nodes.nc, nb = rs->nb;
  const PetscReal             *from = rs->from;
  PetscReal                   *a    = s + 2 * n;

  if (!nb) return;
  for (PetscInt k = 0; k < n; ++k) a[k] = s[n + k];
  for (PetscInt i = 0; from && i < nb; ++i) {
    const PetscReal  rho = rs->rho[i], cb = rs->kappa * rs->g[i] * (1.0 - rho) / (1.0 + rho), ca = rs->kappa * rs->g[i] * rho / (1.0 + rho);
    const PetscReal *b0 = from + (3 + i) * n;

    for (PetscInt k = 0; k < n; ++k) a[k] += cb * b0[k] + ca * from[2 * n + k];
  }
  for (PetscInt k = 0; k < n; ++k) a[k] *= rs->cinv;
  for (PetscInt i = 0; i < nb; ++i) {
    const PetscReal rho = rs->rho[i], c0 = (1.0 - rho) / (1.0 + rho), c1 = rho / (1.0 + rho);
    PetscReal      *b = s + (3 + i) * n, *w = s + (3 + nb + i) * n;

    for (PetscInt k = 0; k < n; ++k) {
      b[k] = from ? c0 * from[(3 + i) * n + k] + c1 * (a[k] + from[2 * n + k]) : c1 * a[k];
      w[k] = from ? c0 * from[(3 + nb + i) * n + k] + c1 * (s[k] + from[k]) : c1 * s[k];
    }
  }
  RollerContactResidualLevelEnergy(c, s, &s[(3 + 2 * nb) * n]);
}

/* e = 1/2 a . r + kappa/2 sum_i g_i (a - b_i) . (r - w_i) of a level's slot (a = f_C for the elastic residual); with
   the branches the slot keeps it (RollerContactResidualBranchesUpdate). */
void RollerContactResidualLevelEnergy(RollerContact c, const PetscReal s[], PetscReal *e)
{
  const RollerContactResidual *rs = &c->nodes.residual;
  const PetscInt               n = 2 * c->nodes.nc, nb = rs->nb;
  const PetscReal             *a;
  PetscReal                    d = 0.0;

  *e = 0.0;
  if (!s) return;
  a = s + (nb ? 2 : 1) * n;
  for (PetscInt k = 0; k < n; ++k) d += a[k] * s[k];
  *e = 0.5 * d;
  for (PetscInt i = 0; i < nb; ++i) {
    const PetscReal *b = s + (3 + i) * n, *w = s + (3 + nb + i) * n;

    d = 0.0;
    for (PetscInt k = 0; k < n; ++k) d += (a[k] - b[k]) * (s[k] - w[k]);
    *e += 0.5 * rs->kappa * rs->g[i] * d;
  }
}

/* *d += D_b = kappa sum_i g_i rho_i (abar - bbar_i) . (rbar - wbar_i) of the levels' slots u (k) and v (k-2), either
   NULL at rest. */
void RollerContactResidualBranchDissipation(RollerContact c, const PetscReal u[], const PetscReal v[], PetscReal *d)
{
  const RollerContactResidual *rs = &c->nodes.residual;
  const PetscInt               n = 2 * c->nodes.nc, nb = rs->nb;

  for (PetscInt i = 0; i < nb; ++i) {
    PetscReal s = 0.0;

    for (PetscInt k = 0; k < n; ++k) {
      const PetscReal ab = 0.5 * ((u ? u[2 * n + k] - u[(3 + i) * n + k] : 0.0) + (v ? v[2 * n + k] - v[(3 + i) * n + k] : 0.0));
      const PetscReal rw = 0.5 * ((u ? u[k] - u[(3 + nb + i) * n + k] : 0.0) + (v ? v[k] - v[(3 + nb + i) * n + k] : 0.0));

      s += ab * rw;
    }
    *d += rs->kappa * rs->g[i] * rs->rho[i] * s;
  }
}
