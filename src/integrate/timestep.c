/* Time stepping: its options (-ts_*, -quiet), the number of steps, and its observers on the console: the
   -ts_monitor line of every step and the progress line (at most every 5 s, and at the last step). */
#include "integrate/integrate.h"
#include "integrate/scheme_impl.h"
#include <petsctime.h>
#include <stdio.h>
#include <unistd.h>

/* The process's start on PetscTime's clock, for -ts_max_wall: now less the process's age (Linux: /proc/uptime less
   the start time of /proc/self/stat, in clock ticks since boot, 0.01 s); elsewhere now (MPI's start-up then not
   counted, about 0.4 s). */
static PetscErrorCode ProcessStart(PetscLogDouble *start)
{
  FILE              *f;
  char               stat[1024], *p;
  double             uptime = -1;
  unsigned long long ticks  = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(start));
  if ((f = fopen("/proc/uptime", "r"))) {
    if (fscanf(f, "%lf", &uptime) != 1) uptime = -1;
    fclose(f);
  }
  if (uptime < 0 || !(f = fopen("/proc/self/stat", "r"))) PetscFunctionReturn(0);
  p = fgets(stat, sizeof(stat), f) ? strrchr(stat, ')') : NULL; /* the fields after the command's name */
  fclose(f);
  if (p && sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %*u %*u %*d %*d %*d %*d %*d %*d %llu", &ticks) == 1 && sysconf(_SC_CLK_TCK) > 0) {
    const double age = uptime - (double)ticks / (double)sysconf(_SC_CLK_TCK);

    if (age >= 0) *start -= age;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerTimeStepSetFromOptions(Roller ctx)
{
  PetscBool monitor_set;

  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: time stepping", NULL);
  PetscCall(PetscOptionsReal("-ts_dt", "Time step dt (0: chosen from -ts_phase_error)", NULL, ctx->ts.dt, &ctx->ts.dt, &ctx->ts.dt_set));
  PetscCall(PetscOptionsReal("-ts_max_time", "End time", NULL, ctx->ts.max_time, &ctx->ts.max_time, NULL));
  PetscCall(PetscOptionsReal("-ts_phase_error", "Accuracy target that sets the default -ts_scheme, -ts_dt and -mesh_h: the relative error of R at the end time, its time half from the radial modes' phase errors weighted by their amplitudes (docs/model.md 6.2)", NULL,
                             ctx->ts.phase_error, &ctx->ts.phase_error, NULL));
  PetscCall(PetscOptionsBool("-ts_view", "Print the discretization (degree, h, scheme, dt) and the rule that chose it (also with -ts_monitor)", NULL, ctx->ts.view, &ctx->ts.view, NULL));
  PetscCall(PetscOptionsInt("-ts_max_steps", "Cap on the number of steps (-1: none)", NULL, ctx->ts.max_steps, &ctx->ts.max_steps, NULL));
  PetscCall(PetscOptionsReal("-ts_max_wall", "Wall time in seconds from the process's start: stop after the step when the next one would end past it (by the mean step time), with the checkpoint (-checkpoint, default checkpoint.h5) and a line that says how to resume (0: no limit)", NULL,
                             ctx->ts.max_wall, &ctx->ts.max_wall, NULL));
  PetscCall(PetscOptionsBool("-quiet", "Silence the progress line", NULL, ctx->ts.quiet, &ctx->ts.quiet, NULL));
  PetscCall(PetscOptionsBool("-ts_monitor", "Print R, alpha, energy (and contact) every step", NULL, ctx->ts.monitor, &ctx->ts.monitor, &monitor_set));
  PetscOptionsEnd();
  PetscCall(RollerSchemeSetFromOptions(ctx));
  if (ctx->ts.scheme[0]) { /* an unknown -ts_scheme refused here with the registered names */
    PetscVoidFunction f;

    PetscCall(PetscFunctionListFind(RollerSchemeList, ctx->ts.scheme, &f));
    if (!f) {
      const char **names;
      int          n;
      char         list[256] = "";

      PetscCall(PetscFunctionListGet(RollerSchemeList, &names, &n));
      for (int i = 0; i < n; ++i) {
        PetscCall(PetscStrlcat(list, " ", sizeof(list)));
        PetscCall(PetscStrlcat(list, names[i], sizeof(list)));
      }
      PetscCall(PetscFree(names));
      SETERRQ(ctx->comm, PETSC_ERR_USER_INPUT, "-ts_scheme %s: no such scheme; allowed:%s", ctx->ts.scheme, list);
    }
  }
  if (monitor_set) ctx->ts.view = PETSC_TRUE; /* -ts_monitor in any form also views the discretization */
  RollerCheckOption(ctx->comm, "-ts_phase_error", ctx->ts.phase_error, ctx->ts.phase_error > 0 && ctx->ts.phase_error < 1, "in (0, 1)");
  RollerCheckOption(ctx->comm, "-ts_dt", ctx->ts.dt, ctx->ts.dt >= 0, "> 0 (or 0: chosen from -ts_phase_error)");
  ctx->ts.dt_set = (PetscBool)(ctx->ts.dt > 0);
  RollerCheckOption(ctx->comm, "-ts_max_time", ctx->ts.max_time, ctx->ts.max_time >= 0, ">= 0");
  PetscCheck(ctx->ts.dt <= ctx->ts.max_time || ctx->ts.max_time == 0, ctx->comm, PETSC_ERR_USER_INPUT, "-ts_dt %.6g: longer than -ts_max_time %.6g, the run would take no step; allowed: (0, %.6g]", (double)ctx->ts.dt, (double)ctx->ts.max_time,
             (double)ctx->ts.max_time);
  RollerCheckOption(ctx->comm, "-ts_max_wall", ctx->ts.max_wall, ctx->ts.max_wall >= 0, ">= 0 seconds (0: no limit)");
  if (ctx->ts.max_wall > 0) PetscCall(ProcessStart(&ctx->ts.wall_start));
  PetscCheck(ctx->ts.max_steps >= -1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-ts_max_steps %" PetscInt_FMT " must be >= 0 (or -1 for no cap)", ctx->ts.max_steps);
  PetscFunctionReturn(0);
}

/* Number of steps: floor(max_time/dt) (to a rounding tolerance), capped by -ts_max_steps. None with -help, which
   lists every option (with the solvers', which set-up has read): no need to run the scene. */
PetscErrorCode RollerStepCount(Roller ctx, PetscInt *nsteps)
{
  PetscReal n = PetscFloorReal(ctx->ts.max_time / ctx->ts.dt + 1e-9);
  PetscBool help;

  PetscFunctionBeginUser;
  if (ctx->ts.max_steps >= 0) n = PetscMin(n, (PetscReal)ctx->ts.max_steps);
  *nsteps = (PetscInt)PetscMin(n, (PetscReal)PETSC_MAX_INT);
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (help) *nsteps = 0;
  PetscFunctionReturn(0);
}

/* -ts_monitor: the diagnostics of every state, the initial one too; after -restart from the step after the
   checkpoint's, like the CSV (the contact force of the checkpoint's step is not in it: a row there would say 0). */
static PetscErrorCode MonitorLine(Roller ctx, RollerMonitorEvent event, void *mctx)
{
  const RollerStepInfo *info = &ctx->info;

  PetscFunctionBeginUser;
  if (event == ROLLER_MONITOR_FINAL || (event == ROLLER_MONITOR_INITIAL && ctx->ck.restart[0])) PetscFunctionReturn(0);
  PetscCall(RollerStepInfoGet(ctx));
  PetscCall(PetscPrintf(ctx->comm, "%5" PetscInt_FMT " t %-10.6g R %+.6e alpha %+.6e energy %.10e", ctx->state.step, (double)ctx->state.time, (double)info->R, (double)info->alpha, (double)info->energy));
  if (ctx->contact)
    PetscCall(PetscPrintf(ctx->comm, " contact %" PetscInt_FMT " force %.6e gap %+.3e its %" PetscInt_FMT " kkt %.2e", info->contact_nodes, (double)info->contact_force, (double)info->gap_min, info->qp_iterations, (double)info->kkt_residual));
  PetscCall(PetscPrintf(ctx->comm, "\n"));
  PetscFunctionReturn(0);
}

typedef struct {
  PetscLogDouble start, last;
} Progress;

/* The progress line, unless -quiet: the clock starts at the initial state. */
static PetscErrorCode MonitorProgress(Roller ctx, RollerMonitorEvent event, void *mctx)
{
  Progress      *p = (Progress *)mctx;
  PetscInt       nsteps;
  PetscLogDouble now;

  PetscFunctionBeginUser;
  PetscCall(RollerStepCount(ctx, &nsteps));
  if (event == ROLLER_MONITOR_INITIAL) {
    PetscCall(PetscTime(&p->start));
    p->last = p->start;
  }
  if (event == ROLLER_MONITOR_FINAL || ctx->state.step == 0) PetscFunctionReturn(0);
  PetscCall(PetscTime(&now));
  if (now - p->last >= 5.0 || ctx->state.step == nsteps) {
    const PetscLogDouble eta = (now - p->start) * (nsteps - ctx->state.step) / ctx->state.step;

    PetscCall(PetscPrintf(ctx->comm, "roller: step %" PetscInt_FMT "/%" PetscInt_FMT " t = %g, %.1f s elapsed, ETA %.1f s\n", ctx->state.step, nsteps, (double)ctx->state.time, now - p->start, eta));
    p->last = now;
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode ProgressDestroy(void **mctx)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(*mctx));
  PetscFunctionReturn(0);
}

/* The console observers, first of all (their lines come before the step's files are written). */
PetscErrorCode RollerTimeStepMonitorSetUp(Roller ctx)
{
  PetscFunctionBeginUser;
  if (ctx->ts.monitor) PetscCall(RollerMonitorSet(ctx, MonitorLine, NULL, NULL));
  if (!ctx->ts.quiet) {
    Progress *p;

    PetscCall(PetscNew(&p));
    PetscCall(RollerMonitorSet(ctx, MonitorProgress, p, ProgressDestroy));
  }
  PetscFunctionReturn(0);
}
