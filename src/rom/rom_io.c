/* -rom_output F / -rom_input F (docs/performance.md "Reduced-order transient"): the reduced basis saved and reused by
   the cases of a map that share a mesh and a rubber, so that only the first pays the eigensolver. The file (plain
   HDF5, h5py reads it) holds the basis' columns V_0 .. V_{nq-1} in the writer's global order beside the positions of
   their nodes ("nodes", as a checkpoint: a reader on any number of ranks matches its nodes by position,
   integrate/checkpoint_order.c), V^T K V's diagonal ("lambda"), with contact the residual flexibility R of the Gamma_C
   dofs, and what the basis was made for. A reader that differs in any of those is refused in one line naming each
   difference; the basis does not depend on the rest (the speed, the obstacle, the friction, the damping, dt). */
#include "rom/rom.h"
#include "contact/contact.h"
#include "integrate/integrate.h"
#include "io/io.h"
#include <petscviewerhdf5.h>

#define ROM_FILE_FORMAT 1

/* What the basis depends on besides the mesh: the rubber's K and M, the modes asked for, the cutoff, the Gamma_C
   nodes and whether R is there. */
typedef struct {
  PetscReal r[4];
  PetscInt  i[7];
} RomIdentity;

static const char *const real_names[4]  = {"young", "poisson", "density", "w_cut"};
static const char *const real_labels[4] = {"-young", "-poisson", "-density", "the cutoff w (rad per unit time: -rom_cutoff, or the default from -ts_dt, -ts_scheme and -ts_phase_error)"};
static const char *const int_names[7]   = {"modes_requested", "degree", "contact_nodes", "residual", "unknowns", "axle", "residual_branches"};
static const char *const int_labels[7]  = {"-rom_modes", "-degree", "Gamma_C contact nodes", "the residual flexibility (-rom_residual with -obstacle)", "free dofs (another mesh: -mesh_h, -mesh_h_contact, -r_inner, -r_outer)", "-axle (the hub's constraint modes)", "the residual's branch ratio kappa (-rubber maxwell with -rom_residual_branches)"};

static PetscErrorCode IdentityOf(Roller ctx, RollerRom rom, RomIdentity *id)
{
  PetscFunctionBeginUser;
  id->r[0] = ctx->material.young;
  id->r[1] = ctx->material.poisson;
  id->r[2] = ctx->material.density;
  id->r[3] = rom->modes_req > 0 ? 0.0 : rom->w_cut; /* -rom_modes N: the N lowest whatever the cutoff */
  id->i[0] = rom->modes_req;
  id->i[1] = ctx->disc.degree;
  id->i[2] = RollerContactNodeCount(ctx->contact);
  id->i[3] = (PetscInt)(ctx->contact && rom->residual);
  PetscCall(VecGetSize(ctx->ops.coordinates, &id->i[4]));
  id->i[5] = (PetscInt)ctx->axle.on;
  id->i[6] = (PetscInt)(id->i[3] && ctx->material.rubber == ROLLER_RUBBER_MAXWELL && rom->residual_branches);
  PetscFunctionReturn(0);
}

PetscErrorCode RollerRomSave(Roller ctx, RollerRom rom, const char path[])
{
  char        tmp[PETSC_MAX_PATH_LEN], name[32];
  PetscViewer viewer;
  RomIdentity id;
  Vec         lam;
  PetscInt    format = ROM_FILE_FORMAT, rstart, rend;

  PetscFunctionBeginUser;
  PetscCall(IdentityOf(ctx, rom, &id));
  PetscCall(RollerJoinPath(tmp, sizeof(tmp), path, ".tmp", "-rom_output"));
  PetscCall(PetscViewerHDF5Open(ctx->comm, tmp, FILE_MODE_WRITE, &viewer));
  PetscCall(RollerPlainVecView(ctx->ops.coordinates, "nodes", viewer, PETSC_FALSE));
  for (PetscInt j = 0; j < rom->nq; ++j) {
    Vec col;

    PetscCall(PetscSNPrintf(name, sizeof(name), "V_%" PetscInt_FMT, j));
    PetscCall(MatDenseGetColumnVecRead(rom->V, j, &col));
    PetscCall(RollerPlainVecView(col, name, viewer, PETSC_FALSE));
    PetscCall(MatDenseRestoreColumnVecRead(rom->V, j, &col));
  }
  PetscCall(VecCreateMPI(ctx->comm, PETSC_DECIDE, rom->nq, &lam));
  PetscCall(VecGetOwnershipRange(lam, &rstart, &rend));
  for (PetscInt i = rstart; i < rend; ++i) PetscCall(VecSetValue(lam, i, rom->lambda[i], INSERT_VALUES));
  PetscCall(VecAssemblyBegin(lam));
  PetscCall(VecAssemblyEnd(lam));
  PetscCall(RollerPlainVecView(lam, "lambda", viewer, PETSC_FALSE));
  PetscCall(VecDestroy(&lam));
  if (id.i[3]) PetscCall(RollerContactResidualView(ctx, ctx->contact, viewer, PETSC_FALSE));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "rom_format", PETSC_INT, &format));
  for (PetscInt k = 0; k < 4; ++k) PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", real_names[k], PETSC_REAL, &id.r[k]));
  for (PetscInt k = 0; k < 7; ++k) PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", int_names[k], PETSC_INT, &id.i[k]));
  if (id.i[6]) PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "residual_branch_ratio", PETSC_REAL, &rom->kappa));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "modes", PETSC_INT, &rom->nmodes));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "coordinates", PETSC_INT, &rom->nq));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "basis_roundoff", PETSC_REAL, &rom->offdiag));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(RollerRenameFile(ctx->comm, tmp, path));
  PetscFunctionReturn(0);
}

/* Open a -rom_input file and refuse it in one line if it was made for another model (the mesh: RollerRomLoad). */
static PetscErrorCode Open(Roller ctx, RollerRom rom, const char path[], PetscViewer *viewer)
{
  PetscBool   exists;
  RomIdentity id, f;
  char        line[1024] = "", part[320];

  PetscFunctionBeginUser;
  PetscCall(PetscTestFile(path, 'r', &exists));
  PetscCheck(exists, ctx->comm, PETSC_ERR_FILE_OPEN, "-rom_input %s: no such readable file", path);
  PetscCall(RollerHDF5Probe(ctx->comm, "-rom_input", path));
  PetscCall(PetscViewerHDF5Open(ctx->comm, path, FILE_MODE_READ, viewer));
  PetscCall(PetscViewerHDF5HasAttribute(*viewer, "/", "rom_format", &exists));
  PetscCheck(exists, ctx->comm, PETSC_ERR_FILE_UNEXPECTED, "-rom_input %s: not a reduced basis of Roller's -rom_output (no rom_format attribute)", path);
  PetscCall(IdentityOf(ctx, rom, &id));
  for (PetscInt k = 0; k < 4; ++k) {
    PetscCall(PetscViewerHDF5ReadAttribute(*viewer, "/", real_names[k], PETSC_REAL, NULL, &f.r[k]));
    if (f.r[k] == id.r[k]) continue;
    PetscCall(PetscSNPrintf(part, sizeof(part), "%s%s %.17g (file) vs %.17g (this run)", line[0] ? "; " : "", real_labels[k], (double)f.r[k], (double)id.r[k]));
    PetscCall(PetscStrlcat(line, part, sizeof(line)));
  }
  for (PetscInt k = 0; k < 7; ++k) {
    PetscBool has = PETSC_TRUE;

    if (k == 6) PetscCall(PetscViewerHDF5HasAttribute(*viewer, "/", int_names[k], &has));
    f.i[k] = 0;
    if (has) PetscCall(PetscViewerHDF5ReadAttribute(*viewer, "/", int_names[k], PETSC_INT, NULL, &f.i[k]));
    if (f.i[k] == id.i[k] || ((k == 3 || k == 6) && f.i[k] && !id.i[k])) continue; /* an R (or kappa) the run does not need is left unread */
    PetscCall(PetscSNPrintf(part, sizeof(part), "%s%s %" PetscInt_FMT " (file) vs %" PetscInt_FMT " (this run)", line[0] ? "; " : "", int_labels[k], f.i[k], id.i[k]));
    PetscCall(PetscStrlcat(line, part, sizeof(line)));
  }
  PetscCheck(!line[0], ctx->comm, PETSC_ERR_ARG_INCOMP, "-rom_input %s: refused, made for another model: %s", path, line);
  PetscFunctionReturn(0);
}

/* The basis from a -rom_input file, on this run's nodes (any number of ranks): V, lambda, the sizes; then Check's
   round-off as the file states it. */
PetscErrorCode RollerRomLoad(Roller ctx, RollerRom rom, const char path[])
{
  PetscViewer        viewer;
  PetscInt           npoints, *from, nloc, N;
  Vec                lam, all;
  VecScatter         sc;
  const PetscScalar *a;
  char               name[32];

  PetscFunctionBeginUser;
  PetscCall(Open(ctx, rom, path, &viewer));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "modes", PETSC_INT, NULL, &rom->nmodes));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "coordinates", PETSC_INT, NULL, &rom->nq));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "basis_roundoff", PETSC_REAL, NULL, &rom->offdiag));
  PetscCall(RollerCheckpointOrderCreate(ctx, viewer, "-rom_input", path, "nodes", ctx->ops.coordinates, &npoints, &from));
  PetscCall(VecGetLocalSize(ctx->state.cur, &nloc));
  PetscCall(VecGetSize(ctx->state.cur, &N));
  PetscCall(MatCreateDense(ctx->comm, nloc, PETSC_DECIDE, N, rom->nq, NULL, &rom->V));
  for (PetscInt j = 0; j < rom->nq; ++j) {
    Vec col;

    PetscCall(PetscSNPrintf(name, sizeof(name), "V_%" PetscInt_FMT, j));
    PetscCall(MatDenseGetColumnVecWrite(rom->V, j, &col));
    PetscCall(RollerCheckpointOrderLoad(viewer, name, npoints, from, col));
    PetscCall(MatDenseRestoreColumnVecWrite(rom->V, j, &col));
  }
  PetscCall(PetscFree(from));
  PetscCall(VecCreateMPI(ctx->comm, PETSC_DECIDE, rom->nq, &lam));
  PetscCall(PetscObjectSetName((PetscObject)lam, "lambda"));
  PetscCall(VecLoad(lam, viewer));
  PetscCall(VecScatterCreateToAll(lam, &sc, &all));
  PetscCall(VecScatterBegin(sc, lam, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, lam, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(PetscMalloc1(rom->nq, &rom->lambda));
  PetscCall(VecGetArrayRead(all, &a));
  for (PetscInt i = 0; i < rom->nq; ++i) rom->lambda[i] = PetscRealPart(a[i]);
  PetscCall(VecRestoreArrayRead(all, &a));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecDestroy(&all));
  PetscCall(VecDestroy(&lam));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscFunctionReturn(0);
}

/* R of the Gamma_C dofs from the file (after RollerContactSetBasis). */
PetscErrorCode RollerRomLoadResidual(Roller ctx, RollerRom rom, const char path[])
{
  PetscViewer viewer;

  PetscFunctionBeginUser;
  PetscCall(Open(ctx, rom, path, &viewer));
  PetscCall(RollerContactResidualView(ctx, ctx->contact, viewer, PETSC_TRUE));
  rom->kappa = -1.0;
  if (ctx->material.rubber == ROLLER_RUBBER_MAXWELL && rom->residual_branches) PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "residual_branch_ratio", PETSC_REAL, NULL, &rom->kappa));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscFunctionReturn(0);
}
