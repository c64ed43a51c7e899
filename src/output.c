/* What a run leaves behind (docs/model.md section 6, docs/output.md): the monitor CSV, one row per step, and the
   fields every N steps to HDF5 with an XDMF index so ParaView opens it directly. Output is what was
   asked: without -monitor_csv no CSV, without -output no field is computed.

   A run that fails must not leave output that looks complete: the files are written as F.part (CSV and
   HDF5) and <base>.part.xmf (the index) and renamed to F and <base>.xmf by RollerOutputDestroy, which only
   a successful run reaches. After every field write the HDF5 file is flushed and the new step appended to
   the index in place (XdmfAppend: written once, not rewritten, so N steps cost O(N)), so a killed run
   still has a readable F.part indexed up to its last written step; the final <base>.xmf is written whole
   once, at the end.

   The fields are written at the mesh vertices (P1), vectors with a zero third component: ParaView's
   vector filters (Warp By Vector, Glyph) need 3-component vectors, and the XDMF Function "JOIN" that
   would pad a 2-component dataset is read differently by the Xdmf2 (interlaces) and Xdmf3 (concatenates)
   readers, so the padding is in the data, where every reader agrees. */
#include <roller_impl.h>
#include <petscviewerhdf5.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "kernels.h"

typedef void (*PointwiseFunc)(PetscInt, PetscInt, PetscInt, const PetscInt[], const PetscInt[], const PetscScalar[], const PetscScalar[], const PetscScalar[], const PetscInt[], const PetscInt[], const PetscScalar[], const PetscScalar[], const PetscScalar[], PetscReal, const PetscReal[], PetscInt, const PetscScalar[], PetscScalar[]);

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
  Vec          velocity; /* on ctx->dm */
  Vec          position; /* (x, y, 0) at every vertex (vdm) */
  Vec          count;    /* the number of cells around every vertex (sdm) */
  OutputField  field[MAX_FIELDS];
  PetscInt     nfields;
  RollerSeries series; /* R, alpha, energy, ... of every step, to /diagnostics at the end */
};

/* Projection kernels (DMProjectField evaluates them at the vertices). */
static void f_pad_vector(PetscInt dim, PetscInt Nf, PetscInt NfAux, const PetscInt uOff[], const PetscInt uOff_x[], const PetscScalar u[], const PetscScalar u_t[], const PetscScalar u_x[], const PetscInt aOff[], const PetscInt aOff_x[], const PetscScalar a[], const PetscScalar a_t[], const PetscScalar a_x[], PetscReal t, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[])
{
  f[0] = u[0];
  f[1] = u[1];
  f[2] = 0.0;
}

static PetscErrorCode Position(PetscInt dim, PetscReal time, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  for (PetscInt c = 0; c < Nc; ++c) u[c] = c < dim ? x[c] : 0.0;
  return 0;
}

static void f_one(PetscInt dim, PetscInt Nf, PetscInt NfAux, const PetscInt uOff[], const PetscInt uOff_x[], const PetscScalar u[], const PetscScalar u_t[], const PetscScalar u_x[], const PetscInt aOff[], const PetscInt aOff_x[], const PetscScalar a[], const PetscScalar a_t[], const PetscScalar a_x[], PetscReal t, const PetscReal x[], PetscInt numConstants, const PetscScalar constants[], PetscScalar f[])
{
  f[0] = 1.0;
}

/* ---------------------------------------------------------------------------------------------------
   Files */

static PetscErrorCode JoinPath(char dst[], size_t len, const char a[], const char b[], const char option[])
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
static PetscErrorCode RenameFile(MPI_Comm comm, const char from[], const char to[])
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
static PetscErrorCode RemoveStale(MPI_Comm comm, const char path[])
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0 && path[0]) PetscCheck(remove(path) == 0 || errno == ENOENT, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot remove the old output %s: %s", path, strerror(errno));
  PetscFunctionReturn(0);
}

/* A restart continues the CSV of the run it restarts: the rows up to its step are copied from the
   earlier file (complete, or .part if that run was killed) into the new .part, so that an interrupted and
   restarted run ends with the same rows as an uninterrupted one. Rank 0 reads and writes. */
static PetscErrorCode CsvResume(Roller ctx, RollerOutput out)
{
  PetscMPIInt rank;
  char        line[4096];
  FILE       *src;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  if (rank) PetscFunctionReturn(0);
  src = fopen(out->csv_old, "r");
  if (!src) {
    PetscCall(PetscInfo(NULL, "-restart: no earlier %s to continue; the CSV starts after step %" PetscInt_FMT "\n", out->csv_path, ctx->step));
    PetscFunctionReturn(0);
  }
  PetscCheck(fgets(line, sizeof(line), src), PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "-monitor_csv %s: empty file, cannot continue it after -restart", out->csv_path);
  while (fgets(line, sizeof(line), src)) {
    if (atol(line) > (long)ctx->step) break;
    PetscCheck(fputs(line, out->csv) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", out->csv_part, strerror(errno));
  }
  fclose(src);
  PetscCheck(remove(out->csv_old) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot remove %s: %s", out->csv_old, strerror(errno));
  PetscFunctionReturn(0);
}

/* Before a restart truncates the CSV: keep the earlier run's rows (complete file, or .part if it was killed). */
static PetscErrorCode CsvKeepOld(MPI_Comm comm, RollerOutput out)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0 && (rename(out->csv_path, out->csv_old) == 0 || rename(out->csv_part, out->csv_old) == 0)) PetscCall(PetscInfo(NULL, "-restart: continuing %s\n", out->csv_path));
  PetscCallMPI(MPI_Barrier(comm));
  PetscFunctionReturn(0);
}

/* Fail early, with the option in the message, if path cannot be created (HDF5 would say it less clearly). */
static PetscErrorCode CheckWritable(MPI_Comm comm, const char option[], const char path[])
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

/* The index lives beside the HDF5 file: F.h5 -> F.xmf (the extension replaced), part name F.part.xmf. */
static PetscErrorCode XdmfPaths(RollerOutput out)
{
  char        base[PETSC_MAX_PATH_LEN];
  const char *slash, *dot;

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(base, out->h5_path, sizeof(base)));
  slash = strrchr(base, '/');
  dot   = strrchr(base, '.');
  if (dot && dot > (slash ? slash + 1 : base)) base[dot - base] = '\0';
  PetscCall(JoinPath(out->xmf_path, sizeof(out->xmf_path), base, ".xmf", "-output"));
  PetscCall(JoinPath(out->xmf_part, sizeof(out->xmf_part), base, ".part.xmf", "-output"));
  PetscCheck(strcmp(out->xmf_path, out->h5_path), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "-output %s: the fields and their XDMF index would have the same name; use F.h5", out->h5_path);
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------
   HDF5 layout: read back from the file, so the index states exactly what is there */

static PetscErrorCode DatasetQuery(PetscViewer h5, const char path[], Dataset *d)
{
  hid_t file, set, space, type;
  int   n;

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(d->path, path, sizeof(d->path)));
  PetscCall(PetscViewerHDF5GetFileId(h5, &file));
  set = H5Dopen2(file, path, H5P_DEFAULT);
  PetscCheck(set >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "The output file has no dataset %s", path);
  space = H5Dget_space(set);
  type  = H5Dget_type(set);
  PetscCheck(space >= 0 && type >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot read the shape of %s", path);
  n = H5Sget_simple_extent_ndims(space);
  PetscCheck(n >= 1 && n <= 3, PETSC_COMM_SELF, PETSC_ERR_LIB, "Dataset %s has %d dimensions, expected 1 to 3", path, n);
  d->ndims = n;
  PetscCheck(H5Sget_simple_extent_dims(space, d->dims, NULL) == n, PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot read the shape of %s", path);
  d->is_int    = H5Tget_class(type) == H5T_INTEGER ? PETSC_TRUE : PETSC_FALSE;
  d->precision = H5Tget_size(type);
  PetscCheck(H5Tclose(type) >= 0 && H5Sclose(space) >= 0 && H5Dclose(set) >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot close %s", path);
  PetscFunctionReturn(0);
}

/* After every field write: the data on disk (a killed run keeps it), then every field's shape. */
static PetscErrorCode LayoutUpdate(RollerOutput out)
{
  hid_t file;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5GetFileId(out->h5, &file));
  PetscCheck(H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot flush %s", out->h5_part);
  for (PetscInt f = 0; f < out->nfields; ++f) {
    Dataset *d = &out->field[f].data;

    PetscCall(DatasetQuery(out->h5, d->path, d));
    PetscCheck(d->ndims >= 2 && d->dims[0] == (hsize_t)out->written && d->dims[1] == out->vertices.dims[0], PETSC_COMM_SELF, PETSC_ERR_LIB, "Dataset %s does not have %" PetscInt_FMT " steps of %d vertices", d->path, out->written, (int)out->vertices.dims[0]);
  }
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------
   XDMF index: a temporal collection of triangle grids, one Attribute per vertex field and step, each a
   HyperSlab of the [steps, vertices(, 3)] dataset. Written by rank 0 to a temporary name and renamed. */

static PetscErrorCode XmlDataItem(FILE *fp, const char h5_name[], const Dataset *d, const char extra[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "<DataItem%s Format=\"HDF\" NumberType=\"%s\" Precision=\"%d\" Dimensions=\"", extra, d->is_int ? "Int" : "Float", (int)d->precision));
  for (int i = 0; i < d->ndims; ++i) PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "%s%llu", i ? " " : "", (unsigned long long)d->dims[i]));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "\">%s:%s</DataItem>\n", h5_name, d->path));
  PetscFunctionReturn(0);
}

static PetscErrorCode XmlAttribute(FILE *fp, const char h5_name[], const char name[], const Dataset *d, PetscInt step)
{
  const unsigned long long nv = (unsigned long long)d->dims[1];

  PetscFunctionBeginUser;
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "        <Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"Node\">\n", name, d->ndims == 3 ? "Vector" : "Scalar"));
  if (d->ndims == 3) {
    const unsigned long long bs = (unsigned long long)d->dims[2];

    PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "          <DataItem ItemType=\"HyperSlab\" Type=\"HyperSlab\" Dimensions=\"1 %llu %llu\">\n", nv, bs));
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "            <DataItem Format=\"XML\" Dimensions=\"3 3\">%" PetscInt_FMT " 0 0 1 1 1 1 %llu %llu</DataItem>\n", step, nv, bs));
  } else {
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "          <DataItem ItemType=\"HyperSlab\" Type=\"HyperSlab\" Dimensions=\"1 %llu\">\n", nv));
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "            <DataItem Format=\"XML\" Dimensions=\"3 2\">%" PetscInt_FMT " 0 1 1 1 %llu</DataItem>\n", step, nv));
  }
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "            "));
  PetscCall(XmlDataItem(fp, h5_name, d, ""));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "          </DataItem>\n        </Attribute>\n"));
  PetscFunctionReturn(0);
}

/* The index is written in three parts: the head (the mesh), one Grid per written step, and a fixed tail
   that closes the document. */
static const char xdmf_tail[] = "    </Grid>\n  </Domain>\n</Xdmf>\n";

/* The name by which the index refers to h5_file: its base name (the index sits beside it). */
static PetscErrorCode XdmfH5Name(const char h5_file[], const char **h5_name)
{
  PetscFunctionBeginUser;
  *h5_name = strrchr(h5_file, '/') ? strrchr(h5_file, '/') + 1 : h5_file;
  PetscCheck(!strpbrk(*h5_name, "&<>\":"), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "-output %s: the XDMF index cannot refer to a file name with any of &<>\": in it", h5_file);
  PetscFunctionReturn(0);
}

static PetscErrorCode XdmfHead(FILE *fp, RollerOutput out, const char h5_name[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n  <Domain Name=\"roller\">\n    "));
  PetscCall(XmlDataItem(fp, h5_name, &out->cells, " Name=\"cells\""));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "    "));
  PetscCall(XmlDataItem(fp, h5_name, &out->vertices, " Name=\"vertices\""));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "    <Grid Name=\"roller\" GridType=\"Collection\" CollectionType=\"Temporal\">\n"));
  PetscFunctionReturn(0);
}

/* The Grid of written step k; the datasets' shapes are those of out->field[] now (LayoutUpdate). */
static PetscErrorCode XdmfGrid(FILE *fp, RollerOutput out, const char h5_name[], PetscInt k)
{
  const char *corners;

  PetscFunctionBeginUser;
  switch (out->cells.dims[1]) {
  case 3:
    corners = "Triangle";
    break;
  case 4:
    corners = "Quadrilateral";
    break;
  default:
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_SUP, "Cells with %d corners in %s", (int)out->cells.dims[1], out->cells.path);
  }
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "      <Grid Name=\"step %" PetscInt_FMT "\" GridType=\"Uniform\">\n        <Time Value=\"%.17g\"/>\n", k, (double)out->times[k]));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "        <Topology TopologyType=\"%s\" NumberOfElements=\"%llu\"><DataItem Reference=\"XML\">/Xdmf/Domain/DataItem[@Name=\"cells\"]</DataItem></Topology>\n", corners, (unsigned long long)out->cells.dims[0]));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "        <Geometry GeometryType=\"%s\"><DataItem Reference=\"XML\">/Xdmf/Domain/DataItem[@Name=\"vertices\"]</DataItem></Geometry>\n", out->vertices.dims[1] == 3 ? "XYZ" : "XY"));
  for (PetscInt f = 0; f < out->nfields; ++f) {
    const char *name;

    PetscCall(PetscObjectGetName((PetscObject)out->field[f].vec, &name));
    PetscCall(XmlAttribute(fp, h5_name, name, &out->field[f].data, k));
  }
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "      </Grid>\n"));
  PetscFunctionReturn(0);
}

/* The complete index of h5_file, every written step, to xmf (through a temporary name, renamed). Once, at
   the end of a successful run: the steps dimension stated is then the final one in every Grid. */
static PetscErrorCode XdmfWrite(MPI_Comm comm, RollerOutput out, const char h5_file[], const char xmf[])
{
  char        tmp[PETSC_MAX_PATH_LEN];
  const char *h5_name;
  PetscMPIInt rank;
  FILE       *fp;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank) PetscFunctionReturn(0);
  PetscCall(XdmfH5Name(h5_file, &h5_name));
  PetscCall(JoinPath(tmp, sizeof(tmp), xmf, ".tmp", "-output"));
  PetscCall(PetscFOpen(PETSC_COMM_SELF, tmp, "w", &fp));
  PetscCall(XdmfHead(fp, out, h5_name));
  for (PetscInt k = 0; k < out->written; ++k) PetscCall(XdmfGrid(fp, out, h5_name, k));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "%s", xdmf_tail));
  PetscCall(PetscFClose(PETSC_COMM_SELF, fp));
  PetscCheck(rename(tmp, xmf) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename %s to %s: %s", tmp, xmf, strerror(errno));
  PetscFunctionReturn(0);
}

/* All of buf[0, len) to fd at offset off, in one pwrite unless the system writes less. */
static PetscErrorCode WriteAt(int fd, const char path[], const char *buf, size_t len, off_t off)
{
  PetscFunctionBeginUser;
  while (len > 0) {
    ssize_t n = pwrite(fd, buf, len, off);

    if (n < 0 && errno == EINTR) continue;
    PetscCheck(n > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write the XDMF index %s: %s", path, n < 0 ? strerror(errno) : "nothing written");
    buf += n;
    len -= (size_t)n;
    off += n;
  }
  PetscFunctionReturn(0);
}

/* After every field write, the running index of the .part HDF5 file grows by the new step in place, so
   writing N steps costs O(N), not O(N^2) as rewriting it would. The first step creates it whole under a
   temporary name and renames it (no reader sees it empty); it stays open on rank 0, and every later step
   overwrites the fixed tail (the closing tags, at out->xmf_tail) with its Grid followed by the tail, in
   one write, so the file is a complete index after every step. Each Grid states the datasets' shapes as
   they were when it was written (the steps dimension grows; readers take its HyperSlab, inside them). */
static PetscErrorCode XdmfAppend(MPI_Comm comm, RollerOutput out)
{
  const char *h5_name;
  char       *buf = NULL;
  size_t      len = 0;
  PetscMPIInt rank;
  FILE       *ms;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank) PetscFunctionReturn(0);
  PetscCall(XdmfH5Name(out->h5_part, &h5_name));
  ms = open_memstream(&buf, &len);
  PetscCheck(ms, PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot build the XDMF index %s in memory: %s", out->xmf_part, strerror(errno));
  if (out->xmf_fd < 0) {
    PetscCall(XdmfHead(ms, out, h5_name));
    for (PetscInt k = 0; k < out->written; ++k) PetscCall(XdmfGrid(ms, out, h5_name, k));
  } else PetscCall(XdmfGrid(ms, out, h5_name, out->written - 1));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, ms, "%s", xdmf_tail));
  PetscCheck(fclose(ms) == 0 && buf, PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot build the XDMF index %s in memory", out->xmf_part);
  if (out->xmf_fd < 0) {
    char tmp[PETSC_MAX_PATH_LEN];

    PetscCall(JoinPath(tmp, sizeof(tmp), out->xmf_part, ".tmp", "-output"));
    out->xmf_fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC, 0666);
    PetscCheck(out->xmf_fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot create the XDMF index %s: %s", tmp, strerror(errno));
    PetscCall(WriteAt(out->xmf_fd, tmp, buf, len, 0));
    PetscCheck(rename(tmp, out->xmf_part) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename %s to %s: %s", tmp, out->xmf_part, strerror(errno));
    out->xmf_tail = 0;
  } else PetscCall(WriteAt(out->xmf_fd, out->xmf_part, buf, len, out->xmf_tail));
  out->xmf_tail += (off_t)(len - strlen(xdmf_tail));
  free(buf); /* open_memstream's, from malloc */
  PetscFunctionReturn(0);
}

/* Rank 0 closes the running index (it stays on disk). */
static PetscErrorCode XdmfClose(RollerOutput out)
{
  PetscFunctionBeginUser;
  if (out->xmf_fd >= 0) PetscCheck(close(out->xmf_fd) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot close the XDMF index %s: %s", out->xmf_part, strerror(errno));
  out->xmf_fd = -1;
  PetscFunctionReturn(0);
}

/* Evaluate a kernel of the field u (on ctx->dm) at the vertices of the output space of X. ADD_VALUES sums
   over the cells around each vertex (then divided by their number: a derivative such as sigma is
   discontinuous across cells and its vertex value is the mean of the cells' values). */
static PetscErrorCode ProjectAtVertices(Roller ctx, Vec u, PointwiseFunc kernel, InsertMode mode, Vec X)
{
  PointwiseFunc funcs[1] = {kernel};
  DM            dm;
  Vec           ul, Xl;

  PetscFunctionBeginUser;
  PetscCall(VecGetDM(X, &dm));
  PetscCall(DMGetLocalVector(ctx->dm, &ul));
  PetscCall(DMGetLocalVector(dm, &Xl));
  /* the Dirichlet dofs are not in the global vector: set them (xi = 0, and so xi_t = 0, on Gamma_D) */
  PetscCall(DMPlexInsertBoundaryValues(ctx->dm, PETSC_TRUE, ul, ctx->time, NULL, NULL, NULL));
  PetscCall(DMGlobalToLocal(ctx->dm, u, INSERT_VALUES, ul));
  PetscCall(VecZeroEntries(Xl));
  PetscCall(DMProjectFieldLocal(dm, ctx->time, ul, funcs, mode, Xl));
  PetscCall(VecZeroEntries(X));
  PetscCall(DMLocalToGlobal(dm, Xl, mode, X));
  PetscCall(DMRestoreLocalVector(dm, &Xl));
  PetscCall(DMRestoreLocalVector(ctx->dm, &ul));
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------
   Set-up */

/* A P1 space on the mesh of ctx->dm with nc components, its field named name (PETSc names the vertex
   datasets <vec>_<field>). */
static PetscErrorCode OutputSpace(Roller ctx, PetscInt nc, const char name[], DM *dm)
{
  PetscFE fe;

  PetscFunctionBeginUser;
  PetscCall(DMClone(ctx->dm, dm));
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 2, nc, PETSC_TRUE, 1, PETSC_DETERMINE, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, name));
  PetscCall(DMSetField(*dm, 0, NULL, (PetscObject)fe));
  PetscCall(PetscFEDestroy(&fe));
  PetscCall(DMCreateDS(*dm));
  PetscFunctionReturn(0);
}

static PetscErrorCode FieldCreate(DM dm, const char name[], OutputField *field)
{
  PetscSection section;
  const char  *fname;

  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(dm, &field->vec));
  PetscCall(PetscObjectSetName((PetscObject)field->vec, name));
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(PetscSectionGetFieldName(section, 0, &fname));
  PetscCall(PetscSNPrintf(field->data.path, sizeof(field->data.path), "/vertex_fields/%s_%s", name, fname));
  PetscFunctionReturn(0);
}

/* The run's parameters as attributes of /parameters, so that scripts (plot_fields.py) need not be told. */
static PetscErrorCode WriteParameters(Roller ctx, PetscViewer h5)
{
  const struct {
    const char *name;
    PetscReal   value;
  } p[] = {
    {"r_inner",        ctx->r_inner       },
    {"r_outer",        ctx->r_outer       },
    {"young",          ctx->young         },
    {"poisson",        ctx->poisson       },
    {"density",        ctx->density       },
    {"omega",          ctx->omega         },
    {"theta_a",        ctx->theta_a       },
    {"theta_b",        ctx->theta_b       },
    {"obstacle_speed", ctx->obstacle_speed},
    {"obstacle_depth", ctx->obstacle_depth},
    {"damping",        ctx->damping       },
    {"dt",             ctx->dt            },
  };
  const PetscInt obstacle = ctx->obstacle ? 1 : 0;

  PetscFunctionBeginUser;
  for (size_t i = 0; i < sizeof(p) / sizeof(p[0]); ++i) PetscCall(PetscViewerHDF5WriteAttribute(h5, "/parameters", p[i].name, PETSC_REAL, &p[i].value));
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/parameters", "obstacle", PETSC_INT, &obstacle));
  PetscCall(PetscViewerHDF5WriteAttribute(h5, "/parameters", "degree", PETSC_INT, &ctx->degree));
  PetscFunctionReturn(0);
}

static PetscErrorCode FieldsCreate(Roller ctx, RollerOutput out)
{
  PetscErrorCode (*position[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {Position};
  PetscBool has;

  PetscFunctionBeginUser;
  PetscCall(XdmfPaths(out));
  PetscCall(JoinPath(out->h5_part, sizeof(out->h5_part), out->h5_path, ".part", "-output"));
  PetscCall(RemoveStale(ctx->comm, out->h5_path));
  PetscCall(RemoveStale(ctx->comm, out->xmf_path));
  PetscCall(RemoveStale(ctx->comm, out->xmf_part)); /* would index the new file before it has a step */
  PetscCall(CheckWritable(ctx->comm, "-output", out->h5_part));
  PetscCall(PetscViewerHDF5Open(ctx->comm, out->h5_part, FILE_MODE_WRITE, &out->h5));
  PetscCall(DMView(ctx->dm_view, out->h5)); /* straight-sided: XDMF draws linear triangles */
  PetscCall(WriteParameters(ctx, out->h5));
  PetscCall(PetscViewerHDF5HasDataset(out->h5, "/viz/geometry/vertices", &has));
  PetscCall(DatasetQuery(out->h5, has ? "/viz/geometry/vertices" : "/geometry/vertices", &out->vertices));
  PetscCall(DatasetQuery(out->h5, "/viz/topology/cells", &out->cells));
  PetscCheck(out->vertices.ndims == 2 && out->cells.ndims == 2, ctx->comm, PETSC_ERR_LIB, "Unexpected mesh layout in %s", out->h5_part);

  PetscCall(OutputSpace(ctx, 3, "displacement", &out->vdm));
  PetscCall(OutputSpace(ctx, 1, "stress_norm", &out->sdm));
  PetscCall(FieldCreate(out->vdm, "displacement", &out->field[FIELD_DISPLACEMENT]));
  PetscCall(FieldCreate(out->vdm, "displacement_lab", &out->field[FIELD_LAB]));
  PetscCall(FieldCreate(out->vdm, "velocity", &out->field[FIELD_VELOCITY]));
  PetscCall(FieldCreate(out->sdm, "stress_norm", &out->field[FIELD_STRESS]));
  out->nfields = FIELD_STRESS + 1;
  if (ctx->contact) {
    PetscCall(OutputSpace(ctx, 1, "contact_pressure", &out->pdm));
    PetscCall(FieldCreate(out->pdm, "contact_pressure", &out->field[FIELD_CONTACT_PRESSURE]));
    out->nfields = FIELD_CONTACT_PRESSURE + 1;
  }
  PetscCall(DMCreateGlobalVector(ctx->dm, &out->velocity));
  PetscCall(DMCreateGlobalVector(out->sdm, &out->count));
  PetscCall(DMCreateGlobalVector(out->vdm, &out->position));
  PetscCall(DMProjectFunction(out->vdm, 0.0, position, NULL, INSERT_VALUES, out->position));
  PetscCall(ProjectAtVertices(ctx, ctx->xi1, f_one, ADD_VALUES, out->count));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerOutputCreate(Roller ctx, RollerOutput *output)
{
  RollerOutput out;
  PetscBool    has_csv = PETSC_FALSE, has_h5 = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&out));
  out->every  = 10;
  out->xmf_fd = -1;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: output", NULL);
  PetscCall(PetscOptionsString("-monitor_csv", "One CSV row per step: step,t,R,alpha,energy,contact_nodes,contact_force,gap_min,qp_iterations,kkt_residual,theta", NULL, out->csv_path, out->csv_path, sizeof(out->csv_path), &has_csv));
  PetscCall(PetscOptionsString("-output", "Fields to this HDF5 file, with an XDMF index beside it (F.h5 -> F.xmf)", NULL, out->h5_path, out->h5_path, sizeof(out->h5_path), &has_h5));
  PetscCall(PetscOptionsInt("-output_every", "Write fields every N steps", NULL, out->every, &out->every, NULL));
  PetscOptionsEnd();
  PetscCheck(out->every > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-output_every %" PetscInt_FMT " must be > 0", out->every);
  PetscCheck(!has_csv || out->csv_path[0], ctx->comm, PETSC_ERR_ARG_WRONG, "-monitor_csv needs a file name");
  PetscCheck(!has_h5 || out->h5_path[0], ctx->comm, PETSC_ERR_ARG_WRONG, "-output needs a file name");
  if (out->csv_path[0]) {
    PetscCall(JoinPath(out->csv_part, sizeof(out->csv_part), out->csv_path, ".part", "-monitor_csv"));
    PetscCall(JoinPath(out->csv_old, sizeof(out->csv_old), out->csv_path, ".old", "-monitor_csv"));
    if (ctx->restart[0]) PetscCall(CsvKeepOld(ctx->comm, out));
    PetscCall(RemoveStale(ctx->comm, out->csv_path));
    PetscCall(PetscFOpen(ctx->comm, out->csv_part, "w", &out->csv));
    PetscCall(PetscFPrintf(ctx->comm, out->csv, "step,t,R,alpha,energy,contact_nodes,contact_force,gap_min,qp_iterations,kkt_residual,theta\n"));
    if (ctx->restart[0]) PetscCall(CsvResume(ctx, out));
  }
  if (out->h5_path[0]) PetscCall(FieldsCreate(ctx, out));
  *output = out;
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------
   Every step */

/* Lab-frame displacement phi(x) - x = R(theta)(x + xi) - x (docs/model.md section 1) at every vertex. */
static PetscErrorCode LabDisplacement(RollerOutput out, PetscReal theta, Vec xi, Vec lab)
{
  const PetscScalar *x, *u;
  PetscScalar       *l;
  PetscInt           n;
  const PetscReal    c = PetscCosReal(theta), s = PetscSinReal(theta);

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(xi, &n));
  PetscCall(VecGetArrayRead(out->position, &x));
  PetscCall(VecGetArrayRead(xi, &u));
  PetscCall(VecGetArrayWrite(lab, &l));
  for (PetscInt i = 0; i < n; i += 3) {
    const PetscScalar p0 = x[i] + u[i], p1 = x[i + 1] + u[i + 1];

    l[i]     = c * p0 - s * p1 - x[i];
    l[i + 1] = s * p0 + c * p1 - x[i + 1];
    l[i + 2] = 0.0;
  }
  PetscCall(VecRestoreArrayRead(out->position, &x));
  PetscCall(VecRestoreArrayRead(xi, &u));
  PetscCall(VecRestoreArrayWrite(lab, &l));
  PetscFunctionReturn(0);
}

static PetscErrorCode WriteFields(Roller ctx, RollerOutput out)
{
  PetscReal theta;

  PetscFunctionBeginUser;
  RollerTheta(ctx, ctx->time, &theta, NULL, NULL);
  PetscCall(ProjectAtVertices(ctx, ctx->xi1, f_pad_vector, INSERT_VALUES, out->field[FIELD_DISPLACEMENT].vec));
  PetscCall(LabDisplacement(out, theta, out->field[FIELD_DISPLACEMENT].vec, out->field[FIELD_LAB].vec));
  PetscCall(VecWAXPY(out->velocity, -1.0, ctx->xi2, ctx->xi1));
  PetscCall(VecScale(out->velocity, 1.0 / ctx->dt));
  PetscCall(ProjectAtVertices(ctx, out->velocity, f_pad_vector, INSERT_VALUES, out->field[FIELD_VELOCITY].vec));
  /* |sigma| (docs/model.md section 4); DMProjectField hands the kernel the constants of the input DS, ctx->dm's */
  PetscCall(ProjectAtVertices(ctx, ctx->xi1, f_stress_norm, ADD_VALUES, out->field[FIELD_STRESS].vec));
  PetscCall(VecPointwiseDivide(out->field[FIELD_STRESS].vec, out->field[FIELD_STRESS].vec, out->count));
  /* multiplier / tributary length at the Gamma_C vertices (docs/contact.md) */
  if (out->nfields > FIELD_CONTACT_PRESSURE) PetscCall(RollerContactPressure(ctx, ctx->contact, out->field[FIELD_CONTACT_PRESSURE].vec));

  PetscCall(DMSetOutputSequenceNumber(out->vdm, out->written, ctx->time));
  PetscCall(DMSetOutputSequenceNumber(out->sdm, out->written, ctx->time));
  if (out->pdm) PetscCall(DMSetOutputSequenceNumber(out->pdm, out->written, ctx->time));
  for (PetscInt f = 0; f < out->nfields; ++f) PetscCall(VecView(out->field[f].vec, out->h5));
  if (out->written == out->times_size) {
    out->times_size = PetscMax(64, 2 * out->times_size);
    PetscCall(PetscRealloc(sizeof(PetscReal) * out->times_size, &out->times));
  }
  out->times[out->written++] = ctx->time;
  PetscCall(LayoutUpdate(out));
  PetscCall(XdmfAppend(ctx->comm, out));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerOutputStep(Roller ctx, RollerOutput out)
{
  const RollerStepInfo *info = &ctx->info;
  PetscReal             theta;

  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_OUTPUT]));
  if (out->csv_path[0]) {
    RollerTheta(ctx, ctx->time, &theta, NULL, NULL);
    PetscCall(PetscFPrintf(ctx->comm, out->csv, "%" PetscInt_FMT ",%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%.17g,%.17g,%" PetscInt_FMT ",%.17g,%.17g\n", ctx->step, (double)ctx->time, (double)info->R, (double)info->alpha, (double)info->energy, info->contact_nodes,
                           (double)info->contact_force, (double)info->gap_min, info->qp_iterations, (double)info->kkt_residual, (double)theta));
    /* a killed run keeps every row it printed */
    if (out->csv) PetscCheck(fflush(out->csv) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", out->csv_part, strerror(errno));
  }
  if (out->h5) PetscCall(RollerSeriesAppend(ctx, &out->series));
  if (out->h5 && ctx->step % out->every == 0) PetscCall(WriteFields(ctx, out));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

/* The successful end: close the files, rename them to their final names, index the final HDF5 file. */
PetscErrorCode RollerOutputDestroy(Roller ctx, RollerOutput *output)
{
  RollerOutput out = *output;

  PetscFunctionBeginUser;
  if (!out) PetscFunctionReturn(0);
  if (out->csv_path[0]) {
    PetscCall(PetscFClose(ctx->comm, out->csv));
    PetscCall(RenameFile(ctx->comm, out->csv_part, out->csv_path));
  }
  if (out->h5) {
    PetscCall(RollerSeriesWrite(ctx, out->series, out->h5));
    PetscCall(PetscViewerDestroy(&out->h5));
    PetscCall(XdmfClose(out));
    PetscCall(RenameFile(ctx->comm, out->h5_part, out->h5_path));
    PetscCall(XdmfWrite(ctx->comm, out, out->h5_path, out->xmf_path));
    PetscCall(RemoveStale(ctx->comm, out->xmf_part));
    PetscCallMPI(MPI_Barrier(ctx->comm));
  }
  for (PetscInt f = 0; f < out->nfields; ++f) PetscCall(VecDestroy(&out->field[f].vec));
  PetscCall(VecDestroy(&out->velocity));
  PetscCall(VecDestroy(&out->count));
  PetscCall(VecDestroy(&out->position));
  PetscCall(DMDestroy(&out->vdm));
  PetscCall(DMDestroy(&out->sdm));
  PetscCall(DMDestroy(&out->pdm));
  PetscCall(PetscFree(out->times));
  PetscCall(RollerSeriesDestroy(&out->series));
  PetscCall(PetscFree(out));
  *output = NULL;
  PetscFunctionReturn(0);
}
