/* What the contact layer reports about a step: the KKT residual of a solution, -contact_check (every other
   registered solver on the same step), -contact_monitor (the contact set, a viewer) and the contact columns
   of the CSV (docs/model.md section 6, docs/contact.md). */
#include "contact_impl.h"

/* The KKT residual of (xi, lambda) for the step's QP (docs/contact.md), with F = max(||b||, ||E N lambda||):
   max of  max(0, -min gap)/r_C,  max(0, -min lambda)/F,  max |lambda_n gap_n|/(F r_C),
   ||A xi - b - E N lambda||/F. Also returns the least gap over all Gamma_C nodes. With M xi and K xi (or NULL), A xi =
   c_M M xi + c_K K xi costs no product (A without the centred Coriolis term and the Maxwell branches' c_D K_d). */
PetscErrorCode RollerContactKKT(Roller ctx, RollerContact c, Vec xi, Vec Mxi, Vec Kxi, const PetscReal lambda[], PetscReal *gap_min, PetscReal *kkt)
{
  RollerContactAccepted *acc = &c->acc;
  PetscReal              nb, nf, nr, fs, lmin = 0.0, comp = 0.0;

  PetscFunctionBeginUser;
  PetscCall(RollerContactGather(c, xi, c->nodes.red));
  PetscCall(RollerContactGaps(c, c->nodes.red, c->step.gap, gap_min));
  PetscCall(RollerContactForce(c, lambda, lambda == acc->result.lambda ? acc->result.lambda_t : NULL, acc->force));
  if (Mxi && Kxi && !c->step.op->G && c->step.op->c_D == 0) PetscCall(VecAXPBYPCZ(acc->work, c->step.op->c_M, c->step.op->c_K, 0.0, Mxi, Kxi));
  else PetscCall(MatMult(c->step.op->A, xi, acc->work));
  if (c->step.op->border) { /* -axle: A_eff xi = A xi - C Dz C^T xi (model/axle.h) */
    PetscScalar d[3];
    PetscReal   r[3], w[3];

    PetscCall(VecMDot(xi, 3, c->step.op->border->C, d));
    for (PetscInt i = 0; i < 3; ++i) r[i] = PetscRealPart(d[i]);
    RollerMat3Vec(ctx->axle.hub->s.Dz, r, w);
    for (PetscInt i = 0; i < 3; ++i) d[i] = -w[i];
    PetscCall(VecMAXPY(acc->work, 3, d, c->step.op->border->C));
  }
  PetscCall(VecAXPBYPCZ(acc->work, -1.0, -1.0, 1.0, acc->b, acc->force));
  PetscCall(VecNorm(acc->work, NORM_2, &nr));
  PetscCall(VecNorm(acc->b, NORM_2, &nb));
  PetscCall(VecNorm(acc->force, NORM_2, &nf));
  fs = PetscMax(nb, nf);
  if (fs == 0.0) fs = 1.0;
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    lmin = PetscMin(lmin, lambda[i]);
    comp = PetscMax(comp, PetscAbsReal(lambda[i] * c->step.gap[i]));
  }
  *kkt = PetscMax(PetscMax(PetscMax(0.0, -*gap_min) / ctx->mesh.r_outer, -lmin / fs), PetscMax(comp / (fs * ctx->mesh.r_outer), nr / fs));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckPrint(Roller ctx, RollerContact c, RollerContactSolver s, PetscInt its, PetscReal diff, PetscReal kkt, PetscReal gap_min)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(ctx->comm, "contact_check: step %" PetscInt_FMT " t %.6g solver %s its %" PetscInt_FMT " diff %.3e kkt %.3e gap_min %+.3e\n", ctx->state.step + 1, (double)c->step.t, s->name, its, (double)diff, (double)kkt, (double)gap_min));
  PetscFunctionReturn(0);
}

/* -contact_check: the same step with every other solver, from the same data and candidate set; the accepted
   solution xi of the step's right-hand side b is that of -contact_solver. */
PetscErrorCode RollerContactCheckStep(Roller ctx, RollerContact c, Vec b, Vec xi)
{
  RollerContactCheck *ck   = &c->check;
  PetscInt            self = -1;
  PetscReal           xmax, gap_min, kkt;

  PetscFunctionBeginUser;
  if (!ck->xi) {
    PetscCall(VecDuplicate(xi, &ck->xi));
    PetscCall(PetscMalloc1(c->nodes.nc, &ck->result.lambda));
    PetscCall(PetscCalloc2(c->nsolvers, &ck->max_diff, c->nsolvers, &ck->max_kkt));
  }
  PetscCall(VecNorm(xi, NORM_INFINITY, &xmax));
  if (xmax == 0.0) xmax = 1.0;
  for (PetscInt k = 0; k < c->nsolvers; ++k)
    if (c->solvers[k] == c->solver) self = k;
  PetscCall(RollerContactKKT(ctx, c, xi, NULL, NULL, c->acc.result.lambda, &gap_min, &kkt));
  ck->max_kkt[self] = PetscMax(ck->max_kkt[self], kkt);
  PetscCall(CheckPrint(ctx, c, c->solver, c->acc.result.its, 0.0, kkt, gap_min));
  for (PetscInt k = 0; k < c->nsolvers; ++k) {
    RollerContactSolver s = c->solvers[k];
    PetscReal           diff;

    if (k == self) continue;
    PetscCall(RollerContactSolveWith(ctx, c, s, b, ck->xi, &ck->result));
    PetscCall(RollerContactKKT(ctx, c, ck->xi, NULL, NULL, ck->result.lambda, &gap_min, &kkt));
    PetscCall(VecAXPY(ck->xi, -1.0, xi));
    PetscCall(VecNorm(ck->xi, NORM_INFINITY, &diff));
    diff /= xmax;
    ck->max_diff[k] = PetscMax(ck->max_diff[k], diff);
    ck->max_kkt[k]  = PetscMax(ck->max_kkt[k], kkt);
    PetscCall(CheckPrint(ctx, c, s, ck->result.its, diff, kkt, gap_min));
  }
  ck->steps++;
  PetscFunctionReturn(0);
}

/* The largest differences and KKT residuals over the run, one line per solver. */
PetscErrorCode RollerContactCheckSummary(RollerContact c)
{
  PetscFunctionBeginUser;
  if (!c->check.steps) PetscFunctionReturn(0);
  for (PetscInt k = 0; k < c->nsolvers; ++k)
    PetscCall(PetscPrintf(c->comm, "contact_check: summary over %" PetscInt_FMT " steps: solver %s max diff %.3e max kkt %.3e\n", c->check.steps, c->solvers[k]->name, (double)c->check.max_diff[k], (double)c->check.max_kkt[k]));
  PetscFunctionReturn(0);
}

/* -contact_monitor: the contact set along the tangent t^k, s_n = (x_n + xi_n) . t^k: its extent, the
   force-weighted centroid (0 for a contact symmetric about the line through the centre along n^k) and the
   force-weighted RMS distance from it (a Hertz pressure p0 sqrt(1 - s^2/a^2) has s_rms = a/2). One line of
   text per step, or with the format ascii_csv a CSV with a header line (for scripts: tests/contact_*.py). */
static PetscErrorCode ContactMonitor(Roller ctx, RollerContact c, const RollerStepInfo *info)
{
  const PetscReal   *lambda = c->acc.result.lambda, *xc = c->nodes.xc, *tg = c->step.tangent;
  const PetscScalar *u;
  PetscViewer        v    = c->opt.monitor;
  PetscReal          smin = 0.0, smax = 0.0, sbar = 0.0, s2 = 0.0;
  PetscBool          first = PETSC_TRUE;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(c->nodes.red, &u));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscReal s = (xc[2 * i] + PetscRealPart(u[2 * i])) * tg[0] + (xc[2 * i + 1] + PetscRealPart(u[2 * i + 1])) * tg[1];

    if (lambda[i] <= 0.0) continue;
    smin = first ? s : PetscMin(smin, s);
    smax = first ? s : PetscMax(smax, s);
    sbar += lambda[i] * s;
    first = PETSC_FALSE;
  }
  if (info->contact_force > 0) sbar /= info->contact_force;
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscReal s = (xc[2 * i] + PetscRealPart(u[2 * i])) * tg[0] + (xc[2 * i + 1] + PetscRealPart(u[2 * i + 1])) * tg[1];

    if (lambda[i] > 0.0) s2 += lambda[i] * PetscSqr(s - sbar);
  }
  PetscCall(VecRestoreArrayRead(c->nodes.red, &u));
  if (info->contact_force > 0) s2 /= info->contact_force;
  if (c->opt.monitor_format == PETSC_VIEWER_ASCII_CSV) {
    if (!c->opt.monitor_header)
      PetscCall(PetscViewerASCIIPrintf(v, c->friction ? "step,t,nodes,force,s_min,s_max,s_centroid,s_rms,candidates,resolves,stick,slip,friction_force,law_residual,coulomb_iterations\n" : "step,t,nodes,force,s_min,s_max,s_centroid,s_rms,candidates,resolves\n"));
    c->opt.monitor_header = PETSC_TRUE;
    PetscCall(PetscViewerASCIIPrintf(v, "%" PetscInt_FMT ",%.17g,%" PetscInt_FMT ",%.17g,%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%" PetscInt_FMT, ctx->state.step, (double)c->step.t, info->contact_nodes, (double)info->contact_force, (double)smin, (double)smax, (double)sbar, (double)PetscSqrtReal(s2),
                                     c->step.ncand, c->step.resolves));
    if (c->friction)
      PetscCall(PetscViewerASCIIPrintf(v, ",%" PetscInt_FMT ",%" PetscInt_FMT ",%.17g,%.17g,%" PetscInt_FMT, info->friction.stick, info->friction.slip, (double)info->friction.force, (double)info->friction.residual, info->friction.iterations));
    PetscCall(PetscViewerASCIIPrintf(v, "\n"));
  } else {
    PetscCall(PetscViewerASCIIPrintf(v, "contact_monitor: step %" PetscInt_FMT " t %.6g nodes %" PetscInt_FMT " force %.10e s_min %+.10e s_max %+.10e s_centroid %+.10e s_rms %.10e candidates %" PetscInt_FMT " resolves %" PetscInt_FMT, ctx->state.step,
                                     (double)c->step.t, info->contact_nodes, (double)info->contact_force, (double)smin, (double)smax, (double)sbar, (double)PetscSqrtReal(s2), c->step.ncand, c->step.resolves));
    if (c->friction)
      PetscCall(PetscViewerASCIIPrintf(v, " stick %" PetscInt_FMT " slip %" PetscInt_FMT " friction_force %+.10e law_residual %.3e coulomb_its %" PetscInt_FMT, info->friction.stick, info->friction.slip, (double)info->friction.force,
                                       (double)info->friction.residual, info->friction.iterations));
    PetscCall(PetscViewerASCIIPrintf(v, "\n"));
  }
  PetscFunctionReturn(0);
}

/* The contact columns of the CSV (docs/model.md section 6) for the solution xi at t (M xi, K xi: its products, or NULL). */
PetscErrorCode RollerContactInfo(Roller ctx, RollerContact c, Vec xi, Vec Mxi, Vec Kxi, PetscReal t, RollerStepInfo *info)
{
  RollerContactResult *res = &c->acc.result;
  PetscReal            gap_min, kkt;

  PetscFunctionBeginUser;
  if (!c->acc.solved || t != c->step.t) { /* before the first step: no multipliers yet (a restart's are the checkpoint's) */
    PetscCall(RollerContactSetTime(ctx, c, t));
    if (c->acc.solved || !ctx->ck.restart[0]) PetscCall(PetscArrayzero(res->lambda, c->nodes.nc));
    res->its = 0;
    PetscCall(RollerContactGather(c, xi, c->nodes.red));
    PetscCall(RollerContactGaps(c, c->nodes.red, c->step.gap, &gap_min));
    kkt = PetscMax(0.0, -gap_min) / ctx->mesh.r_outer;
  } else PetscCall(RollerContactKKT(ctx, c, xi, Mxi, Kxi, res->lambda, &gap_min, &kkt));
  info->contact_nodes = 0;
  info->contact_force = 0.0;
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    if (res->lambda[i] > 0.0) info->contact_nodes++;
    info->contact_force += res->lambda[i];
  }
  info->gap_min       = gap_min;
  info->qp_iterations = res->its;
  info->kkt_residual  = kkt;
  PetscCall(RollerContactFlips(ctx, c, res->lambda, info));
  if (c->friction) PetscCall(RollerContactFrictionInfo(ctx, c, res->lambda, info));
  /* after -restart, the checkpoint's state has no multipliers: its row is the run's before the stop, not a row of 0 */
  if (c->opt.monitor && (c->acc.solved || !ctx->ck.restart[0])) PetscCall(ContactMonitor(ctx, c, info));
  PetscFunctionReturn(0);
}
