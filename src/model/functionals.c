/* The boundary functionals behind R and alpha (docs/model.md section 4): w_R . xi = int_{Gamma_C} xi . x/|x| ds,
   w_alpha . xi = int_{Gamma_C} xi . x_perp/|x| ds, and |Gamma_C|; the circumferential orders of xi . x/|x| (the
   surface's radial displacement, -monitor_surface_csv), integrated by PETSc over the faces of the
   "outer" label on the discrete (polygonal, or curved P2) Gamma_C. */
#include "model/model.h"
#include "model/kernels.h"

/* The displacement space with a 5-point Gauss rule on its faces: x/|x| on a curved edge is not a polynomial,
   so the rule is part of R and alpha; 5 points is the rule of every result so far (the default, k + 1 points,
   would move R and alpha by ~1e-8). */
static PetscErrorCode FunctionalSpace(Roller ctx, PetscFE *fe)
{
  PetscQuadrature q;

  PetscFunctionBeginUser;
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 2, 2, PETSC_TRUE, ctx->disc.degree, 2 * ctx->disc.degree, fe));
  PetscCall(PetscObjectSetName((PetscObject)*fe, "displacement"));
  PetscCall(PetscDTGaussTensorQuadrature(1, 1, 5, -1.0, 1.0, &q));
  PetscCall(PetscFESetFaceQuadrature(*fe, q));
  PetscCall(PetscQuadratureDestroy(&q));
  PetscFunctionReturn(0);
}

/* The faces of Gamma_C on this rank and their geometry at the face quadrature points, with the face data
   (local face number, supporting cell's Jacobians) of PetscFEIntegrateBd*. Not DMPlexComputeBdResidualSingle or
   DMPlexComputeBdIntegral: in PETSc 3.18 DMFieldCreateFEGeom sets isAffine from the degree DMFieldGetDegree
   gives for the faces, -1 for a P2 coordinate field (its height trace has no maximum degree), so a curved edge
   is integrated as the straight segment through its first quadrature point (|Gamma_C| off by 5e-4 at
   h = 1/16). Every point's position, Jacobian and face data are computed right (the face data from the
   cells' degree); isAffine is set here from the cells' degree too. */
static PetscErrorCode OuterFacesGeometry(DM dm, DMLabel label, PetscQuadrature q, IS *faces, PetscFEGeom **geom)
{
  IS       all, is, cells;
  PetscInt fStart, fEnd, cStart, cEnd, degree;
  DMField  coordinates;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, fEnd - fStart, fStart, 1, &all));
  PetscCall(DMLabelGetStratumIS(label, 1, &is));
  if (is) PetscCall(ISIntersect(all, is, faces));
  else PetscCall(ISCreateStride(PETSC_COMM_SELF, 0, 0, 1, faces));
  PetscCall(ISDestroy(&all));
  PetscCall(ISDestroy(&is));
  PetscCall(DMGetCoordinateField(dm, &coordinates));
  PetscCall(DMFieldCreateFEGeom(coordinates, *faces, q, PETSC_TRUE, geom));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, cEnd - cStart, cStart, 1, &cells));
  PetscCall(DMFieldGetDegree(coordinates, cells, NULL, &degree)); /* the cells' degree: 2 for the curved geometry */
  PetscCall(ISDestroy(&cells));
  (*geom)->isAffine = (PetscBool)(degree <= 1);
  PetscFunctionReturn(0);
}

/* The faces of Gamma_C with the functionals' space, two boundary residuals (parts 0 and 1 of the weak form) and
   scratch: what each set of functionals integrates. */
typedef struct {
  PetscFE         fe;
  DM              dm; /* a clone of ctx->mesh.dm with a DS of its own */
  PetscDS         ds;
  PetscWeakForm   wf;
  PetscFormKey    key;
  PetscFEGeom    *geom;
  IS              faces;
  const PetscInt *f;
  PetscInt        n, totDim;
  PetscScalar    *u, *elem;
} Faces;

typedef void (*BdKernel)(ROLLER_KERNEL_ARGS, const PetscReal[], const PetscReal[], PetscInt, const PetscScalar[], PetscScalar[]);

static PetscErrorCode FacesCreate(Roller ctx, BdKernel part0, BdKernel part1, Faces *F)
{
  DMLabel         label;
  PetscQuadrature q;

  PetscFunctionBeginUser;
  PetscCall(FunctionalSpace(ctx, &F->fe));
  PetscCall(RollerOperatorDMCreate(ctx, F->fe, &F->dm));
  PetscCall(DMGetLabel(F->dm, "outer", &label));
  PetscCall(DMGetDS(F->dm, &F->ds));
  PetscCall(PetscDSGetTotalDimension(F->ds, &F->totDim));
  PetscCall(PetscDSGetWeakForm(F->ds, &F->wf));
  PetscCall(PetscWeakFormSetIndexBdResidual(F->wf, label, 1, 0, 0, 0, part0, 0, NULL));
  PetscCall(PetscWeakFormSetIndexBdResidual(F->wf, label, 1, 0, 1, 0, part1, 0, NULL));
  PetscCall(PetscFEGetFaceQuadrature(F->fe, &q));
  PetscCall(OuterFacesGeometry(F->dm, label, q, &F->faces, &F->geom));
  PetscCall(ISGetLocalSize(F->faces, &F->n));
  PetscCall(ISGetIndices(F->faces, &F->f));
  PetscCall(PetscCalloc2(F->n * F->totDim, &F->u, F->n * F->totDim, &F->elem));
  F->key.label = label;
  F->key.value = 1;
  F->key.field = 0;
  PetscFunctionReturn(0);
}

static PetscErrorCode FacesDestroy(Faces *F)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(F->u, F->elem));
  PetscCall(ISRestoreIndices(F->faces, &F->f));
  PetscCall(ISDestroy(&F->faces));
  PetscCall(PetscFEGeomDestroy(&F->geom));
  PetscCall(PetscFEDestroy(&F->fe));
  PetscCall(DMDestroy(&F->dm));
  PetscFunctionReturn(0);
}

/* w = the boundary residual `part` integrated over the faces, assembled into a new global vector on ctx->mesh.dm. */
static PetscErrorCode FacesIntegrate(Roller ctx, Faces *F, PetscInt part, Vec *w)
{
  Vec loc;

  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, w));
  F->key.part = part;
  PetscCall(DMGetLocalVector(F->dm, &loc));
  PetscCall(PetscArrayzero(F->elem, F->n * F->totDim));
  PetscCall(PetscFEIntegrateBdResidual(F->ds, F->wf, F->key, F->n, F->geom, F->u, NULL, NULL, NULL, 0.0, F->elem));
  PetscCall(VecZeroEntries(loc));
  for (PetscInt i = 0; i < F->n; ++i) {
    const PetscInt *support;

    PetscCall(DMPlexGetSupport(F->dm, F->f[i], &support));
    PetscCall(DMPlexVecSetClosure(F->dm, NULL, loc, support[0], &F->elem[i * F->totDim], ADD_ALL_VALUES));
  }
  PetscCall(DMLocalToGlobal(F->dm, loc, ADD_VALUES, *w));
  PetscCall(DMRestoreLocalVector(F->dm, &loc));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerComputeBoundaryFunctionals(Roller ctx)
{
  Faces       F;
  PetscScalar length = 0.0;

  PetscFunctionBeginUser;
  /* two boundary residuals on Gamma_C, parts 0 (w_R) and 1 (w_alpha) of the weak form */
  PetscCall(FacesCreate(ctx, f0_bd_radial, f0_bd_angular, &F));
  PetscCall(FacesIntegrate(ctx, &F, 0, &ctx->ops.w_R));
  PetscCall(FacesIntegrate(ctx, &F, 1, &ctx->ops.w_alpha));
  /* |Gamma_C|; a boundary face is in the closure of one cell, so on one rank (overlap 0): the local sums add */
  PetscCall(PetscArrayzero(F.elem, F.n));
  PetscCall(PetscFEIntegrateBd(F.ds, 0, f_bd_one, F.n, F.geom, F.u, NULL, NULL, F.elem));
  for (PetscInt i = 0; i < F.n; ++i) length += F.elem[i];
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &length, 1, MPIU_SCALAR, MPIU_SUM, ctx->comm));
  ctx->mesh.boundary_length = PetscRealPart(length);
  PetscCall(FacesDestroy(&F));
  PetscFunctionReturn(0);
}

/* The circumferential orders of the radial displacement on Gamma_C (docs/output.md, -monitor_surface_csv): w[2 (n - 1)]
   . xi = (2 / |Gamma_C|) int xi . x/|x| cos(n phi) ds and w[2 (n - 1) + 1] the same with sin(n phi), n = 1 ... orders,
   phi the material (co-rotating) angle: xi_r(phi) = R + sum_n c_n cos(n phi) + s_n sin(n phi). The same faces, space
   and 5-point rule as w_R; after RollerComputeBoundaryFunctionals (|Gamma_C|). */
PetscErrorCode RollerComputeOrderFunctionals(Roller ctx, PetscInt orders, Vec w[])
{
  Faces F;

  PetscFunctionBeginUser;
  PetscCall(FacesCreate(ctx, f0_bd_radial_cos, f0_bd_radial_sin, &F));
  for (PetscInt k = 1; k <= orders; ++k) {
    PetscScalar order = (PetscScalar)k;

    PetscCall(PetscDSSetConstants(F.ds, 1, &order));
    for (PetscInt part = 0; part < 2; ++part) {
      PetscCall(FacesIntegrate(ctx, &F, part, &w[2 * (k - 1) + part]));
      PetscCall(VecScale(w[2 * (k - 1) + part], 2.0 / ctx->mesh.boundary_length));
    }
  }
  PetscCall(FacesDestroy(&F));
  PetscFunctionReturn(0);
}
