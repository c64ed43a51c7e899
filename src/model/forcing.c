/* The prescribed motions: the driving rotation theta(t) (its options) and the obstacle height g(t) (docs/model.md
   sections 1, 5), and the pointwise R(-pi/2) that the Euler and Coriolis terms of f apply. */
#include "model/model.h"

PetscErrorCode RollerRotationSetFromOptions(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: rotation theta(t) = omega (t - t0) + a cos(b (t - t0)) for t >= t0, a before", NULL);
  PetscCall(PetscOptionsReal("-omega", "Angular velocity omega", NULL, ctx->rotation.omega, &ctx->rotation.omega, NULL));
  PetscCall(PetscOptionsReal("-theta_a", "Amplitude a of the rotation perturbation", NULL, ctx->rotation.a, &ctx->rotation.a, NULL));
  PetscCall(PetscOptionsReal("-theta_b", "Angular frequency b of the rotation perturbation", NULL, ctx->rotation.b, &ctx->rotation.b, NULL));
  PetscCall(PetscOptionsReal("-theta_start", "Time t0 at which the drive starts (the roller is held at theta = a before: press first, then turn)", NULL, ctx->rotation.start, &ctx->rotation.start, NULL));
  PetscCall(PetscOptionsReal("-drive_ramp", "Start from rest: the motor's speed rises smoothly (cubic) from 0 to omega over this time after t0 (0: at once)", NULL, ctx->rotation.ramp, &ctx->rotation.ramp, NULL));
  PetscCall(PetscOptionsReal("-drive_ripple", "The motor's angular ripple a_r (radians): theta += a_r s(t) sin(2 pi f (t - t0)), s the ramp's speed fraction", NULL, ctx->rotation.ripple, &ctx->rotation.ripple, NULL));
  PetscCall(PetscOptionsReal("-drive_ripple_frequency", "Frequency f of the motor's ripple (cycles per unit time: Hz in SI scenes)", NULL, ctx->rotation.ripple_frequency, &ctx->rotation.ripple_frequency, NULL));
  PetscOptionsEnd();
  RollerCheckOption(ctx->comm, "-drive_ramp", ctx->rotation.ramp, ctx->rotation.ramp >= 0, ">= 0 (a time; 0: no ramp)");
  RollerCheckOption(ctx->comm, "-drive_ripple", ctx->rotation.ripple, PETSC_TRUE, "");
  RollerCheckOption(ctx->comm, "-drive_ripple_frequency", ctx->rotation.ripple_frequency, ctx->rotation.ripple_frequency >= 0, ">= 0 (cycles per unit time)");
  PetscCheck(ctx->rotation.ripple == 0 || ctx->rotation.ripple_frequency > 0, ctx->comm, PETSC_ERR_ARG_INCOMP, "-drive_ripple %g needs -drive_ripple_frequency > 0", (double)ctx->rotation.ripple);
  RollerCheckOption(ctx->comm, "-omega", ctx->rotation.omega, PETSC_TRUE, "");
  RollerCheckOption(ctx->comm, "-theta_a", ctx->rotation.a, PETSC_TRUE, "");
  RollerCheckOption(ctx->comm, "-theta_start", ctx->rotation.start, ctx->rotation.start >= 0, ">= 0");
  RollerCheckOption(ctx->comm, "-theta_b", ctx->rotation.b, ctx->rotation.b >= 0, ">= 0");
  PetscFunctionReturn(0);
}

/* The start from rest over T = -drive_ramp: the speed fraction s(x) = x^2 (3 - 2 x), x = t/T in [0, 1] (C1), its
   integral and derivative: theta = omega T (x^3 - x^4/2) during the ramp, omega (t - T/2) after. */
static void Ramp(PetscReal T, PetscReal t, PetscReal *angle, PetscReal *s, PetscReal *ds)
{
  const PetscReal x = T > 0 ? PetscMax(0.0, PetscMin(1.0, t / T)) : 1.0;

  *s  = x * x * (3.0 - 2.0 * x);
  *ds = (T > 0 && x < 1.0) ? 6.0 * x * (1.0 - x) / T : 0.0;
  if (T <= 0) *angle = t;
  else if (x < 1.0) *angle = T * x * x * x * (1.0 - 0.5 * x);
  else *angle = t - 0.5 * T;
}

/* theta(t) = omega (t - t0) + a cos(b (t - t0)) and its first two derivatives; theta = a, at rest, before t0 > 0.
   With t0 = 0 the formula holds for t < 0 too: the initial state turns with theta'(0) (the levels xi^{-1}, xi^{-2}).
   -drive_ramp and -drive_ripple (the motor's start from rest and its ripple) change omega (t - t0) into omega times
   the ramp's angle and add a_r s sin(2 pi f (t - t0)); before t0 (and before the ramp starts) the roller is at rest. */
void RollerTheta(Roller ctx, PetscReal t_abs, PetscReal *theta, PetscReal *theta_dot, PetscReal *theta_ddot)
{
  const PetscReal a = ctx->rotation.a, b = ctx->rotation.b, t = t_abs - ctx->rotation.start;

  if (ctx->rotation.ramp > 0 || ctx->rotation.ripple != 0) {
    const PetscReal w = ctx->rotation.omega, ar = ctx->rotation.ripple, f = 2.0 * PETSC_PI * ctx->rotation.ripple_frequency;
    PetscReal       ang, s, ds, sn, cs;

    if (t < 0 && (ctx->rotation.start > 0 || ctx->rotation.ramp > 0)) {
      if (theta) *theta = a;
      if (theta_dot) *theta_dot = 0.0;
      if (theta_ddot) *theta_ddot = 0.0;
      return;
    }
    Ramp(ctx->rotation.ramp, t, &ang, &s, &ds);
    sn = PetscSinReal(f * t);
    cs = PetscCosReal(f * t);
    /* the ripple's envelope s has s'' = 6 (1 - 2 t/T)/T^2 during the ramp: d2/dt2 (s sin) = s'' sin + 2 s' f cos - s f^2 sin */
    if (theta) *theta = w * ang + a * PetscCosReal(b * t) + ar * s * sn;
    if (theta_dot) *theta_dot = w * s - a * b * PetscSinReal(b * t) + ar * (ds * sn + s * f * cs);
    if (theta_ddot) {
      const PetscReal T = ctx->rotation.ramp, dds = (T > 0 && t < T) ? 6.0 * (1.0 - 2.0 * t / T) / (T * T) : 0.0;

      *theta_ddot = w * ds - a * b * b * PetscCosReal(b * t) + ar * (dds * sn + 2.0 * ds * f * cs - s * f * f * sn);
    }
    return;
  }
  if (t < 0 && ctx->rotation.start > 0) {
    if (theta) *theta = a;
    if (theta_dot) *theta_dot = 0.0;
    if (theta_ddot) *theta_ddot = 0.0;
    return;
  }
  if (theta) *theta = ctx->rotation.omega * t + a * PetscCosReal(b * t);
  if (theta_dot) *theta_dot = ctx->rotation.omega - a * b * PetscSinReal(b * t);
  if (theta_ddot) *theta_ddot = -a * b * b * PetscCosReal(b * t);
}

/* g(t) = min(speed t, depth) - r_outer (docs/model.md section 6); with -axle the sheet does not move up: -r_outer. */
PetscReal RollerObstacleHeight(Roller ctx, PetscReal t)
{
  if (ctx->axle.on) return -ctx->mesh.r_outer; /* the sheet stays at the roller's undeformed bottom; the spring presses */
  return PetscMin(ctx->obstacle.speed * t, ctx->obstacle.depth) - ctx->mesh.r_outer;
}

/* X(t) = V t: the sheet's lab-frame position along e1 (docs/friction.md). */
PetscReal RollerSheetPosition(Roller ctx, PetscReal t)
{
  return ctx->obstacle.sheet_speed * t;
}

/* y = R(-pi/2) x at every node: (a, b) -> (b, -a). Displacement dofs are stored in (x, y) pairs, and a
   Dirichlet node drops both, so pairs stay aligned in the global vector. */
PetscErrorCode RollerApplyRotate90(Vec x, Vec y)
{
  const PetscScalar *xa;
  PetscScalar       *ya;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(x, &xa));
  PetscCall(VecGetArrayWrite(y, &ya));
  for (PetscInt i = 0; i < n; i += 2) {
    const PetscScalar a = xa[i], b = xa[i + 1];
    ya[i]     = b;
    ya[i + 1] = -a;
  }
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCall(VecRestoreArrayWrite(y, &ya));
  PetscFunctionReturn(0);
}

/* y = cos(phi) x + sin(phi) R(-pi/2) x at every node: the exact flow of the Coriolis force on the velocity,
   v' = 2 theta' R(-pi/2) v, over an interval in which theta advances by phi/2 (docs/model.md section 2.1); x and y
   may be the same Vec. It commutes with M (M acts alike on both components) and keeps v . M v. */
PetscErrorCode RollerApplyRotation(Vec x, PetscReal phi, Vec y)
{
  const PetscReal    c = PetscCosReal(phi), s = PetscSinReal(phi);
  const PetscScalar *xa;
  PetscScalar       *ya;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  if (x == y) {
    PetscCall(VecGetArray(y, &ya));
    xa = ya;
  } else {
    PetscCall(VecGetArrayRead(x, &xa));
    PetscCall(VecGetArrayWrite(y, &ya));
  }
  for (PetscInt i = 0; i < n; i += 2) {
    const PetscScalar a = xa[i], b = xa[i + 1];

    ya[i]     = c * a + s * b;
    ya[i + 1] = c * b - s * a;
  }
  if (x == y) PetscCall(VecRestoreArray(y, &ya));
  else {
    PetscCall(VecRestoreArrayRead(x, &xa));
    PetscCall(VecRestoreArrayWrite(y, &ya));
  }
  PetscFunctionReturn(0);
}
