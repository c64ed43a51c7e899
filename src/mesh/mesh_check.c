/* The cells of a mesh file checked at read time (issue 26): counter-clockwise, none inverted or degenerate. A gmsh
   annulus whose surface was meshed with clockwise curves has every cell clockwise (negative Jacobian): its
   outward normals point inward and the step matrix of a contact run is singular ("zero pivot" at step 1), so it is
   refused here with the reason and the fix. */
#include "mesh/mesh.h"

PetscErrorCode RollerMeshCheckOrientation(Roller ctx, const char *what)
{
  PetscInt  c_start, c_end, first[2] = {-1, -1};
  PetscReal v0[2], J[4], invJ[4], detJ, count[4] = {0, 0, 0, 0}, global[4]; /* cells, clockwise, |det| max, -|det| min */

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(ctx->mesh.dm, 0, &c_start, &c_end));
  count[3] = -PETSC_MAX_REAL;
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscCall(DMPlexComputeCellGeometryAffineFEM(ctx->mesh.dm, c, v0, J, invJ, &detJ));
    count[0] += 1;
    if (detJ < 0) {
      count[1] += 1;
      if (first[0] < 0) first[0] = c;
    }
    count[2] = PetscMax(count[2], PetscAbsReal(detJ));
    count[3] = PetscMax(count[3], -PetscAbsReal(detJ));
  }
  PetscCall(MPIU_Allreduce(count, global, 2, MPIU_REAL, MPI_SUM, ctx->comm));
  PetscCall(MPIU_Allreduce(count + 2, global + 2, 2, MPIU_REAL, MPI_MAX, ctx->comm));
  PetscCheck(global[1] < global[0], ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: every cell is clockwise (negative Jacobian), the surface was meshed with clockwise curves; Roller needs counter-clockwise cells (outward normals): reverse it in gmsh (ReverseMesh Surface{:}; in the .geo file, or the curve loop's orientation)", what);
  PetscCheck(global[1] == 0, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: %.0f of %.0f cells are inverted (clockwise, negative Jacobian) while the others are not: the mesh is tangled", what, (double)global[1], (double)global[0]);
  PetscCheck(-global[3] > 1e-10 * global[2], ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: a degenerate cell (area %g, the largest %g: relative %g <= 1e-10)", what, (double)(-global[3] / 2), (double)(global[2] / 2), (double)(-global[3] / global[2]));
  PetscFunctionReturn(0);
}
