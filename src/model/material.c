/* The material (docs/model.md section 1): its options, the plane-strain Lame constants, and the constants of
   the kernels that read them (kernels.h). */
#include "model/model.h"
#include "model/kernels.h"

/* Plane-strain Lame constants (docs/model.md section 1). */
PetscErrorCode RollerLameFromYoung(PetscReal young, PetscReal poisson, PetscReal *lambda, PetscReal *mu)
{
  PetscFunctionBeginUser;
  *lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
  *mu     = young / (2.0 * (1.0 + poisson));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerMaterialSetFromOptions(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: material", NULL);
  PetscCall(PetscOptionsReal("-young", "Young's modulus E", NULL, ctx->material.young, &ctx->material.young, NULL));
  PetscCall(PetscOptionsReal("-poisson", "Poisson's ratio nu", NULL, ctx->material.poisson, &ctx->material.poisson, NULL));
  PetscCall(PetscOptionsReal("-density", "Density rho", NULL, ctx->material.density, &ctx->material.density, NULL));
  PetscCall(PetscOptionsReal("-viscosity", "Kelvin-Voigt damping tau of the rubber, sigma = C:(eps + tau eps_t) (time)", NULL, ctx->material.viscosity, &ctx->material.viscosity, NULL));
  PetscOptionsEnd();
  RollerCheckOption(ctx->comm, "-young", ctx->material.young, ctx->material.young > 0, "> 0");
  RollerCheckOption(ctx->comm, "-poisson", ctx->material.poisson, ctx->material.poisson > -1 && ctx->material.poisson < 0.5, "in (-1, 0.5)");
  RollerCheckOption(ctx->comm, "-density", ctx->material.density, ctx->material.density > 0, "> 0");
  RollerCheckOption(ctx->comm, "-viscosity", ctx->material.viscosity, ctx->material.viscosity >= 0, ">= 0 (a time: tau of sigma = C:(eps + tau eps_t))");
  PetscCall(RollerLameFromYoung(ctx->material.young, ctx->material.poisson, &ctx->material.lambda, &ctx->material.mu));
  PetscFunctionReturn(0);
}

/* The material constants (lambda, mu) of a DS whose kernels read them: ctx->mesh.dm's (the stress
   projection of the output) and K's, set once at set-up. */
PetscErrorCode RollerMaterialSetConstants(Roller ctx, PetscDS ds)
{
  PetscScalar constants[ROLLER_NUM_MATERIAL_CONSTANTS];

  PetscFunctionBeginUser;
  constants[ROLLER_C_LAMBDA] = ctx->material.lambda;
  constants[ROLLER_C_MU]     = ctx->material.mu;
  PetscCall(PetscDSSetConstants(ds, ROLLER_NUM_MATERIAL_CONSTANTS, constants));
  PetscFunctionReturn(0);
}
