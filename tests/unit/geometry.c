static const char help[] = "Unit test: the curved (isoparametric P2) boundary of -degree 2 (mesh/geometry.c): every geometry node of\n"
                           "Gamma_C (vertices and edge midpoints of the coordinate field) lies on the circle r_outer, every one of Gamma_D\n"
                           "on r_inner, to 1e-14 relative; the discrete |Gamma_C| (ctx->mesh.boundary_length, model/functionals.c) is\n"
                           "2 pi r_outer to O(h^4): relative error < 2e-3 (h/r_outer)^4 (run on two meshes, -mesh_h 0.1 and 0.05), h the Gamma_C\n"
                           "edge: h_c on the meshes graded toward Gamma_C (-mesh_h_contact 0.05 and 0.025 at -mesh_h 0.1).\n";

#include "model/model.h"
#include "unit.h"

/* Every coordinate node of the points of label `name` (vertices and edges) at radius r. */
static PetscErrorCode CheckCircle(Roller ctx, const char *name, PetscReal r)
{
  DM                 cdm;
  PetscSection       section;
  Vec                coordinates;
  DMLabel            label;
  IS                 is;
  const PetscInt    *pts;
  const PetscScalar *x;
  PetscInt           n, nodes[2] = {0, 0}, vStart, vEnd;
  PetscReal          dev = 0;

  PetscFunctionBeginUser;
  PetscCheck(ctx->mesh.curved, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "-degree 2 should make the boundary curved");
  PetscCall(DMGetCoordinateDM(ctx->mesh.dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &section));
  PetscCall(DMGetCoordinatesLocal(ctx->mesh.dm, &coordinates));
  PetscCall(DMPlexGetDepthStratum(ctx->mesh.dm, 0, &vStart, &vEnd));
  PetscCall(DMGetLabel(ctx->mesh.dm, name, &label));
  PetscCall(DMLabelGetStratumIS(label, 1, &is));
  PetscCall(ISGetLocalSize(is, &n));
  PetscCall(ISGetIndices(is, &pts));
  PetscCall(VecGetArrayRead(coordinates, &x));
  for (PetscInt i = 0; i < n; ++i) {
    PetscInt dof, off;

    PetscCall(PetscSectionGetDof(section, pts[i], &dof));
    PetscCall(PetscSectionGetOffset(section, pts[i], &off));
    PetscCheck(dof == 0 || dof == 2, PETSC_COMM_SELF, PETSC_ERR_PLIB, "point %" PetscInt_FMT " of %s has %" PetscInt_FMT " coordinate dofs", pts[i], name, dof);
    if (!dof) continue;
    dev = PetscMax(dev, PetscAbsReal(PetscSqrtReal(PetscSqr(PetscRealPart(x[off])) + PetscSqr(PetscRealPart(x[off + 1]))) - r));
    ++nodes[pts[i] >= vStart && pts[i] < vEnd ? 0 : 1];
  }
  PetscCall(VecRestoreArrayRead(coordinates, &x));
  PetscCall(ISRestoreIndices(is, &pts));
  PetscCall(ISDestroy(&is));
  /* a closed polygon: as many edges as vertices, each edge with its P2 geometry node */
  PetscCheck(nodes[0] >= 3 && nodes[1] == nodes[0], PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s: %" PetscInt_FMT " vertex and %" PetscInt_FMT " edge geometry nodes, expected as many edges as vertices (P2 geometry)", name, nodes[0], nodes[1]);
  PetscCheck(dev <= 1e-14 * r, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s: a geometry node lies %g off the circle r = %g (relative %g > 1e-14)", name, (double)dev, (double)r, (double)(dev / r));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "h %g (h_c %g): %" PetscInt_FMT " vertices and %" PetscInt_FMT " edge nodes of %s on r = %g to %.1e relative\n", (double)ctx->mesh.h, (double)ctx->mesh.h_contact, nodes[0], nodes[1], name, (double)r, (double)(dev / r)));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  Roller    ctx;
  PetscReal exact, err, h, rel;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsSetValue(NULL, "-degree", "2"));
  PetscCall(RollerUnitAnnulus(&ctx)); /* one Roller per process: RollerCreate registers the log stages */
  PetscCall(CheckCircle(ctx, "outer", ctx->mesh.r_outer));
  PetscCall(CheckCircle(ctx, "inner", ctx->mesh.r_inner));
  /* The P2 edge interpolates its arc at both ends and the middle: for an edge of angle theta the discrete length
     is short by ~ theta^4/1000 relative (measured 0.96e-3 to 1.03e-3 (h/r)^4 for h = 0.2 ... 0.025), two orders
     in h below the polygon's theta^2/24. Bounded by 2e-3 (h/r)^4 on every mesh, the error is O(h^4). */
  exact = 2 * PETSC_PI * ctx->mesh.r_outer;
  err   = (exact - ctx->mesh.boundary_length) / exact;
  h     = (ctx->mesh.h_contact > 0 ? ctx->mesh.h_contact : ctx->mesh.h) / ctx->mesh.r_outer; /* the Gamma_C edge */
  rel   = err / PetscPowReal(h, 4);
  PetscCheck(err > 0 && rel < 2e-3, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "Gamma_C edge %g: |Gamma_C| = %.16g, 2 pi r_outer = %.16g: relative error %g = %g (h/r)^4, expected in (0, 2e-3 (h/r)^4)", (double)(h * ctx->mesh.r_outer), (double)ctx->mesh.boundary_length, (double)exact, (double)err, (double)rel);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Gamma_C edge %g: |Gamma_C| = %.15g, relative error %.3e = %.2e (h/r)^4 < 2e-3 (h/r)^4\n", (double)(h * ctx->mesh.r_outer), (double)ctx->mesh.boundary_length, (double)err, (double)rel));
  PetscCall(RollerDestroy(&ctx));
  PetscCall(PetscFinalize());
  return 0;
}
