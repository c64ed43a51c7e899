/* -modes (docs/squeal.md): instead of stepping, the modes of the scene, the quadratic eigenproblem of
   operators.c solved by pep.c, each eigenvalue classified (classify.c), written one row per eigenvalue to the
   CSV (-modes_csv F: re,im,frequency,growth_rate,order,wave,error,loss_factor,rubber_loss_factor, sorted by
   frequency; loss_factor = -2 re/im, rubber_loss_factor the rubber's for the shape at im, branches.c; written as F.part and
   renamed when complete) and printed; the shapes to HDF5 + XDMF (-modes_output F.h5, io/output_modes.c). */
#include "modes/modes.h"

const char *const RollerFrames[]          = {"rotating", "lab", "RollerFrame", "ROLLER_FRAME_", NULL};
const char *const RollerSlipDifferences[] = {"box", "upwind", "upwind2", "RollerSlipDifference", "ROLLER_SLIP_", NULL};

PetscErrorCode RollerModesSetFromOptions(Roller ctx)
{
  PetscFunctionBeginUser;
  ctx->eig.nev             = 20;
  ctx->eig.slip_difference = ROLLER_SLIP_BOX; /* the stick CEA converges with h_c (docs/squeal.md 4.4.4) */
  ctx->eig.skew_defect[0] = ctx->eig.skew_defect[1] = -1.0;
  ctx->eig.branch_transport                         = PETSC_TRUE; /* the lab frame's Maxwell branches transported with the material (docs/squeal.md 1.2) */
  PetscOptionsBegin(ctx->comm, NULL, "Roller: modes (docs/squeal.md); the eigensolver takes -pep_* and -st_* options (SLEPc PEP, TOAR, shift-and-invert about -pep_target 0)", NULL);
  PetscCall(PetscOptionsBool("-modes", "Compute the modes of the scene (the quadratic eigenproblem) instead of stepping", NULL, ctx->eig.on, &ctx->eig.on, NULL));
  ctx->eig.frame = ctx->obstacle.on || ctx->axle.on ? ROLLER_FRAME_LAB : ROLLER_FRAME_ROTATING; /* rolling, and the axle's vertical guide, are steady in the lab only */
  PetscCall(PetscOptionsEnum("-modes_frame", "Frame of the linearization: rotating (co-rotating, Lagrangian; the default without -obstacle and -axle) or lab (Eulerian; the default and the only one with -obstacle, and with -axle unless -omega 0)", "RollerFrame", RollerFrames,
                             (PetscEnum)ctx->eig.frame, (PetscEnum *)&ctx->eig.frame, NULL));
  PetscCall(PetscOptionsInt("-modes_nev", "Number of eigenvalues wanted (-pep_nev overrides); each complex pair counts twice; 0 with -obstacle: the steady state only", NULL, ctx->eig.nev, &ctx->eig.nev, NULL));
  PetscCall(PetscOptionsReal("-modes_stick_eps", "With -obstacle: the stick nodes' regularized Coulomb cone T = -mu N v/sqrt(v^2 + eps^2), eps a slip speed (docs/squeal.md 4.4); 0: each stick node rigidly stuck (a multiplier)", NULL, ctx->eig.stick_eps,
                             &ctx->eig.stick_eps, NULL));
  PetscCall(PetscOptionsReal("-modes_stick_margin", "With -obstacle: a stick node whose friction is within this fraction of the cone, |T| > (1 - margin) mu N, is linearized as slipping (docs/squeal.md 4.4.2); 0: every stick node stuck", NULL,
                             ctx->eig.stick_margin, &ctx->eig.stick_margin, NULL));
  PetscCall(PetscOptionsEnum("-modes_slip_difference", "With -obstacle: the steady state's slip along Gamma_C from the displacement at a candidate and its upstream neighbour (docs/squeal.md 3, 4.4.4): box (the slip at their midpoint: the stick CEA converges), upwind (at the candidate) or upwind2 (three points at the candidate: not monotone, fragmented stick zones)", "RollerSlipDifference", RollerSlipDifferences,
                             (PetscEnum)ctx->eig.slip_difference, (PetscEnum *)&ctx->eig.slip_difference, NULL));
  PetscCall(PetscOptionsBool("-modes_branch_transport", "-rubber maxwell, lab frame: the branches' fields transported with the material (exact); false: frozen in the lab, their transported creep left out (docs/squeal.md 1.2)", NULL, ctx->eig.branch_transport,
                             &ctx->eig.branch_transport, NULL));
  PetscCall(PetscOptionsString("-modes_csv", "Eigenvalue CSV: re,im,frequency,growth_rate,order,wave,error,loss_factor,rubber_loss_factor", NULL, ctx->eig.csv, ctx->eig.csv, sizeof(ctx->eig.csv), NULL));
  PetscCall(PetscOptionsString("-modes_steady_csv", "With -obstacle: the steady state's contact nodes x,y,normal_force,tangential_force,gap,slip_velocity,mu,state", NULL, ctx->eig.steady_csv, ctx->eig.steady_csv, sizeof(ctx->eig.steady_csv), NULL));
  PetscCall(PetscOptionsString("-modes_output", "Mode shapes: HDF5 file F.h5 (+ XDMF index F.xmf for ParaView)", NULL, ctx->eig.output, ctx->eig.output, sizeof(ctx->eig.output), NULL));
  PetscOptionsEnd();
  PetscCheck(ctx->eig.stick_eps >= 0 && !PetscIsInfOrNanReal(ctx->eig.stick_eps), ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-modes_stick_eps %g must be a finite slip speed >= 0 (0: rigid stick)", (double)ctx->eig.stick_eps);
  PetscCheck(ctx->eig.stick_margin >= 0 && ctx->eig.stick_margin < 1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-modes_stick_margin %g must be in [0, 1): a fraction of the Coulomb cone (0: every stick node stuck)", (double)ctx->eig.stick_margin);
  PetscCheck(ctx->eig.nev > 0 || (ctx->eig.nev == 0 && ctx->obstacle.on), ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-modes_nev %" PetscInt_FMT " must be > 0 (or 0 with -obstacle: the steady state only)", ctx->eig.nev);
  PetscFunctionReturn(0);
}

/* z <- z conj(z_p) / |z_p|^2, p the dof of largest |z|: the largest displacement component 1, real there; the factor
   (re, im) into f (NULL: not wanted). */
static PetscErrorCode Normalize(Vec xr, Vec xi, Vec w, PetscReal f[2])
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)xr);
  PetscInt  p, lo, hi;
  PetscReal big, ab[2] = {0, 0}, g[2], s;
  Vec       t;

  PetscFunctionBeginUser;
  PetscCall(VecPointwiseMult(w, xr, xr));
  PetscCall(VecDuplicate(xi, &t));
  PetscCall(VecPointwiseMult(t, xi, xi));
  PetscCall(VecAXPY(w, 1.0, t));
  PetscCall(VecMax(w, &p, &big));
  PetscCall(VecGetOwnershipRange(xr, &lo, &hi));
  if (p >= lo && p < hi) {
    const PetscScalar *a, *b;

    PetscCall(VecGetArrayRead(xr, &a));
    PetscCall(VecGetArrayRead(xi, &b));
    ab[0] = PetscRealPart(a[p - lo]);
    ab[1] = PetscRealPart(b[p - lo]);
    PetscCall(VecRestoreArrayRead(xr, &a));
    PetscCall(VecRestoreArrayRead(xi, &b));
  }
  PetscCall(MPIU_Allreduce(ab, g, 2, MPIU_REAL, MPIU_SUM, comm));
  s = g[0] * g[0] + g[1] * g[1];
  PetscCheck(s > 0, comm, PETSC_ERR_PLIB, "A zero eigenvector");
  /* (xr + i xi)(a - i b)/s = (a xr + b xi)/s + i (a xi - b xr)/s */
  PetscCall(VecCopy(xr, t));
  PetscCall(VecAXPBY(xr, g[1] / s, g[0] / s, xi));
  PetscCall(VecAXPBY(xi, -g[1] / s, g[0] / s, t));
  PetscCall(VecDestroy(&t));
  if (f) f[0] = g[0] / s, f[1] = -g[1] / s;
  PetscFunctionReturn(0);
}

/* x = the reduced vector z's kept dofs (its leading local entries; the stick multipliers after them dropped), 0 on
   the dofs removed. */
static PetscErrorCode KeptToFull(IS kept, Vec z, Vec x)
{
  PetscScalar *a;
  PetscInt     nloc;
  Vec          t;

  PetscFunctionBeginUser;
  PetscCall(ISGetLocalSize(kept, &nloc));
  PetscCall(VecGetArray(z, &a));
  PetscCall(VecCreateMPIWithArray(PetscObjectComm((PetscObject)z), 1, nloc, PETSC_DECIDE, a, &t));
  PetscCall(VecZeroEntries(x));
  PetscCall(VecISCopy(x, kept, SCATTER_FORWARD, t));
  PetscCall(VecDestroy(&t));
  PetscCall(VecRestoreArray(z, &a));
  PetscFunctionReturn(0);
}

/* The eigenvalue CSV, rank 0, as F.part renamed when complete; with -axle (hub not NULL) the hub's amplitudes |Y|,
   |phi| of the normalized mode appended (axle_y,hub_phi). */
static PetscErrorCode WriteCsv(Roller ctx, const PetscReal *hub)
{
  const RollerEigen *e = &ctx->eig;
  char               part[PETSC_MAX_PATH_LEN];
  FILE              *fp;

  PetscFunctionBeginUser;
  PetscCall(RollerPartFileOpen(ctx->comm, e->csv, "-modes_csv", part, sizeof(part), &fp));
  if (fp) {
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "re,im,frequency,growth_rate,order,wave,error,loss_factor,rubber_loss_factor%s\n", hub ? ",axle_y,hub_phi" : ""));
    for (PetscInt j = 0; j < e->n; ++j) {
      PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%s,%.3e,%.17g,%.17g", (double)e->re[j], (double)e->im[j], (double)e->im[j], (double)e->re[j], e->order[j], RollerWaves[e->wave[j]], (double)e->error[j], e->im[j] > 0 ? (double)(-2 * e->re[j] / e->im[j]) : 0.0,
                             (double)e->rubber_loss[j]));
      if (hub) PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, ",%.17g,%.17g", (double)hub[2 * j], (double)hub[2 * j + 1]));
      PetscCall(PetscFPrintf(PETSC_COMM_SELF, fp, "\n"));
    }
  }
  PetscCall(RollerPartFileClose(ctx->comm, &fp, part, e->csv));
  PetscFunctionReturn(0);
}

/* -axle: the hub's border (axle_modes.c), then the Maxwell branches over the bordered body, their flow rules weighted
   by its mass (the bordered K_d is singular on the rigid fields) */
static PetscErrorCode AxleOperators(Roller ctx, Mat *M, Mat *C, Mat *K)
{
  const PetscBool branches = ctx->material.rubber == ROLLER_RUBBER_MAXWELL && ctx->material.nbranch ? PETSC_TRUE : PETSC_FALSE;
  Mat             Kd       = NULL;

  PetscFunctionBeginUser;
  PetscCall(RollerAxleModeOperators(ctx, M, C, K, branches ? &Kd : NULL));
  if (Kd) PetscCall(RollerBranchOperators(ctx, Kd, M, C, K));
  PetscCall(MatDestroy(&Kd));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerModesSolve(Roller ctx)
{
  RollerEigen         *e = &ctx->eig;
  Mat                  M, C, K;
  RollerPEP            pep;
  RollerModeClassifier cls;
  Vec                 *xr, *xi, w, rel = NULL, zr = NULL, zi = NULL, fr = NULL, fi = NULL, steady = NULL; /* z: the PEP's vectors; f: with -obstacle, the full ones before the reduction */
  PetscReal           *hub    = NULL;                                                                     /* with -axle: |Y|, |phi| of each mode */
  IS                   kept   = NULL;                                                                     /* with -obstacle: the dofs of the reduced problem */
  PetscInt             nstick = 0;                                                                        /* and the stick nodes' multipliers after them */
  PetscReal            band[2];                                                                           /* the Maxwell branches' relaxation band, left out */

  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_MODES]));
  PetscCall(RollerModeOperators(ctx, &M, &C, &K));
  if (!ctx->axle.on) PetscCall(RollerBranchOperators(ctx, NULL, &M, &C, &K)); /* with -axle after the hub's border */
  if (ctx->obstacle.on) {                                                     /* the steady state, and the linearization about it on the kept dofs */
    RollerSteady st;
    Mat          Mr, Cr, Kr, Ks;
    PetscReal    q[2]; /* with -axle: the hub's steady (Y, phi) */

    PetscCall(RollerBranchSteadyStiffness(ctx, K, ctx->axle.on ? PETSC_FALSE : PETSC_TRUE, &Ks));
    if (ctx->axle.on) PetscCall(RollerAxleSteadySolve(ctx, Ks, &st, q));
    else PetscCall(RollerSteadySolve(ctx, Ks, &st));
    PetscCall(MatDestroy(&Ks));
    PetscCall(RollerSteadyReport(ctx, &st));
    if (ctx->axle.on && e->nev) PetscCall(AxleOperators(ctx, &M, &C, &K));
    PetscCall(MatCreateVecs(K, &fr, &fi));
    if (e->nev) PetscCall(RollerSquealOperators(ctx, &st, M, C, K, &Mr, &Cr, &Kr, &kept, &nstick));
    PetscCall(VecDuplicate(ctx->ops.coordinates, &steady)); /* kept for the shapes' file: the displacement */
    PetscCall(RollerBranchRestrict(st.u, steady));
    PetscCall(RollerSteadyDestroy(&st, PETSC_TRUE));
    PetscCall(MatDestroy(&M));
    PetscCall(MatDestroy(&C));
    PetscCall(MatDestroy(&K));
    if (!e->nev) { /* the steady state only */
      PetscCall(PetscLogStagePop());
      if (e->output[0]) PetscCall(RollerModeShapesWrite(ctx, e->output, 0, NULL, NULL, NULL, NULL, NULL, steady));
      PetscCall(VecDestroy(&steady));
      PetscFunctionReturn(0);
    }
    M = Mr;
    C = Cr;
    K = Kr;
  } else if (ctx->axle.on) PetscCall(AxleOperators(ctx, &M, &C, &K));
  PetscCall(RollerPEPCreate(ctx->comm, M, C, K, e->nev, nstick ? PETSC_TRUE : PETSC_FALSE, RollerBranchRelaxationBand(ctx, band) ? band : NULL, &pep));
  PetscCall(RollerPEPSolve(pep, &e->n));
  PetscCall(RollerModeClassifierCreate(ctx, &cls));
  PetscCall(PetscFree6(e->order, e->wave, e->re, e->im, e->error, e->rubber_loss));
  PetscCall(PetscMalloc6(e->n, &e->order, e->n, &e->wave, e->n, &e->re, e->n, &e->im, e->n, &e->error, e->n, &e->rubber_loss));
  PetscCall(VecDuplicateVecs(ctx->ops.coordinates, e->n, &xr));
  PetscCall(VecDuplicateVecs(ctx->ops.coordinates, e->n, &xi));
  PetscCall(VecDuplicate(ctx->ops.coordinates, &w));
  PetscCall(MatCreateVecs(M, &zr, &zi));
  if (ctx->axle.on) PetscCall(VecDuplicate(w, &rel));
  if (ctx->axle.on) PetscCall(PetscMalloc1(2 * e->n, &hub));
  for (PetscInt j = 0; j < e->n; ++j) {
    RollerWave wave;
    PetscReal  qr[2] = {0, 0}, qi[2] = {0, 0}, f[2] = {0, 0};

    PetscCall(RollerPEPGetPair(pep, j, &e->re[j], &e->im[j], zr, zi));
    if (kept) { /* the reduced vector into the full space; the active nodes' normal dofs are 0 */
      PetscCall(KeptToFull(kept, zr, fr));
      PetscCall(KeptToFull(kept, zi, fi));
    }
    if (ctx->ops.V && !kept) { /* -rom: the shape V z of the reduced model's coordinates z (-rom refuses -axle) */
      PetscCall(MatMult(ctx->ops.V, zr, xr[j]));
      PetscCall(MatMult(ctx->ops.V, zi, xi[j]));
    } else if (hub) { /* the body's part, and the hub's */
      PetscCall(RollerAxleModeSplit(kept ? fr : zr, xr[j], qr));
      PetscCall(RollerAxleModeSplit(kept ? fi : zi, xi[j], qi));
    } else {
      PetscCall(RollerBranchRestrict(kept ? fr : zr, xr[j])); /* the displacement part (all of it without branches) */
      PetscCall(RollerBranchRestrict(kept ? fi : zi, xi[j]));
    }
    PetscCall(RollerPEPGetError(pep, j, &e->error[j]));
    if (hub) { /* the rubber's loss factor of the strain: the shape relative to the hub (its scale drops out) */
      PetscCall(RollerAxleModeRelative(ctx, xr[j], qr, w));
      PetscCall(RollerAxleModeRelative(ctx, xi[j], qi, rel));
      PetscCall(RollerBranchLossFactor(ctx, w, rel, e->im[j], &e->rubber_loss[j]));
    }
    PetscCall(Normalize(xr[j], xi[j], w, f));
    if (hub) /* scaled like the body: |q f| */
      for (PetscInt k = 0; k < 2; ++k) hub[2 * j + k] = PetscSqrtReal((qr[k] * qr[k] + qi[k] * qi[k]) * (f[0] * f[0] + f[1] * f[1]));
    PetscCall(RollerModeClassify(cls, xr[j], xi[j], &e->order[j], &wave));
    if (!hub) PetscCall(RollerBranchLossFactor(ctx, xr[j], xi[j], e->im[j], &e->rubber_loss[j]));
    e->wave[j] = wave;
  }
  PetscCall(PetscLogStagePop());
  PetscCall(MatGetSize(M, &e->dofs, NULL));
  if (!ctx->ts.quiet) {
    PetscCall(PetscPrintf(ctx->comm, "roller: %" PetscInt_FMT " modes (%s frame, omega %g, %" PetscInt_FMT " unknowns), lambda = re + i im:\n  %4s %14s %14s %12s %5s %9s %9s\n", e->n, RollerFrames[e->frame], (double)ctx->rotation.omega, e->dofs, "#", "growth_rate", "frequency", "period", "order", "wave", "error"));
    for (PetscInt j = 0; j < e->n; ++j)
      PetscCall(
        PetscPrintf(ctx->comm, "  %4" PetscInt_FMT " %14.6e %14.8f %12.6f %5" PetscInt_FMT " %9s %9.1e\n", j, (double)e->re[j], (double)e->im[j], e->im[j] > 0 ? (double)(2 * PETSC_PI / e->im[j]) : 0.0, e->order[j], RollerWaves[e->wave[j]], (double)e->error[j]));
  }
  PetscCall(PetscLogStagePush(ctx->stage[ROLLER_STAGE_OUTPUT]));
  if (e->csv[0]) PetscCall(WriteCsv(ctx, hub));
  if (e->output[0]) PetscCall(RollerModeShapesWrite(ctx, e->output, e->n, e->re, e->im, e->order, xr, xi, steady));
  PetscCall(PetscLogStagePop());
  PetscCall(VecDestroyVecs(e->n, &xr));
  PetscCall(VecDestroyVecs(e->n, &xi));
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&rel));
  PetscCall(VecDestroy(&steady));
  PetscCall(VecDestroy(&zr));
  PetscCall(VecDestroy(&zi));
  PetscCall(VecDestroy(&fr));
  PetscCall(VecDestroy(&fi));
  PetscCall(PetscFree(hub));
  PetscCall(ISDestroy(&kept));
  PetscCall(RollerModeClassifierDestroy(&cls));
  PetscCall(RollerPEPDestroy(&pep));
  PetscCall(MatDestroy(&M));
  PetscCall(MatDestroy(&C));
  PetscCall(MatDestroy(&K));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerModesDestroy(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree6(ctx->eig.order, ctx->eig.wave, ctx->eig.re, ctx->eig.im, ctx->eig.error, ctx->eig.rubber_loss));
  ctx->eig.n = 0;
  PetscFunctionReturn(0);
}
