/* The observers of the run, TSMonitorSet-style: each component that reports on the run (the CSV, the HDF5
   fields, the -ts_monitor and progress lines, the periodic checkpoint, the MMS errors) sets its monitor
   during set-up, and RollerSolve calls them all, in the order they were set, at the initial state, after
   every step and at the successful end. A new output is a new monitor: the driver does not change. */
#include "integrate/integrate.h"

#define ROLLER_MAX_MONITORS 16

const char *const RollerMonitorEvents[] = {"initial", "step", "final", "RollerMonitorEvent", "ROLLER_MONITOR_", NULL};

struct _n_RollerMonitors {
  PetscInt n;
  PetscErrorCode (*monitor[ROLLER_MAX_MONITORS])(Roller, RollerMonitorEvent, void *);
  void *mctx[ROLLER_MAX_MONITORS];
  PetscErrorCode (*destroy[ROLLER_MAX_MONITORS])(void **);
};

/*
  RollerMonitorSet - Adds a monitor that RollerSolve calls at the initial state (ROLLER_MONITOR_INITIAL), after
  every step (ROLLER_MONITOR_STEP) and at the successful end (ROLLER_MONITOR_FINAL).

  Input Parameters:
+ ctx     - the Roller
. monitor - the monitor: monitor(ctx, event, mctx); the state is ctx->state, the step's diagnostics ctx->info
. mctx    - its context (or NULL)
- destroy - frees mctx when the Roller is destroyed (or NULL)

  Monitors are called in the order they were set; a run that fails never reaches ROLLER_MONITOR_FINAL.
*/
PetscErrorCode RollerMonitorSet(Roller ctx, PetscErrorCode (*monitor)(Roller, RollerMonitorEvent, void *), void *mctx, PetscErrorCode (*destroy)(void **))
{
  RollerMonitors m;

  PetscFunctionBeginUser;
  if (!ctx->monitors) PetscCall(PetscNew(&ctx->monitors));
  m = ctx->monitors;
  PetscCheck(m->n < ROLLER_MAX_MONITORS, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "Too many monitors set, at most %d", ROLLER_MAX_MONITORS);
  m->monitor[m->n] = monitor;
  m->mctx[m->n]    = mctx;
  m->destroy[m->n] = destroy;
  m->n++;
  PetscFunctionReturn(0);
}

/* RollerMonitorCancel - Removes every monitor, destroying their contexts. */
PetscErrorCode RollerMonitorCancel(Roller ctx)
{
  RollerMonitors m = ctx->monitors;

  PetscFunctionBeginUser;
  if (!m) PetscFunctionReturn(0);
  for (PetscInt i = 0; i < m->n; ++i)
    if (m->destroy[i]) PetscCall((*m->destroy[i])(&m->mctx[i]));
  PetscCall(PetscFree(ctx->monitors));
  PetscFunctionReturn(0);
}

/* Every monitor, in order, for one event. */
PetscErrorCode RollerMonitorRun(Roller ctx, RollerMonitorEvent event)
{
  RollerMonitors m = ctx->monitors;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; m && i < m->n; ++i) PetscCall((*m->monitor[i])(ctx, event, m->mctx[i]));
  PetscFunctionReturn(0);
}
