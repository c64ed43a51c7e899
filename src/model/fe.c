/* The PetscFE discretization (docs/model.md section 3): its options, the Lagrange displacement space with
   the Dirichlet boundary on ctx->mesh.dm, and the DM of each operator: a clone of it with the same space and
   boundary and a PetscDS of its own. */
#include "model/model.h"
#include "model/kernels.h"

const char *const RollerCoriolisVelocities[] = {"backward", "extrapolated", "centered", "RollerCoriolisVelocity", "ROLLER_CORIOLIS_", NULL};

PetscErrorCode RollerDiscretizationSetFromOptions(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: discretization", NULL);
  PetscCall(PetscOptionsInt("-degree", "Lagrange degree of the displacement: 1 (the paper), 2, 3 (default: 3 without -obstacle when -mesh_h comes from -ts_phase_error, else 2)", NULL, ctx->disc.degree, &ctx->disc.degree, &ctx->disc.degree_set));
  ctx->mesh.curved = (PetscBool)(ctx->disc.degree >= 2);
  PetscCall(PetscOptionsBool("-mesh_curved", "Curved (P2 geometric map) boundary: mid-edge nodes of Gamma_D, Gamma_C on the circles (default: on with -degree 2 or 3)", NULL, ctx->mesh.curved, &ctx->mesh.curved, NULL));
  PetscCall(PetscOptionsEnum("-coriolis_velocity", "Coriolis velocity: backward (the paper, explicit, 1st order), extrapolated (explicit, 2nd order), centered (implicit, 2nd order, stable)", "RollerCoriolisVelocity", RollerCoriolisVelocities,
                             (PetscEnum)ctx->disc.coriolis, (PetscEnum *)&ctx->disc.coriolis, NULL));
  PetscCall(PetscOptionsBool("-clamp_outer", "Also clamp Gamma_C (xi = 0 on the whole boundary, Theorem 1)", NULL, ctx->disc.clamp_outer, &ctx->disc.clamp_outer, NULL));
  PetscCall(PetscOptionsReal("-damping", "Damping eta of the DMF functional", NULL, ctx->disc.damping, &ctx->disc.damping, NULL));
  PetscCall(PetscOptionsBool("-static", "Solve the static contact (Signorini) problem K xi = E N lambda at the obstacle of t = -ts_max_time in one step, the state a damped run with -omega 0 comes to rest in (docs/validation.md section 5)", NULL,
                             ctx->disc.static_solve, &ctx->disc.static_solve, NULL));
  PetscCall(PetscOptionsBool("-solver_schur", "On several ranks: symmetric positive definite step matrices by substructuring (each rank factors its interior, the interface's dense Schur complement on every rank); false: as the non-symmetric ones (-solver_redundant_max) (docs/performance.md)", NULL,
                             ctx->disc.schur, &ctx->disc.schur, NULL));
  PetscCall(PetscOptionsInt("-solver_schur_ranks", "The substructuring on groups of at most this many ranks, each group holding a copy of the step matrix: its dense interface grows with the ranks (bench/rank_model.py: 8 ranks pay most)", NULL,
                            ctx->disc.schur_ranks, &ctx->disc.schur_ranks, NULL));
  PetscCall(PetscOptionsInt("-solver_redundant_max", "On several ranks, step matrices not solved by substructuring (non-symmetric, or -solver_schur false): at most this many unknowns factored whole on every rank (serial Cholesky or LU), larger ones by MUMPS (docs/performance.md)", NULL,
                            ctx->disc.redundant_max, &ctx->disc.redundant_max, NULL));
  PetscOptionsEnd();
  PetscCheck(ctx->disc.schur_ranks >= 2, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-solver_schur_ranks %" PetscInt_FMT " must be >= 2 (a group of one rank: -solver_schur false)", ctx->disc.schur_ranks);
  PetscCheck(ctx->disc.redundant_max >= 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-solver_redundant_max %" PetscInt_FMT " must be >= 0 (0: MUMPS for every step matrix not solved by substructuring)", ctx->disc.redundant_max);
  PetscCheck(ctx->disc.degree >= 1 && ctx->disc.degree <= 3, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-degree %" PetscInt_FMT " must be 1, 2 or 3", ctx->disc.degree);
  PetscCheck(!ctx->mesh.curved || ctx->disc.degree >= 2, ctx->comm, PETSC_ERR_ARG_INCOMP, "-mesh_curved needs -degree 2 or 3 (a P1 field cannot see a curved edge), got -degree %" PetscInt_FMT, ctx->disc.degree);
  RollerCheckOption(ctx->comm, "-damping", ctx->disc.damping, ctx->disc.damping >= 0, ">= 0");
  PetscFunctionReturn(0);
}

static PetscErrorCode Zero(PetscInt dim, PetscReal time, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  for (PetscInt c = 0; c < Nc; ++c) u[c] = 0.0;
  return 0;
}

static PetscErrorCode AddDirichlet(DM dm, const char *name)
{
  DMLabel        label;
  const PetscInt one = 1;

  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(dm, name, &label));
  PetscCheck(label, PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONG, "The mesh has no label \"%s\"", name);
  PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, name, label, 1, &one, 0, 0, NULL, (void (*)(void))Zero, NULL, NULL, NULL));
  PetscFunctionReturn(0);
}

/* The displacement space fe on dm, xi = 0 on Gamma_D (and on Gamma_C with -clamp_outer) removed from the
   global space, so every global vector and matrix lives on the free dofs; an empty PetscDS. */
static PetscErrorCode SpaceSetUp(Roller ctx, DM dm, PetscFE fe)
{
  PetscFunctionBeginUser;
  PetscCall(DMSetField(dm, 0, NULL, (PetscObject)fe));
  PetscCall(DMCreateDS(dm));
  PetscCall(AddDirichlet(dm, "inner"));
  if (ctx->disc.clamp_outer) PetscCall(AddDirichlet(dm, "outer"));
  PetscFunctionReturn(0);
}

/* Lagrange P1, P2 or P3 displacement on ctx->mesh.dm. Its DS holds no kernel and only the material constants,
   set here once: the output's stress projection reads them (f_stress_norm). */
PetscErrorCode RollerDiscretizationSetUp(Roller ctx)
{
  PetscFE fe;
  PetscDS ds;

  PetscFunctionBeginUser;
  /* quadrature of order 2k integrates the mass matrix exactly on affine triangles */
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 2, 2, PETSC_TRUE, ctx->disc.degree, 2 * ctx->disc.degree, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, "displacement"));
  PetscCall(SpaceSetUp(ctx, ctx->mesh.dm, fe));
  PetscCall(PetscFEDestroy(&fe));
  PetscCall(DMGetDS(ctx->mesh.dm, &ds));
  PetscCall(RollerMaterialSetConstants(ctx, ds));
  PetscFunctionReturn(0);
}

/* The DM of one operator: ctx->mesh.dm's mesh (curved geometry included), its displacement space (fe, or
   NULL for the same PetscFE, so the same quadrature) and Dirichlet boundary, hence the same local and global
   layouts, and a PetscDS of its own, empty: the operator sets its kernels and constants there, and no other
   operator sees them. */
PetscErrorCode RollerOperatorDMCreate(Roller ctx, PetscFE fe, DM *dm)
{
  PetscFunctionBeginUser;
  if (!fe) PetscCall(DMGetField(ctx->mesh.dm, 0, NULL, (PetscObject *)&fe));
  PetscCall(DMClone(ctx->mesh.dm, dm));
  PetscCall(SpaceSetUp(ctx, *dm, fe));
  PetscFunctionReturn(0);
}

/* The displacement space on a clone of ctx->mesh.dm WITHOUT the Dirichlet boundary: its global vectors hold every
   node, Gamma_D's too. Only for the set-up products of the rigid hub with the whole body (model/axle.c). */
PetscErrorCode RollerUnconstrainedDMCreate(Roller ctx, DM *dm)
{
  PetscFE fe;

  PetscFunctionBeginUser;
  PetscCall(DMGetField(ctx->mesh.dm, 0, NULL, (PetscObject *)&fe));
  PetscCall(DMClone(ctx->mesh.dm, dm));
  PetscCall(DMSetField(*dm, 0, NULL, (PetscObject)fe));
  PetscCall(DMCreateDS(*dm));
  PetscFunctionReturn(0);
}
