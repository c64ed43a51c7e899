/* The material (docs/model.md sections 1, 1.1): its options (the rubber's branches: rubber.c), the plane-strain Lame
   constants, and the constants of the kernels that read them (kernels.h). */
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
  RollerMaterial *m = &ctx->material;
  PetscBool       given[4];
  PetscReal       tau[ROLLER_MAX_BRANCHES + 1] = {0.0}, weight[ROLLER_MAX_BRANCHES + 1] = {0.0};
  PetscInt        nband = 2, ntau = ROLLER_MAX_BRANCHES + 1, nweight = ROLLER_MAX_BRANCHES + 1; /* one more than allowed: seen and refused */

  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: material", NULL);
  PetscCall(PetscOptionsReal("-young", "Young's modulus E (with -rubber maxwell the relaxed, static one)", NULL, m->young, &m->young, NULL));
  PetscCall(PetscOptionsReal("-poisson", "Poisson's ratio nu (with -rubber maxwell the relaxed one)", NULL, m->poisson, &m->poisson, NULL));
  PetscCall(PetscOptionsReal("-density", "Density rho", NULL, m->density, &m->density, NULL));
  PetscCall(PetscOptionsEnum("-rubber", "The rubber's damping: kelvin_voigt (-viscosity) or maxwell, a generalized Maxwell solid of deviatoric branches, fitted (-rubber_loss_factor, -rubber_band) or given (-maxwell_tau, -maxwell_weight) (docs/model.md section 1.1)", "RollerRubber", RollerRubbers,
                             (PetscEnum)m->rubber, (PetscEnum *)&m->rubber, NULL));
  PetscCall(PetscOptionsReal("-viscosity", "Kelvin-Voigt damping tau of the rubber, sigma = C:(eps + tau eps_t) (time); with -rubber maxwell a term beside the branches, the loss w tau growing above their band", NULL, m->viscosity, &m->viscosity, NULL));
  PetscCall(PetscOptionsReal("-rubber_loss_factor", "-rubber maxwell: the loss factor eta = G''/G' the branches are fitted to, flat over -rubber_band (in (0, 1])", NULL, m->loss_factor, &m->loss_factor, &given[0]));
  PetscCall(PetscOptionsRealArray("-rubber_band", "-rubber maxwell: the band F1,F2 of the fitted loss factor, cycles per unit time (Hz in SI scenes)", NULL, m->band, &nband, &given[1]));
  PetscCall(PetscOptionsRealArray("-maxwell_tau", "-rubber maxwell: the branches' relaxation times T1,... (at most 16; instead of the fit)", NULL, tau, &ntau, &given[2]));
  PetscCall(PetscOptionsRealArray("-maxwell_weight", "-rubber maxwell: the branches' shear moduli g1,... over the relaxed shear modulus mu, one per -maxwell_tau", NULL, weight, &nweight, &given[3]));
  PetscOptionsEnd();
  RollerCheckOption(ctx->comm, "-young", ctx->material.young, ctx->material.young > 0, "> 0");
  RollerCheckOption(ctx->comm, "-poisson", ctx->material.poisson, ctx->material.poisson > -1 && ctx->material.poisson < 0.5, "in (-1, 0.5)");
  RollerCheckOption(ctx->comm, "-density", ctx->material.density, ctx->material.density > 0, "> 0");
  RollerCheckOption(ctx->comm, "-viscosity", ctx->material.viscosity, ctx->material.viscosity >= 0, ">= 0 (a time: tau of sigma = C:(eps + tau eps_t))");
  PetscCall(RollerLameFromYoung(ctx->material.young, ctx->material.poisson, &ctx->material.lambda, &ctx->material.mu));
  PetscCall(RollerRubberSetUp(ctx, given, nband, given[2] ? ntau : 0, tau, given[3] ? nweight : 0, weight));
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
