/* The output layer (docs/output.md):
     output.c        the HDF5 fields and the output object's life
     output_csv.c    the monitor CSV (docs/model.md section 6)
     output_xdmf.c   the HDF5 layout and the XDMF index
     series.c        the diagnostics time series in the HDF5 file
     output_files.c  .part files renamed on success, stale outputs, writable paths (also the checkpoint's) */
#ifndef ROLLER_IO_H
#define ROLLER_IO_H

#include <roller_impl.h>
#include "contact/contact.h"

/* output_files.c: output that must not look complete before it is (CSV, HDF5, XDMF, checkpoint) */
PETSC_INTERN PetscErrorCode RollerJoinPath(char[], size_t, const char[], const char[], const char[]);
PETSC_INTERN PetscErrorCode RollerRenameFile(MPI_Comm, const char[], const char[]);
PETSC_INTERN PetscErrorCode RollerRemoveStale(MPI_Comm, const char[]);
PETSC_INTERN PetscErrorCode RollerCheckWritable(MPI_Comm, const char[], const char[]);

/* series.c: the diagnostics time series written into the HDF5 output */
typedef struct _n_RollerSeries *RollerSeries;
PETSC_INTERN PetscErrorCode     RollerSeriesAppend(Roller, RollerSeries *);
PETSC_INTERN PetscErrorCode     RollerSeriesWrite(Roller, RollerSeries, PetscViewer);
PETSC_INTERN PetscErrorCode     RollerSeriesDestroy(RollerSeries *);

/* output.c, output_csv.c, output_xdmf.c */
PETSC_INTERN PetscErrorCode RollerOutputCreate(Roller, RollerOutput *);
PETSC_INTERN PetscErrorCode RollerOutputStep(Roller, RollerOutput);
PETSC_INTERN PetscErrorCode RollerOutputDestroy(Roller, RollerOutput *);

#endif
