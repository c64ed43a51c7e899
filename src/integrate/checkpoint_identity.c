/* What a checkpoint was written for, and the refusal of a restart of anything else: the mesh (its vertices, cells,
   free dofs, -mesh_h, -mesh_h_contact, -mesh_contact_layer, -mesh_curved and a checksum of the free nodes' positions,
   sum |x_n|^2, which does not depend on the partition but to round-off), -degree, -ts_dt, -ts_scheme, and whether the
   model is reduced (-rom: its state is the basis' coordinates; a reduced run itself does not restart, rom/rom.c). A restart that differs in any of them is refused in one line that
   names each difference with both values: a state continued on another discretization would be a silent wrong
   run. The number of ranks is not part of it (integrate/checkpoint_order.c). */
#include "integrate/integrate.h"
#include "mesh/mesh.h"
#include <petscviewerhdf5.h>
#include <stdlib.h>

typedef struct {
  PetscInt  i[6]; /* as int_names */
  PetscReal r[7]; /* as real_names */
  char      scheme[64];
} Identity;

static const char *const int_names[6]   = {"mesh_vertices", "mesh_cells", "dofs", "mesh_curved", "degree", "reduced"};
static const char *const int_labels[6]  = {"mesh vertices", "mesh cells", "mesh free dofs", "-mesh_curved", "-degree", "reduced (-rom)"};
static const char *const real_names[7]  = {"r_inner", "r_outer", "mesh_h", "mesh_h_contact", "mesh_contact_layer", "mesh_checksum", "dt"};
static const char *const real_labels[7] = {"-r_inner", "-r_outer", "-mesh_h", "-mesh_h_contact", "-mesh_contact_layer", "mesh checksum sum |x_n|^2", "-ts_dt"};

static PetscErrorCode IdentityOfRun(Roller ctx, Identity *id)
{
  PetscBool  *owned;
  PetscInt    p_start, p_end, v_start, v_end, c_start, c_end, counts[2] = {0, 0}, global[2];
  PetscScalar sq;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(ctx->mesh.dm, &p_start, &p_end));
  PetscCall(DMPlexGetDepthStratum(ctx->mesh.dm, 0, &v_start, &v_end));
  PetscCall(DMPlexGetHeightStratum(ctx->mesh.dm, 0, &c_start, &c_end));
  PetscCall(RollerMeshOwnedMask(ctx->mesh.dm, &owned));
  for (PetscInt p = v_start; p < v_end; ++p) counts[0] += owned[p - p_start];
  for (PetscInt p = c_start; p < c_end; ++p) counts[1] += owned[p - p_start];
  PetscCall(PetscFree(owned));
  PetscCall(MPIU_Allreduce(counts, global, 2, MPIU_INT, MPI_SUM, ctx->comm));
  id->i[0] = global[0];
  id->i[1] = global[1];
  PetscCall(VecGetSize(ctx->ops.coordinates, &id->i[2]));
  id->i[3] = ctx->mesh.curved;
  id->i[4] = ctx->disc.degree;
  id->i[5] = (PetscInt)ctx->ops.reduced; /* a reduced run's checkpoint holds coordinates, not the nodal state */
  id->r[0] = ctx->mesh.r_inner;
  id->r[1] = ctx->mesh.r_outer;
  id->r[2] = ctx->mesh.h;
  id->r[3] = ctx->mesh.h_contact;
  id->r[4] = ctx->mesh.contact_layer;
  PetscCall(VecDot(ctx->ops.coordinates, ctx->ops.coordinates, &sq));
  id->r[5] = PetscRealPart(sq);
  id->r[6] = ctx->ts.dt;
  PetscCall(PetscStrncpy(id->scheme, RollerSchemeName(ctx), sizeof(id->scheme)));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerCheckpointIdentityWrite(Roller ctx, PetscViewer viewer)
{
  Identity    id;
  PetscMPIInt size;
  PetscInt    ranks;

  PetscFunctionBeginUser;
  PetscCall(IdentityOfRun(ctx, &id));
  for (PetscInt i = 0; i < 6; ++i) PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", int_names[i], PETSC_INT, &id.i[i]));
  for (PetscInt i = 0; i < 7; ++i) PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", real_names[i], PETSC_REAL, &id.r[i]));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "scheme", PETSC_STRING, id.scheme));
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  ranks = size; /* for the record: a restart may have any number */
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "ranks", PETSC_INT, &ranks));
  PetscFunctionReturn(0);
}

/* Both values of a difference, appended to the refusal's line. */
static PetscErrorCode Append(char line[], size_t len, const char label[], const char ck[], const char run[])
{
  char part[256];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(part, sizeof(part), "%s%s %s (checkpoint) vs %s (this run)", line[0] ? "; " : "", label, ck, run));
  PetscCall(PetscStrlcat(line, part, len));
  PetscFunctionReturn(0);
}

/* x in the fewest digits that read back as x (0.05, not 0.050000000000000003). */
static PetscErrorCode FormatReal(char str[], size_t len, PetscReal x)
{
  PetscFunctionBeginUser;
  for (int digits = 6; digits <= 17; ++digits) {
    PetscCall(PetscSNPrintf(str, len, "%.*g", digits, (double)x));
    if (strtod(str, NULL) == (double)x) break;
  }
  PetscFunctionReturn(0);
}

/* Refused in one line naming every difference. Reals are compared exactly (the checkpoint's -ts_dt and -mesh_h
   are the defaults of a restart: the same doubles) except the checksum, a sum whose order the partition sets. */
PetscErrorCode RollerCheckpointIdentityCheck(Roller ctx, PetscViewer viewer, const char path[])
{
  Identity id, ck;
  char     line[1024] = "", a[64], b[64], *scheme;

  PetscFunctionBeginUser;
  PetscCall(IdentityOfRun(ctx, &id));
  for (PetscInt i = 0; i < 6; ++i) {
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", int_names[i], PETSC_INT, NULL, &ck.i[i]));
    if (ck.i[i] == id.i[i]) continue;
    PetscCall(PetscSNPrintf(a, sizeof(a), "%" PetscInt_FMT, ck.i[i]));
    PetscCall(PetscSNPrintf(b, sizeof(b), "%" PetscInt_FMT, id.i[i]));
    PetscCall(Append(line, sizeof(line), int_labels[i], a, b));
  }
  for (PetscInt i = 0; i < 7; ++i) {
    const PetscReal x = id.r[i], tol = i == 5 ? 1e-12 * PetscAbsReal(x) : 0;

    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", real_names[i], PETSC_REAL, NULL, &ck.r[i]));
    if (PetscAbsReal(ck.r[i] - x) <= tol) continue;
    PetscCall(FormatReal(a, sizeof(a), ck.r[i]));
    PetscCall(FormatReal(b, sizeof(b), x));
    PetscCall(Append(line, sizeof(line), real_labels[i], a, b));
  }
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "scheme", PETSC_STRING, NULL, &scheme));
  PetscCall(PetscStrncpy(ck.scheme, scheme, sizeof(ck.scheme)));
  PetscCall(PetscFree(scheme));
  if (strcmp(ck.scheme, id.scheme)) PetscCall(Append(line, sizeof(line), "-ts_scheme", ck.scheme, id.scheme));
  PetscCheck(!line[0], ctx->comm, PETSC_ERR_ARG_INCOMP, "-restart %s: refused, written for another discretization: %s", path, line);
  PetscFunctionReturn(0);
}
