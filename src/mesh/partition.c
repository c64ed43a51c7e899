/* Distribution of the annulus over the ranks. By default METIS k-way partitions the cell graph (cells
   adjacent through a face) on rank 0, where the gmsh reader put every cell; -petscpartitioner_type X selects
   one of PETSc's partitioners instead (this PETSc build has no METIS of its own, PETSC-NOTES.md).
   -partition_view reports the cells per rank and the edge cut. */
#include "mesh/mesh.h"
#include <metis.h>

/* Partitions the cell graph with METIS_PartGraphKway on rank 0 and wraps the result in a shell partitioner.
   The graph is copied into idx_t arrays so that the METIS and PETSc integer widths need not agree. */
static PetscErrorCode RollerPartitionerCreateMetis(Roller ctx, PetscPartitioner *part, PetscInt *edge_cut)
{
  PetscInt   *offsets, *adjacency, *sizes, *points, *start, n_vertices;
  PetscMPIInt size, rank;
  int         status[2] = {METIS_OK, 0}; /* METIS return code, its edge cut */

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  PetscCall(DMPlexCreatePartitionerGraph(ctx->mesh.dm, 0, &n_vertices, &offsets, &adjacency, NULL));
  PetscCheck(rank == 0 || n_vertices == 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "The METIS partition expects every cell on rank 0, but rank %d has %" PetscInt_FMT, rank, n_vertices);
  PetscCall(PetscCalloc3(size, &sizes, size, &start, n_vertices, &points));
  if (n_vertices > 0) {
    idx_t *xadj, *adjncy, *where, n = (idx_t)n_vertices, n_constraints = 1, n_parts = (idx_t)size, objval = 0, options[METIS_NOPTIONS];

    PetscCall(PetscMalloc3(n_vertices + 1, &xadj, offsets[n_vertices], &adjncy, n_vertices, &where));
    for (PetscInt i = 0; i <= n_vertices; ++i) xadj[i] = (idx_t)offsets[i];
    for (PetscInt i = 0; i < offsets[n_vertices]; ++i) adjncy[i] = (idx_t)adjacency[i];
    /* Default options: edge-cut objective, fixed seed, so the partition is reproducible. */
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    status[0]                       = METIS_PartGraphKway(&n, &n_constraints, xadj, adjncy, NULL, NULL, NULL, &n_parts, NULL, NULL, options, &objval, where);
    status[1]                       = (int)objval;
    if (status[0] == METIS_OK) {
      /* Shell partitions list the graph vertices (local cell numbers) grouped by rank. */
      for (PetscInt i = 0; i < n_vertices; ++i) sizes[where[i]]++;
      for (PetscMPIInt r = 1; r < size; ++r) start[r] = start[r - 1] + sizes[r - 1];
      for (PetscInt i = 0; i < n_vertices; ++i) points[start[where[i]]++] = i;
    }
    PetscCall(PetscFree3(xadj, adjncy, where));
  }
  PetscCall(PetscFree(offsets));
  PetscCall(PetscFree(adjacency));
  PetscCallMPI(MPI_Bcast(status, 2, MPI_INT, 0, ctx->comm));
  PetscCheck(status[0] == METIS_OK, ctx->comm, PETSC_ERR_LIB, "METIS_PartGraphKway failed with code %d partitioning the cell graph into %d parts", status[0], size);
  *edge_cut = status[1];
  PetscCall(PetscPartitionerCreate(ctx->comm, part));
  PetscCall(PetscPartitionerSetType(*part, PETSCPARTITIONERSHELL));
  PetscCall(PetscPartitionerShellSetPartition(*part, size, sizes, points));
  PetscCall(PetscFree3(sizes, start, points));
  PetscFunctionReturn(0);
}

/* Number of cell-graph edges between ranks. With overlap 0 a face exists on two ranks exactly when its two
   cells lie on different ranks, and then it is a leaf of the point SF on one of them. */
static PetscErrorCode RollerPartitionEdgeCut(DM dm, PetscInt *edge_cut)
{
  PetscSF         sf;
  PetscInt        f_start, f_end, n_leaves, cut = 0;
  const PetscInt *leaves;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f_start, &f_end));
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, NULL, &n_leaves, &leaves, NULL));
  for (PetscInt l = 0; l < n_leaves; ++l) {
    const PetscInt p = leaves ? leaves[l] : l;
    cut += f_start <= p && p < f_end;
  }
  PetscCall(MPIU_Allreduce(&cut, edge_cut, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

/* -partition_view: one summary line, then the cells of each rank. */
static PetscErrorCode RollerPartitionView(Roller ctx, const char *type, PetscInt metis_edge_cut)
{
  PetscMPIInt size, rank;
  PetscInt    c_start, c_end, n_cells, *cells = NULL, edge_cut, min_cells = PETSC_MAX_INT, max_cells = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  PetscCall(RollerPartitionEdgeCut(ctx->mesh.dm, &edge_cut));
  PetscCall(DMPlexGetHeightStratum(ctx->mesh.dm, 0, &c_start, &c_end));
  n_cells = c_end - c_start;
  if (rank == 0) PetscCall(PetscMalloc1(size, &cells));
  PetscCallMPI(MPI_Gather(&n_cells, 1, MPIU_INT, cells, 1, MPIU_INT, 0, ctx->comm));
  for (PetscMPIInt r = 0; rank == 0 && r < size; ++r) {
    min_cells = PetscMin(min_cells, cells[r]);
    max_cells = PetscMax(max_cells, cells[r]);
  }
  PetscCall(PetscPrintf(ctx->comm, "partition: %s ranks %d edge_cut %" PetscInt_FMT " cells_min %" PetscInt_FMT " cells_max %" PetscInt_FMT, type, size, edge_cut, min_cells, max_cells));
  if (metis_edge_cut >= 0) PetscCall(PetscPrintf(ctx->comm, " metis_objval %" PetscInt_FMT, metis_edge_cut));
  PetscCall(PetscPrintf(ctx->comm, "\n"));
  for (PetscMPIInt r = 0; rank == 0 && r < size; ++r) PetscCall(PetscPrintf(PETSC_COMM_SELF, "partition: rank %d cells %" PetscInt_FMT "\n", r, cells[r]));
  PetscCall(PetscFree(cells));
  PetscFunctionReturn(0);
}

/* DMPlexDistribute answers its own -partition_view by printing the whole partition label, the migration SF
   and the point renumbering (hundreds of thousands of lines on the paper's mesh): it looks the option up
   under the DM's options prefix, in the DM's options database (the label, the SF) and in the global one (the
   renumbering). Roller's -partition_view (ctx->mesh.partition_view, read with the mesh options) means the
   summary of RollerPartitionView, so with it the DM distributes under a private prefix and a private options
   database that holds only what else DMPlexDistribute reads there, the partitioner graph's -dm_plex_csr_alg:
   the options database itself is left as it is. */
static PetscErrorCode RollerDistributeQuietly(Roller ctx, DM dm, DM *dm_dist)
{
  const char   prefix[] = "roller_distribute_";
  PetscOptions options;
  char         alg[64], name[64];
  PetscBool    set;

  PetscFunctionBeginUser;
  if (!ctx->mesh.partition_view) {
    PetscCall(DMPlexDistribute(dm, 0, NULL, dm_dist));
    PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsCreate(&options));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-dm_plex_csr_alg", alg, sizeof(alg), &set));
  PetscCall(PetscSNPrintf(name, sizeof(name), "-%sdm_plex_csr_alg", prefix));
  if (set) PetscCall(PetscOptionsSetValue(options, name, alg));
  PetscCall(PetscObjectSetOptions((PetscObject)dm, options));
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)dm, prefix));
  PetscCall(DMPlexDistribute(dm, 0, NULL, dm_dist));
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)dm, NULL));
  PetscCall(PetscObjectSetOptions((PetscObject)dm, NULL));
  PetscCall(PetscOptionsDestroy(&options));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerMeshDistribute(Roller ctx)
{
  PetscMPIInt size;
  PetscInt    metis_edge_cut = -1;
  char        type[64]       = "serial";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  if (size > 1) {
    PetscPartitioner     part;
    PetscPartitionerType part_type;
    PetscBool            user_type;
    DM                   dm_dist = NULL;

    PetscCall(PetscOptionsHasName(NULL, NULL, "-petscpartitioner_type", &user_type));
    if (user_type) {
      PetscCall(DMPlexGetPartitioner(ctx->mesh.dm, &part));
      PetscCall(PetscPartitionerSetFromOptions(part));
    } else {
      PetscCall(RollerPartitionerCreateMetis(ctx, &part, &metis_edge_cut));
      PetscCall(DMPlexSetPartitioner(ctx->mesh.dm, part));
      PetscCall(PetscPartitionerDestroy(&part));
      PetscCall(DMPlexGetPartitioner(ctx->mesh.dm, &part));
    }
    /* Copied: the partitioner may go with the serial DM below. */
    PetscCall(PetscPartitionerGetType(part, &part_type));
    PetscCall(PetscStrncpy(type, user_type ? part_type : "metis", sizeof(type)));
    PetscCall(RollerDistributeQuietly(ctx, ctx->mesh.dm, &dm_dist));
    if (dm_dist) {
      PetscCall(DMDestroy(&ctx->mesh.dm));
      ctx->mesh.dm = dm_dist;
    }
  }
  /* Distributed once, here: DMSetFromOptions must not partition again, but still honours -dm_view etc. */
  PetscCall(DMPlexDistributeSetDefault(ctx->mesh.dm, PETSC_FALSE));
  PetscCall(DMSetFromOptions(ctx->mesh.dm));
  PetscCall(DMViewFromOptions(ctx->mesh.dm, NULL, "-dm_view"));
  if (ctx->mesh.partition_view) PetscCall(RollerPartitionView(ctx, type, metis_edge_cut));
  PetscCall(RollerMeshMeasure(ctx));
  PetscFunctionReturn(0);
}
