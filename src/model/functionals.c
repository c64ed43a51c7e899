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

/* w += the boundary residual `key` integrated over the n faces f of Gamma_C (their geometry geom), assembled
   into the global vector w (on ctx->mesh.dm's layout: dm is its clone). u, elem: n * totDim of scratch. */
static PetscErrorCode IntegrateFaces(DM dm, PetscDS ds, PetscWeakForm wf, PetscFormKey key, PetscInt n, const PetscInt f[], PetscFEGeom *geom, PetscScalar u[], PetscScalar elem[], Vec w)
{
  PetscInt totDim;
  Vec      loc;

  PetscFunctionBeginUser;
  PetscCall(PetscDSGetTotalDimension(ds, &totDim));
  PetscCall(DMGetLocalVector(dm, &loc));
  PetscCall(PetscArrayzero(elem, n * totDim));
  PetscCall(PetscFEIntegrateBdResidual(ds, wf, key, n, geom, u, NULL, NULL, NULL, 0.0, elem));
  PetscCall(VecZeroEntries(loc));
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt *support;

    PetscCall(DMPlexGetSupport(dm, f[i], &support));
    PetscCall(DMPlexVecSetClosure(dm, NULL, loc, support[0], &elem[i * totDim], ADD_ALL_VALUES));
  }
  PetscCall(DMLocalToGlobal(dm, loc, ADD_VALUES, w));
  PetscCall(DMRestoreLocalVector(dm, &loc));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerComputeBoundaryFunctionals(Roller ctx)
{
  PetscFE         fe;
  DM              dm;
  DMLabel         label;
  PetscDS         ds;
  PetscWeakForm   wf;
  PetscFormKey    key;
  PetscQuadrature q;
  PetscFEGeom    *geom;
  IS              faces;
  const PetscInt *f;
  PetscInt        n, totDim;
  PetscScalar    *u, *elem, length = 0.0;
  Vec             w[2];

  PetscFunctionBeginUser;
  PetscCall(FunctionalSpace(ctx, &fe));
  PetscCall(RollerOperatorDMCreate(ctx, fe, &dm));
  PetscCall(DMGetLabel(dm, "outer", &label));
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(PetscDSGetTotalDimension(ds, &totDim));
  PetscCall(PetscDSGetWeakForm(ds, &wf));
  /* two boundary residuals on Gamma_C, parts 0 (w_R) and 1 (w_alpha) of the weak form */
  PetscCall(PetscWeakFormSetIndexBdResidual(wf, label, 1, 0, 0, 0, f0_bd_radial, 0, NULL));
  PetscCall(PetscWeakFormSetIndexBdResidual(wf, label, 1, 0, 1, 0, f0_bd_angular, 0, NULL));
  PetscCall(PetscFEGetFaceQuadrature(fe, &q));
  PetscCall(OuterFacesGeometry(dm, label, q, &faces, &geom));
  PetscCall(ISGetLocalSize(faces, &n));
  PetscCall(ISGetIndices(faces, &f));
  PetscCall(PetscCalloc2(n * totDim, &u, n * totDim, &elem));
  key.label = label;
  key.value = 1;
  key.field = 0;
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, &ctx->ops.w_R));
  PetscCall(DMCreateGlobalVector(ctx->mesh.dm, &ctx->ops.w_alpha));
  w[0] = ctx->ops.w_R;
  w[1] = ctx->ops.w_alpha;
  for (key.part = 0; key.part < 2; ++key.part) PetscCall(IntegrateFaces(dm, ds, wf, key, n, f, geom, u, elem, w[key.part]));
  /* |Gamma_C|; a boundary face is in the closure of one cell, so on one rank (overlap 0): the local sums add */
  PetscCall(PetscArrayzero(elem, n));
  PetscCall(PetscFEIntegrateBd(ds, 0, f_bd_one, n, geom, u, NULL, NULL, elem));
  for (PetscInt i = 0; i < n; ++i) length += elem[i];
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &length, 1, MPIU_SCALAR, MPIU_SUM, ctx->comm));
  ctx->mesh.boundary_length = PetscRealPart(length);
  PetscCall(PetscFree2(u, elem));
  PetscCall(ISRestoreIndices(faces, &f));
  PetscCall(ISDestroy(&faces));
  PetscCall(PetscFEGeomDestroy(&geom));
  PetscCall(PetscFEDestroy(&fe));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

/* The circumferential orders of the radial displacement on Gamma_C (docs/output.md, -monitor_surface_csv): w[2 (n - 1)]
   . xi = (2 / |Gamma_C|) int xi . x/|x| cos(n phi) ds and w[2 (n - 1) + 1] the same with sin(n phi), n = 1 ... orders,
   phi the material (co-rotating) angle: xi_r(phi) = R + sum_n c_n cos(n phi) + s_n sin(n phi). The same faces, space
   and 5-point rule as w_R; after RollerComputeBoundaryFunctionals (|Gamma_C|). */
PetscErrorCode RollerComputeOrderFunctionals(Roller ctx, PetscInt orders, Vec w[])
{
  PetscFE         fe;
  DM              dm;
  DMLabel         label;
  PetscDS         ds;
  PetscWeakForm   wf;
  PetscFormKey    key;
  PetscQuadrature q;
  PetscFEGeom    *geom;
  IS              faces;
  const PetscInt *f;
  PetscInt        n, totDim;
  PetscScalar    *u, *elem;

  PetscFunctionBeginUser;
  PetscCall(FunctionalSpace(ctx, &fe));
  PetscCall(RollerOperatorDMCreate(ctx, fe, &dm));
  PetscCall(DMGetLabel(dm, "outer", &label));
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(PetscDSGetTotalDimension(ds, &totDim));
  PetscCall(PetscDSGetWeakForm(ds, &wf));
  PetscCall(PetscWeakFormSetIndexBdResidual(wf, label, 1, 0, 0, 0, f0_bd_radial_cos, 0, NULL));
  PetscCall(PetscWeakFormSetIndexBdResidual(wf, label, 1, 0, 1, 0, f0_bd_radial_sin, 0, NULL));
  PetscCall(PetscFEGetFaceQuadrature(fe, &q));
  PetscCall(OuterFacesGeometry(dm, label, q, &faces, &geom));
  PetscCall(ISGetLocalSize(faces, &n));
  PetscCall(ISGetIndices(faces, &f));
  PetscCall(PetscCalloc2(n * totDim, &u, n * totDim, &elem));
  key.label = label;
  key.value = 1;
  key.field = 0;
  for (PetscInt k = 1; k <= orders; ++k) {
    PetscScalar order = (PetscScalar)k;

    PetscCall(PetscDSSetConstants(ds, 1, &order));
    for (key.part = 0; key.part < 2; ++key.part) {
      Vec *wk = &w[2 * (k - 1) + key.part];

      PetscCall(DMCreateGlobalVector(ctx->mesh.dm, wk));
      PetscCall(IntegrateFaces(dm, ds, wf, key, n, f, geom, u, elem, *wk));
      PetscCall(VecScale(*wk, 2.0 / ctx->mesh.boundary_length));
    }
  }
  PetscCall(PetscFree2(u, elem));
  PetscCall(ISRestoreIndices(faces, &f));
  PetscCall(ISDestroy(&faces));
  PetscCall(PetscFEGeomDestroy(&geom));
  PetscCall(PetscFEDestroy(&fe));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}
