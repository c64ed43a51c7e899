/* Pointwise kernels for PetscFE (plane-strain linear elasticity, mass, loads, boundary functionals),
   docs/model.md sections 1-4. Every operator has a PetscDS of its own (model/operators.c), set once: the
   kernels below read only the constants of their own DS, listed with each. */
#ifndef ROLLER_KERNELS_H
#define ROLLER_KERNELS_H

#include <petscsys.h>

/* The arguments every PetscFE pointwise kernel begins with; a kernel then takes, after them,
     residual, objective, projection:  const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[]
     Jacobian:                         PetscReal u_tShift, then the same
     boundary residual and integral:   const PetscReal x[], const PetscReal n[], then the same */
#define ROLLER_KERNEL_ARGS \
  PetscInt dim, PetscInt Nf, PetscInt NfAux, const PetscInt uOff[], const PetscInt uOff_x[], const PetscScalar u[], const PetscScalar u_t[], const PetscScalar u_x[], const PetscInt aOff[], const PetscInt aOff_x[], const PetscScalar a[], const PetscScalar a_t[], const PetscScalar a_x[], PetscReal t

/* A residual, objective or projection kernel (DMProjectField, PetscDSSetResidual, PetscDSSetObjective). */
typedef void (*RollerPointFunc)(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[]);

/* The material constants, set once at set-up (RollerMaterialSetConstants) on the DS of ctx->mesh.dm (the
   output's stress projection) and of K, and never changed. */
typedef enum { ROLLER_C_LAMBDA, ROLLER_C_MU, ROLLER_NUM_MATERIAL_CONSTANTS } RollerMaterialConstant;

/* The position x as a field (DMProjectFunction), padded with zeros beyond the dimension (the 3-component
   output vectors): the nodal coordinates of the step (operators.c) and of the output (output.c). */
static inline PetscErrorCode RollerPosition(PetscInt dim, PetscReal time, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  for (PetscInt c = 0; c < Nc; ++c) u[c] = c < dim ? x[c] : 0.0;
  return 0;
}

/* Plane-strain stress sigma = 2 mu eps + lambda tr(eps) I from the gradient u_x[c*dim+d] = d u_c / d x_d. */
static inline void RollerStress(PetscReal lambda, PetscReal mu, const PetscScalar u_x[], PetscScalar sigma[])
{
  const PetscScalar div = u_x[0] + u_x[3];

  sigma[0] = 2.0 * mu * u_x[0] + lambda * div;
  sigma[1] = mu * (u_x[1] + u_x[2]);
  sigma[2] = sigma[1];
  sigma[3] = 2.0 * mu * u_x[3] + lambda * div;
}

/* K: a(u, v) = int sigma[u] : eps[v] (docs/model.md section 2). Constants: the material's. */
static inline void g3_elastic(ROLLER_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g3[])
{
  const PetscReal lambda = PetscRealPart(constants[ROLLER_C_LAMBDA]), mu = PetscRealPart(constants[ROLLER_C_MU]);

  for (PetscInt c = 0; c < dim; ++c) {
    for (PetscInt d = 0; d < dim; ++d) {
      g3[((c * dim + c) * dim + d) * dim + d] += mu;
      g3[((c * dim + d) * dim + d) * dim + c] += mu;
      g3[((c * dim + d) * dim + c) * dim + d] += lambda;
    }
  }
}

/* K_d: the Maxwell branches' deviatoric stiffness at the relaxed shear modulus (docs/model.md section 1.1),
   int 2 mu dev eps[u] : dev eps[v], dev the 3-D deviator of the plane strain (eps_zz = 0): the elastic kernel with
   (lambda, mu) -> (-2/3 mu, mu), 2 mu (eps : eps - tr(eps)^2/3) > 0 for every eps != 0. Constants: the material's (mu). */
static inline void g3_deviatoric(ROLLER_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g3[])
{
  const PetscReal mu = PetscRealPart(constants[ROLLER_C_MU]), lambda = -2.0 * mu / 3.0;

  for (PetscInt c = 0; c < dim; ++c) {
    for (PetscInt d = 0; d < dim; ++d) {
      g3[((c * dim + c) * dim + d) * dim + d] += mu;
      g3[((c * dim + d) * dim + d) * dim + c] += mu;
      g3[((c * dim + d) * dim + c) * dim + d] += lambda;
    }
  }
}

/* M: the L2 inner product (u, v) (no density; A carries rho). No constants. */
static inline void g0_mass(ROLLER_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g0[])
{
  g0[0] = 1.0;
  g0[3] = 1.0;
}

/* G: (R(-pi/2) u, v), skew, the Coriolis operator; R(-pi/2)(a, b) = (b, -a). No constants. */
static inline void g0_gyro(ROLLER_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g0[])
{
  g0[1] = 1.0;
  g0[2] = -1.0;
}

/* The convective operators of the Eulerian (lab) description (docs/squeal.md section 1): d_phi = x1 d/dx2 - x2 d/dx1,
   the derivative along the rotation, acting on each Cartesian component. D: (d_phi u, v), skew (d_phi is
   divergence-free and tangent to both circles); P: (d_phi u, d_phi v), symmetric. No constants. */
static inline void g1_convective(ROLLER_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g1[])
{
  for (PetscInt c = 0; c < dim; ++c) {
    g1[(c * dim + c) * dim + 0] = -x[1];
    g1[(c * dim + c) * dim + 1] = x[0];
  }
}

static inline void g3_convective(ROLLER_KERNEL_ARGS, PetscReal u_tShift, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar g3[])
{
  const PetscReal e[2] = {-x[1], x[0]};

  for (PetscInt c = 0; c < dim; ++c)
    for (PetscInt d = 0; d < dim; ++d)
      for (PetscInt f = 0; f < dim; ++f) g3[((c * dim + c) * dim + d) * dim + f] = e[d] * e[f];
}

/* Load of the rigid-body part of the centrifugal force: (x, v). No constants. */
static inline void f0_centrifugal(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  f0[0] = x[0];
  f0[1] = x[1];
}

/* Load of the rigid-body part of the Euler force: (R(-pi/2) x, v), R(-pi/2)(a, b) = (b, -a). No constants. */
static inline void f0_euler(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  f0[0] = x[1];
  f0[1] = -x[0];
}

/* Loads of the unit translations e1, e2 (the rigid hub's coupling with the body, model/axle.c). No constants. */
static inline void f0_translation_x(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  f0[0] = 1.0;
  f0[1] = 0.0;
}

static inline void f0_translation_y(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  f0[0] = 0.0;
  f0[1] = 1.0;
}

/* The boundary functionals on Gamma_C (docs/model.md section 4): w_R . v = int v . x/|x| ds,
   w_alpha . v = int v . x_perp/|x| ds, x_perp = (-x_1, x_0), and |Gamma_C| = int 1 ds. No constants. */
static inline void f0_bd_radial(ROLLER_KERNEL_ARGS, const PetscReal x[], const PetscReal n[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  const PetscReal r = PetscSqrtReal(x[0] * x[0] + x[1] * x[1]);

  f0[0] = x[0] / r;
  f0[1] = x[1] / r;
}

static inline void f0_bd_angular(ROLLER_KERNEL_ARGS, const PetscReal x[], const PetscReal n[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  const PetscReal r = PetscSqrtReal(x[0] * x[0] + x[1] * x[1]);

  f0[0] = -x[1] / r;
  f0[1] = x[0] / r;
}

/* The order n = constants[0] of the radial displacement on Gamma_C: x/|x| cos(n phi), x/|x| sin(n phi), phi the angle
   of x (RollerComputeOrderFunctionals). */
static inline void f0_bd_radial_cos(ROLLER_KERNEL_ARGS, const PetscReal x[], const PetscReal n[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  const PetscReal r = PetscSqrtReal(x[0] * x[0] + x[1] * x[1]), c = PetscCosReal(PetscRealPart(constants[0]) * PetscAtan2Real(x[1], x[0]));

  f0[0] = c * x[0] / r;
  f0[1] = c * x[1] / r;
}

static inline void f0_bd_radial_sin(ROLLER_KERNEL_ARGS, const PetscReal x[], const PetscReal n[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  const PetscReal r = PetscSqrtReal(x[0] * x[0] + x[1] * x[1]), s = PetscSinReal(PetscRealPart(constants[0]) * PetscAtan2Real(x[1], x[0]));

  f0[0] = s * x[0] / r;
  f0[1] = s * x[1] / r;
}

static inline void f_bd_one(ROLLER_KERNEL_ARGS, const PetscReal x[], const PetscReal n[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[])
{
  f[0] = 1.0;
}

/* |sigma| = sqrt(sum_ij sigma_ij^2) (docs/model.md section 4), projected to a scalar field. Constants: the
   material's, those of the input DS (ctx->mesh.dm's). */
static inline void f_stress_norm(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[])
{
  PetscScalar sigma[4];

  RollerStress(PetscRealPart(constants[ROLLER_C_LAMBDA]), PetscRealPart(constants[ROLLER_C_MU]), u_x, sigma);
  f[0] = PetscSqrtReal(PetscRealPart(sigma[0] * sigma[0] + sigma[1] * sigma[1] + sigma[2] * sigma[2] + sigma[3] * sigma[3]));
}

#endif
