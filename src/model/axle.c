/* The axle and the drive (-axle, docs/model.md section 10): the options, the hub's coupling with the body (the bordered
   mass and stiffness of model/axle.h, computed once), its springs and the forces on it. */
#include "model/model.h"
#include "model/kernels.h"

PetscErrorCode RollerAxleSetFromOptions(Roller ctx)
{
  RollerAxle *ax = &ctx->axle;

  PetscFunctionBeginUser;
  ax->nip_ramp = ctx->obstacle.speed > 0 ? ctx->obstacle.depth / ctx->obstacle.speed : 0.0;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: the axle, the drive and the sheet's own motion (-axle, -sheet_mass; docs/model.md section 10)", NULL);
  PetscCall(PetscOptionsBool("-axle", "The hub a rigid body on a vertical spring preloaded to -nip_force, driven through a torsional spring and damper (off: the hub turns exactly at theta(t), the sheet at -obstacle_depth)", NULL, ax->on, &ax->on, NULL));
  PetscCall(PetscOptionsReal("-axle_mass", "Mass of the hub, shaft and bracket per unit width (0: the rubber body's own mass)", NULL, ax->mass, &ax->mass, NULL));
  PetscCall(PetscOptionsReal("-axle_inertia", "Polar inertia per unit width of the hub, shaft, gears and the motor's referred to the roller (0: the rubber body's own)", NULL, ax->inertia, &ax->inertia, NULL));
  PetscCall(PetscOptionsReal("-axle_stiffness", "Stiffness per unit width of the vertical (pick) spring about the hub's position at the end of -nip_ramp", NULL, ax->stiffness, &ax->stiffness, NULL));
  PetscCall(PetscOptionsReal("-nip_force", "Preload of the vertical spring per unit width: the mean contact force", NULL, ax->nip_force, &ax->nip_force, NULL));
  PetscCall(PetscOptionsReal("-nip_ramp", "Time over which the preload rises smoothly to -nip_force (default: the press time -obstacle_depth/-obstacle_speed)", NULL, ax->nip_ramp, &ax->nip_ramp, NULL));
  PetscCall(PetscOptionsReal("-drive_stiffness", "Torsional stiffness per unit width of the drive (gear train and motor) between the motor and the hub (required with -axle)", NULL, ax->drive_stiffness, &ax->drive_stiffness, NULL));
  PetscCall(PetscOptionsReal("-drive_damping", "Torsional damping per unit width of the drive", NULL, ax->drive_damping, &ax->drive_damping, NULL));
  PetscCall(PetscOptionsReal("-drive_kick", "A disturbance: the angular impulse per unit width given to the hub at -drive_kick_time (0: none; docs/squeal.md 9.5)", NULL, ax->kick, &ax->kick, NULL));
  PetscCall(PetscOptionsReal("-drive_kick_time", "The time of -drive_kick (the step's level nearest to it takes the impulse)", NULL, ax->kick_time, &ax->kick_time, NULL));
  PetscCall(
    PetscOptionsReal("-sheet_mass", "The sheet's mass per unit width: its speed follows from the friction and -sheet_resistance, from -sheet_speed at t = 0 (0: the kinematic sheet at -sheet_speed)", NULL, ctx->obstacle.sheet_mass, &ctx->obstacle.sheet_mass, NULL));
  PetscCall(PetscOptionsReal("-sheet_resistance", "With -sheet_mass: the force per unit width holding the sheet back (the stack, the separation pad), a Coulomb element on its motion", NULL, ctx->obstacle.sheet_resistance, &ctx->obstacle.sheet_resistance, NULL));
  PetscOptionsEnd();
  RollerCheckOption(ctx->comm, "-sheet_mass", ctx->obstacle.sheet_mass, ctx->obstacle.sheet_mass >= 0, ">= 0 (0: the kinematic sheet)");
  RollerCheckOption(ctx->comm, "-sheet_resistance", ctx->obstacle.sheet_resistance, ctx->obstacle.sheet_resistance >= 0, ">= 0");
  PetscCheck(ctx->obstacle.sheet_resistance == 0 || ctx->obstacle.sheet_mass > 0, ctx->comm, PETSC_ERR_ARG_INCOMP, "-sheet_resistance %g holds a sheet that moves by its own forces: give -sheet_mass > 0", (double)ctx->obstacle.sheet_resistance);
  PetscCheck(ctx->obstacle.sheet_mass == 0 || (ctx->obstacle.on && ctx->obstacle.friction > 0), ctx->comm, PETSC_ERR_ARG_INCOMP, "-sheet_mass %g: the sheet moves by the friction: needs -obstacle and -friction > 0 (or -friction_table)",
             (double)ctx->obstacle.sheet_mass);
  RollerCheckOption(ctx->comm, "-axle_mass", ax->mass, ax->mass >= 0, ">= 0 (0: the rubber's mass)");
  RollerCheckOption(ctx->comm, "-axle_inertia", ax->inertia, ax->inertia >= 0, ">= 0 (0: the rubber's polar inertia)");
  RollerCheckOption(ctx->comm, "-axle_stiffness", ax->stiffness, ax->stiffness >= 0, ">= 0");
  RollerCheckOption(ctx->comm, "-nip_force", ax->nip_force, ax->nip_force >= 0, ">= 0");
  RollerCheckOption(ctx->comm, "-nip_ramp", ax->nip_ramp, ax->nip_ramp >= 0, ">= 0");
  RollerCheckOption(ctx->comm, "-drive_stiffness", ax->drive_stiffness, ax->drive_stiffness >= 0, ">= 0");
  RollerCheckOption(ctx->comm, "-drive_damping", ax->drive_damping, ax->drive_damping >= 0, ">= 0");
  RollerCheckOption(ctx->comm, "-drive_kick", ax->kick, PetscAbsReal(ax->kick) <= 1e100, "|J| <= 1e100 (its energy J^2/(2 I) representable)");
  RollerCheckOption(ctx->comm, "-drive_kick_time", ax->kick_time, ax->kick_time >= 0, ">= 0");
  PetscCheck(ax->kick == 0 || ax->on, ctx->comm, PETSC_ERR_ARG_INCOMP, "-drive_kick %g is an impulse on the hub: needs -axle", (double)ax->kick);
  if (ax->on)
    PetscCheck(ax->nip_force < ctx->material.young * (ctx->mesh.r_outer - ctx->mesh.r_inner), ctx->comm, PETSC_ERR_USER_INPUT, "-nip_force %g must be below E (r_outer - r_inner) = %g (a force per unit width that would squeeze the rubber's wall flat)",
               (double)ax->nip_force, (double)(ctx->material.young * (ctx->mesh.r_outer - ctx->mesh.r_inner)));
  if (ax->on) PetscCheck(ax->drive_stiffness > 0, ctx->comm, PETSC_ERR_USER_INPUT, "-axle needs -drive_stiffness > 0 (the drive's torsional stiffness), got %g", (double)ax->drive_stiffness);
  PetscFunctionReturn(0);
}

void RollerMat3Vec(const PetscReal A[9], const PetscReal x[3], PetscReal y[3])
{
  for (PetscInt i = 0; i < 3; ++i) y[i] = A[3 * i] * x[0] + A[3 * i + 1] * x[1] + A[3 * i + 2] * x[2];
}

PetscReal RollerDot3(const PetscReal a[3], const PetscReal b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* n(theta(t)) = R(theta)^T e2 = (sin theta, cos theta): the lab's vertical in the frame's components. */
void RollerAxleFrame(Roller ctx, PetscReal t, PetscReal n[2])
{
  PetscReal th;

  RollerTheta(ctx, t, &th, NULL, NULL);
  n[0] = PetscSinReal(th);
  n[1] = PetscCosReal(th);
}

/* The springs on q: the vertical spring on u (isotropic: the constraint u = Y n removes the horizontal part), from the
   end of -nip_ramp on, and the drive's torsional spring on phi. */
void RollerAxleSprings(Roller ctx, PetscReal S[9])
{
  const RollerAxle *ax = &ctx->axle;
  const PetscReal   k  = ax->hub && ax->hub->s.anchor[0] != 0 ? ax->stiffness : 0.0;

  for (PetscInt i = 0; i < 9; ++i) S[i] = 0.0;
  S[0] = S[4] = k;
  S[8]        = ax->drive_stiffness;
}

/* The preload P(t) = F s(t/T), s = x^2 (3 - 2 x) the smooth ramp over T = -nip_ramp. */
PetscReal RollerAxleNipForce(Roller ctx, PetscReal t)
{
  const PetscReal T = ctx->axle.nip_ramp, x = T > 0 ? PetscMax(0.0, PetscMin(1.0, t / T)) : 1.0;

  return ctx->axle.nip_force * x * x * (3.0 - 2.0 * x);
}

/* The forces on q at t besides the springs: the preload pushing the hub down, -P(t) n, and once anchored the spring's
   pull toward its anchor, k Y_w n (the spring's force is -k (Y - Y_w) along n). */
void RollerAxleForce(Roller ctx, PetscReal t, PetscReal f[3])
{
  const RollerHub *hub = ctx->axle.hub;
  PetscReal        n[2], a;

  RollerAxleFrame(ctx, t, n);
  a    = -RollerAxleNipForce(ctx, t) + (hub->s.anchor[0] != 0 ? ctx->axle.stiffness * hub->s.anchor[1] : 0.0);
  f[0] = a * n[0];
  f[1] = a * n[1];
  f[2] = 0.0;
  /* -drive_kick J: the torque J/dt at the one level within half a step of the kick's time (the three-level step's
     momentum jumps by J: (I (phi^{k+1} - phi^k) - I (phi^k - phi^{k-1}))/dt = J) */
  if (ctx->axle.kick != 0 && t >= ctx->axle.kick_time - 0.5 * ctx->ts.dt && t < ctx->axle.kick_time + 0.5 * ctx->ts.dt) f[2] = ctx->axle.kick / ctx->ts.dt;
}

/* Dz = Z (Z^T D Z)^{-1} Z^T, Z = [[n, 0], [0, 1]] at t: the inverse of D on the hub's admissible motions (u along n). */
void RollerAxleProject(Roller ctx, PetscReal t, const PetscReal D[9], PetscReal Dz[9])
{
  PetscReal n[2], Z[3][2], R[2][2], det, Ri[2][2];

  RollerAxleFrame(ctx, t, n);
  Z[0][0] = n[0], Z[1][0] = n[1], Z[2][0] = 0.0;
  Z[0][1] = 0.0, Z[1][1] = 0.0, Z[2][1] = 1.0;
  for (PetscInt a = 0; a < 2; ++a)
    for (PetscInt b = 0; b < 2; ++b) {
      R[a][b] = 0.0;
      for (PetscInt i = 0; i < 3; ++i)
        for (PetscInt j = 0; j < 3; ++j) R[a][b] += Z[i][a] * D[3 * i + j] * Z[j][b];
    }
  det      = R[0][0] * R[1][1] - R[0][1] * R[1][0];
  Ri[0][0] = R[1][1] / det, Ri[1][1] = R[0][0] / det;
  Ri[0][1] = -R[0][1] / det, Ri[1][0] = -R[1][0] / det;
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) {
      Dz[3 * i + j] = 0.0;
      for (PetscInt a = 0; a < 2; ++a)
        for (PetscInt b = 0; b < 2; ++b) Dz[3 * i + j] += Z[i][a] * Ri[a][b] * Z[j][b];
    }
}

/* The rigid fields at the free nodes: r_1 = e1, r_2 = e2, r_3 = J x = (-x2, x1), from the nodal positions (also the
   reduced model's constraint modes of the hub, rom/rom_basis.c). */
PetscErrorCode RollerRigidFields(Roller ctx, Vec r[3])
{
  const PetscScalar *x;
  PetscScalar       *a[3];
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(ctx->ops.coordinates, &n));
  PetscCall(VecGetArrayRead(ctx->ops.coordinates, &x));
  for (PetscInt j = 0; j < 3; ++j) {
    PetscCall(VecDuplicate(ctx->ops.coordinates, &r[j]));
    PetscCall(VecGetArrayWrite(r[j], &a[j]));
  }
  for (PetscInt i = 0; i < n; i += 2) {
    a[0][i] = 1.0, a[0][i + 1] = 0.0;
    a[1][i] = 0.0, a[1][i + 1] = 1.0;
    a[2][i] = -x[i + 1], a[2][i + 1] = x[i];
  }
  for (PetscInt j = 0; j < 3; ++j) PetscCall(VecRestoreArrayWrite(r[j], &a[j]));
  PetscCall(VecRestoreArrayRead(ctx->ops.coordinates, &x));
  PetscFunctionReturn(0);
}

static PetscErrorCode FieldE1(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *c)
{
  u[0] = 1.0, u[1] = 0.0;
  return 0;
}
static PetscErrorCode FieldE2(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *c)
{
  u[0] = 0.0, u[1] = 1.0;
  return 0;
}
static PetscErrorCode FieldJx(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *c)
{
  u[0] = -x[1], u[1] = x[0];
  return 0;
}
static PetscErrorCode FieldRx(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *c)
{
  u[0] = x[1], u[1] = -x[0];
  return 0;
}

/* The whole body's products with its mass (Gamma_D's nodes included, on the space without the Dirichlet boundary):
   T_ij = r_i . M r_j, ax_i = r_i . M x, aR_i = r_i . M R(-pi/2) x, over every node. */
static PetscErrorCode WholeBodyProducts(Roller ctx, PetscReal T[9], PetscReal ax[3], PetscReal aR[3])
{
  PetscErrorCode (*fields[5])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {FieldE1, FieldE2, FieldJx, RollerPosition, FieldRx};
  DM      dm;
  PetscDS ds;
  Mat     M;
  Vec     f[5], Mf[5], loc;

  PetscFunctionBeginUser;
  PetscCall(RollerUnconstrainedDMCreate(ctx, &dm));
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(PetscDSSetJacobian(ds, 0, 0, g0_mass, NULL, NULL, NULL));
  PetscCall(DMCreateMatrix(dm, &M));
  PetscCall(DMGetLocalVector(dm, &loc));
  PetscCall(VecZeroEntries(loc));
  PetscCall(DMPlexSNESComputeJacobianFEM(dm, loc, M, M, NULL));
  PetscCall(DMRestoreLocalVector(dm, &loc));
  for (PetscInt k = 0; k < 5; ++k) {
    PetscErrorCode (*one[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {fields[k]};

    PetscCall(DMCreateGlobalVector(dm, &f[k]));
    PetscCall(VecDuplicate(f[k], &Mf[k]));
    PetscCall(DMProjectFunction(dm, 0.0, one, NULL, INSERT_VALUES, f[k]));
    PetscCall(MatMult(M, f[k], Mf[k]));
  }
  for (PetscInt i = 0; i < 3; ++i) {
    PetscScalar d;

    for (PetscInt j = 0; j < 3; ++j) {
      PetscCall(VecDot(f[i], Mf[j], &d));
      T[3 * i + j] = PetscRealPart(d);
    }
    PetscCall(VecDot(f[i], Mf[3], &d));
    ax[i] = PetscRealPart(d);
    PetscCall(VecDot(f[i], Mf[4], &d));
    aR[i] = PetscRealPart(d);
  }
  for (PetscInt k = 0; k < 5; ++k) {
    PetscCall(VecDestroy(&f[k]));
    PetscCall(VecDestroy(&Mf[k]));
  }
  PetscCall(MatDestroy(&M));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

static PetscReal Dot(Vec a, Vec b)
{
  PetscScalar d = 0.0;

  PetscCallAbort(PETSC_COMM_SELF, VecDot(a, b, &d));
  return PetscRealPart(d);
}

/* The coupling of model/axle.h from the free space's M, K and loads L_r = (M r)_f of the rigid fields (the whole
   body's M applied to r, on the free rows): with a, b fields over the whole body,
     M_fG b_G = L_b - M b_f,   a_G^T (M b)_G = a . M b - a_f . L_b,   a_G^T M_GG b_G = a . M b - a_f . L_b - (M_fG a_G) . b_f,
   and, K annihilating the rigid fields, K_fG r_G = -K r_f and r_G^T K_GG r'_G = r_f . K r'_f. */
PetscErrorCode RollerAxleSetUp(Roller ctx)
{
  RollerHub         *hub;
  RollerHubCoupling *c;
  Vec                r[3], L[3], Mr;
  PetscReal          T[9], ax[3], aR[3];

  PetscFunctionBeginUser;
  if (!ctx->axle.on) PetscFunctionReturn(0);
  PetscCall(PetscNew(&hub));
  ctx->axle.hub = hub;
  c             = &hub->c;
  PetscCall(RollerRigidFields(ctx, r));
  PetscCall(RollerAssembleLoad(ctx, f0_translation_x, &L[0]));
  PetscCall(RollerAssembleLoad(ctx, f0_translation_y, &L[1]));
  PetscCall(VecDuplicate(ctx->ops.L_euler, &L[2]));
  PetscCall(VecAXPBY(L[2], -1.0, 0.0, ctx->ops.L_euler)); /* J x = -R(-pi/2) x */
  PetscCall(VecDuplicate(r[0], &Mr));
  for (PetscInt j = 0; j < 3; ++j) {
    PetscCall(VecDuplicate(r[0], &c->CM[j]));
    PetscCall(VecDuplicate(r[0], &c->CK[j]));
    PetscCall(VecDuplicate(r[0], &c->RCM[j]));
    PetscCall(MatMult(ctx->ops.M, r[j], Mr));
    PetscCall(VecWAXPY(c->CM[j], -1.0, Mr, L[j]));
    PetscCall(MatMult(ctx->ops.K, r[j], c->CK[j]));
    PetscCall(VecScale(c->CK[j], -1.0));
    PetscCall(RollerApplyRotate90(ctx, c->CM[j], c->RCM[j]));
  }
  PetscCall(VecDuplicate(r[0], &c->cx));
  PetscCall(MatMult(ctx->ops.M, ctx->ops.coordinates, Mr));
  PetscCall(VecWAXPY(c->cx, -1.0, Mr, ctx->ops.L_centrifugal));
  PetscCall(WholeBodyProducts(ctx, T, ax, aR));
  for (PetscInt i = 0; i < 3; ++i) {
    for (PetscInt j = 0; j < 3; ++j) {
      c->DM[3 * i + j] = T[3 * i + j] - Dot(r[i], L[j]) - Dot(c->CM[i], r[j]);
      PetscCall(MatMult(ctx->ops.K, r[j], Mr));
      c->DK[3 * i + j] = Dot(r[i], Mr);
    }
    c->lc[i] = ax[i] - Dot(r[i], ctx->ops.L_centrifugal);
    c->le[i] = aR[i] - Dot(r[i], ctx->ops.L_euler);
    c->dx[i] = c->lc[i] - Dot(c->CM[i], ctx->ops.coordinates);
  }
  for (PetscInt i = 0; i < 3; ++i) /* symmetric to the last bit */
    for (PetscInt j = 0; j < i; ++j) {
      c->DM[3 * i + j] = c->DM[3 * j + i] = 0.5 * (c->DM[3 * i + j] + c->DM[3 * j + i]);
      c->DK[3 * i + j] = c->DK[3 * j + i] = 0.5 * (c->DK[3 * i + j] + c->DK[3 * j + i]);
    }
  if (ctx->ops.Kd) { /* the Maxwell branches' deviatoric stiffness annihilates the rigid fields too */
    for (PetscInt j = 0; j < 3; ++j) {
      PetscCall(VecDuplicate(r[0], &c->CD[j]));
      PetscCall(MatMult(ctx->ops.Kd, r[j], c->CD[j]));
      PetscCall(VecScale(c->CD[j], -1.0));
    }
    for (PetscInt i = 0; i < 3; ++i)
      for (PetscInt j = 0; j < 3; ++j) c->DD[3 * i + j] = -Dot(r[i], c->CD[j]);
    for (PetscInt i = 0; i < 3; ++i)
      for (PetscInt j = 0; j < i; ++j) c->DD[3 * i + j] = c->DD[3 * j + i] = 0.5 * (c->DD[3 * i + j] + c->DD[3 * j + i]);
    for (PetscInt j = 0; j < 3; ++j) c->RF[j] = r[j]; /* kept: the branches' products r_f . K_d z_i */
  }
  c->mass    = T[0];
  c->inertia = T[8];
  if (ctx->axle.mass == 0) ctx->axle.mass = ctx->material.density * c->mass;
  if (ctx->axle.inertia == 0) ctx->axle.inertia = ctx->material.density * c->inertia;
  for (PetscInt j = 0; j < 3; ++j) {
    if (!c->RF[j]) PetscCall(VecDestroy(&r[j]));
    PetscCall(VecDestroy(&L[j]));
  }
  PetscCall(VecDestroy(&Mr));
  if (ctx->ts.view)
    PetscCall(PetscPrintf(ctx->comm, "roller: -axle: hub mass %g and polar inertia %g per unit width (the rubber's: %g, %g), vertical spring %g preloaded to -nip_force %g over %g, drive %g (damping %g): free torsion sqrt(k_d/(I + I_rubber)) = %g rad per unit time\n",
                          (double)ctx->axle.mass, (double)ctx->axle.inertia, (double)(ctx->material.density * c->mass), (double)(ctx->material.density * c->inertia), (double)ctx->axle.stiffness, (double)ctx->axle.nip_force, (double)ctx->axle.nip_ramp,
                          (double)ctx->axle.drive_stiffness, (double)ctx->axle.drive_damping, (double)PetscSqrtReal(ctx->axle.drive_stiffness / (ctx->axle.inertia + ctx->material.density * c->inertia))));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerAxleDestroy(Roller ctx)
{
  RollerHub *hub = ctx->axle.hub;

  PetscFunctionBeginUser;
  if (!hub) PetscFunctionReturn(0);
  for (PetscInt j = 0; j < 3; ++j) {
    PetscCall(VecDestroy(&hub->c.CM[j]));
    PetscCall(VecDestroy(&hub->c.CK[j]));
    PetscCall(VecDestroy(&hub->c.RCM[j]));
    PetscCall(VecDestroy(&hub->c.CD[j]));
    PetscCall(VecDestroy(&hub->c.RF[j]));
  }
  PetscCall(VecDestroy(&hub->c.cx));
  PetscCall(PetscFree(ctx->axle.hub));
  PetscFunctionReturn(0);
}
