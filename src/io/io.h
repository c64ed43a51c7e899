/* The output layer (docs/output.md): the writers; the observers of the run that call them are the driver's
   (integrate/observers.c), set up from the "Roller: output" options read here.
     output.c        the HDF5 fields; the output options
     output_csv.c    the monitor CSV (docs/model.md section 6)
     output_xdmf.c   the HDF5 layout and the XDMF index
     series.c        the diagnostics time series in the HDF5 file
     output_modes.c  the mode shapes of -modes and their XDMF index; one read back
     output_files.c  .part files renamed on success, stale outputs, writable paths (also the checkpoint's) */
#ifndef ROLLER_IO_H
#define ROLLER_IO_H

#include <roller_impl.h>
#include "contact/contact.h"

#define ROLLER_SURFACE_ORDERS 4 /* -monitor_surface_orders' default */

/* output_files.c: output that must not look complete before it is (CSV, HDF5, XDMF, checkpoint) */
PETSC_INTERN PetscErrorCode RollerJoinPath(char[], size_t, const char[], const char[], const char[]);
PETSC_INTERN PetscErrorCode RollerRenameFile(MPI_Comm, const char[], const char[]);
PETSC_INTERN PetscErrorCode RollerRemoveStale(MPI_Comm, const char[]);
PETSC_INTERN PetscErrorCode RollerCheckWritable(MPI_Comm, const char[], const char[]);
PETSC_INTERN PetscErrorCode RollerHDF5Probe(MPI_Comm, const char[], const char[]);                             /* option, path: HDF5 that opens, or one line */
PETSC_INTERN PetscErrorCode RollerPartFileOpen(MPI_Comm, const char[], const char[], char[], size_t, FILE **); /* path, option, part */
PETSC_INTERN PetscErrorCode RollerPartFileClose(MPI_Comm, FILE **, const char[], const char[]);                /* part, path */
PETSC_INTERN PetscErrorCode RollerPlainVecView(Vec, const char[], PetscViewer, PetscBool);                     /* a flat dataset by name: view, or load (PETSC_TRUE) */

/* series.c: the diagnostics time series written into the HDF5 output */
typedef struct _n_RollerSeries *RollerSeries;
PETSC_INTERN PetscErrorCode     RollerSeriesAppend(Roller, RollerSeries *);
PETSC_INTERN PetscErrorCode     RollerSeriesWrite(Roller, RollerSeries, PetscViewer);
PETSC_INTERN PetscErrorCode     RollerSeriesDestroy(RollerSeries *);

/* output_csv.c: the CSV writer (RollerCsvOpen's resume: the step a restart continues after, -1 for a new run;
   RollerCsvClose: the successful end, F.part renamed to F) */
typedef struct _n_RollerCsv *RollerCsv;
PETSC_INTERN PetscErrorCode  RollerCsvOpen(MPI_Comm, const char[], PetscInt, RollerCsv *);
PETSC_INTERN PetscErrorCode  RollerCsvRow(RollerCsv, PetscInt, PetscReal, const RollerStepInfo *, PetscReal);
PETSC_INTERN PetscErrorCode  RollerCsvClose(RollerCsv);
PETSC_INTERN PetscErrorCode  RollerCsvDestroy(RollerCsv *);

/* output.c: the fields (HDF5 + XDMF index, the diagnostics series) and the output options */
typedef struct _n_RollerOutput *RollerOutput;
PETSC_INTERN PetscErrorCode     RollerOutputSetFromOptions(Roller, char[], char[], size_t, PetscInt *, PetscReal *); /* csv, h5 paths (empty: none), every, start */
PETSC_INTERN PetscErrorCode     RollerFieldsCreate(Roller, const char[], PetscInt, PetscReal, RollerOutput *);       /* path, every, start */
PETSC_INTERN PetscErrorCode     RollerFieldsStep(Roller, RollerOutput);                                              /* the step's diagnostics (ctx->info) and, every N steps, its fields */
PETSC_INTERN PetscErrorCode     RollerFieldsClose(Roller, RollerOutput);
PETSC_INTERN PetscErrorCode     RollerFieldsDestroy(RollerOutput *);

/* output_modes.c: the shapes of -modes (HDF5 + XDMF) and one of them read back */
PETSC_INTERN PetscErrorCode RollerModeShapesWrite(Roller, const char[], PetscInt, const PetscReal[], const PetscReal[], const PetscInt[], Vec[], Vec[], Vec);
PETSC_INTERN PetscErrorCode RollerModeFileRead(Roller, const char[], PetscInt, RollerFrame *, PetscReal *, PetscReal *, Vec, Vec, Vec, PetscBool *);

#endif
