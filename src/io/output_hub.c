/* The fields output on the axle (-output with -axle): the hub's rigid motion at the vertices of Gamma_D. */
#include "output.h"
#include "model/axle.h"

/* -axle: the vertices of Gamma_D (the inner circle) move with the hub, xi = u + phi J x (model/axle.h), which the body's
   vector does not hold (its Dirichlet dofs are 0): set there from the hub's level q^k, the rate from (q^k - q^{k-1})/dt.
   The stress's vertex mean in the cells at Gamma_D still sees the body's 0 there. */
PetscErrorCode RollerOutputHubAtVertices(Roller ctx, RollerOutput out, Vec xi, Vec v)
{
  const RollerHubState *s  = &ctx->axle.hub->s;
  const PetscReal       ri = ctx->mesh.r_inner, tol = 1e-8 * ctx->mesh.r_outer, dt = ctx->ts.dt;
  const PetscScalar    *x;
  PetscScalar          *u, *w;
  PetscInt              n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(xi, &n));
  PetscCall(VecGetArrayRead(out->position, &x));
  PetscCall(VecGetArray(xi, &u));
  PetscCall(VecGetArray(v, &w));
  for (PetscInt i = 0; i < n; i += 3) {
    const PetscReal x0 = PetscRealPart(x[i]), x1 = PetscRealPart(x[i + 1]);

    if (PetscAbsReal(PetscSqrtReal(x0 * x0 + x1 * x1) - ri) > tol) continue;
    u[i]     = s->cur[0] - s->cur[2] * x1;
    u[i + 1] = s->cur[1] + s->cur[2] * x0;
    w[i]     = (s->cur[0] - s->prev[0] - (s->cur[2] - s->prev[2]) * x1) / dt;
    w[i + 1] = (s->cur[1] - s->prev[1] + (s->cur[2] - s->prev[2]) * x0) / dt;
  }
  PetscCall(VecRestoreArrayRead(out->position, &x));
  PetscCall(VecRestoreArray(xi, &u));
  PetscCall(VecRestoreArray(v, &w));
  PetscFunctionReturn(0);
}
