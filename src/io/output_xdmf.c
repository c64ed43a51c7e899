/* The HDF5 layout read back from the file, so the index states exactly what is there, and the XDMF index:
   a temporal collection of triangle grids, one Attribute per vertex field and step, each a HyperSlab of the
   [steps, vertices(, 3)] dataset. The running index of a .part file grows in place (RollerXdmfAppend); the
   final one is written whole once (RollerXdmfWrite). Rank 0 writes. */
#include "output.h"
#include <fcntl.h>
#include <unistd.h>

/* The index lives beside the HDF5 file: F.h5 -> F.xmf (the extension replaced), part name F.part.xmf. */
PetscErrorCode RollerXdmfPaths(RollerOutput out)
{
  char        base[PETSC_MAX_PATH_LEN];
  const char *slash, *dot;

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(base, out->h5_path, sizeof(base)));
  slash = strrchr(base, '/');
  dot   = strrchr(base, '.');
  if (dot && dot > (slash ? slash + 1 : base)) base[dot - base] = '\0';
  PetscCall(RollerJoinPath(out->xdmf.path, sizeof(out->xdmf.path), base, ".xmf", "-output"));
  PetscCall(RollerJoinPath(out->xdmf.part, sizeof(out->xdmf.part), base, ".part.xmf", "-output"));
  PetscCheck(strcmp(out->xdmf.path, out->h5_path), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "-output %s: the fields and their XDMF index would have the same name; use F.h5", out->h5_path);
  PetscFunctionReturn(0);
}

PetscErrorCode RollerDatasetQuery(PetscViewer h5, const char path[], Dataset *d)
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
PetscErrorCode RollerLayoutUpdate(RollerOutput out)
{
  hid_t file;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5GetFileId(out->h5, &file));
  PetscCheck(H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot flush %s", out->h5_part);
  for (PetscInt f = 0; f < out->nfields; ++f) {
    Dataset *d = &out->field[f].data;

    PetscCall(RollerDatasetQuery(out->h5, d->path, d));
    PetscCheck(d->ndims >= 2 && d->dims[0] == (hsize_t)out->xdmf.written && d->dims[1] == out->xdmf.vertices.dims[0], PETSC_COMM_SELF, PETSC_ERR_LIB, "Dataset %s does not have %" PetscInt_FMT " steps of %d vertices", d->path, out->xdmf.written,
               (int)out->xdmf.vertices.dims[0]);
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
  PetscCall(XmlDataItem(fp, h5_name, &out->xdmf.cells, " Name=\"cells\""));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "    "));
  PetscCall(XmlDataItem(fp, h5_name, &out->xdmf.vertices, " Name=\"vertices\""));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "    <Grid Name=\"roller\" GridType=\"Collection\" CollectionType=\"Temporal\">\n"));
  PetscFunctionReturn(0);
}

/* The Grid of written step k; the datasets' shapes are those of out->field[] now (LayoutUpdate). */
static PetscErrorCode XdmfGrid(FILE *fp, RollerOutput out, const char h5_name[], PetscInt k)
{
  const char *corners;

  PetscFunctionBeginUser;
  switch (out->xdmf.cells.dims[1]) {
  case 3:
    corners = "Triangle";
    break;
  case 4:
    corners = "Quadrilateral";
    break;
  default:
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_SUP, "Cells with %d corners in %s", (int)out->xdmf.cells.dims[1], out->xdmf.cells.path);
  }
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "      <Grid Name=\"step %" PetscInt_FMT "\" GridType=\"Uniform\">\n        <Time Value=\"%.17g\"/>\n", k, (double)out->xdmf.times[k]));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "        <Topology TopologyType=\"%s\" NumberOfElements=\"%llu\"><DataItem Reference=\"XML\">/Xdmf/Domain/DataItem[@Name=\"cells\"]</DataItem></Topology>\n", corners, (unsigned long long)out->xdmf.cells.dims[0]));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "        <Geometry GeometryType=\"%s\"><DataItem Reference=\"XML\">/Xdmf/Domain/DataItem[@Name=\"vertices\"]</DataItem></Geometry>\n", out->xdmf.vertices.dims[1] == 3 ? "XYZ" : "XY"));
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
PetscErrorCode RollerXdmfWrite(MPI_Comm comm, RollerOutput out, const char h5_file[], const char xmf[])
{
  char        tmp[PETSC_MAX_PATH_LEN];
  const char *h5_name;
  PetscMPIInt rank;
  FILE       *fp;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank) PetscFunctionReturn(0);
  PetscCall(XdmfH5Name(h5_file, &h5_name));
  PetscCall(RollerJoinPath(tmp, sizeof(tmp), xmf, ".tmp", "-output"));
  PetscCall(PetscFOpen(PETSC_COMM_SELF, tmp, "w", &fp));
  PetscCall(XdmfHead(fp, out, h5_name));
  for (PetscInt k = 0; k < out->xdmf.written; ++k) PetscCall(XdmfGrid(fp, out, h5_name, k));
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
   overwrites the fixed tail (the closing tags, at out->xdmf.tail) with its Grid followed by the tail, in
   one write, so the file is a complete index after every step. Each Grid states the datasets' shapes as
   they were when it was written (the steps dimension grows; readers take its HyperSlab, inside them). */
PetscErrorCode RollerXdmfAppend(MPI_Comm comm, RollerOutput out)
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
  PetscCheck(ms, PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot build the XDMF index %s in memory: %s", out->xdmf.part, strerror(errno));
  if (out->xdmf.fd < 0) {
    PetscCall(XdmfHead(ms, out, h5_name));
    for (PetscInt k = 0; k < out->xdmf.written; ++k) PetscCall(XdmfGrid(ms, out, h5_name, k));
  } else PetscCall(XdmfGrid(ms, out, h5_name, out->xdmf.written - 1));
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, ms, "%s", xdmf_tail));
  PetscCheck(fclose(ms) == 0 && buf, PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot build the XDMF index %s in memory", out->xdmf.part);
  if (out->xdmf.fd < 0) {
    char tmp[PETSC_MAX_PATH_LEN];

    PetscCall(RollerJoinPath(tmp, sizeof(tmp), out->xdmf.part, ".tmp", "-output"));
    out->xdmf.fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC, 0666);
    PetscCheck(out->xdmf.fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot create the XDMF index %s: %s", tmp, strerror(errno));
    PetscCall(WriteAt(out->xdmf.fd, tmp, buf, len, 0));
    PetscCheck(rename(tmp, out->xdmf.part) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename %s to %s: %s", tmp, out->xdmf.part, strerror(errno));
    out->xdmf.tail = 0;
  } else PetscCall(WriteAt(out->xdmf.fd, out->xdmf.part, buf, len, out->xdmf.tail));
  out->xdmf.tail += (off_t)(len - strlen(xdmf_tail));
  free(buf); /* open_memstream's, from malloc */
  PetscFunctionReturn(0);
}

/* Rank 0 closes the running index (it stays on disk). */
PetscErrorCode RollerXdmfClose(RollerOutput out)
{
  PetscFunctionBeginUser;
  if (out->xdmf.fd >= 0) PetscCheck(close(out->xdmf.fd) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot close the XDMF index %s: %s", out->xdmf.part, strerror(errno));
  out->xdmf.fd = -1;
  PetscFunctionReturn(0);
}
