/* Pointwise kernels for PetscFE (plane-strain linear elasticity, mass, loads), docs/model.md sections 1-3.
   Constants (PetscDSSetConstants), see RollerConstant. */
#ifndef ROLLER_KERNELS_H
#define ROLLER_KERNELS_H

#include <petscsys.h>

typedef enum {
  ROLLER_C_LAMBDA,
  ROLLER_C_MU,
  ROLLER_C_RHO,
  ROLLER_C_TIME,       /* time at which a load kernel is evaluated */
  ROLLER_C_THETA_DOT,  /* theta'(t)  */
  ROLLER_C_THETA_DDOT, /* theta''(t) */
  ROLLER_C_MMS,        /* RollerMMSType */
  ROLLER_C_R_INNER,
  ROLLER_C_R_OUTER,
  ROLLER_C_MASS_WEIGHT,      /* the Jacobian kernels assemble c_M M + c_K K: a DS keeps every kernel */
  ROLLER_C_STIFFNESS_WEIGHT, /* once set, so M and K are assembled with weights (1, 0) and (0, 1) */
  ROLLER_C_GYRO_WEIGHT,      /* and the gyroscopic (R(-pi/2) u, v), i.e. R(-pi/2) M, with c_G */
  ROLLER_C_MMS_AMPLITUDE,
  ROLLER_NUM_CONSTANTS
} RollerConstant;

#define ROLLER_KERNEL_ARGS \
  PetscInt dim, PetscInt Nf, PetscInt NfAux, const PetscInt uOff[], const PetscInt uOff_x[], const PetscScalar u[], const PetscScalar u_t[], const PetscScalar u_x[], const PetscInt aOff[], const PetscInt aOff_x[], const PetscScalar a[], const PetscScalar a_t[], const PetscScalar a_x[], PetscReal t

/* Plane-strain stress sigma = 2 mu eps + lambda tr(eps) I from the gradient u_x[c*dim+d] = d u_c / d x_d. */
/* The position x as a field (DMProjectFunction), padded with zeros beyond the dimension (the 3-component
   output vectors): the nodal coordinates of the step (discretization.c) and of the output (output.c). */
static inline PetscErrorCode RollerPosition(PetscInt dim, PetscReal time, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  for (PetscInt c = 0; c < Nc; ++c) u[c] = c < dim ? x[c] : 0.0;
  return 0;
}

static inline void RollerStress(PetscReal lambda, PetscReal mu, const PetscScalar u_x[], PetscScalar sigma[])
{
  const PetscScalar div = u_x[0] + u_x[3];

  sigma[0] = 2.0 * mu * u_x[0] + lambda * div;
  sigma[1] = mu * (u_x[1] + u_x[2]);
  sigma[2] = sigma[1];
  sigma[3] = 2.0 * mu * u_x[3] + lambda * div;
}

/* K: a(u, v) = int sigma[u] : eps[v] (docs/model.md section 2). */
static inline void g3_elastic(ROLLER_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g3[])
{
  const PetscReal w      = PetscRealPart(constants[ROLLER_C_STIFFNESS_WEIGHT]);
  const PetscReal lambda = w * PetscRealPart(constants[ROLLER_C_LAMBDA]), mu = w * PetscRealPart(constants[ROLLER_C_MU]);

  for (PetscInt c = 0; c < dim; ++c) {
    for (PetscInt d = 0; d < dim; ++d) {
      g3[((c * dim + c) * dim + d) * dim + d] += mu;
      g3[((c * dim + d) * dim + d) * dim + c] += mu;
      g3[((c * dim + d) * dim + c) * dim + d] += lambda;
    }
  }
}

/* M: the L2 inner product (no density; A carries rho); G: (R(-pi/2) u, v), skew, the Coriolis operator. */
static inline void g0_mass(ROLLER_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g0[])
{
  const PetscScalar cm = constants[ROLLER_C_MASS_WEIGHT], cg = constants[ROLLER_C_GYRO_WEIGHT];

  g0[0] = cm;
  g0[3] = cm;
  g0[1] = cg; /* R(-pi/2)(a, b) = (b, -a) */
  g0[2] = -cg;
}

/* Load of the rigid-body part of the centrifugal force: (x, v). */
static inline void f0_centrifugal(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  f0[0] = x[0];
  f0[1] = x[1];
}

/* Load of the rigid-body part of the Euler force: (R(-pi/2) x, v), R(-pi/2)(a, b) = (b, -a). */
static inline void f0_euler(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  f0[0] = x[1];
  f0[1] = -x[0];
}

/* |sigma| = sqrt(sum_ij sigma_ij^2) (docs/model.md section 4), projected to a scalar field. */
static inline void f_stress_norm(PetscInt dim, PetscInt Nf, PetscInt NfAux, const PetscInt uOff[], const PetscInt uOff_x[], const PetscScalar u[], const PetscScalar u_t[], const PetscScalar u_x[], const PetscInt aOff[], const PetscInt aOff_x[], const PetscScalar a[], const PetscScalar a_t[], const PetscScalar a_x[], PetscReal t, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[])
{
  PetscScalar sigma[4];

  RollerStress(PetscRealPart(constants[ROLLER_C_LAMBDA]), PetscRealPart(constants[ROLLER_C_MU]), u_x, sigma);
  f[0] = PetscSqrtReal(PetscRealPart(sigma[0] * sigma[0] + sigma[1] * sigma[1] + sigma[2] * sigma[2] + sigma[3] * sigma[3]));
}

#endif
