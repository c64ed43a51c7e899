/* The in-process gmsh annulus (the geometry of meshes/annulus.geo) through the gmsh C API, uniform at -mesh_h or
   graded toward Gamma_C (-mesh_h_contact h_c, -mesh_contact_layer L).

   Grading (docs/contact.md, "Graded mesh"): in the co-rotating frame the contact patch travels around the whole
   outer circle, so the fine layer runs all the way around it. A gmsh "Distance" field measures the distance d
   to the outer circle and a "Threshold" field sets the edge length h_c for d <= L, growing linearly to h at
   d = L + 3 (h - h_c) (a gradient of 1/3: neighbouring elements differ by about a third at most) and h beyond,
   as the background mesh; the sizes of the points and their extension from the boundary are switched off, so
   that the outer circle's edges are all h_c (one sharp element-passing line: every Gamma_C edge equal) and the
   inner circle keeps h. */
#include "mesh/mesh.h"
#include <gmshc.h>

/* Distance sample points per edge of length h_c on the outer curves: every point of the outer circle then lies
   within h_c/4 of a sample, so the size on the circle is h_c for any layer L >= h_c/4 (and -mesh_contact_layer
   must be >= h_c). */
#define ROLLER_MESH_SAMPLES_PER_EDGE 2

/* The size field of the graded mesh (gmsh state of rank 0, after synchronize): see the top of the file. */
static void RollerMeshGradingField(const RollerMesh *mesh, const int outer[2], int *ierr)
{
  const double h = mesh->h, h_c = mesh->h_contact, layer = mesh->contact_layer;
  const double samples = ceil(ROLLER_MESH_SAMPLES_PER_EDGE * PETSC_PI * mesh->r_outer / h_c); /* per half circle */
  double       curves[2];
  int          distance = -1, threshold = -1;

  curves[0] = outer[0];
  curves[1] = outer[1];
  distance  = gmshModelMeshFieldAdd("Distance", -1, ierr);
  if (!*ierr) gmshModelMeshFieldSetNumbers(distance, "CurvesList", curves, 2, ierr);
  if (!*ierr) gmshModelMeshFieldSetNumber(distance, "NumPointsPerCurve", samples, ierr);
  if (!*ierr) threshold = gmshModelMeshFieldAdd("Threshold", -1, ierr);
  if (!*ierr) gmshModelMeshFieldSetNumber(threshold, "InField", distance, ierr);
  if (!*ierr) gmshModelMeshFieldSetNumber(threshold, "SizeMin", h_c, ierr);
  if (!*ierr) gmshModelMeshFieldSetNumber(threshold, "SizeMax", h, ierr);
  if (!*ierr) gmshModelMeshFieldSetNumber(threshold, "DistMin", layer, ierr);
  if (!*ierr) gmshModelMeshFieldSetNumber(threshold, "DistMax", layer + 3 * (h - h_c), ierr);
  if (!*ierr) gmshModelMeshFieldSetAsBackgroundMesh(threshold, ierr);
}

/* Meshes the annulus on rank 0 and writes it as msh 4.1 into a fresh temporary directory `dir` (file `file`),
   so that it is read through the same path as a user's file. */
PetscErrorCode RollerMeshGenerate(Roller ctx, PetscBool verbose, char dir[], char file[])
{
  const RollerMesh *mesh   = &ctx->mesh;
  const PetscBool   graded = (PetscBool)(mesh->h_contact > 0);
  PetscMPIInt       rank;
  int               ierr = 0;

  PetscFunctionBeginUser;
  PetscCheck(mesh->h > 0 && mesh->h <= mesh->r_outer - mesh->r_inner, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_h %g must lie in (0, r_outer - r_inner = %g]", (double)mesh->h, (double)(mesh->r_outer - mesh->r_inner));
  PetscCheck(mesh->h_contact <= mesh->h, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_h_contact %g must not exceed the bulk edge length -mesh_h %g (%s): allowed 0 (uniform) or (0, %g]", (double)mesh->h_contact, (double)mesh->h, mesh->h_set ? "given" : "chosen from -ts_phase_error",
             (double)mesh->h);
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  if (rank == 0) {
    const double h = mesh->h, ri = mesh->r_inner, ro = mesh->r_outer;
    int          loops[2], inner[2], outer[2], body;

    PetscCall(PetscGetTmp(PETSC_COMM_SELF, dir, PETSC_MAX_PATH_LEN));
    PetscCall(PetscStrlcat(dir, "/roller-mesh-XXXXXX", PETSC_MAX_PATH_LEN));
    PetscCall(PetscMkdtemp(dir));
    PetscCall(PetscSNPrintf(file, PETSC_MAX_PATH_LEN, "%s/annulus.msh", dir));
    gmshInitialize(0, NULL, 0, &ierr);
    if (!ierr) gmshOptionSetNumber("General.Terminal", verbose ? 1 : 0, &ierr);
    if (!ierr) gmshModelAdd("roller", &ierr);
    /* Two half circles per boundary, as in meshes/annulus.geo, so both meshes agree for equal h. */
    if (!ierr) gmshModelGeoAddPoint(0, 0, 0, h, 1, &ierr);
    if (!ierr) gmshModelGeoAddPoint(ri, 0, 0, h, 2, &ierr);
    if (!ierr) gmshModelGeoAddPoint(-ri, 0, 0, h, 3, &ierr);
    if (!ierr) gmshModelGeoAddPoint(ro, 0, 0, h, 4, &ierr);
    if (!ierr) gmshModelGeoAddPoint(-ro, 0, 0, h, 5, &ierr);
    if (!ierr) inner[0] = gmshModelGeoAddCircleArc(2, 1, 3, 1, 0, 0, 0, &ierr);
    if (!ierr) inner[1] = gmshModelGeoAddCircleArc(3, 1, 2, 2, 0, 0, 0, &ierr);
    if (!ierr) outer[0] = gmshModelGeoAddCircleArc(4, 1, 5, 3, 0, 0, 0, &ierr);
    if (!ierr) outer[1] = gmshModelGeoAddCircleArc(5, 1, 4, 4, 0, 0, 0, &ierr);
    if (!ierr) loops[0] = gmshModelGeoAddCurveLoop(outer, 2, 1, 0, &ierr);
    if (!ierr) loops[1] = gmshModelGeoAddCurveLoop(inner, 2, 2, 0, &ierr);
    if (!ierr) body = gmshModelGeoAddPlaneSurface(loops, 2, 1, &ierr);
    if (!ierr) gmshModelGeoSynchronize(&ierr);
    if (!ierr) gmshModelAddPhysicalGroup(1, inner, 2, 1, &ierr);
    if (!ierr) gmshModelSetPhysicalName(1, 1, "inner", &ierr);
    if (!ierr) gmshModelAddPhysicalGroup(1, outer, 2, 2, &ierr);
    if (!ierr) gmshModelSetPhysicalName(1, 2, "outer", &ierr);
    if (!ierr) gmshModelAddPhysicalGroup(2, &body, 1, 3, &ierr);
    if (!ierr) gmshModelSetPhysicalName(2, 3, "body", &ierr);
    if (!ierr && graded) RollerMeshGradingField(mesh, outer, &ierr);
    if (!ierr) gmshOptionSetNumber("Mesh.CharacteristicLengthFromPoints", graded ? 0 : 1, &ierr);
    if (!ierr) gmshOptionSetNumber("Mesh.CharacteristicLengthExtendFromBoundary", graded ? 0 : 1, &ierr);
    if (!ierr) gmshModelMeshGenerate(2, &ierr);
    if (!ierr) gmshOptionSetNumber("Mesh.MshFileVersion", 4.1, &ierr);
    if (!ierr) gmshOptionSetNumber("Mesh.Binary", 0, &ierr);
    if (!ierr) gmshWrite(file, &ierr);
    {
      int ierr_finalize;
      gmshFinalize(&ierr_finalize);
    }
    if (ierr) PetscCall(PetscRMTree(dir)); /* nothing left behind by a mesh that failed */
  }
  PetscCallMPI(MPI_Bcast(&ierr, 1, MPI_INT, 0, ctx->comm));
  PetscCheck(!ierr, ctx->comm, PETSC_ERR_LIB, "gmsh failed (error %d) to mesh the annulus r_inner %g, r_outer %g at -mesh_h %g (-mesh_h_contact %g, -mesh_contact_layer %g); rerun with -mesh_gmsh_verbose", ierr, (double)mesh->r_inner, (double)mesh->r_outer,
             (double)mesh->h, (double)mesh->h_contact, (double)mesh->contact_layer);
  PetscCallMPI(MPI_Bcast(file, PETSC_MAX_PATH_LEN, MPI_CHAR, 0, ctx->comm));
  PetscFunctionReturn(0);
}
