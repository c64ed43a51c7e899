static const char help[] = "Unit test: the mesh graded toward Gamma_C (-mesh_h_contact h_c, -mesh_contact_layer L; mesh/generate.c), on one rank:\n"
                           "(a) every Gamma_C edge has the same arc length (relative spread < 1e-6: one sharp element-passing line), within\n"
                           "3 %% below h_c (gmsh rounds each half circle up to a whole number of edges); (b) the edges in the layer (midpoint\n"
                           "within L of Gamma_C) average h_c to 15 %%, the edges beyond the transition (farther than L + 3 (h - h_c)) average\n"
                           "h to 15 %% and the Gamma_D edges are h to 3 %%; (c) the graded mesh has fewer than 40 %% of the cells of the\n"
                           "uniform mesh at h_c and more than the uniform mesh at h. The curved boundary and |Gamma_C| are checked by\n"
                           "unit_geometry_graded (geometry.c on graded meshes).\n";

#include "model/model.h"
#include "unit.h"

/* Arc length of a boundary chord c on the circle of radius r. */
static PetscReal Arc(PetscReal c, PetscReal r)
{
  return 2 * r * PetscAsinReal(PetscMin(1.0, c / (2 * r)));
}

typedef struct {
  PetscReal outer[2], inner[2]; /* least and largest arc length on Gamma_C, Gamma_D */
  PetscReal layer[2], bulk[2];  /* sum and count of the chord lengths in the fine layer and beyond the transition */
} EdgeStats;

/* Edge lengths of the straight-sided mesh (ctx->mesh.dm_view), by where their midpoint lies. */
static PetscErrorCode MeasureEdges(Roller ctx, EdgeStats *s)
{
  DM              dm = ctx->mesh.dm_view;
  DMLabel         outer, inner;
  PetscInt        e_start, e_end;
  const PetscReal ro = ctx->mesh.r_outer, ri = ctx->mesh.r_inner, L = ctx->mesh.contact_layer;
  const PetscReal far = L + 3 * (ctx->mesh.h - ctx->mesh.h_contact);

  PetscFunctionBeginUser;
  *s = (EdgeStats){
    {PETSC_MAX_REAL, 0},
    {PETSC_MAX_REAL, 0},
    {0,              0},
    {0,              0}
  };
  PetscCall(DMGetLabel(dm, "outer", &outer));
  PetscCall(DMGetLabel(dm, "inner", &inner));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &e_start, &e_end));
  for (PetscInt e = e_start; e < e_end; ++e) {
    PetscReal length, mid[2], d;
    PetscInt  on_outer, on_inner;

    PetscCall(DMPlexComputeCellGeometryFVM(dm, e, &length, mid, NULL));
    PetscCall(DMLabelGetValue(outer, e, &on_outer));
    PetscCall(DMLabelGetValue(inner, e, &on_inner));
    d = ro - PetscSqrtReal(PetscSqr(mid[0]) + PetscSqr(mid[1]));
    if (on_outer == 1) {
      s->outer[0] = PetscMin(s->outer[0], Arc(length, ro));
      s->outer[1] = PetscMax(s->outer[1], Arc(length, ro));
    } else if (on_inner == 1) {
      s->inner[0] = PetscMin(s->inner[0], Arc(length, ri));
      s->inner[1] = PetscMax(s->inner[1], Arc(length, ri));
    }
    if (d < L) {
      s->layer[0] += length;
      s->layer[1] += 1;
    } else if (d > far && on_inner != 1) {
      s->bulk[0] += length;
      s->bulk[1] += 1;
    }
  }
  PetscFunctionReturn(0);
}

/* Cells of the uniform in-process mesh at edge length h (the Roller's own mesh put aside meanwhile). */
static PetscErrorCode UniformCells(Roller ctx, PetscReal h, PetscInt *cells)
{
  RollerMesh saved = ctx->mesh;
  PetscInt   c_start, c_end;

  PetscFunctionBeginUser;
  ctx->mesh.h         = h;
  ctx->mesh.h_contact = 0;
  PetscCall(RollerMeshCreate(ctx));
  PetscCall(DMPlexGetHeightStratum(ctx->mesh.dm, 0, &c_start, &c_end));
  *cells = c_end - c_start;
  PetscCall(DMDestroy(&ctx->mesh.dm));
  ctx->mesh = saved;
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  const char *const scene[][2] = {
    {"-mesh_h",         "0.05"  },
    {"-mesh_h_contact", "0.0125"},
    {"-degree",         "2"     },
    {"-ts_dt",          "0.01"  },
    {"-omega",          "0"     }
  };
  Roller      ctx;
  PetscMPIInt size;
  EdgeStats   s;
  PetscInt    c_start, c_end, cells, fine, coarse;
  PetscReal   h, h_c, spread, layer, bulk;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCheck(size == 1, PETSC_COMM_WORLD, PETSC_ERR_WRONG_MPI_SIZE, "mesh_graded runs on one rank");
  PetscCall(RollerUnitSetUp(scene, ROLLER_UNIT_COUNT(scene), &ctx));
  h   = ctx->mesh.h;
  h_c = ctx->mesh.h_contact;
  PetscCheck(h_c > 0 && h_c < h, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "mesh_graded needs 0 < -mesh_h_contact < -mesh_h, got %g and %g", (double)h_c, (double)h);
  PetscCall(MeasureEdges(ctx, &s));
  spread = (s.outer[1] - s.outer[0]) / s.outer[1];
  layer  = s.layer[0] / s.layer[1];
  bulk   = s.bulk[0] / s.bulk[1];
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "h %g, h_c %g, L %g: Gamma_C arcs %.8g to %.8g (spread %.1e), Gamma_D arcs %.6g to %.6g; mean edge in the layer %.5g (%g edges), beyond the transition %.5g (%g edges)\n", (double)h, (double)h_c,
                        (double)ctx->mesh.contact_layer, (double)s.outer[0], (double)s.outer[1], (double)spread, (double)s.inner[0], (double)s.inner[1], (double)layer, (double)s.layer[1], (double)bulk, (double)s.bulk[1]));
  PetscCheck(spread < 1e-6, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "Gamma_C edges differ: arcs %.10g to %.10g (relative spread %g >= 1e-6)", (double)s.outer[0], (double)s.outer[1], (double)spread);
  PetscCheck(s.outer[1] <= h_c * (1 + 1e-12) && s.outer[0] > 0.97 * h_c, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "Gamma_C arcs %g to %g, expected within 3 %% below h_c = %g", (double)s.outer[0], (double)s.outer[1], (double)h_c);
  PetscCheck(s.inner[1] <= h * (1 + 1e-12) && s.inner[0] > 0.97 * h, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "Gamma_D arcs %g to %g, expected within 3 %% below h = %g (the inner circle keeps h)", (double)s.inner[0], (double)s.inner[1], (double)h);
  PetscCheck(s.layer[1] > 0 && PetscAbsReal(layer / h_c - 1) < 0.15, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the mean edge in the layer is %g, expected h_c = %g to 15 %%", (double)layer, (double)h_c);
  PetscCheck(s.bulk[1] > 0 && PetscAbsReal(bulk / h - 1) < 0.15, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the mean edge beyond the transition is %g, expected h = %g to 15 %%", (double)bulk, (double)h);
  PetscCall(DMPlexGetHeightStratum(ctx->mesh.dm, 0, &c_start, &c_end));
  cells = c_end - c_start;
  PetscCall(UniformCells(ctx, h_c, &fine));
  PetscCall(UniformCells(ctx, h, &coarse));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "cells: graded %" PetscInt_FMT ", uniform h_c %" PetscInt_FMT " (ratio %.3f), uniform h %" PetscInt_FMT "\n", cells, fine, (double)cells / fine, coarse));
  PetscCheck(cells < 0.4 * fine && cells > coarse, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the graded mesh has %" PetscInt_FMT " cells: expected fewer than 40 %% of the uniform h_c mesh's %" PetscInt_FMT " and more than the uniform h mesh's %" PetscInt_FMT, cells, fine, coarse);
  PetscCall(RollerDestroy(&ctx));
  PetscCall(PetscFinalize());
  return 0;
}
