/* Files that must not look complete before they are: joined names checked for length, the rank-0 rename
   of a finished .part file, stale outputs of an earlier run removed, a writable path checked early. Used by
   the CSV, the HDF5/XDMF output and the checkpoint. */
#include "io/io.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <hdf5.h>

PetscErrorCode RollerJoinPath(char dst[], size_t len, const char a[], const char b[], const char option[])
{
  size_t la, lb;

  PetscFunctionBeginUser;
  PetscCall(PetscStrlen(a, &la));
  PetscCall(PetscStrlen(b, &lb));
  PetscCheck(la + lb < len, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s %s: the file name is too long (at most %d characters)", option, a, (int)(len - lb - 1));
  PetscCall(PetscStrncpy(dst, a, len));
  PetscCall(PetscStrlcat(dst, b, len));
  PetscFunctionReturn(0);
}

/* Rank 0 renames from -> to (atomic on one file system); everyone waits for it. */
PetscErrorCode RollerRenameFile(MPI_Comm comm, const char from[], const char to[])
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) PetscCheck(rename(from, to) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename %s to %s: %s", from, to, strerror(errno));
  PetscCallMPI(MPI_Barrier(comm));
  PetscFunctionReturn(0);
}

/* Remove what an earlier run left under these names, so that a failed run cannot sit next to a
   complete-looking output of another run (the files would have been truncated anyway). */
PetscErrorCode RollerRemoveStale(MPI_Comm comm, const char path[])
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0 && path[0]) PetscCheck(remove(path) == 0 || errno == ENOENT, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot remove the old output %s: %s", path, strerror(errno));
  PetscFunctionReturn(0);
}

/* Fail early, with the option in the message, if path cannot be created (HDF5 would say it less clearly). */
PetscErrorCode RollerCheckWritable(MPI_Comm comm, const char option[], const char path[])
{
  PetscMPIInt rank;
  int         err = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    FILE *fp = fopen(path, "w");

    if (!fp) err = errno;
    else {
      fclose(fp);
      remove(path);
    }
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_OPEN, "%s: cannot write %s: %s", option, path, strerror(err));
  PetscFunctionReturn(0);
}

/* A small file that rank 0 writes whole (the -modes CSVs): the stale path removed, path.part checked writable (option
   named in the message) and opened on rank 0 (*fp NULL on the others); RollerPartFileClose closes it and renames
   it to path. */
PetscErrorCode RollerPartFileOpen(MPI_Comm comm, const char path[], const char option[], char part[], size_t len, FILE **fp)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  *fp = NULL;
  PetscCall(RollerJoinPath(part, len, path, ".part", option));
  PetscCall(RollerRemoveStale(comm, path));
  PetscCall(RollerCheckWritable(comm, option, part));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) PetscCall(PetscFOpen(PETSC_COMM_SELF, part, "w", fp));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerPartFileClose(MPI_Comm comm, FILE **fp, const char part[], const char path[])
{
  PetscFunctionBeginUser;
  if (*fp) PetscCall(PetscFClose(PETSC_COMM_SELF, *fp));
  *fp = NULL;
  PetscCall(RollerRenameFile(comm, part, path));
  PetscFunctionReturn(0);
}

/* Through a plain MPI vector of the same layout, HDF5 writes a flat dataset by name, not the DM's fields.
   (VecLoad replaces a vector's array, so the load goes through a copy.) */
PetscErrorCode RollerPlainVecView(Vec v, const char *name, PetscViewer viewer, PetscBool load)
{
  Vec      plain;
  PetscInt n, N;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetSize(v, &N));
  PetscCall(VecCreateMPI(PetscObjectComm((PetscObject)v), n, N, &plain));
  PetscCall(PetscObjectSetName((PetscObject)plain, name));
  if (load) {
    PetscCall(VecLoad(plain, viewer));
    PetscCall(VecCopy(plain, v));
  } else {
    PetscCall(VecCopy(v, plain));
    PetscCall(VecView(plain, viewer));
  }
  PetscCall(VecDestroy(&plain));
  PetscFunctionReturn(0);
}

/* A file to read with HDF5: one line, not HDF5's error stack, if it is not HDF5 or does not open (truncated or
   damaged); HDF5's error printing is off during the probe. */
PetscErrorCode RollerHDF5Probe(MPI_Comm comm, const char option[], const char path[])
{
  H5E_auto2_t func;
  void       *data;
  htri_t      is_h5;
  hid_t       f = -1;

  PetscFunctionBeginUser;
  (void)H5Eget_auto2(H5E_DEFAULT, &func, &data);
  (void)H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  is_h5 = H5Fis_hdf5(path);
  if (is_h5 > 0) f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f >= 0) H5Fclose(f);
  (void)H5Eset_auto2(H5E_DEFAULT, func, data);
  PetscCheck(is_h5 > 0, comm, PETSC_ERR_FILE_UNEXPECTED, "%s %s: not an HDF5 file (not one Roller wrote)", option, path);
  PetscCheck(f >= 0, comm, PETSC_ERR_FILE_UNEXPECTED, "%s %s: an HDF5 file that does not open (truncated or damaged)", option, path);
  PetscFunctionReturn(0);
}
