/* The annulus mesh (docs/model.md section 3): gmsh, either in-process through its C API (mesh/generate.c) or a
   user's .msh file, read into DMPlex; the labels "inner" (Gamma_D) and "outer" (Gamma_C); the checks that the mesh really is a
   triangulated annulus about the origin; the measures of the distributed mesh; the mesh options. */
#include "mesh/mesh.h"

/* Relative spread allowed for the radii of the vertices of one boundary circle. */
#define ROLLER_MESH_RTOL 1e-6

/* The physical groups Roller needs, identified by name, and the dimension each must have. */
typedef enum { ROLLER_GROUP_INNER, ROLLER_GROUP_OUTER, ROLLER_GROUP_BODY, ROLLER_NUM_GROUPS } RollerGroup;
static const char *const roller_group_names[ROLLER_NUM_GROUPS] = {"inner", "outer", "body"};
static const int         roller_group_dims[ROLLER_NUM_GROUPS]  = {1, 1, 2};

/* The physical tags of the groups (-1: missing) and, for error messages, the names the file has. */
typedef struct {
  PetscInt tags[ROLLER_NUM_GROUPS];
  char     found[256];
} RollerMeshGroups;

/* Reads the header and $PhysicalNames of a gmsh file on rank 0 and maps the group names to physical tags.
   We parse the names ourselves because -dm_plex_gmsh_use_regions mislabels msh 2.2 files (PETSC-NOTES.md);
   $PhysicalNames precedes $Entities/$Nodes in both 2.2 and 4.x. */
static PetscErrorCode RollerMeshReadPhysicalNames(Roller ctx, const char *file, const char *what, RollerMeshGroups *groups)
{
  PetscMPIInt rank;
  PetscInt    status[2 + ROLLER_NUM_GROUPS] = {0, 0, -1, -1, -1}; /* opened, format major version, tags */
  char       *found                         = groups->found;

  PetscFunctionBeginUser;
  found[0] = 0;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  if (rank == 0) {
    FILE *fp = fopen(file, "r");
    char  line[PETSC_MAX_PATH_LEN];

    if (fp) {
      status[0] = 1;
      while (fgets(line, sizeof(line), fp)) {
        if (!strncmp(line, "$MeshFormat", 11)) {
          double version = 0;
          if (fgets(line, sizeof(line), fp) && sscanf(line, "%lf", &version) == 1) status[1] = (PetscInt)version;
        } else if (!strncmp(line, "$PhysicalNames", 14)) {
          int n = 0;
          if (!fgets(line, sizeof(line), fp) || sscanf(line, "%d", &n) != 1) break;
          for (int i = 0; i < n && fgets(line, sizeof(line), fp); ++i) {
            int  dim, tag;
            char name[PETSC_MAX_PATH_LEN];

            if (sscanf(line, "%d %d \"%[^\"]\"", &dim, &tag, name) != 3) continue;
            if (strlen(found) + strlen(name) + 4 < sizeof(groups->found)) PetscCall(PetscSNPrintf(found + strlen(found), sizeof(groups->found) - strlen(found), "%s\"%s\"", found[0] ? ", " : "", name));
            for (int g = 0; g < ROLLER_NUM_GROUPS; ++g)
              if (!strcmp(name, roller_group_names[g]) && dim == roller_group_dims[g]) status[2 + g] = tag;
          }
        } else if (!strncmp(line, "$Entities", 9) || !strncmp(line, "$Nodes", 6)) break;
      }
      fclose(fp);
    }
  }
  PetscCallMPI(MPI_Bcast(status, 2 + ROLLER_NUM_GROUPS, MPIU_INT, 0, ctx->comm));
  PetscCallMPI(MPI_Bcast(found, sizeof(groups->found), MPI_CHAR, 0, ctx->comm));
  PetscCheck(status[0], ctx->comm, PETSC_ERR_FILE_OPEN, "%s: cannot open the file (missing or unreadable)", what);
  PetscCheck(status[1] != 0, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: not a gmsh mesh (no $MeshFormat section); Roller reads gmsh 2.2 and 4.x files", what);
  PetscCheck(status[1] == 2 || status[1] == 4, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: gmsh format version %" PetscInt_FMT ".x is not supported; write 2.2 or 4.1 (gmsh -format msh41)", what, status[1]);
  for (int g = 0; g < ROLLER_NUM_GROUPS; ++g) groups->tags[g] = status[2 + g];
  PetscFunctionReturn(0);
}

static PetscErrorCode RollerMeshCheckGroups(Roller ctx, const char *what, const RollerMeshGroups *groups)
{
  PetscFunctionBeginUser;
  for (int g = 0; g < ROLLER_NUM_GROUPS; ++g)
    PetscCheck(groups->tags[g] >= 0, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: no %s physical group named \"%s\" (physical groups found: %s); Roller needs curves \"inner\" and \"outer\" and surface \"body\"", what, roller_group_dims[g] == 1 ? "curve" : "surface", roller_group_names[g],
               groups->found[0] ? groups->found : "none");
  PetscFunctionReturn(0);
}

/* The mesh options, one block for the mesh layer (the partition's and the measures' too). */
PetscErrorCode RollerMeshSetFromOptions(Roller ctx)
{
  RollerMesh *mesh      = &ctx->mesh;
  PetscBool   layer_set = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: geometry and mesh", NULL);
  PetscCall(PetscOptionsReal("-mesh_h", "Edge length of the gmsh annulus mesh (0: chosen from -ts_phase_error)", NULL, mesh->h, &mesh->h, &mesh->h_set));
  PetscCall(PetscOptionsReal("-mesh_h_contact", "Edge length h_c on Gamma_C of a mesh graded toward it, <= -mesh_h (0: uniform; with -obstacle and no -mesh_h: sqrt(r_outer depth)/14)", NULL, mesh->h_contact, &mesh->h_contact, &mesh->h_contact_set));
  PetscCall(PetscOptionsReal("-mesh_contact_layer", "Thickness L of the layer of edge length h_c under Gamma_C, >= h_c; then growing to -mesh_h over 3 (h - h_c) (0: 2 h_c)", NULL, mesh->contact_layer, &mesh->contact_layer, &layer_set));
  PetscCall(PetscOptionsString("-dm_plex_filename", "gmsh mesh file (physical groups inner, outer, body) instead of -mesh_h", NULL, mesh->file, mesh->file, sizeof(mesh->file), NULL));
  PetscCall(PetscOptionsReal("-r_inner", "Inner radius r_D (Gamma_D, driven)", NULL, mesh->r_inner, &mesh->r_inner, &mesh->radii_set[0]));
  PetscCall(PetscOptionsReal("-r_outer", "Outer radius r_C (Gamma_C, contact)", NULL, mesh->r_outer, &mesh->r_outer, &mesh->radii_set[1]));
  PetscCall(PetscOptionsBool("-partition_view", "Print the partition sizes and edge cut", NULL, mesh->partition_view, &mesh->partition_view, NULL));
  PetscCall(PetscOptionsBool("-mesh_gmsh_verbose", "Let gmsh print its progress (in-process mesh, no -dm_plex_filename)", NULL, mesh->gmsh_verbose, &mesh->gmsh_verbose, NULL));
  PetscCall(PetscOptionsBool("-mesh_view_info", "Print the global vertex, cell and boundary counts, area and boundary lengths", NULL, mesh->view_info, &mesh->view_info, NULL));
  PetscOptionsEnd();
  RollerCheckOption(ctx->comm, "-mesh_h", mesh->h, mesh->h >= 0, "> 0 (or 0: chosen from -ts_phase_error)");
  mesh->h_set = (PetscBool)(mesh->h > 0);
  RollerCheckOption(ctx->comm, "-r_outer", mesh->r_outer, mesh->r_outer > 0, "> 0");
  RollerCheckOption(ctx->comm, "-r_inner", mesh->r_inner, mesh->r_inner > 0, "> 0 (and < r_outer)");
  RollerCheckOption(ctx->comm, "-mesh_contact_layer", mesh->contact_layer, mesh->contact_layer >= 0, ">= 0 (0: 2 h_c)");
  PetscCheck(mesh->r_inner > 0 && mesh->r_inner < mesh->r_outer, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-r_inner %g and -r_outer %g must satisfy 0 < r_inner < r_outer", (double)mesh->r_inner, (double)mesh->r_outer);
  RollerCheckOption(ctx->comm, "-mesh_h_contact", mesh->h_contact, mesh->h_contact >= 0, ">= 0 (0: uniform mesh; > 0: the edge length on Gamma_C, at most -mesh_h)");
  PetscCheck(!(mesh->h_contact > 0 && mesh->file[0]), ctx->comm, PETSC_ERR_ARG_INCOMP, "-mesh_h_contact %g grades the in-process gmsh mesh; it cannot apply to -dm_plex_filename %s (grade that mesh in gmsh, or drop one of the two)", (double)mesh->h_contact,
             mesh->file);
  PetscCheck(!(mesh->h_contact > 0 && mesh->h_set && mesh->h_contact > mesh->h), ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_h_contact %g must not exceed -mesh_h %g (the bulk edge length): allowed 0 (uniform) or (0, %g]", (double)mesh->h_contact,
             (double)mesh->h, (double)mesh->h);
  PetscCheck(!layer_set || mesh->h_contact > 0 || mesh->contact_layer == 0, ctx->comm, PETSC_ERR_ARG_INCOMP, "-mesh_contact_layer %g needs a graded mesh: give -mesh_h_contact > 0 too", (double)mesh->contact_layer);
  if (mesh->h_contact > 0 && mesh->contact_layer == 0) mesh->contact_layer = 2 * mesh->h_contact;
  PetscCheck(!(mesh->h_contact > 0) || (mesh->contact_layer >= mesh->h_contact && mesh->contact_layer < mesh->r_outer - mesh->r_inner), ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_contact_layer %g must lie in [h_c = %g, r_outer - r_inner = %g): at least one element row of edge h_c, inside the wall",
             (double)mesh->contact_layer, (double)mesh->h_contact, (double)(mesh->r_outer - mesh->r_inner));
  PetscCheck(mesh->file[0] || !mesh->h_set || mesh->h < mesh->r_outer - mesh->r_inner, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_h %g must be smaller than the annulus width r_outer - r_inner = %g", (double)mesh->h, (double)(mesh->r_outer - mesh->r_inner));
  PetscFunctionReturn(0);
}

/* The DM must be two-dimensional with 2D coordinates and triangles only (P1/P2 Lagrange on simplices). */
static PetscErrorCode RollerMeshCheckCells(Roller ctx, const char *what)
{
  PetscInt       dim, cdim, c_start, c_end, bad[2] = {0, -1}, bad_global[2];
  DMPolytopeType ct;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(ctx->mesh.dm, &dim));
  PetscCall(DMGetCoordinateDim(ctx->mesh.dm, &cdim));
  PetscCheck(dim == 2 && cdim == 2, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: the mesh has dimension %" PetscInt_FMT " with %" PetscInt_FMT "-D coordinates; Roller needs a 2-D mesh in the plane", what, dim, cdim);
  PetscCall(DMPlexGetHeightStratum(ctx->mesh.dm, 0, &c_start, &c_end));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscCall(DMPlexGetCellType(ctx->mesh.dm, c, &ct));
    if (ct != DM_POLYTOPE_TRIANGLE) {
      bad[0]++;
      bad[1] = (PetscInt)ct;
    }
  }
  PetscCall(MPIU_Allreduce(bad, bad_global, 2, MPIU_INT, MPI_MAX, ctx->comm));
  PetscCheck(!bad_global[0], ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: the mesh has cells of type %s; Roller needs triangles only", what, DMPolytopeTypes[bad_global[1]]);
  PetscFunctionReturn(0);
}

/* Creates the label `name` with value 1 on the faces of physical tag `tag` ("Face Sets") and their closure,
   so that Dirichlet data and boundary integrals see both edges and vertices. */
static PetscErrorCode RollerMeshLabelGroup(Roller ctx, const char *what, const char *name, PetscInt tag)
{
  DMLabel  face_sets, label;
  PetscInt n = 0, n_global;

  PetscFunctionBeginUser;
  PetscCall(DMCreateLabel(ctx->mesh.dm, name));
  PetscCall(DMGetLabel(ctx->mesh.dm, name, &label));
  PetscCall(DMGetLabel(ctx->mesh.dm, "Face Sets", &face_sets));
  if (face_sets) {
    IS              is;
    const PetscInt *faces;

    PetscCall(DMLabelGetStratumIS(face_sets, tag, &is));
    if (is) {
      PetscCall(ISGetLocalSize(is, &n));
      PetscCall(ISGetIndices(is, &faces));
      for (PetscInt i = 0; i < n; ++i) PetscCall(DMLabelSetValue(label, faces[i], 1));
      PetscCall(ISRestoreIndices(is, &faces));
      PetscCall(ISDestroy(&is));
    }
  }
  PetscCall(MPIU_Allreduce(&n, &n_global, 1, MPIU_INT, MPI_SUM, ctx->comm));
  PetscCheck(n_global > 0, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: physical group \"%s\" (tag %" PetscInt_FMT ") has no edges in \"Face Sets\" (do not pass -dm_plex_gmsh_use_regions)", what, name, tag);
  PetscCall(DMPlexLabelComplete(ctx->mesh.dm, label));
  PetscFunctionReturn(0);
}

/* Least and largest |x| over the vertices of label `name` (all vertices when name is NULL), over all ranks. */
static PetscErrorCode RollerMeshRadii(Roller ctx, const char *name, PetscReal *r_min, PetscReal *r_max)
{
  Vec                coordinates;
  PetscSection       section;
  const PetscScalar *x;
  PetscInt           v_start, v_end;
  DMLabel            label    = NULL;
  PetscReal          range[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, range_global[2]; /* min r, -max r */

  PetscFunctionBeginUser;
  if (name) PetscCall(DMGetLabel(ctx->mesh.dm, name, &label));
  PetscCall(DMPlexGetDepthStratum(ctx->mesh.dm, 0, &v_start, &v_end));
  PetscCall(DMGetCoordinateSection(ctx->mesh.dm, &section));
  PetscCall(DMGetCoordinatesLocal(ctx->mesh.dm, &coordinates));
  PetscCall(VecGetArrayRead(coordinates, &x));
  for (PetscInt v = v_start; v < v_end; ++v) {
    PetscInt  value = 1, off;
    PetscReal r;

    if (label) PetscCall(DMLabelGetValue(label, v, &value));
    if (value != 1) continue;
    PetscCall(PetscSectionGetOffset(section, v, &off));
    r        = PetscSqrtReal(PetscSqr(PetscRealPart(x[off])) + PetscSqr(PetscRealPart(x[off + 1])));
    range[0] = PetscMin(range[0], r);
    range[1] = PetscMin(range[1], -r);
  }
  PetscCall(VecRestoreArrayRead(coordinates, &x));
  PetscCall(MPIU_Allreduce(range, range_global, 2, MPIU_REAL, MPI_MIN, ctx->comm));
  *r_min = range_global[0];
  *r_max = -range_global[1];
  PetscFunctionReturn(0);
}

/* Checks that "inner" and "outer" are circles about the origin, inner inside outer, every vertex between
   them; with a file, takes the radii from the mesh (and checks them against -r_inner/-r_outer if given). */
static PetscErrorCode RollerMeshCheckAnnulus(Roller ctx, const char *what)
{
  const char *names[2] = {"inner", "outer"}, *options[2] = {"-r_inner", "-r_outer"};
  PetscReal   radius[2], r_min, r_max, *given[2] = {&ctx->mesh.r_inner, &ctx->mesh.r_outer};

  PetscFunctionBeginUser;
  for (int i = 0; i < 2; ++i) {
    PetscCall(RollerMeshRadii(ctx, names[i], &r_min, &r_max));
    radius[i] = 0.5 * (r_min + r_max);
    PetscCheck(r_max - r_min <= ROLLER_MESH_RTOL * radius[i], ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: the \"%s\" vertices are not on one circle about the origin: |x| ranges over [%.10g, %.10g], relative spread %g, allowed %g", what, names[i], (double)r_min, (double)r_max, (double)((r_max - r_min) / radius[i]), ROLLER_MESH_RTOL);
    if (!ctx->mesh.file[0]) continue;
    PetscCheck(!ctx->mesh.radii_set[i] || PetscAbsReal(*given[i] - radius[i]) <= ROLLER_MESH_RTOL * radius[i], ctx->comm, PETSC_ERR_ARG_INCOMP, "%s %g disagrees with the radius %.10g of the \"%s\" circle of %s (allowed relative difference %g); drop the option or fix the mesh", options[i], (double)*given[i], (double)radius[i], names[i], what, ROLLER_MESH_RTOL);
  }
  PetscCheck(radius[0] < radius[1], ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: the \"inner\" radius %g must be smaller than the \"outer\" radius %g", what, (double)radius[0], (double)radius[1]);
  PetscCall(RollerMeshRadii(ctx, NULL, &r_min, &r_max));
  PetscCheck(r_min >= radius[0] * (1 - ROLLER_MESH_RTOL) && r_max <= radius[1] * (1 + ROLLER_MESH_RTOL), ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: vertices with |x| in [%g, %g] lie outside the annulus %g <= |x| <= %g", what, (double)r_min, (double)r_max, (double)radius[0], (double)radius[1]);
  if (ctx->mesh.file[0]) {
    ctx->mesh.r_inner = radius[0];
    ctx->mesh.r_outer = radius[1];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerMeshCreate(Roller ctx)
{
  char             dir[PETSC_MAX_PATH_LEN] = "", file[PETSC_MAX_PATH_LEN], what[PETSC_MAX_PATH_LEN + 64];
  RollerMeshGroups groups;
  PetscMPIInt      rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  if (ctx->mesh.file[0]) {
    PetscCall(PetscStrncpy(file, ctx->mesh.file, sizeof(file)));
    PetscCall(PetscSNPrintf(what, sizeof(what), "-dm_plex_filename %s", ctx->mesh.file));
  } else {
    PetscCall(RollerMeshGenerate(ctx, ctx->mesh.gmsh_verbose, dir, file));
    if (ctx->mesh.h_contact > 0) PetscCall(PetscSNPrintf(what, sizeof(what), "gmsh annulus at -mesh_h %g graded to -mesh_h_contact %g", (double)ctx->mesh.h, (double)ctx->mesh.h_contact));
    else PetscCall(PetscSNPrintf(what, sizeof(what), "gmsh annulus at -mesh_h %g", (double)ctx->mesh.h));
  }
  PetscCall(RollerMeshReadPhysicalNames(ctx, file, what, &groups));
  /* The gmsh reader puts every cell on rank 0; RollerMeshDistribute spreads them. */
  PetscCall(DMPlexCreateGmshFromFile(ctx->comm, file, PETSC_TRUE, &ctx->mesh.dm));
  if (rank == 0 && dir[0]) PetscCall(PetscRMTree(dir));
  PetscCall(PetscObjectSetName((PetscObject)ctx->mesh.dm, "annulus"));
  PetscCall(RollerMeshCheckCells(ctx, what));
  PetscCall(RollerMeshCheckOrientation(ctx, what));
  PetscCall(RollerMeshCheckGroups(ctx, what, &groups));
  PetscCall(RollerMeshLabelGroup(ctx, what, "inner", groups.tags[ROLLER_GROUP_INNER]));
  PetscCall(RollerMeshLabelGroup(ctx, what, "outer", groups.tags[ROLLER_GROUP_OUTER]));
  PetscCall(RollerMeshCheckAnnulus(ctx, what));
  PetscFunctionReturn(0);
}

/* Owned-point test through the point SF: a point that is a leaf belongs to another rank. The mask is indexed
   by p - pStart of the chart; free it with PetscFree. */
PetscErrorCode RollerMeshOwnedMask(DM dm, PetscBool **owned)
{
  PetscSF         sf;
  PetscInt        p_start, p_end, n_leaves;
  const PetscInt *leaves;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &p_start, &p_end));
  PetscCall(PetscMalloc1(p_end - p_start, owned));
  for (PetscInt p = p_start; p < p_end; ++p) (*owned)[p - p_start] = PETSC_TRUE;
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, NULL, &n_leaves, &leaves, NULL));
  for (PetscInt l = 0; l < n_leaves; ++l) (*owned)[(leaves ? leaves[l] : l) - p_start] = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* Global counts and measures of the distributed (straight-sided) mesh, each point counted once (by its
   owner); -mesh_view_info prints them. */
PetscErrorCode RollerMeshMeasure(Roller ctx)
{
  DM         dm = ctx->mesh.dm;
  DMLabel    labels[2];
  PetscBool *owned;
  PetscInt   counts[4] = {0, 0, 0, 0}, counts_global[4];                    /* vertices, cells, inner vertices, outer vertices */
  PetscReal  sums[3]   = {0, 0, 0}, sums_global[3];                         /* area, inner length, outer length */
  PetscReal  range[2]  = {PETSC_MAX_REAL, PETSC_MAX_REAL}, range_global[2]; /* min and -max of the Gamma_C edge lengths */
  PetscInt   p_start, p_end, v_start, v_end, f_start, f_end, c_start, c_end;

  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(dm, "inner", &labels[0]));
  PetscCall(DMGetLabel(dm, "outer", &labels[1]));
  PetscCheck(labels[0] && labels[1], ctx->comm, PETSC_ERR_ARG_WRONGSTATE, "The mesh has no \"inner\"/\"outer\" labels: call RollerMeshCreate first");
  PetscCall(DMPlexGetChart(dm, &p_start, &p_end));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f_start, &f_end));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  PetscCall(RollerMeshOwnedMask(dm, &owned));
  for (PetscInt p = p_start; p < p_end; ++p) {
    PetscInt  value[2];
    PetscReal measure;

    if (!owned[p - p_start]) continue;
    for (int i = 0; i < 2; ++i) PetscCall(DMLabelGetValue(labels[i], p, &value[i]));
    if (v_start <= p && p < v_end) {
      counts[0]++;
      for (int i = 0; i < 2; ++i) counts[2 + i] += value[i] == 1;
    } else if (c_start <= p && p < c_end) {
      counts[1]++;
      PetscCall(DMPlexComputeCellGeometryFVM(dm, p, &measure, NULL, NULL));
      sums[0] += measure;
    } else if (f_start <= p && p < f_end && (value[0] == 1 || value[1] == 1)) {
      PetscCall(DMPlexComputeCellGeometryFVM(dm, p, &measure, NULL, NULL));
      for (int i = 0; i < 2; ++i) sums[1 + i] += value[i] == 1 ? measure : 0;
      if (value[1] == 1) {
        range[0] = PetscMin(range[0], measure);
        range[1] = PetscMin(range[1], -measure);
      }
    }
  }
  PetscCall(PetscFree(owned));
  PetscCall(MPIU_Allreduce(counts, counts_global, 4, MPIU_INT, MPI_SUM, ctx->comm));
  PetscCall(MPIU_Allreduce(sums, sums_global, 3, MPIU_REAL, MPI_SUM, ctx->comm));
  PetscCall(MPIU_Allreduce(range, range_global, 2, MPIU_REAL, MPI_MIN, ctx->comm));
  if (ctx->mesh.view_info)
    PetscCall(PetscPrintf(ctx->comm, "mesh: vertices %" PetscInt_FMT " cells %" PetscInt_FMT " inner_vertices %" PetscInt_FMT " outer_vertices %" PetscInt_FMT " area %.15g inner_length %.15g outer_length %.15g\n", counts_global[0], counts_global[1], counts_global[2], counts_global[3], (double)sums_global[0], (double)sums_global[1], (double)sums_global[2]));
  /* a line of its own: the one above keeps its format (tests/mesh.py, bench/) */
  if (ctx->mesh.view_info && ctx->mesh.h_contact > 0)
    PetscCall(PetscPrintf(ctx->comm, "mesh: graded -mesh_h %g -mesh_h_contact %g -mesh_contact_layer %g: Gamma_C edges (chords) %.6g to %.6g\n", (double)ctx->mesh.h, (double)ctx->mesh.h_contact, (double)ctx->mesh.contact_layer, (double)range_global[0], (double)-range_global[1]));
  PetscFunctionReturn(0);
}
