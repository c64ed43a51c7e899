static const char help[] = "Unit test of the output layer (src/io):\n"
                           "  CSV: rows of known values written by RollerCsvRow read back with strtod equal exactly (%.17g round-trips),\n"
                           "       the header is the contract of docs/model.md section 6.1 (-model_md), a resumed CSV keeps the rows to its step;\n"
                           "  HDF5/XDMF: a tiny run (-output, 3 steps) through include/roller.h: every dataset the .xmf index names exists\n"
                           "       in the HDF5 file with the dimensions, number type and precision the index states, and its times are\n"
                           "       the /time dataset's, the /diagnostics/t rows and k dt.\n";

#include <roller.h>
#include "io/io.h"
#include "unit.h"
#include <hdf5.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NCOLUMNS 32

/* One CSV row as written: the step, t, the diagnostics and theta. */
typedef struct {
  PetscInt       step;
  PetscReal      t;
  RollerStepInfo info;
  PetscReal      theta;
} Row;

/* The contract header: the backquoted line that starts with `step, after "### 6.1" in docs/model.md. */
static PetscErrorCode ContractHeader(const char path[], char header[], size_t len)
{
  FILE     *fp = fopen(path, "r");
  char      line[1024];
  PetscBool in_section = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open %s (give docs/model.md with -model_md)", path);
  header[0] = 0;
  while (fgets(line, sizeof(line), fp) && !header[0]) {
    if (!strncmp(line, "### 6.1", 7)) in_section = PETSC_TRUE;
    else if (in_section && !strncmp(line, "`step,", 6)) {
      char *end = strchr(line + 1, '`');

      PetscCheck(end, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: the column line of section 6.1 has no closing backquote: %s", path, line);
      *end = 0;
      PetscCall(PetscStrncpy(header, line + 1, len));
    }
  }
  fclose(fp);
  PetscCheck(header[0], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: no `step,...` column line in section 6.1", path);
  PetscFunctionReturn(0);
}

static PetscErrorCode WriteRows(RollerCsv csv, const Row rows[], PetscInt n)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < n; ++i) PetscCall(RollerCsvRow(csv, rows[i].step, rows[i].t, &rows[i].info, rows[i].theta));
  PetscFunctionReturn(0);
}

/* A written value against the one read back: equal, or both NaN. */
static PetscErrorCode CheckValue(const char path[], PetscInt row, const char *column, double wrote, double read)
{
  PetscFunctionBeginUser;
  PetscCheck(wrote == read || (isnan(wrote) && isnan(read)), PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s row %" PetscInt_FMT " column %s: wrote %.17g, read back %.17g", path, row, column, wrote, read);
  PetscFunctionReturn(0);
}

/* Reads path back: the header must be the contract's, then exactly n rows equal to rows[]. */
static PetscErrorCode CheckCsv(const char path[], const char header[], const Row rows[], PetscInt n)
{
  static const char *const columns[NCOLUMNS] = {"step", "t", "R", "alpha", "energy", "contact_nodes", "contact_force", "gap_min", "qp_iterations", "kkt_residual", "theta", "load_work", "obstacle_work", "contact_dissipation", "damping_dissipation", "viscous_dissipation", "contact_flips", "contact_reversals", "friction_force", "shaft_torque", "stick_nodes", "slip_nodes", "friction_work", "shaft_work", "sheet_work", "friction_residual", "coulomb_iterations", "coulomb_fallback", "axle_y", "hub_rate", "drive_torque", "sheet_speed"};
  char                     line[4096];
  PetscInt                 count = 0;
  FILE                    *fp    = fopen(path, "r");

  PetscFunctionBeginUser;
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "The CSV %s was not renamed into place", path);
  PetscCheck(fgets(line, sizeof(line), fp), PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "%s is empty", path);
  line[strcspn(line, "\r\n")] = 0;
  PetscCheck(!strcmp(line, header), PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s header \"%s\" is not the contract's \"%s\"", path, line, header);
  while (fgets(line, sizeof(line), fp)) {
    const Row *r = &rows[count];
    double     v[NCOLUMNS];
    char      *p = line, *end;

    PetscCheck(count < n, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s has more than the %" PetscInt_FMT " rows written", path, n);
    for (int c = 0; c < NCOLUMNS; ++c) {
      v[c] = strtod(p, &end);
      PetscCheck(end != p && (*end == (c < NCOLUMNS - 1 ? ',' : '\n')), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s row %" PetscInt_FMT ": column %s unreadable at \"%s\"", path, count, columns[c], p);
      p = end + 1;
    }
    {
      const double wrote[NCOLUMNS] = {(double)r->step,
                                      (double)r->t,
                                      (double)r->info.R,
                                      (double)r->info.alpha,
                                      (double)r->info.energy,
                                      (double)r->info.contact_nodes,
                                      (double)r->info.contact_force,
                                      (double)r->info.gap_min,
                                      (double)r->info.qp_iterations,
                                      (double)r->info.kkt_residual,
                                      (double)r->theta,
                                      (double)r->info.load_work,
                                      (double)r->info.obstacle_work,
                                      (double)r->info.contact_dissipation,
                                      (double)r->info.damping_dissipation,
                                      (double)r->info.viscous_dissipation,
                                      (double)r->info.contact_flips,
                                      (double)r->info.contact_reversals,
                                      (double)r->info.friction.force,
                                      (double)r->info.friction.torque,
                                      (double)r->info.friction.stick,
                                      (double)r->info.friction.slip,
                                      (double)r->info.friction.work,
                                      (double)r->info.friction.shaft_work,
                                      (double)r->info.friction.sheet_work,
                                      (double)r->info.friction.residual,
                                      (double)r->info.friction.iterations,
                                      (double)r->info.friction.fallback,
                                      (double)r->info.axle.y,
                                      (double)r->info.axle.hub_rate,
                                      (double)r->info.axle.drive_torque,
                                      (double)r->info.axle.sheet_speed};

      for (int c = 0; c < NCOLUMNS; ++c) PetscCall(CheckValue(path, count, columns[c], wrote[c], v[c]));
    }
    count++;
  }
  fclose(fp);
  PetscCheck(count == n, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s has %" PetscInt_FMT " rows, %" PetscInt_FMT " were written", path, count, n);
  PetscFunctionReturn(0);
}

static PetscErrorCode TestCsv(const char model_md[])
{
  const char path[] = "io_roundtrip.csv";
  char       header[1024];
  RollerCsv  csv;
  PetscBool  exists;
  /* hard cases for a text round trip: -0, non-dyadic fractions, extremes, a subnormal, NaN (no gap without an obstacle) */
  const Row rows[3] = {
    {0, 0.0, {0.0, -0.0, 0.0, 0, 0.0, (PetscReal)NAN, 0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0, {0.0, -0.0, 0, 0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0}, {0.0, 0.0, -0.0, 0.0}},                                                                                                              0.0              },
    {1, 0.1, {1.0 / 3.0, -2.0 / 7.0 * 1e-5, PETSC_PI * 1e10, 17, 1e-300, -1e-18, 123456, DBL_EPSILON, -1.0 / 7.0, 1e-19, 5e-324, 0.1, 2.0 / 3.0, 4, 1, {-1.0 / 3.0, 1e-310, 7, 11, 1.0 / 7.0, -2.0 / 3.0, 1e-200, 0.0, 0.0, 0.0, 3e-13, 15, 1}, {-1.0 / 3.0, PETSC_PI / 10.0, 1e-310, 0.15}}, 1.0 + DBL_EPSILON},
    {2, 0.2, {DBL_MAX, -DBL_MIN, 4.9406564584124654e-324, 2147483647, 6.02214076e23, 2.5e-3, 1, 0.7, -DBL_MAX, 3.0, -0.0, 1e300, DBL_MIN, 2147483647, 0, {DBL_MAX, -DBL_MIN, 2147483647, 0, 6.02214076e23, -1e300, 0.1, 0.0, 0.0, 0.0, 5e-324, 1, 2}, {DBL_MAX, -DBL_MIN, 5e-324, -1e300}},   -PETSC_PI        },
  };
  const Row resumed[3] = {
    rows[0], rows[1], {2, 0.2, {-1.0 / 9.0, 1e-7, 2.0 / 3.0, 3, 0.125, -0.5, 9, 1e-17, 1.0 / 3.0, -1.0 / 3.0, 0.25, 0.0, 7e-8, 2, 0, {0.5, -0.25, 1, 2, 3.0, 4.0, -5.0, 0.0, 0.0, 0.0, 1e-9, 3, 0}, {2.0 / 3.0, 0.1, -0.5, 7e-8}}, 0.30000000000000004}
  };

  PetscFunctionBeginUser;
  PetscCall(ContractHeader(model_md, header, sizeof(header)));
  PetscCall(RollerCsvOpen(PETSC_COMM_WORLD, path, -1, &csv));
  PetscCall(WriteRows(csv, rows, 3));
  PetscCall(PetscTestFile(path, 'r', &exists));
  PetscCheck(!exists, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s exists before the CSV is closed: only %s.part should", path, path);
  PetscCall(RollerCsvClose(csv));
  PetscCall(RollerCsvDestroy(&csv));
  PetscCall(CheckCsv(path, header, rows, 3));

  /* a restart from step 1 keeps rows 0 and 1 of the earlier file and continues after them */
  PetscCall(RollerCsvOpen(PETSC_COMM_WORLD, path, 1, &csv));
  PetscCall(WriteRows(csv, &resumed[2], 1));
  PetscCall(RollerCsvClose(csv));
  PetscCall(RollerCsvDestroy(&csv));
  PetscCall(CheckCsv(path, header, resumed, 3));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "io_roundtrip: CSV: %d rows round-trip exactly, header = docs/model.md 6.1, resumed after step 1\n", 3));
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------
   HDF5 and the XDMF index */

/* The value of attribute name="..." inside the tag [tag, tag_end), or NULL. */
static const char *TagAttribute(const char *tag, const char *tag_end, const char *name, char value[], size_t len)
{
  char        key[64];
  const char *p, *q;

  snprintf(key, sizeof(key), " %s=\"", name);
  p = strstr(tag, key);
  if (!p || p > tag_end) return NULL;
  p += strlen(key);
  q = strchr(p, '"');
  if (!q || (size_t)(q - p) >= len) return NULL;
  memcpy(value, p, q - p);
  value[q - p] = 0;
  return value;
}

/* One HDF dataset the index names: exists in file with the stated dimensions, number type and precision. */
static PetscErrorCode CheckDataItem(hid_t file, const char h5_name[], const char *tag, const char *tag_end, const char *text, const char *text_end)
{
  char    ref[PETSC_MAX_PATH_LEN], dims[256], type[32], precision[32], *colon, *p, *end;
  hsize_t actual[8];
  hid_t   set, space, dtype;
  int     ndims, nstated = 0;
  long    stated[8];

  PetscFunctionBeginUser;
  PetscCheck((size_t)(text_end - text) < sizeof(ref), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "A DataItem reference is too long");
  memcpy(ref, text, text_end - text);
  ref[text_end - text] = 0;
  colon                = strchr(ref, ':');
  PetscCheck(colon, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "DataItem \"%s\" is not FILE:/path", ref);
  *colon = 0;
  PetscCheck(!strcmp(ref, h5_name), PETSC_COMM_SELF, PETSC_ERR_PLIB, "The index refers to file %s, expected %s", ref, h5_name);
  PetscCheck(TagAttribute(tag, tag_end, "Dimensions", dims, sizeof(dims)) && TagAttribute(tag, tag_end, "NumberType", type, sizeof(type)) && TagAttribute(tag, tag_end, "Precision", precision, sizeof(precision)), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "The DataItem of %s lacks Dimensions, NumberType or Precision", colon + 1);
  for (p = dims; nstated < 8; p = end) {
    long v = strtol(p, &end, 10);

    if (end == p) break;
    stated[nstated++] = v;
  }
  set = H5Dopen2(file, colon + 1, H5P_DEFAULT);
  PetscCheck(set >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The index names %s:%s, which the HDF5 file does not have", h5_name, colon + 1);
  space = H5Dget_space(set);
  dtype = H5Dget_type(set);
  ndims = H5Sget_simple_extent_ndims(space);
  PetscCheck(ndims == nstated && ndims <= 8, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s has %d dimensions, the index states %d (\"%s\")", colon + 1, ndims, nstated, dims);
  H5Sget_simple_extent_dims(space, actual, NULL);
  for (int d = 0; d < ndims; ++d) PetscCheck((long)actual[d] == stated[d], PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s dimension %d is %ld, the index states %ld", colon + 1, d, (long)actual[d], stated[d]);
  PetscCheck((H5Tget_class(dtype) == H5T_INTEGER) == !strcmp(type, "Int") && (long)H5Tget_size(dtype) == atol(precision), PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s is %s of %ld bytes, the index states %s of %s", colon + 1, H5Tget_class(dtype) == H5T_INTEGER ? "Int" : "Float", (long)H5Tget_size(dtype), type, precision);
  H5Tclose(dtype);
  H5Sclose(space);
  H5Dclose(set);
  PetscFunctionReturn(0);
}

/* A 1-D (or n x 1) double dataset, n values into v (at most max). */
static PetscErrorCode ReadReals(hid_t file, const char path[], double v[], PetscInt max, PetscInt *n)
{
  hid_t   set     = H5Dopen2(file, path, H5P_DEFAULT), space;
  hsize_t dims[2] = {0, 1};

  PetscFunctionBeginUser;
  PetscCheck(set >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The HDF5 file has no %s", path);
  space = H5Dget_space(set);
  H5Sget_simple_extent_dims(space, dims, NULL);
  *n = (PetscInt)(dims[0] * dims[1]);
  PetscCheck(*n <= max, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s has %" PetscInt_FMT " values, expected at most %" PetscInt_FMT, path, *n, max);
  PetscCheck(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot read %s", path);
  H5Sclose(space);
  H5Dclose(set);
  PetscFunctionReturn(0);
}

static PetscErrorCode TestFields(void)
{
  const char        h5[] = "io_roundtrip.h5", xmf[] = "io_roundtrip.xmf";
  const char *const scene[][2] = {
    {"-output",       h5   },
    {"-output_every", "1"  },
    {"-ts_max_steps", "3"  },
    {"-mesh_h",       "0.1"},
    {"-quiet",        NULL }
  };
  const int nsteps = 3;
  Roller    roller;
  PetscBool exists;
  FILE     *fp;
  char     *text;
  long      len;
  hid_t     file, attr;
  double    dt, times[16], t_series[16], t_data[16];
  PetscInt  ntimes = 0, nseries, ndata, nitems = 0;

  PetscFunctionBeginUser;
  PetscCall(RollerUnitSetUp(scene, ROLLER_UNIT_COUNT(scene), &roller));
  PetscCall(RollerSolve(roller));
  PetscCall(RollerDestroy(&roller));
  PetscCall(PetscTestFile("io_roundtrip.h5.part", 'r', &exists));
  PetscCheck(!exists, PETSC_COMM_SELF, PETSC_ERR_PLIB, "io_roundtrip.h5.part is left after a successful run");
  PetscCall(PetscTestFile("io_roundtrip.part.xmf", 'r', &exists));
  PetscCheck(!exists, PETSC_COMM_SELF, PETSC_ERR_PLIB, "io_roundtrip.part.xmf is left after a successful run");

  fp = fopen(xmf, "r");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "The run left no index %s", xmf);
  fseek(fp, 0, SEEK_END);
  len = ftell(fp);
  rewind(fp);
  PetscCall(PetscMalloc1(len + 1, &text));
  PetscCheck(fread(text, 1, (size_t)len, fp) == (size_t)len, PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "Cannot read %s", xmf);
  text[len] = 0;
  fclose(fp);

  file = H5Fopen(h5, H5F_ACC_RDONLY, H5P_DEFAULT);
  PetscCheck(file >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open %s with HDF5", h5);
  /* every HDF DataItem of the index */
  for (const char *p = strstr(text, "Format=\"HDF\""); p; p = strstr(p + 1, "Format=\"HDF\"")) {
    const char *tag = p, *tag_end = strchr(p, '>'), *text_end;

    while (tag > text && strncmp(tag, "<DataItem", 9)) --tag;
    PetscCheck(tag_end && !strncmp(tag, "<DataItem", 9), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: Format=\"HDF\" outside a DataItem tag at offset %ld", xmf, (long)(p - text));
    text_end = strstr(tag_end, "</DataItem>");
    PetscCheck(text_end, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: unclosed DataItem at offset %ld", xmf, (long)(tag - text));
    PetscCall(CheckDataItem(file, h5, tag, tag_end, tag_end + 1, text_end));
    nitems++;
  }
  /* the times of the grids */
  for (const char *p = strstr(text, "<Time Value=\""); p; p = strstr(p + 1, "<Time Value=\"")) {
    PetscCheck(ntimes < 16, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s has more than 16 grids", xmf);
    times[ntimes++] = strtod(p + strlen("<Time Value=\""), NULL);
  }
  PetscCheck(ntimes == nsteps + 1, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s has %" PetscInt_FMT " time steps, expected %d (steps 0 to %d, -output_every 1)", xmf, ntimes, nsteps + 1, nsteps);
  PetscCheck(nitems >= 2 + 4 * ntimes, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s names %" PetscInt_FMT " HDF datasets, expected the mesh's 2 and 4 fields in each of %" PetscInt_FMT " grids", xmf, nitems, ntimes);
  attr = H5Aopen_by_name(file, "/parameters", "dt", H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(attr >= 0 && H5Aread(attr, H5T_NATIVE_DOUBLE, &dt) >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s has no /parameters dt attribute", h5);
  H5Aclose(attr);
  PetscCall(ReadReals(file, "/time", t_data, 16, &ndata));
  PetscCall(ReadReals(file, "/diagnostics/t", t_series, 16, &nseries));
  PetscCheck(ndata == ntimes && nseries == ntimes, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s has %" PetscInt_FMT " /time and %" PetscInt_FMT " /diagnostics/t values, the index %" PetscInt_FMT " times", h5, ndata, nseries, ntimes);
  for (PetscInt k = 0; k < ntimes; ++k)
    PetscCheck(times[k] == t_data[k] && times[k] == t_series[k] && times[k] == k * dt, PETSC_COMM_SELF, PETSC_ERR_PLIB, "time of grid %" PetscInt_FMT ": index %.17g, /time %.17g, /diagnostics/t %.17g, k dt %.17g", k, times[k], t_data[k], t_series[k], k * dt);
  H5Fclose(file);
  PetscCall(PetscFree(text));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "io_roundtrip: XDMF: %" PetscInt_FMT " HDF datasets named by %s exist with the stated shapes; %" PetscInt_FMT " times = /time = /diagnostics/t = k dt\n", nitems, xmf, ntimes));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  char model_md[PETSC_MAX_PATH_LEN] = "docs/model.md";

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-model_md", model_md, sizeof(model_md), NULL));
  PetscCall(TestCsv(model_md));
  PetscCall(TestFields());
  PetscCall(PetscFinalize());
  return 0;
}
