/* -monitor_surface_csv F (docs/output.md): the lab-frame circumferential orders of the radial displacement of Gamma_C,
   one row per state, for the sound a listener hears (scripts/rollerreport/heard.py: each order of the surface's
   normal velocity radiates as from a cylinder). Columns step,t,theta,ur0,ur1c,ur1s,...,urNc,urNs:
   xi_r(Phi) = ur0 + sum_n urnc cos(n Phi) + urns sin(n Phi) at the lab angle Phi = phi + theta(t) of the material
   angle phi (the lab frame of the HDF5 output's displacement_lab = R(theta)(x + xi) - x). ur0 is the monitor's R.
   The co-rotating orders (c_n, s_n) = w_n . xi (RollerComputeOrderFunctionals) turn into the lab's by the angle
   n theta. Rank 0 writes F.part, renamed at the successful end; a restart starts the file at its step. */
#include "integrate/integrate.h"

typedef struct {
  PetscInt   orders;
  Vec       *w;    /* 2 orders functionals: cos, sin of orders 1..N (-rom: their reduced V^T w) */
  PetscReal *rows; /* -rom with the residual flexibility: their Gamma_C rows (2 orders x 2 nc), for the levels' residual */
  FILE      *fp;
  char       path[PETSC_MAX_PATH_LEN], part[PETSC_MAX_PATH_LEN];
  PetscBool  open;
} SurfaceMonitor;

static PetscErrorCode MonitorSurface(Roller ctx, RollerMonitorEvent event, void *mctx)
{
  SurfaceMonitor *m = (SurfaceMonitor *)mctx;
  PetscScalar    *dots;
  PetscScalar     r;
  PetscReal       theta;

  PetscFunctionBeginUser;
  if (event == ROLLER_MONITOR_INITIAL && ctx->ck.restart[0]) PetscFunctionReturn(0);
  if (event == ROLLER_MONITOR_FINAL) {
    PetscCall(RollerPartFileClose(ctx->comm, &m->fp, m->part, m->path));
    m->open = PETSC_FALSE;
    PetscFunctionReturn(0);
  }
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_OUTPUT]));
  PetscCall(PetscMalloc1(2 * m->orders, &dots));
  PetscCall(VecMDot(ctx->state.cur, 2 * m->orders, m->w, dots));
  PetscCall(VecDot(ctx->ops.w_R, ctx->state.cur, &r));
  if (m->rows) { /* -rom: + the functionals on the residual at Gamma_C */
    PetscReal      wr = PetscRealPart(r), wa = 0.0;
    const PetscInt nr = RollerContactNodeCount(ctx->contact) * 2;

    PetscCall(RollerContactResidualDots(ctx->contact, ctx->state.cur, &wr, &wa));
    r = wr;
    for (PetscInt k = 0; k < 2 * m->orders; ++k) {
      PetscReal d = PetscRealPart(dots[k]);

      PetscCall(RollerContactResidualDot(ctx->contact, ctx->state.cur, m->rows + (size_t)k * nr, &d));
      dots[k] = d;
    }
  }
  RollerTheta(ctx, ctx->state.time, &theta, NULL, NULL);
  if (m->fp) {
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, m->fp, "%" PetscInt_FMT ",%.17g,%.17g,%.17g", ctx->state.step, (double)ctx->state.time, (double)theta, (double)(PetscRealPart(r) / ctx->mesh.boundary_length)));
    for (PetscInt n = 1; n <= m->orders; ++n) {
      const PetscReal a = PetscRealPart(dots[2 * (n - 1)]), b = PetscRealPart(dots[2 * (n - 1) + 1]), c = PetscCosReal(n * theta), s = PetscSinReal(n * theta);

      PetscCall(PetscFPrintf(PETSC_COMM_SELF, m->fp, ",%.17g,%.17g", (double)(a * c - b * s), (double)(a * s + b * c)));
    }
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, m->fp, "\n"));
  }
  PetscCall(PetscFree(dots));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

static PetscErrorCode MonitorSurfaceDestroy(void **mctx)
{
  SurfaceMonitor *m = (SurfaceMonitor *)*mctx;

  PetscFunctionBeginUser;
  if (m->fp) PetscCall(PetscFClose(PETSC_COMM_SELF, m->fp)); /* a run that did not end: F.part stays */
  if (m->w) PetscCall(VecDestroyVecs(2 * m->orders, &m->w));
  PetscCall(PetscFree(m->rows));
  PetscCall(PetscFree(m));
  *mctx = NULL;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSurfaceMonitorSetUp(Roller ctx)
{
  char            path[PETSC_MAX_PATH_LEN] = "";
  PetscInt        orders                   = ROLLER_SURFACE_ORDERS;
  PetscBool       has                      = PETSC_FALSE;
  SurfaceMonitor *m;

  PetscFunctionBeginUser;
  /* the options are listed and checked with the outputs' (io/output.c, RollerOutputSetFromOptions) */
  PetscCall(PetscOptionsGetString(NULL, NULL, "-monitor_surface_csv", path, sizeof(path), &has));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-monitor_surface_orders", &orders, NULL));
  if (!has) PetscFunctionReturn(0);
  PetscCall(PetscNew(&m));
  m->orders = orders;
  PetscCall(PetscMalloc1(2 * orders, &m->w));
  PetscCall(RollerComputeOrderFunctionals(ctx, orders, m->w));
  if (ctx->ops.V) { /* -rom: the functionals' reduced images V^T w (and their Gamma_C rows for the residual) */
    const PetscInt nr = 2 * RollerContactNodeCount(ctx->contact);
    Vec           *wr;
    PetscInt       nl, ns;

    PetscCall(VecDuplicateVecs(ctx->state.cur, 2 * orders, &wr));
    for (PetscInt k = 0; k < 2 * orders; ++k) {
      Vec p;

      PetscCall(MatCreateVecs(ctx->ops.V, &p, NULL));
      PetscCall(MatMultTranspose(ctx->ops.V, m->w[k], p));
      PetscCall(VecGetLocalSize(p, &nl));
      PetscCall(VecGetLocalSize(wr[k], &ns));
      PetscCheck(nl == ns, PETSC_COMM_SELF, PETSC_ERR_PLIB, "-monitor_surface_csv with -rom: the basis' column layout (%" PetscInt_FMT ") is not the reduced state's (%" PetscInt_FMT ")", nl, ns);
      PetscCall(VecCopy(p, wr[k]));
      PetscCall(VecDestroy(&p));
      if (nr) {
        PetscReal *rows;

        if (!m->rows) PetscCall(PetscCalloc1((size_t)2 * orders * nr, &m->rows));
        PetscCall(RollerContactResidualRows(ctx->contact, m->w[k], &rows));
        if (rows) PetscCall(PetscArraycpy(m->rows + (size_t)k * nr, rows, nr));
        PetscCall(PetscFree(rows));
      }
    }
    PetscCall(VecDestroyVecs(2 * orders, &m->w));
    m->w = wr;
  }
  PetscCall(PetscStrncpy(m->path, path, sizeof(m->path)));
  PetscCall(RollerPartFileOpen(ctx->comm, path, "-monitor_surface_csv", m->part, sizeof(m->part), &m->fp));
  if (m->fp) {
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, m->fp, "step,t,theta,ur0"));
    for (PetscInt n = 1; n <= orders; ++n) PetscCall(PetscFPrintf(PETSC_COMM_SELF, m->fp, ",ur%" PetscInt_FMT "c,ur%" PetscInt_FMT "s", n, n));
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, m->fp, "\n"));
  }
  m->open = PETSC_TRUE;
  PetscCall(RollerMonitorSet(ctx, MonitorSurface, m, MonitorSurfaceDestroy));
  PetscFunctionReturn(0);
}
