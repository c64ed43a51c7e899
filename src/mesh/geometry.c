/* The curved (isoparametric) boundary. A gmsh mesh has straight edges: its outer boundary is the polygon
   inscribed in the circle r = r_outer, and the annulus it bounds is too small by O(h^2) (relative area
   error about (2 pi / N)^2 / 6 for N boundary edges). For P1 that is below the discretization error; for P2
   it is not: on the figure-4 scene it stalls the error in R at 2.7 % whatever dt (docs/performance.md).
   With -degree 2 the mesh geometry is made P2 too (DMPlexCreateCoordinateSpace) and the mid-edge
   geometry node of every edge of Gamma_D and Gamma_C is moved radially onto its circle: the elements
   next to the boundary become curved and the discrete domain is the annulus to O(h^3) (-mesh_curved,
   default on with -degree 2). Every integral (M, K, loads, R, alpha, errors) then uses the curved map.
   The straight-sided DM is kept for the HDF5/XDMF mesh (ctx->mesh.dm_view): ParaView draws linear cells. */
#include "mesh/mesh.h"

/* Moves the geometry node of every edge of `label` onto the circle of radius r: the midpoint m of an
   edge v0 v1 with |v0| = |v1| = r goes to r m / |m|. Every rank moves its local (owned and ghost) edges
   the same way, so the local coordinates stay consistent. */
static PetscErrorCode SnapEdges(Roller ctx, const char *name, PetscReal r, Vec coordinates, PetscSection section)
{
  DMLabel         label;
  IS              is;
  const PetscInt *points;
  PetscInt        n = 0, e_start, e_end;
  PetscScalar    *x;

  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(ctx->mesh.dm, name, &label));
  PetscCall(DMPlexGetHeightStratum(ctx->mesh.dm, 1, &e_start, &e_end));
  PetscCall(DMLabelGetStratumIS(label, 1, &is));
  if (is) PetscCall(ISGetLocalSize(is, &n));
  if (is) PetscCall(ISGetIndices(is, &points));
  PetscCall(VecGetArray(coordinates, &x));
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt e = points[i];
    PetscInt       dof, off;
    PetscReal      m;

    if (e < e_start || e >= e_end) continue;
    PetscCall(PetscSectionGetDof(section, e, &dof));
    PetscCall(PetscSectionGetOffset(section, e, &off));
    PetscCheck(dof == 2, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Edge %" PetscInt_FMT " of \"%s\" has %" PetscInt_FMT " coordinate dofs, expected 2 (P2 geometry)", e, name, dof);
    m = PetscSqrtReal(PetscSqr(PetscRealPart(x[off])) + PetscSqr(PetscRealPart(x[off + 1])));
    PetscCheck(m > 0.5 * r, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Edge %" PetscInt_FMT " of \"%s\" has its midpoint at |x| = %g, far from the circle r = %g", e, name, (double)m, (double)r);
    x[off] *= r / m;
    x[off + 1] *= r / m;
  }
  PetscCall(VecRestoreArray(coordinates, &x));
  if (is) PetscCall(ISRestoreIndices(is, &points));
  PetscCall(ISDestroy(&is));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerGeometrySetUp(Roller ctx)
{
  DM           cdm;
  Vec          coordinates;
  PetscSection section;

  PetscFunctionBeginUser;
  if (!ctx->mesh.curved) {
    PetscCall(PetscObjectReference((PetscObject)ctx->mesh.dm));
    ctx->mesh.dm_view = ctx->mesh.dm;
    PetscFunctionReturn(0);
  }
  PetscCall(DMClone(ctx->mesh.dm, &ctx->mesh.dm_view)); /* keeps the straight-sided coordinate DM */
  PetscCall(DMPlexCreateCoordinateSpace(ctx->mesh.dm, 2, NULL));
  PetscCall(DMGetCoordinateDM(ctx->mesh.dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &section));
  PetscCall(DMGetCoordinatesLocal(ctx->mesh.dm, &coordinates));
  PetscCall(SnapEdges(ctx, "inner", ctx->mesh.r_inner, coordinates, section));
  PetscCall(SnapEdges(ctx, "outer", ctx->mesh.r_outer, coordinates, section));
  PetscCall(DMSetCoordinatesLocal(ctx->mesh.dm, coordinates)); /* the global coordinates are rebuilt from these */
  PetscFunctionReturn(0);
}
