/* -modes with -axle (docs/squeal.md section 3.1): the hub's steady state pressed by the spring and the vectors of the
   bordered layout (axle_modes.c borders the operators).

   The steady state: the hub's height Y0 is the one at which the steady contact force is -nip_force (a secant on the
   depth of the clamped-hub steady state, steady.c: a rigid translation of the whole body leaves its strain alone), and
   the hub's mean rotation is the friction torque over k_d (a rigid rotation of the round annulus changes no contact
   force). */
#include "modes/modes.h"
#include "model/axle.h"

/* u += q_0 r_0 + q_1 r_1 on the body's part of u (all of it, or the leading local entries of the Maxwell branches'
   augmented layout: the branches' fields are not read from the steady state) */
static PetscErrorCode AddToBody(Vec u, const PetscReal q[2], Vec r[2])
{
  const PetscScalar *a, *b;
  PetscScalar       *pu;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(r[0], &n));
  PetscCall(VecGetArray(u, &pu));
  PetscCall(VecGetArrayRead(r[0], &a));
  PetscCall(VecGetArrayRead(r[1], &b));
  for (PetscInt i = 0; i < n; ++i) pu[i] += q[0] * a[i] + q[1] * b[i];
  PetscCall(VecRestoreArrayRead(r[1], &b));
  PetscCall(VecRestoreArrayRead(r[0], &a));
  PetscCall(VecRestoreArray(u, &pu));
  PetscFunctionReturn(0);
}

/* The total normal force of a steady state */
static PetscReal NormalForce(const RollerSteady *st)
{
  PetscReal N = 0;

  for (PetscInt j = 0; j < st->n; ++j) N += st->normal[j];
  return N;
}

/* The clamped-hub steady state at depth d (the sheet at d - r_outer) */
static PetscErrorCode SteadyAt(Roller ctx, KSP ksp, PetscReal d, RollerSteady *st, PetscReal *N)
{
  PetscFunctionBeginUser;
  ctx->obstacle.depth = d;
  PetscCall(RollerSteadySolveWith(ctx, ksp, st));
  *N = NormalForce(st);
  PetscFunctionReturn(0);
}

PetscErrorCode RollerAxleSteadySolve(Roller ctx, Mat Klab, RollerSteady *st, PetscReal q[2])
{
  const PetscReal F = ctx->axle.nip_force, depth = ctx->obstacle.depth;
  PetscReal       d0, d1, N0, N1, torque = 0;
  PetscInt        it;
  Vec             r[2];
  KSP             ksp; /* K_lab factored once for every depth */

  PetscFunctionBeginUser;
  PetscCheck(F > 0, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "-modes -axle -obstacle: the steady state is pressed by the spring's preload: -nip_force must be > 0, got %g", (double)F);
  /* a secant on the depth d: N(d) rises monotonically; the first two guesses -obstacle_depth and its scaling by F/N */
  d0 = depth > 0 ? depth : 1e-3 * ctx->mesh.r_outer;
  PetscCall(RollerSteadyKSPCreate(ctx, Klab, &ksp));
  PetscCall(SteadyAt(ctx, ksp, d0, st, &N0));
  PetscCheck(N0 > 0, ctx->comm, PETSC_ERR_NOT_CONVERGED, "-modes -axle: no contact at the first depth %g", (double)d0);
  d1 = d0 * F / N0;
  for (it = 0; it < 40; ++it) {
    PetscReal d2;

    PetscCall(RollerSteadyDestroy(st, PETSC_TRUE));
    PetscCall(SteadyAt(ctx, ksp, d1, st, &N1));
    if (PetscAbsReal(N1 - F) <= 1e-10 * F) break;
    d2 = N1 != N0 ? d1 - (N1 - F) * (d1 - d0) / (N1 - N0) : d1 * F / PetscMax(N1, 1e-300);
    if (d2 <= 0) d2 = 0.5 * d1; /* stay in contact */
    d0 = d1, N0 = N1, d1 = d2;
  }
  PetscCheck(it < 40, ctx->comm, PETSC_ERR_NOT_CONVERGED, "-modes -axle: the hub's height for -nip_force %g did not settle in 40 steady solves (force %g at depth %g)", (double)F, (double)N1, (double)d1);
  ctx->obstacle.depth = depth;
  PetscCall(KSPDestroy(&ksp));
  for (PetscInt j = 0; j < st->n; ++j) torque += st->xy[2 * j] * st->normal[j] - st->xy[2 * j + 1] * st->tangent[j];
  q[0] = -d1;                                /* the hub lowered onto the sheet at -r_outer */
  q[1] = torque / ctx->axle.drive_stiffness; /* the drive's spring holds the friction torque */
  PetscCall(RollerAxleRigidFields(ctx, r));
  PetscCall(AddToBody(st->u, q, r));
  PetscCall(VecDestroy(&r[0]));
  PetscCall(VecDestroy(&r[1]));
  if (!ctx->ts.quiet)
    PetscCall(PetscPrintf(ctx->comm, "roller: -modes -axle: the hub at Y = %.10g (the clamped hub's depth; %" PetscInt_FMT " steady solves) gives the contact force %.10g against -nip_force %g; the drive's mean twist %.6g (friction torque %.6g)\n", (double)q[0], it + 2, (double)NormalForce(st), (double)F, (double)q[1], (double)torque));
  PetscFunctionReturn(0);
}

/* An augmented vector (the body's local rows, then on the last rank Y, phi) into the body's vector and q (on every
   rank) */
PetscErrorCode RollerAxleModeSplit(Vec z, Vec x, PetscReal q[2])
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)z);
  PetscMPIInt        rank, size;
  const PetscScalar *a;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(RollerBranchRestrict(z, x)); /* the body's part: the leading local entries */
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(z, &a));
  if (rank == size - 1) q[0] = PetscRealPart(a[n]), q[1] = PetscRealPart(a[n + 1]);
  PetscCall(VecRestoreArrayRead(z, &a));
  PetscCallMPI(MPI_Bcast(q, 2, MPIU_REAL, size - 1, comm));
  PetscFunctionReturn(0);
}

/* rel = x - Y e2 - phi J x on the free nodes: the body's shape relative to the hub, whose strain is the whole body's
   (K and K_d annihilate the rigid fields; Gamma_D's nodes carry no relative motion), for the clamped body's quadratic
   forms (the rubber's loss factor of a mode, branches.c) */
PetscErrorCode RollerAxleModeRelative(Roller ctx, Vec x, const PetscReal q[2], Vec rel)
{
  const PetscReal mq[2] = {-q[0], -q[1]};
  Vec             r[2];

  PetscFunctionBeginUser;
  PetscCall(RollerAxleRigidFields(ctx, r));
  PetscCall(VecCopy(x, rel));
  PetscCall(AddToBody(rel, mq, r));
  PetscCall(VecDestroy(&r[0]));
  PetscCall(VecDestroy(&r[1]));
  PetscFunctionReturn(0);
}

/* An augmented vector with the body's layout and the hub's two entries on the last rank */
PetscErrorCode RollerAxleModeVec(Vec x, Vec *z)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)x);
  PetscMPIInt rank, size;
  PetscInt    n;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecCreateMPI(comm, n + (rank == size - 1 ? 2 : 0), PETSC_DETERMINE, z));
  PetscFunctionReturn(0);
}
