/* Private to the output*.c files: the fields output (HDF5 fields, XDMF index) and the helpers the files
   share. One concern a file: output.c the fields, output_csv.c the CSV,
   output_xdmf.c the HDF5 layout and the XDMF index (the file handling they share with the checkpoint is
   output_files.c, declared in io.h). */
#ifndef ROLLER_IO_OUTPUT_H
#define ROLLER_IO_OUTPUT_H

#include "io/io.h"
#include "model/kernels.h"
#include <petscviewerhdf5.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The shape and number type of one HDF5 dataset, as the XDMF index must state them. */
typedef struct {
  char      path[PETSC_MAX_PATH_LEN];
  int       ndims;
  hsize_t   dims[3];
  PetscBool is_int;
  size_t    precision; /* bytes */
} Dataset;

/* One vertex field: the Vec written with VecView, and the dataset PETSc makes of it,
   /vertex_fields/<vec name>_<field name>, of shape [steps, vertices] or [steps, vertices, 3]. */
typedef struct {
  Vec     vec;
  Dataset data;
} OutputField;

/* The fields written every -output_every steps; optional ones (the contact pressure with -obstacle, the
   tangential traction and the stick/slip state with -friction) go
   at the end, and out->nfields counts those in use: the index and the checks follow the table. */
enum { FIELD_DISPLACEMENT, FIELD_LAB, FIELD_VELOCITY, FIELD_STRESS, FIELD_CONTACT_PRESSURE, FIELD_CONTACT_TRACTION, FIELD_CONTACT_STATE, MAX_FIELDS };

/* The XDMF index of the HDF5 file: path (written as part, grown in place by RollerXdmfAppend), the steps
   written so far and their times, the mesh datasets every step's grid refers to. */
typedef struct {
  char       path[PETSC_MAX_PATH_LEN], part[PETSC_MAX_PATH_LEN];
  int        fd;   /* rank 0: the open part, grown in place by RollerXdmfAppend (-1: not yet created) */
  off_t      tail; /* where its closing tags start */
  PetscInt   written, size;
  PetscReal *times; /* t of every written step, the XDMF time values (size allocated) */
  Dataset    vertices, cells;
} RollerXdmf;

/* The fields output (-output F.h5): the writer (its observer is integrate/observers.c). */
struct _n_RollerOutput {
  /* HDF5 h5_path (written as h5_part) and its index */
  char        h5_path[PETSC_MAX_PATH_LEN], h5_part[PETSC_MAX_PATH_LEN];
  PetscViewer h5;
  PetscInt    every;
  PetscReal   start; /* -output_start: no fields before this time */
  RollerXdmf  xdmf;

  /* Output spaces on the same mesh: vdm P1 with 3 components; sdm, pdm (contact pressure), tdm and cdm (the
     friction traction and the stick/slip state) P1 scalar */
  DM           vdm, sdm, pdm, tdm, cdm;
  Vec          position;     /* (x, y, 0) at every vertex (vdm) */
  Vec          count;        /* the number of cells around every vertex (sdm) */
  Vec          xfull, vfull; /* -rom: the displacement V q (+ the Gamma_C residual) and velocity V v on the mesh */
  OutputField  field[MAX_FIELDS];
  PetscInt     nfields;
  RollerSeries series; /* R, alpha, energy, ... of every step, to /diagnostics at the end */
};

/* output.c: what the fields output shares with the mode shapes (output_modes.c) */
PETSC_INTERN PetscErrorCode RollerOutputSpace(Roller, PetscInt, const char[], DM *); /* P1, nc components */
PETSC_INTERN PetscErrorCode RollerFieldCreate(DM, const char[], OutputField *);
PETSC_INTERN PetscErrorCode RollerProjectAtVertices(Roller, Vec, RollerPointFunc, InsertMode, Vec); /* u on ctx->mesh.dm */
PETSC_INTERN PetscErrorCode RollerWriteParameters(Roller, PetscViewer);
PETSC_INTERN PetscErrorCode RollerOutputHubAtVertices(Roller, RollerOutput, Vec, Vec);              /* -axle: xi, v at Gamma_D's vertices (output_hub.c) */
PETSC_INTERN PetscErrorCode RollerCheckParameters(Roller, PetscViewer, const char[], const char[]); /* option, file */
PETSC_INTERN void           RollerPadVector(ROLLER_KERNEL_ARGS, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[]);

/* output_xdmf.c */
PETSC_INTERN PetscErrorCode RollerXdmfPaths(RollerOutput);
PETSC_INTERN PetscErrorCode RollerDatasetQuery(PetscViewer, const char[], Dataset *);
PETSC_INTERN PetscErrorCode RollerLayoutUpdate(RollerOutput);
PETSC_INTERN PetscErrorCode RollerXdmfWrite(MPI_Comm, RollerOutput, const char[], const char[]);
PETSC_INTERN PetscErrorCode RollerXdmfAppend(MPI_Comm, RollerOutput);
PETSC_INTERN PetscErrorCode RollerXdmfClose(RollerOutput);

#endif
