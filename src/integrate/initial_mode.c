/* -initial_condition mode -initial_mode_file F.h5 -initial_mode j -ic_amplitude A (docs/squeal.md section 4): the
   transient starts on mode j of a -modes_output file, so that it can be compared with the eigenvalue.

   Co-rotating modes (the free annulus): the steady state of the rotation xi_s ((K - rho omega^2 M) xi_s =
   rho omega^2 L_centrifugal, which the DMF keeps exactly) plus A Re(z e^{lambda t}) at t = 0, -dt, -2 dt: the
   mode's exact history.

   Lab-frame modes (the squeal analysis about the steady rolling or sliding state u_s, stored in the file): the lab field
   u = u_s + A Re(z e^{lambda t}) seen from the co-rotating frame, xi(X, t) = R(-theta) u(R(theta) X, t), at
   t = 0 (theta = 0): xi = u and xi_t = u_t + omega (d_phi u - J u), J = R(pi/2); d_phi u by the L2 projection
   M^-1 D u (D = (d_phi u, v)). The history xi^{-k} = xi^0 - k dt xi_t (first order: the difference excites the
   other modes at O(dt^2) of A). The sheet must be at its final depth from the first step (-obstacle_speed large). */
#include "integrate/integrate.h"
#include "model/model.h"
#include "model/kernels.h"

static PetscErrorCode DirectSolve(Roller ctx, Mat B, Vec b, Vec x)
{
  KSP ksp;

  PetscFunctionBeginUser;
  PetscCall(KSPCreate(ctx->comm, &ksp));
  PetscCall(KSPSetOperators(ksp, B, B));
  PetscCall(RollerDirectSolverDefaults(ksp, PCLU));
  PetscCall(KSPSetOptionsPrefix(ksp, "initial_"));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(KSPDestroy(&ksp));
  PetscFunctionReturn(0);
}

/* v = omega (d_phi u - J u): the co-rotating rate of a lab field frozen in the lab; M0 the consistent mass (the
   step's mass may be the massless contact nodes' T^T M T, singular) */
static PetscErrorCode CorotatingRate(Roller ctx, Mat M0, Mat D, Vec u, Vec v)
{
  Vec t;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(u, &t));
  PetscCall(MatMult(D, u, ctx->state.rhs));
  PetscCall(DirectSolve(ctx, M0, ctx->state.rhs, v)); /* d_phi u */
  PetscCall(RollerApplyRotate90(ctx, u, t));          /* R(-pi/2) u = -J u */
  PetscCall(VecAXPY(v, 1.0, t));
  PetscCall(VecScale(v, ctx->rotation.omega));
  PetscCall(VecDestroy(&t));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerInitialModeState(Roller ctx)
{
  const PetscReal A = ctx->init.amplitude, w = ctx->rotation.omega, rho = ctx->material.density, dt = ctx->ts.dt;
  Vec             lev[3] = {ctx->state.cur, ctx->state.prev, ctx->state.prev2}, xr, xi, steady;
  PetscReal       re, im;
  RollerFrame     frame;
  PetscBool       has;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(ctx->state.cur, &xr));
  PetscCall(VecDuplicate(ctx->state.cur, &xi));
  PetscCall(VecDuplicate(ctx->state.cur, &steady));
  PetscCall(RollerModeFileRead(ctx, ctx->init.mode_file, ctx->init.mode_index, &frame, &re, &im, xr, xi, steady, &has));
  if (frame == ROLLER_FRAME_ROTATING) {
    PetscCall(VecZeroEntries(steady));
    if (w != 0) {
      Mat B;

      PetscCall(MatDuplicate(ctx->ops.K, MAT_COPY_VALUES, &B));
      PetscCall(MatAXPY(B, -rho * w * w, ctx->ops.M, DIFFERENT_NONZERO_PATTERN));
      PetscCall(VecCopy(ctx->ops.L_centrifugal, ctx->state.rhs));
      PetscCall(VecScale(ctx->state.rhs, rho * w * w));
      PetscCall(DirectSolve(ctx, B, ctx->state.rhs, steady));
      PetscCall(MatDestroy(&B));
    }
    PetscCall(VecAXPBYPCZ(ctx->state.velocity, A * re, -A * im, 0.0, xr, xi)); /* eta^0 = A Re(lambda z) */
    for (PetscInt k = 0; k < 3; ++k) {                                         /* A Re(z e^{lambda t}), t = -k dt: e^{lambda t} = e^{re t}(cos(im t) + i sin(im t)) */
      const PetscReal t = -k * dt, cr = PetscExpReal(re * t) * PetscCosReal(im * t), ci = PetscExpReal(re * t) * PetscSinReal(im * t);

      PetscCall(VecCopy(steady, lev[k]));
      PetscCall(VecAXPBYPCZ(lev[k], A * cr, -A * ci, 1.0, xr, xi));
    }
  } else {
    Mat D, M0;
    Vec rate;

    if (!has) PetscCall(VecZeroEntries(steady)); /* the free annulus in the lab: about the undeformed state */
    PetscCall(VecDuplicate(steady, &rate));
    PetscCall(RollerAssembleMatrix(ctx, "D", NULL, g1_convective, NULL, &D));
    PetscCall(RollerAssembleMatrix(ctx, "M", g0_mass, NULL, NULL, &M0));
    PetscCall(VecWAXPY(lev[0], A, xr, steady));                 /* xi^0 = u_s + A Re z */
    PetscCall(CorotatingRate(ctx, M0, D, lev[0], rate));        /* omega (d_phi - J) xi^0 */
    PetscCall(VecAXPBYPCZ(rate, A * re, -A * im, 1.0, xr, xi)); /* + A Re(lambda z) */
    for (PetscInt k = 1; k < 3; ++k) PetscCall(VecWAXPY(lev[k], -k * dt, rate, lev[0]));
    PetscCall(VecCopy(rate, ctx->state.velocity)); /* eta^0 */
    PetscCall(MatDestroy(&D));
    PetscCall(MatDestroy(&M0));
    PetscCall(VecDestroy(&rate));
  }
  PetscCall(VecDestroy(&xr));
  PetscCall(VecDestroy(&xi));
  PetscCall(VecDestroy(&steady));
  PetscFunctionReturn(0);
}
