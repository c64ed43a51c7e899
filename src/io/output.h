/* Private to the output*.c files: the output object (CSV, HDF5 fields, XDMF index) and the helpers the
   files share. One concern a file: output.c the fields and the object's life, output_csv.c the CSV,
   output_xdmf.c the HDF5 layout and the XDMF index (the file handling they share with the
   checkpoint is output_files.c, declared in roller_impl.h). */
#ifndef ROLLER_IO_OUTPUT_H
#define ROLLER_IO_OUTPUT_H

#include "io/io.h"
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

/* The fields written every -output_every steps; an optional one (the contact pressure, with -obstacle) goes
   at the end, and out->nfields counts those in use: the index and the checks follow the table. */
enum { FIELD_DISPLACEMENT, FIELD_LAB, FIELD_VELOCITY, FIELD_STRESS, FIELD_CONTACT_PRESSURE, MAX_FIELDS };

struct _n_RollerOutput {
  /* CSV: written to csv_part, renamed to csv_path at the end */
  char  csv_path[PETSC_MAX_PATH_LEN], csv_part[PETSC_MAX_PATH_LEN], csv_old[PETSC_MAX_PATH_LEN];
  FILE *csv; /* rank 0 only */

  /* HDF5 h5_path (written as h5_part) and its index xmf_path (written as xmf_part) */
  char        h5_path[PETSC_MAX_PATH_LEN], h5_part[PETSC_MAX_PATH_LEN];
  char        xmf_path[PETSC_MAX_PATH_LEN], xmf_part[PETSC_MAX_PATH_LEN];
  PetscViewer h5;
  int         xmf_fd;   /* rank 0: the open xmf_part, grown in place by XdmfAppend (-1: not yet created) */
  off_t       xmf_tail; /* where its closing tags start */
  PetscInt    every, written, times_size;
  PetscReal  *times; /* t of every written step, the XDMF time values */
  Dataset     vertices, cells;

  /* Output spaces on the same mesh: vdm P1 with 3 components, sdm and pdm (contact pressure) P1 scalar */
  DM           vdm, sdm, pdm;
  Vec          velocity; /* on ctx->mesh.dm */
  Vec          position; /* (x, y, 0) at every vertex (vdm) */
  Vec          count;    /* the number of cells around every vertex (sdm) */
  OutputField  field[MAX_FIELDS];
  PetscInt     nfields;
  RollerSeries series; /* R, alpha, energy, ... of every step, to /diagnostics at the end */
};

/* output_xdmf.c */
PETSC_INTERN PetscErrorCode RollerXdmfPaths(RollerOutput);
PETSC_INTERN PetscErrorCode RollerDatasetQuery(PetscViewer, const char[], Dataset *);
PETSC_INTERN PetscErrorCode RollerLayoutUpdate(RollerOutput);
PETSC_INTERN PetscErrorCode RollerXdmfWrite(MPI_Comm, RollerOutput, const char[], const char[]);
PETSC_INTERN PetscErrorCode RollerXdmfAppend(MPI_Comm, RollerOutput);
PETSC_INTERN PetscErrorCode RollerXdmfClose(RollerOutput);

/* output_csv.c */
PETSC_INTERN PetscErrorCode RollerCsvOpen(Roller, RollerOutput);
PETSC_INTERN PetscErrorCode RollerCsvRow(Roller, RollerOutput);
PETSC_INTERN PetscErrorCode RollerCsvClose(Roller, RollerOutput);

#endif
