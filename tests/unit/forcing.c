static const char help[] = "Unit test: theta(t) = omega t + a cos(b t) and its derivatives (model/forcing.c) against central\n"
                           "differences; the obstacle height g(t) = min(v t, depth) - r_outer; R(-pi/2) at every node pair.\n";

#include "model/model.h"

int main(int argc, char **argv)
{
  struct _n_Roller ctx;
  const PetscReal  h    = 1e-4;
  PetscReal        err1 = 0, err2 = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscMemzero(&ctx, sizeof(ctx)));
  ctx.comm           = PETSC_COMM_WORLD;
  ctx.rotation.omega = 0.3;
  ctx.rotation.a     = 0.2;
  ctx.rotation.b     = 1.7;
  for (PetscReal t = 0; t < 5; t += 0.37) {
    PetscReal thm, th, thp, td, tdd;

    RollerTheta(&ctx, t - h, &thm, NULL, NULL);
    RollerTheta(&ctx, t + h, &thp, NULL, NULL);
    RollerTheta(&ctx, t, &th, &td, &tdd);
    err1 = PetscMax(err1, PetscAbsReal((thp - thm) / (2 * h) - td));
    err2 = PetscMax(err2, PetscAbsReal((thp - 2 * th + thm) / (h * h) - tdd));
  }
  /* central differences: O(h^2 b^3 a) = 1e-8 for theta', O(h^2 b^4 a) + round-off 1e-16/h^2 for theta'' */
  PetscCheck(err1 < 1e-7 && err2 < 1e-6, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "theta derivatives: errors %g, %g against central differences", (double)err1, (double)err2);

  ctx.mesh.r_outer   = 0.5;
  ctx.obstacle.speed = 0.005;
  ctx.obstacle.depth = 0.025;
  PetscCheck(RollerObstacleHeight(&ctx, 1.0) == 0.005 - 0.5 && RollerObstacleHeight(&ctx, 10.0) == 0.025 - 0.5, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "obstacle height: g(1) = %g, g(10) = %g", (double)RollerObstacleHeight(&ctx, 1.0), (double)RollerObstacleHeight(&ctx, 10.0));

  {
    Vec                x, y;
    const PetscScalar *ya;

    PetscCall(VecCreateMPI(PETSC_COMM_WORLD, 4, PETSC_DETERMINE, &x));
    PetscCall(VecDuplicate(x, &y));
    PetscCall(VecSetValue(x, 0, 1.0, INSERT_VALUES));
    PetscCall(VecSetValue(x, 1, 2.0, INSERT_VALUES));
    PetscCall(VecSetValue(x, 2, -3.0, INSERT_VALUES));
    PetscCall(VecSetValue(x, 3, 4.0, INSERT_VALUES));
    PetscCall(VecAssemblyBegin(x));
    PetscCall(VecAssemblyEnd(x));
    PetscCall(RollerApplyRotate90(&ctx, x, y)); /* ops.R90 NULL: the nodal rotation */
    PetscCall(VecGetArrayRead(y, &ya));
    /* R(-pi/2)(a, b) = (b, -a) */
    PetscCheck(ya[0] == 2.0 && ya[1] == -1.0 && ya[2] == 4.0 && ya[3] == 3.0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "R(-pi/2): got (%g, %g), (%g, %g)", (double)ya[0], (double)ya[1], (double)ya[2], (double)ya[3]);
    PetscCall(VecRestoreArrayRead(y, &ya));
    PetscCall(VecDestroy(&x));
    PetscCall(VecDestroy(&y));
  }
  PetscCall(PetscFinalize());
  return 0;
}
