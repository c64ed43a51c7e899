/* Manufactured solutions that verify the space and time discretization (docs/validation.md).
   u(x, t) = T(t) A B(x) c, c = (1, 1/2), B = g(s)/g_max, s = |x|^2, g(s) = (s - r_i^2)^2 (r_o^2 - s)^2:
   u vanishes to second order on both circles, so the polygonal boundary of the mesh (chords at
   distance O(h^2) from the circle) costs only O(h^4) and does not spoil the P2 rates. With -clamp_outer
   it satisfies the boundary conditions; the body force F = rho u_tt - div sigma[u + tau u_t] - rho f(t, x, u, u_t)
   (f of docs/model.md section 1, all of it) makes it a solution of (P) without obstacle.
   T(t) = 1 + t ("linear": the DMF scheme is exact in time, so the error is spatial only) or
   T(t) = sin(2 pi t) ("sine": the time error shows). */
#include "verify/verify.h"
#include "model/kernels.h"

static const PetscReal mms_c[2] = {1.0, 0.5};

static void MMSTime(PetscInt type, PetscReal t, PetscReal T[3])
{
  if (type == ROLLER_MMS_LINEAR) {
    T[0] = 1.0 + t;
    T[1] = 1.0;
    T[2] = 0.0;
  } else {
    const PetscReal w = 2.0 * PETSC_PI;
    T[0]              = PetscSinReal(w * t);
    T[1]              = w * PetscCosReal(w * t);
    T[2]              = -w * w * PetscSinReal(w * t);
  }
}

/* B and its first and second derivatives at x: dB[2], d2B[4]. */
static void MMSShape(PetscReal ri, PetscReal ro, const PetscReal x[], PetscReal *B, PetscReal dB[], PetscReal d2B[])
{
  const PetscReal a = ri * ri, b = ro * ro, s = x[0] * x[0] + x[1] * x[1];
  const PetscReal p = (s - a) * (b - s), dp = a + b - 2.0 * s;
  const PetscReal gmax = PetscPowReal(0.5 * (b - a), 4.0);
  const PetscReal g = p * p / gmax, dg = 2.0 * p * dp / gmax, d2g = (2.0 * dp * dp - 4.0 * p) / gmax;

  *B = g;
  if (dB) {
    dB[0] = 2.0 * x[0] * dg;
    dB[1] = 2.0 * x[1] * dg;
  }
  if (d2B) {
    d2B[0] = 4.0 * x[0] * x[0] * d2g + 2.0 * dg;
    d2B[1] = 4.0 * x[0] * x[1] * d2g;
    d2B[2] = d2B[1];
    d2B[3] = 4.0 * x[1] * x[1] * d2g + 2.0 * dg;
  }
}

/* The constants of the MMS load and error functionals (their own DS each): the material and the
   manufactured solution, and the time t, the functional's argument, set at every call. */
typedef enum {
  MMS_C_LAMBDA,
  MMS_C_MU,
  MMS_C_RHO,
  MMS_C_TYPE, /* RollerMMSType */
  MMS_C_AMPLITUDE,
  MMS_C_R_INNER,
  MMS_C_R_OUTER,
  MMS_C_TIME,
  MMS_C_THETA_DOT,  /* theta'(t)  */
  MMS_C_THETA_DDOT, /* theta''(t) */
  MMS_C_VISCOSITY,  /* tau of Kelvin-Voigt damping */
  MMS_NUM_CONSTANTS
} MMSConstant;

static PetscErrorCode MMSSetConstants(Roller ctx, PetscReal t, DM dm)
{
  PetscDS     ds;
  PetscScalar constants[MMS_NUM_CONSTANTS];
  PetscReal   td, tdd;

  PetscFunctionBeginUser;
  RollerTheta(ctx, t, NULL, &td, &tdd);
  constants[MMS_C_LAMBDA]     = ctx->material.lambda;
  constants[MMS_C_MU]         = ctx->material.mu;
  constants[MMS_C_RHO]        = ctx->material.density;
  constants[MMS_C_TYPE]       = ctx->init.mms;
  constants[MMS_C_AMPLITUDE]  = ctx->init.amplitude;
  constants[MMS_C_R_INNER]    = ctx->mesh.r_inner;
  constants[MMS_C_R_OUTER]    = ctx->mesh.r_outer;
  constants[MMS_C_TIME]       = t;
  constants[MMS_C_THETA_DOT]  = td;
  constants[MMS_C_THETA_DDOT] = tdd;
  constants[MMS_C_VISCOSITY]  = ctx->material.viscosity;
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(PetscDSSetConstants(ds, MMS_NUM_CONSTANTS, constants));
  PetscFunctionReturn(0);
}

/* Body force F(x, t) at the constants' time, loaded as (F, v). */
static void f0_mms(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f0[])
{
  const PetscReal lambda = PetscRealPart(constants[MMS_C_LAMBDA]), mu = PetscRealPart(constants[MMS_C_MU]), rho = PetscRealPart(constants[MMS_C_RHO]);
  const PetscReal time = PetscRealPart(constants[MMS_C_TIME]), td = PetscRealPart(constants[MMS_C_THETA_DOT]), tdd = PetscRealPart(constants[MMS_C_THETA_DDOT]);
  const PetscReal amp = PetscRealPart(constants[MMS_C_AMPLITUDE]), tau = PetscRealPart(constants[MMS_C_VISCOSITY]);
  PetscReal       T[3], B, dB[2], H[4], ue[2], ut[2], utt[2], divsig[2], f[2];

  MMSTime((PetscInt)PetscRealPart(constants[MMS_C_TYPE]), time, T);
  MMSShape(PetscRealPart(constants[MMS_C_R_INNER]), PetscRealPart(constants[MMS_C_R_OUTER]), x, &B, dB, H);
  for (PetscInt c = 0; c < 2; ++c) {
    ue[c]  = T[0] * amp * B * mms_c[c];
    ut[c]  = T[1] * amp * B * mms_c[c];
    utt[c] = T[2] * amp * B * mms_c[c];
    /* div sigma[B c] = mu Lap(B) c + (lambda + mu) Hess(B) c; Kelvin-Voigt: sigma[u + tau u_t] */
    divsig[c] = (T[0] + tau * T[1]) * amp * (mu * (H[0] + H[3]) * mms_c[c] + (lambda + mu) * (H[c * 2 + 0] * mms_c[0] + H[c * 2 + 1] * mms_c[1]));
  }
  /* f = theta'' R(-pi/2)(x + u) + theta'^2 (x + u) + 2 theta' R(-pi/2) u_t (docs/model.md section 1) */
  f[0] = tdd * (x[1] + ue[1]) + td * td * (x[0] + ue[0]) + 2.0 * td * ut[1];
  f[1] = -tdd * (x[0] + ue[0]) + td * td * (x[1] + ue[1]) - 2.0 * td * ut[0];
  for (PetscInt c = 0; c < 2; ++c) f0[c] = rho * utt[c] - divsig[c] - rho * f[c];
}

/* The manufactured field's k-th time derivative (0: the displacement, 1: the velocity) at x. */
static void MMSField(Roller ctx, PetscReal time, const PetscReal x[], PetscInt k, PetscScalar *u)
{
  PetscReal T[3], B;

  MMSTime(ctx->init.mms, time, T);
  MMSShape(ctx->mesh.r_inner, ctx->mesh.r_outer, x, &B, NULL, NULL);
  for (PetscInt c = 0; c < 2; ++c) u[c] = T[k] * ctx->init.amplitude * B * mms_c[c];
}

static PetscErrorCode MMSExact(PetscInt dim, PetscReal time, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *vctx)
{
  MMSField((Roller)vctx, time, x, 0, u);
  return 0;
}

static PetscErrorCode MMSVelocity(PetscInt dim, PetscReal time, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *vctx)
{
  MMSField((Roller)vctx, time, x, 1, u);
  return 0;
}

/* The bump initial state of the Theorem 1 setting: the MMS shape at T = 1, at rest. */
static PetscErrorCode BumpShape(PetscInt dim, PetscReal time, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *vctx)
{
  Roller    ctx = (Roller)vctx;
  PetscReal B;

  MMSShape(ctx->mesh.r_inner, ctx->mesh.r_outer, x, &B, NULL, NULL);
  for (PetscInt c = 0; c < 2; ++c) u[c] = ctx->init.amplitude * B * mms_c[c];
  return 0;
}

/* xi = I u(t), the nodal interpolant of the exact solution (or of the bump). */
PetscErrorCode RollerMMSExact(Roller ctx, PetscReal t, Vec xi)
{
  PetscErrorCode (*funcs[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {ctx->init.mms == ROLLER_MMS_NONE ? BumpShape : MMSExact};
  void *ctxs[1]                                                                                       = {ctx};

  PetscFunctionBeginUser;
  PetscCall(DMProjectFunction(ctx->mesh.dm, t, funcs, ctxs, INSERT_VALUES, xi));
  PetscFunctionReturn(0);
}

/* v = I u_t(t), the nodal interpolant of the exact velocity (a one-step scheme's initial state). */
PetscErrorCode RollerMMSVelocity(Roller ctx, PetscReal t, Vec v)
{
  PetscErrorCode (*funcs[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {MMSVelocity};
  void *ctxs[1]                                                                                       = {ctx};

  PetscFunctionBeginUser;
  PetscCall(DMProjectFunction(ctx->mesh.dm, t, funcs, ctxs, INSERT_VALUES, v));
  PetscFunctionReturn(0);
}

/* b += (F(t), v): the manufactured body force at time t, on the load's own DM (made at the first call, kept in
   ctx->init.dm), whose DS holds f0_mms and its constants; only the time changes from call to call. */
PetscErrorCode RollerAddMMSLoad(Roller ctx, PetscReal t, Vec b)
{
  PetscFunctionBeginUser;
  if (!ctx->init.dm) {
    PetscDS ds;

    PetscCall(RollerOperatorDMCreate(ctx, NULL, &ctx->init.dm));
    PetscCall(DMGetDS(ctx->init.dm, &ds));
    PetscCall(PetscDSSetResidual(ds, 0, f0_mms, NULL));
  }
  PetscCall(MMSSetConstants(ctx, t, ctx->init.dm));
  PetscCall(RollerAddLoad(ctx->init.dm, b));
  PetscFunctionReturn(0);
}

/* Squared L2 and H1-seminorm error densities against the manufactured solution at the constants' time. */
static void f0_l2_error(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar obj[])
{
  const PetscReal amp = PetscRealPart(constants[MMS_C_AMPLITUDE]);
  PetscReal       T[3], B;

  MMSTime((PetscInt)PetscRealPart(constants[MMS_C_TYPE]), PetscRealPart(constants[MMS_C_TIME]), T);
  MMSShape(PetscRealPart(constants[MMS_C_R_INNER]), PetscRealPart(constants[MMS_C_R_OUTER]), x, &B, NULL, NULL);
  obj[0] = 0.0;
  for (PetscInt c = 0; c < 2; ++c) obj[0] += PetscSqr(PetscRealPart(u[c]) - T[0] * amp * B * mms_c[c]);
}

static void f0_h1_error(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar obj[])
{
  const PetscReal amp = PetscRealPart(constants[MMS_C_AMPLITUDE]);
  PetscReal       T[3], B, dB[2];

  MMSTime((PetscInt)PetscRealPart(constants[MMS_C_TYPE]), PetscRealPart(constants[MMS_C_TIME]), T);
  MMSShape(PetscRealPart(constants[MMS_C_R_INNER]), PetscRealPart(constants[MMS_C_R_OUTER]), x, &B, dB, NULL);
  obj[0] = 0.0;
  for (PetscInt c = 0; c < 2; ++c)
    for (PetscInt d = 0; d < 2; ++d) obj[0] += PetscSqr(PetscRealPart(u_x[c * 2 + d]) - T[0] * amp * dB[d] * mms_c[c]);
}

/* sqrt(int f0(xi^k)) at time t, the functional f0 on its own DM. */
static PetscErrorCode IntegrateError(Roller ctx, RollerPointFunc f0, PetscReal t, PetscReal *err)
{
  DM          dm;
  PetscDS     ds;
  PetscScalar integral;

  PetscFunctionBeginUser;
  PetscCall(RollerOperatorDMCreate(ctx, NULL, &dm));
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(PetscDSSetObjective(ds, 0, f0));
  PetscCall(MMSSetConstants(ctx, t, dm));
  PetscCall(DMPlexComputeIntegralFEM(dm, ctx->state.cur, &integral, NULL));
  PetscCall(DMDestroy(&dm));
  *err = PetscSqrtReal(PetscRealPart(integral));
  PetscFunctionReturn(0);
}

/* L2 and H1-seminorm errors of the newest level xi^k against the manufactured solution at time t. */
PetscErrorCode RollerComputeErrors(Roller ctx, PetscReal t, PetscReal *l2, PetscReal *h1)
{
  PetscFunctionBeginUser;
  PetscCall(IntegrateError(ctx, f0_l2_error, t, l2));
  PetscCall(IntegrateError(ctx, f0_h1_error, t, h1));
  PetscFunctionReturn(0);
}
