/* The circumferential order and the travelling direction of a mode shape z = x_re + i x_im (motion
   Re(z e^{i w t}), w >= 0). The polar components (z_r, z_phi) at every node, weighted by the node's mass m_j
   (the row sums of M), give the Fourier coefficients c_m = sum_j m_j z_j e^{-i m phi_j}, m = -N..N; the power
   P_m = |c_m(z_r)|^2 + |c_m(z_phi)|^2. The order is n = argmax (P_n + P_-n). A term e^{i(m phi + w t)} travels
   toward -sign(m) phi: with P_-n dominant the wave travels toward +phi, the direction of rotation for theta' > 0
   ("forward"), with P_n dominant against it ("backward"); balanced (within a factor 3), or n = 0, or theta' = 0
   (each order's pair degenerate): "standing". */
#include "modes/modes.h"

const char *const RollerWaves[] = {"forward", "backward", "standing", "RollerWave", "ROLLER_WAVE_", NULL};

#define MAX_ORDER 48

struct _n_RollerModeClassifier {
  MPI_Comm   comm;
  PetscInt   n;                 /* local nodes */
  PetscReal  omega;             /* theta': the sense of "forward" */
  PetscReal *phi, *weight, *cs; /* angle, mass, (cos, sin) of the angle at every local node */
};

PetscErrorCode RollerModeClassifierCreate(Roller ctx, RollerModeClassifier *p)
{
  RollerModeClassifier c;
  Vec                  ones, mass;
  const PetscScalar   *x, *m;
  PetscInt             n;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&c));
  c->comm  = ctx->comm;
  c->omega = ctx->rotation.omega;
  PetscCall(VecDuplicate(ctx->ops.coordinates, &ones));
  PetscCall(VecDuplicate(ctx->ops.coordinates, &mass));
  PetscCall(VecSet(ones, 1.0));
  PetscCall(MatMult(ctx->ops.M_full ? ctx->ops.M_full : ctx->ops.M, ones, mass)); /* -rom: the full model's */
  PetscCall(VecGetLocalSize(mass, &n));
  c->n = n / 2;
  PetscCall(PetscMalloc3(c->n, &c->phi, c->n, &c->weight, 2 * c->n, &c->cs));
  PetscCall(VecGetArrayRead(ctx->ops.coordinates, &x));
  PetscCall(VecGetArrayRead(mass, &m));
  for (PetscInt j = 0; j < c->n; ++j) {
    const PetscReal r = PetscSqrtReal(PetscSqr(PetscRealPart(x[2 * j])) + PetscSqr(PetscRealPart(x[2 * j + 1])));

    c->phi[j]        = PetscAtan2Real(PetscRealPart(x[2 * j + 1]), PetscRealPart(x[2 * j]));
    c->weight[j]     = PetscRealPart(m[2 * j]);
    c->cs[2 * j]     = PetscRealPart(x[2 * j]) / r;
    c->cs[2 * j + 1] = PetscRealPart(x[2 * j + 1]) / r;
  }
  PetscCall(VecRestoreArrayRead(ctx->ops.coordinates, &x));
  PetscCall(VecRestoreArrayRead(mass, &m));
  PetscCall(VecDestroy(&ones));
  PetscCall(VecDestroy(&mass));
  *p = c;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerModeClassify(RollerModeClassifier c, Vec xr, Vec xi, PetscInt *order, RollerWave *wave)
{
  /* coefficient m + MAX_ORDER of component k (r, phi), real and imaginary parts: [k][m][re/im] */
  PetscReal          sum[2][2 * MAX_ORDER + 1][2] = {{{0}}}, total[2][2 * MAX_ORDER + 1][2], power[2 * MAX_ORDER + 1], best = -1;
  const PetscScalar *a, *b;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(xr, &a));
  PetscCall(VecGetArrayRead(xi, &b));
  for (PetscInt j = 0; j < c->n; ++j) {
    const PetscReal co = c->cs[2 * j], si = c->cs[2 * j + 1];
    /* polar components of z = a + i b: z_r = e_r . z, z_phi = e_phi . z */
    const PetscReal zr[2] = {co * PetscRealPart(a[2 * j]) + si * PetscRealPart(a[2 * j + 1]), co * PetscRealPart(b[2 * j]) + si * PetscRealPart(b[2 * j + 1])};
    const PetscReal zp[2] = {-si * PetscRealPart(a[2 * j]) + co * PetscRealPart(a[2 * j + 1]), -si * PetscRealPart(b[2 * j]) + co * PetscRealPart(b[2 * j + 1])};

    for (PetscInt m = -MAX_ORDER; m <= MAX_ORDER; ++m) {
      const PetscReal cm = PetscCosReal(m * c->phi[j]), sm = -PetscSinReal(m * c->phi[j]); /* e^{-i m phi} */
      const PetscReal w = c->weight[j];

      sum[0][m + MAX_ORDER][0] += w * (zr[0] * cm - zr[1] * sm);
      sum[0][m + MAX_ORDER][1] += w * (zr[0] * sm + zr[1] * cm);
      sum[1][m + MAX_ORDER][0] += w * (zp[0] * cm - zp[1] * sm);
      sum[1][m + MAX_ORDER][1] += w * (zp[0] * sm + zp[1] * cm);
    }
  }
  PetscCall(VecRestoreArrayRead(xr, &a));
  PetscCall(VecRestoreArrayRead(xi, &b));
  PetscCall(MPIU_Allreduce(sum, total, 4 * (2 * MAX_ORDER + 1), MPIU_REAL, MPIU_SUM, c->comm));
  for (PetscInt m = 0; m <= 2 * MAX_ORDER; ++m) power[m] = PetscSqr(total[0][m][0]) + PetscSqr(total[0][m][1]) + PetscSqr(total[1][m][0]) + PetscSqr(total[1][m][1]);
  *order = 0;
  for (PetscInt n = 0; n <= MAX_ORDER; ++n) {
    const PetscReal p = power[MAX_ORDER + n] + (n ? power[MAX_ORDER - n] : 0);

    if (p > best) {
      best   = p;
      *order = n;
    }
  }
  *wave = ROLLER_WAVE_STANDING;
  if (*order > 0 && c->omega != 0) {
    const PetscReal plus = power[MAX_ORDER + *order], minus = power[MAX_ORDER - *order];

    if (minus > 3 * plus) *wave = c->omega > 0 ? ROLLER_WAVE_FORWARD : ROLLER_WAVE_BACKWARD;
    else if (plus > 3 * minus) *wave = c->omega > 0 ? ROLLER_WAVE_BACKWARD : ROLLER_WAVE_FORWARD;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerModeClassifierDestroy(RollerModeClassifier *p)
{
  PetscFunctionBeginUser;
  if (!*p) PetscFunctionReturn(0);
  PetscCall(PetscFree3((*p)->phi, (*p)->weight, (*p)->cs));
  PetscCall(PetscFree(*p));
  PetscFunctionReturn(0);
}
