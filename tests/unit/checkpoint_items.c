static const char help[] = "Unit test of a component's own state in the checkpoint (src/integrate/checkpoint.c, checkpoint_order.c):\n"
                           "a vector on the displacement's nodes, a vector of 3 values per cell at the cells' centroids and 3 reals,\n"
                           "registered (RollerCheckpointAddVec, RollerCheckpointAddReals), written by a Roller on one number of ranks\n"
                           "and read by a Roller on another (2 -> 1 and 1 -> 2 when run on 2 ranks): every value read is the function\n"
                           "of its point's position it was written as, to 1e-13 (the positions agree to round-off), the reals exactly.\n";

#include "integrate/integrate.h"
#include "unit.h"

static const PetscReal axle_written[3] = {1.5, -2.25, 3e-7};

/* 3 values per point at (x, y), and the displacement-like pair at a node */
static void CellValues(PetscReal x, PetscReal y, PetscScalar f[3])
{
  f[0] = x + 2 * y;
  f[1] = x * y;
  f[2] = 1 + x * x;
}

static void NodeValues(PetscReal x, PetscReal y, PetscScalar f[2])
{
  f[0] = 3 * x - y;
  f[1] = 0.5 * x + 4 * y;
}

typedef struct {
  Vec       centroids, q, u;
  PetscReal axle[3];
} Items;

/* The cells' centroids (2 per cell this rank has), a 3-per-cell vector and a vector of the displacement's layout,
   registered with the checkpoint of ctx. */
static PetscErrorCode ItemsRegister(Roller ctx, Items *it)
{
  PetscInt     c_start, c_end;
  PetscScalar *x;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(ctx->mesh.dm, 0, &c_start, &c_end));
  PetscCall(VecCreateMPI(ctx->comm, 2 * (c_end - c_start), PETSC_DETERMINE, &it->centroids));
  PetscCall(VecCreateMPI(ctx->comm, 3 * (c_end - c_start), PETSC_DETERMINE, &it->q));
  PetscCall(VecDuplicate(ctx->ops.coordinates, &it->u));
  PetscCall(VecGetArray(it->centroids, &x));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscReal centroid[3], vol;

    PetscCall(DMPlexComputeCellGeometryFVM(ctx->mesh.dm, c, &vol, centroid, NULL));
    x[2 * (c - c_start)]     = centroid[0];
    x[2 * (c - c_start) + 1] = centroid[1];
  }
  PetscCall(VecRestoreArray(it->centroids, &x));
  PetscCall(RollerCheckpointAddVec(ctx, "cell_q", &it->q, "cell_centroids", it->centroids));
  PetscCall(RollerCheckpointAddVec(ctx, "u_extra", &it->u, NULL, NULL));
  PetscCall(RollerCheckpointAddReals(ctx, "axle", 3, it->axle));
  PetscFunctionReturn(0);
}

/* v (bs values per point of where) filled with f of the positions, or checked against it: the largest difference. */
static PetscErrorCode PointValues(Vec where, Vec v, PetscInt bs, void (*f)(PetscReal, PetscReal, PetscScalar[]), PetscBool check, PetscReal *err)
{
  const PetscScalar *x;
  PetscScalar       *a, fx[3];
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(where, &n));
  PetscCall(VecGetArrayRead(where, &x));
  PetscCall(VecGetArray(v, &a));
  for (PetscInt p = 0; p < n / 2; ++p) {
    f(PetscRealPart(x[2 * p]), PetscRealPart(x[2 * p + 1]), fx);
    for (PetscInt k = 0; k < bs; ++k) {
      if (check) *err = PetscMax(*err, PetscAbsScalar(a[bs * p + k] - fx[k]));
      else a[bs * p + k] = fx[k];
    }
  }
  PetscCall(VecRestoreArray(v, &a));
  PetscCall(VecRestoreArrayRead(where, &x));
  PetscFunctionReturn(0);
}

/* Fill (check == FALSE) or check the values against their positions. */
static PetscErrorCode ItemsValues(Roller ctx, Items *it, PetscBool check)
{
  PetscReal err = 0, max;

  PetscFunctionBeginUser;
  PetscCall(PointValues(it->centroids, it->q, 3, CellValues, check, &err));
  PetscCall(PointValues(ctx->ops.coordinates, it->u, 2, NodeValues, check, &err));
  for (PetscInt k = 0; k < 3; ++k) {
    if (check) PetscCheck(it->axle[k] == axle_written[k], PETSC_COMM_SELF, PETSC_ERR_PLIB, "axle[%" PetscInt_FMT "]: read %.17g, written %.17g", k, (double)it->axle[k], (double)axle_written[k]);
    else it->axle[k] = axle_written[k];
  }
  PetscCall(MPIU_Allreduce(&err, &max, 1, MPIU_REAL, MPIU_MAX, ctx->comm));
  PetscCheck(max <= 1e-13, ctx->comm, PETSC_ERR_PLIB, "values read against the functions of their points' positions: %g", (double)max);
  PetscFunctionReturn(0);
}

static PetscErrorCode ItemsDestroy(Items *it)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&it->centroids));
  PetscCall(VecDestroy(&it->q));
  PetscCall(VecDestroy(&it->u));
  PetscFunctionReturn(0);
}

/* A Roller on comm writes path (write) or reads it and checks what it read. */
static PetscErrorCode WriteOrRead(MPI_Comm comm, const char path[], PetscBool write)
{
  Roller      ctx;
  Items       it;
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCall(RollerCreate(comm, &ctx));
  PetscCall(RollerSetFromOptions(ctx));
  PetscCall(RollerSetUp(ctx));
  PetscCall(ItemsRegister(ctx, &it));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (write) {
    PetscCall(ItemsValues(ctx, &it, PETSC_FALSE));
    PetscCall(RollerCheckpointWrite(ctx, path));
  } else {
    PetscCall(VecZeroEntries(it.q));
    PetscCall(VecZeroEntries(it.u));
    for (PetscInt k = 0; k < 3; ++k) it.axle[k] = 0;
    PetscCall(RollerCheckpointReadItems(ctx, path));
    PetscCall(ItemsValues(ctx, &it, PETSC_TRUE));
  }
  PetscCall(PetscPrintf(comm, "checkpoint_items: %s %s on %d rank(s)\n", write ? "wrote" : "read and checked", path, size));
  PetscCall(ItemsDestroy(&it));
  PetscCall(RollerDestroy(&ctx));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscMPIInt       rank;
  const char *const scene[][2] = {
    {"-mesh_h",      "0.1" },
    {"-ts_dt",       "0.01"},
    {"-omega",       "0"   },
    {"-ts_max_time", "0.1" },
    {"-quiet",       NULL  }
  };

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  for (size_t i = 0; i < ROLLER_UNIT_COUNT(scene); ++i) PetscCall(PetscOptionsSetValue(NULL, scene[i][0], scene[i][1]));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCall(WriteOrRead(PETSC_COMM_WORLD, "items_world.h5", PETSC_TRUE)); /* all ranks -> rank 0 alone */
  if (!rank) PetscCall(WriteOrRead(PETSC_COMM_SELF, "items_world.h5", PETSC_FALSE));
  if (!rank) PetscCall(WriteOrRead(PETSC_COMM_SELF, "items_self.h5", PETSC_TRUE)); /* rank 0 alone -> all ranks */
  PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD));
  PetscCall(WriteOrRead(PETSC_COMM_WORLD, "items_self.h5", PETSC_FALSE));
  PetscCall(PetscFinalize());
  return 0;
}
