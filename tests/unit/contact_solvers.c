static const char help[] = "Unit test: every registered contact solver (contact/contact_registry.c) on small problems with\n"
                           "known answers, -mesh_h 0.1 and the -degree given (ctest: 1 and 2). (a) An obstacle that does not\n"
                           "reach the roller: the unconstrained solution A^{-1} b and zero multipliers. (b) The static indentation\n"
                           "(-static, the Signorini problem in one step): all solvers agree and satisfy the KKT conditions. (c) The\n"
                           "same with a shrunk candidate set (-contact_margin < 0): the re-solves end at it, without penetration.\n";

#include "contact/contact_impl.h"
#include "unit.h"

/* The Roller with the obstacle in the static scene of docs/validation.md section 5 (depth 0.025 reached at
   t = 5, the one step of -static at t = 5), set up through the public API; -degree from the command line.
   (One per process: RollerCreate registers the log stages.) */
static PetscErrorCode MakeRoller(Roller *ctx)
{
  /* -contact_pc_type: tao (tron)'s inner KSP (prefix contact_) preconditioned by a factorization. With the
     default ILU, tron does not reach the 1e-12 tolerance on this stiff problem (A = K, no mass term) with P2: it
     stops at 100000 iterations, with the code before the registry as well (-contact_solver tao -static -degree 2) */
  const char *const scene[][2] = {
    {"-mesh_h",          "0.1"     },
    {"-obstacle",        NULL      },
    {"-omega",           "0"       },
    {"-static",          NULL      },
    {"-ts_max_time",     "5"       },
    {"-quiet",           NULL      },
    {"-contact_pc_type", "cholesky"}
  };

  PetscFunctionBeginUser;
  PetscCall(RollerUnitSetUp(scene, ROLLER_UNIT_COUNT(scene), ctx));
  PetscCheck((*ctx)->contact, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "-obstacle did not create the contact layer");
  PetscFunctionReturn(0);
}

/* One solver on the step at t = dt (the static step) from the rest state, with its re-solves; the KKT residual
   and the least gap of its answer. */
static PetscErrorCode SolveStep(Roller ctx, RollerContactSolver s, Vec b, Vec xi, RollerContactResult *res, PetscReal *kkt, PetscReal *gap_min)
{
  RollerContact            c     = ctx->contact;
  const RollerContactStage stage = {
    c->step.op, ctx->state.time, ctx->state.cur, ctx->state.prev, {2.0, -1.0},
        {1.0, -1.0}
  }; /* the DMF's (-static) */

  PetscFunctionBeginUser;
  PetscCall(RollerContactSetUpStep(ctx, c, &stage, ctx->ts.dt));
  PetscCall(VecCopy(b, c->acc.b));
  PetscCall(RollerContactSolveWith(ctx, c, s, b, xi, res));
  PetscCall(RollerContactKKT(ctx, c, xi, NULL, NULL, res->lambda, gap_min, kkt));
  PetscFunctionReturn(0);
}

static PetscReal Sum(PetscInt n, const PetscReal a[])
{
  PetscReal s = 0.0;

  for (PetscInt i = 0; i < n; ++i) s += a[i];
  return s;
}

/* ||x - y||_inf / ||y||_inf */
static PetscErrorCode RelDiff(Vec x, Vec y, Vec work, PetscReal *d)
{
  PetscReal ny;

  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(work, -1.0, y, x));
  PetscCall(VecNorm(work, NORM_INFINITY, d));
  PetscCall(VecNorm(y, NORM_INFINITY, &ny));
  *d /= ny > 0 ? ny : 1.0;
  PetscFunctionReturn(0);
}

/* (a) b = A u with u lifting Gamma_C by 0.05 (twice the indentation) and the inner circle by 0: the free
   solution u clears the obstacle, so each solver must return it with all multipliers zero, although the
   bottom nodes are candidates (predicted from the rest state) and carry bounds. */
static PetscErrorCode TestNoReach(Roller ctx)
{
  RollerContact       c    = ctx->contact;
  const PetscReal     lift = 0.05, r0 = ctx->mesh.r_inner, r1 = ctx->mesh.r_outer;
  Vec                 u, b, xi, xf, work;
  PetscScalar        *ua;
  const PetscScalar  *x;
  PetscInt            n;
  RollerContactResult res;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(ctx->state.cur, &u));
  PetscCall(VecDuplicate(u, &b));
  PetscCall(VecDuplicate(u, &xi));
  PetscCall(VecDuplicate(u, &xf));
  PetscCall(VecDuplicate(u, &work));
  PetscCall(PetscMalloc1(c->nodes.nc, &res.lambda));
  PetscCall(VecGetLocalSize(u, &n));
  PetscCall(VecGetArrayRead(ctx->ops.coordinates, &x));
  PetscCall(VecGetArray(u, &ua));
  for (PetscInt i = 0; i < n; i += 2) {
    const PetscReal r = PetscSqrtReal(PetscSqr(PetscRealPart(x[i])) + PetscSqr(PetscRealPart(x[i + 1])));

    ua[i]     = 0.0;
    ua[i + 1] = lift * (r - r0) / (r1 - r0);
  }
  PetscCall(VecRestoreArray(u, &ua));
  PetscCall(VecRestoreArrayRead(ctx->ops.coordinates, &x));
  PetscCall(MatMult(c->step.op->A, u, b)); /* the step matrix (the scheme's, made known to the contact layer) */
  PetscCall(KSPSolve(c->step.op->ksp, b, xf));
  for (PetscInt k = 0; k < c->nsolvers; ++k) {
    RollerContactSolver s = c->solvers[k];
    PetscReal           kkt, gap_min, diff, lmax = 0.0;

    PetscCall(SolveStep(ctx, s, b, xi, &res, &kkt, &gap_min));
    PetscCall(RelDiff(xi, xf, work, &diff));
    for (PetscInt i = 0; i < c->nodes.nc; ++i) lmax = PetscMax(lmax, PetscAbsReal(res.lambda[i]));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  (a) %-9s candidates %" PetscInt_FMT " |xi - A^-1 b|/|A^-1 b| %.2e max|lambda| %.2e gap_min %.3e\n", s->name, c->step.ncand, (double)diff, (double)lmax, (double)gap_min));
    PetscCheck(c->step.ncand > 0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "(a) %s: no candidates, the bounds were not exercised", s->name);
    PetscCheck(diff < 1e-8, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "(a) %s: the solution differs from A^-1 b by %g (relative)", s->name, (double)diff);
    PetscCheck(lmax == 0.0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "(a) %s: nonzero multiplier %g where nothing touches", s->name, (double)lmax);
    PetscCheck(gap_min > 0.5 * lift - 0.025, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "(a) %s: least gap %g, expected about %g", s->name, (double)gap_min, (double)(lift - 0.025));
  }
  PetscCall(PetscFree(res.lambda));
  PetscCall(VecDestroy(&u));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&xi));
  PetscCall(VecDestroy(&xf));
  PetscCall(VecDestroy(&work));
  PetscFunctionReturn(0);
}

/* (b) and (c): the static step from rest (b = 0, A = K, the obstacle 0.025 into Gamma_C). Every solver's
   answer satisfies the KKT conditions and agrees with the reference solution ref (the first solver's when
   ref_set is false); with shrink, the candidate set is too small and the re-solves must end without
   penetration. */
static PetscErrorCode TestIndentation(Roller ctx, PetscBool shrink, Vec ref, PetscReal *ref_force, PetscBool ref_set)
{
  RollerContact       c   = ctx->contact;
  const PetscReal     tol = RollerContactGapTolerance(ctx);
  const char         *tag = shrink ? "(c)" : "(b)";
  Vec                 b, xi, work;
  RollerContactResult res;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(ctx->state.cur, &b));
  PetscCall(VecDuplicate(b, &xi));
  PetscCall(VecDuplicate(b, &work));
  PetscCall(VecZeroEntries(b));
  PetscCall(PetscMalloc1(c->nodes.nc, &res.lambda));
  for (PetscInt k = 0; k < c->nsolvers; ++k) {
    RollerContactSolver s = c->solvers[k];
    PetscReal           kkt, gap_min, diff, force;

    PetscCall(SolveStep(ctx, s, b, xi, &res, &kkt, &gap_min));
    force = Sum(c->nodes.nc, res.lambda);
    if (!ref_set) {
      PetscCall(VecCopy(xi, ref));
      *ref_force = force;
      ref_set    = PETSC_TRUE;
    }
    PetscCall(RelDiff(xi, ref, work, &diff));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  %s %-9s force %.10e candidates %" PetscInt_FMT " resolves %" PetscInt_FMT " its %" PetscInt_FMT " diff %.2e kkt %.2e gap_min %+.2e\n", tag, s->name, (double)force, c->step.ncand, c->step.resolves, res.its, (double)diff, (double)kkt, (double)gap_min));
    PetscCheck(force > 0.0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s %s: no contact force (%g) at an indentation of 0.025", tag, s->name, (double)force);
    PetscCheck(kkt < 1e-9, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s %s: KKT residual %g >= 1e-9", tag, s->name, (double)kkt);
    PetscCheck(gap_min >= -tol, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s %s: penetration, least gap %g < -%g", tag, s->name, (double)gap_min, (double)tol);
    PetscCheck(diff < 1e-8 && PetscAbsReal(force / *ref_force - 1) < 1e-8, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s %s: differs from the reference: displacement %g, force %g (relative)", tag, s->name, (double)diff, (double)PetscAbsReal(force / *ref_force - 1));
    PetscCheck(!shrink || c->step.resolves > 0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s %s: no re-solve, the penetration path was not exercised", tag, s->name);
  }
  PetscCall(PetscFree(res.lambda));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&xi));
  PetscCall(VecDestroy(&work));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  const char   *builtin[] = {"condensed", "vi", "tao", "pcg"};
  Roller        ctx;
  RollerContact c;
  Vec           ref;
  PetscReal     ref_force;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(MakeRoller(&ctx));
  c = ctx->contact;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "P%" PetscInt_FMT ", %" PetscInt_FMT " Gamma_C nodes:\n", ctx->disc.degree, c->nodes.nc));
  /* the registry: the built-in solvers, in registration order, the default one chosen */
  PetscCheck(c->nsolvers >= 4, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%" PetscInt_FMT " contact solvers registered, expected at least 4", c->nsolvers);
  for (PetscInt k = 0; k < 4; ++k) {
    PetscBool same;

    PetscCall(PetscStrcmp(c->solvers[k]->name, builtin[k], &same));
    PetscCheck(same, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "Contact solver %" PetscInt_FMT " is %s, expected %s", k, c->solvers[k]->name, builtin[k]);
  }
  PetscCheck(c->solver == c->solvers[0], PETSC_COMM_WORLD, PETSC_ERR_PLIB, "The default -contact_solver is %s, not condensed", c->solver->name);
  PetscCall(TestNoReach(ctx));
  PetscCall(VecDuplicate(ctx->state.cur, &ref));
  PetscCall(TestIndentation(ctx, PETSC_FALSE, ref, &ref_force, PETSC_FALSE));
  /* (c) the same problem with -contact_margin -0.1 (set here, where the option lands: the reach becomes
     -0.075, below the deepest predicted gap -0.025, so the candidate set misses every node) */
  c->opt.margin = -0.1;
  PetscCall(TestIndentation(ctx, PETSC_TRUE, ref, &ref_force, PETSC_TRUE));
  PetscCall(VecDestroy(&ref));
  PetscCall(RollerDestroy(&ctx));
  PetscCall(PetscFinalize());
  return 0;
}
