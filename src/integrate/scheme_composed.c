/* -ts_scheme composed (docs/model.md section 2.1): a symmetric composition of a one-step trapezoidal stage, fourth
   order. The state is (xi, v) at t_k (state.cur, state.velocity). One stage of length h (h < 0 too) from t0 to t1:
     1. the Coriolis force's exact flow over [t0, t0 + h/2]: v <- rotation of every nodal v by 2 (theta(t0 + h/2) - theta(t0))
        (v' = 2 theta' R(-pi/2) v: it does no work and commutes with M);
     2. a kick of the rest of the rotational force over h/2: v += h/2 (theta'' R(-pi/2) xi + theta'^2 xi) at t0;
     3. the trapezoidal rule for rho M xi'' + delta (eta M + tau K) xi' + K xi = L(t) (+ the contact force at t1):
          xi1 - xi0 = h (v0 + v1)/2,
          rho M (v1 - v0) + delta (eta M + tau K)(xi1 - xi0) + h K (xi0 + xi1)/2 = h (L(t0) + L(t1))/2 + h E N lambda,
        i.e. the QP of A_h = (2 rho/h^2 + delta eta/h) M + (1/2 + delta tau/h) K, SPD for any sign of h when delta = 0,
          b = (2 rho/h^2 + delta eta/h) M xi0 + 2 rho/h M v0 + (delta tau/h - 1/2) K xi0 + (L(t0) + L(t1))/2,
        with lambda the contact force (L: the rigid loads of the rotation and the manufactured load); without the
        obstacle its unknown is the increment xi1 - xi0 (the same solution, without the round-off of 2 rho/h^2 M xi0);
     4. the kick at t1 and 5. the Coriolis flow over [t0 + h/2, t1] (steps 2, 1 mirrored).
   The stage is symmetric (its adjoint is itself), second order, and conserves E = rho/2 v . M v + 1/2 xi . K xi
   without loads, damping and contact exactly (the trapezoidal rule is a Cayley transform). Composed with fractions
   gamma_i of dt, sum gamma_i = 1, sum gamma_i^3 = 0 (a negative one among them), it is fourth order (Suzuki 1990,
   Yoshida 1990); each stage keeps A_h SPD (h^2 > 0), so every stage is a convex QP, and there are two distinct
   matrices. The damping acts only in the positive stages, weighted delta = 1/sum_{gamma_i > 0} gamma_i (total
   impulse right, dissipation >= 0 in every stage, second order in the damping terms). Energy balance per stage:
     E1 - E0 = (xi1 - xi0) . L + lambda . N^T (xi1 - xi0) - delta/h (xi1 - xi0) . (eta M + tau K)(xi1 - xi0) + kick work,
   each term computed on its own (load_work includes the kicks' work; the contact's, contact_energy.c, w = 1).
   Friction is not offered: Coulomb's dissipation cannot change sign in the negative stage, so a composition would
   not be consistent (docs/model.md section 2.1); the three-level schemes take it. */
#include "scheme_impl.h"
#include "model/model.h"

#define COMPOSED_MAX_STAGES 7

typedef enum { COMPOSITION_SUZUKI, COMPOSITION_YOSHIDA, COMPOSITION_NONE } CompositionType;
static const char *const CompositionTypes[] = {"suzuki", "yoshida", "none", "CompositionType", "COMPOSITION_", NULL};

typedef struct {
  CompositionType     type;
  PetscInt            n;
  PetscReal           gamma[COMPOSED_MAX_STAGES], delta;
  RollerStepOperator *op[COMPOSED_MAX_STAGES];
  Vec                 X[2], MX[2], KX[2]; /* the stages' new levels and their products (alternating) */
  Vec                 Mv;                 /* M v of the newest level (kept) */
  RollerStageWork     w;                  /* what the stages share (scheme_stage.c) */
} Composed;

/* The fractions: Suzuki's five (p, p, 1 - 4p, p, p), p = 1/(4 - 4^(1/3)): its fifth-order phase term sum gamma^5/80 is
   70 times Yoshida's; Yoshida's triple jump (a, 1 - 2a, a), a = 1/(2 - 2^(1/3)); none: the stage alone (second order). */
static void Fractions(Composed *cp)
{
  if (cp->type == COMPOSITION_SUZUKI) {
    const PetscReal p = 1.0 / (4.0 - PetscCbrtReal(4.0));

    cp->n        = 5;
    cp->gamma[0] = cp->gamma[1] = cp->gamma[3] = cp->gamma[4] = p;
    cp->gamma[2]                                              = 1.0 - 4.0 * p;
  } else if (cp->type == COMPOSITION_YOSHIDA) {
    const PetscReal a = 1.0 / (2.0 - PetscCbrtReal(2.0));

    cp->n        = 3;
    cp->gamma[0] = cp->gamma[2] = a;
    cp->gamma[1]                = 1.0 - 2.0 * a;
  } else {
    cp->n        = 1;
    cp->gamma[0] = 1.0;
  }
  cp->delta = 0.0;
  for (PetscInt i = 0; i < cp->n; ++i)
    if (cp->gamma[i] > 0) cp->delta += cp->gamma[i];
  cp->delta = 1.0 / cp->delta;
}

static PetscErrorCode ComposedSetFromOptions(RollerScheme s, Roller ctx, PetscOptionItems *PetscOptionsObject)
{
  Composed *cp = (Composed *)s->data;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsEnum("-ts_composition", "-ts_scheme composed: suzuki (5 stages, fourth order), yoshida (3 stages, fourth order, 70 times Suzuki's error), none (the trapezoidal stage alone, second order)", NULL, CompositionTypes, (PetscEnum)cp->type,
                             (PetscEnum *)&cp->type, NULL));
  Fractions(cp);
  s->stages = cp->n;
  s->order  = cp->n > 1 ? 4 : 2;
  PetscFunctionReturn(0);
}

/* One step from t_k to t_{k+1}: the stages, then the levels move up (cur = xi^{k+1}; prev, prev2 the last two). */
static PetscErrorCode ComposedStep(RollerScheme s, Roller ctx)
{
  Composed       *cp = (Composed *)s->data;
  const PetscReal dt = ctx->ts.dt, t_start = ctx->state.step * dt, t_end = (ctx->state.step + 1) * dt;
  Vec             x0 = ctx->state.cur, Mx0 = ctx->state.Mcur, Kx0 = ctx->state.Kcur, tmp;
  PetscReal       frac = 0.0, norm;
  PetscInt        j    = 0;

  PetscFunctionBeginUser;
  cp->w.load_work = cp->w.damping_dissipation = cp->w.viscous_dissipation = 0.0;
  PetscCall(PetscMemzero(&cp->w.contact, sizeof(cp->w.contact)));
  PetscCall(VecCopy(ctx->state.velocity, cp->w.V));
  PetscCall(VecCopy(cp->Mv, cp->w.MV));
  for (PetscInt i = 0; i < cp->n; ++i) {
    const PetscReal t0 = t_start + frac * dt, t1 = (i == cp->n - 1) ? t_end : t_start + (frac + cp->gamma[i]) * dt;

    j = i % 2;
    PetscCall(RollerSchemeStage(ctx, &cp->w, cp->op[i], cp->gamma[i] * dt, t0, t1, cp->gamma[i] > 0 ? cp->delta : 0.0, (PetscBool)(i == 0), x0, Mx0, Kx0, cp->X[j], cp->MX[j], cp->KX[j]));
    x0  = cp->X[j];
    Mx0 = cp->MX[j];
    Kx0 = cp->KX[j];
    frac += cp->gamma[i];
  }
  PetscCall(VecNorm(x0, NORM_INFINITY, &norm));
  PetscCheck(!PetscIsInfOrNanReal(norm), ctx->comm, PETSC_ERR_FP, "The solution is not finite at step %" PetscInt_FMT ", t = %g; the last good state (step %" PetscInt_FMT ") is in the checkpoint %s", ctx->state.step + 1, (double)t_end, ctx->state.step,
             ctx->ck.file);
  /* the levels move up: the last stage's vectors become the newest level's */
  tmp                 = ctx->state.prev2;
  ctx->state.prev2    = ctx->state.prev;
  ctx->state.prev     = ctx->state.cur;
  ctx->state.cur      = cp->X[j];
  cp->X[j]            = tmp;
  tmp                 = ctx->state.Kprev2;
  ctx->state.Kprev2   = ctx->state.Kprev;
  ctx->state.Kprev    = ctx->state.Kcur;
  ctx->state.Kcur     = cp->KX[j];
  cp->KX[j]           = tmp;
  tmp                 = ctx->state.Mcur;
  ctx->state.Mcur     = cp->MX[j];
  cp->MX[j]           = tmp;
  tmp                 = ctx->state.velocity;
  ctx->state.velocity = cp->w.V;
  cp->w.V             = tmp;
  tmp                 = cp->Mv;
  cp->Mv              = cp->w.MV;
  cp->w.MV            = tmp;
  ctx->state.step++;
  ctx->state.time = ctx->state.step * dt;
  PetscFunctionReturn(0);
}

/* E = rho/2 v . M v + 1/2 xi . K xi */
static PetscErrorCode ComposedEnergy(RollerScheme s, Roller ctx, PetscReal *energy)
{
  Composed   *cp = (Composed *)s->data;
  PetscScalar kin, pot;

  PetscFunctionBeginUser;
  PetscCall(VecDot(ctx->state.velocity, cp->Mv, &kin));
  PetscCall(VecDot(ctx->state.cur, ctx->state.Kcur, &pot));
  *energy = 0.5 * ctx->material.density * PetscRealPart(kin) + 0.5 * PetscRealPart(pot);
  PetscFunctionReturn(0);
}

/* The step's terms, summed over its stages in ComposedStep. */
static PetscErrorCode ComposedBalance(RollerScheme s, Roller ctx, RollerStepInfo *info)
{
  Composed *cp = (Composed *)s->data;

  PetscFunctionBeginUser;
  if (ctx->state.step == 0) PetscFunctionReturn(0);
  info->load_work += cp->w.load_work;
  info->damping_dissipation += cp->w.damping_dissipation;
  info->viscous_dissipation += cp->w.viscous_dissipation;
  info->obstacle_work += cp->w.contact.obstacle_work;
  info->contact_dissipation += cp->w.contact.contact_dissipation;
  info->friction.shaft_step += cp->w.contact.friction.shaft_step;
  info->friction.sheet_step += cp->w.contact.friction.sheet_step;
  PetscFunctionReturn(0);
}

/* A matrix per distinct stage (h^2 and the damping weight): Suzuki's and Yoshida's have two. */
static PetscErrorCode ComposedSetUp(RollerScheme s, Roller ctx)
{
  Composed       *cp  = (Composed *)s->data;
  const PetscReal rho = ctx->material.density, dt = ctx->ts.dt;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < cp->n; ++i) {
    const PetscReal h = cp->gamma[i] * dt, delta = cp->gamma[i] > 0 ? cp->delta : 0.0;

    cp->op[i] = NULL;
    for (PetscInt k = 0; k < i; ++k)
      if (cp->gamma[k] == cp->gamma[i]) cp->op[i] = cp->op[k];
    if (!cp->op[i]) PetscCall(RollerSchemeAddOperator(s, ctx, 2.0 * rho / (h * h) + delta * ctx->disc.damping / h, 0.5 + delta * ctx->material.viscosity / h, 0.0, NULL, 0.0, &cp->op[i]));
  }
  for (PetscInt j = 0; j < 2; ++j) {
    PetscCall(VecDuplicate(ctx->state.cur, &cp->X[j]));
    PetscCall(VecDuplicate(ctx->state.cur, &cp->MX[j]));
    PetscCall(VecDuplicate(ctx->state.cur, &cp->KX[j]));
  }
  PetscCall(VecDuplicate(ctx->state.cur, &cp->Mv));
  PetscCall(RollerStageWorkCreate(ctx, &cp->w));
  PetscCall(MatMult(ctx->ops.M, ctx->state.cur, ctx->state.Mcur));
  PetscCall(MatMult(ctx->ops.M, ctx->state.velocity, cp->Mv));
  PetscFunctionReturn(0);
}

static PetscErrorCode ComposedKept(RollerScheme s, Roller ctx, PetscInt *n, Vec *v[], const char *names[])
{
  Composed *cp = (Composed *)s->data;

  PetscFunctionBeginUser;
  *n       = 3;
  v[0]     = &ctx->state.velocity;
  v[1]     = &ctx->state.Mcur;
  v[2]     = &cp->Mv;
  names[0] = "v_k";
  names[1] = "M_xi_k";
  names[2] = "M_v_k";
  PetscFunctionReturn(0);
}

/* The phase of an undamped mode over a step: the stages' trapezoidal phases 2 atan(gamma_i x/2) add up (for a linear
   time-invariant system the stages commute), against x = w dt. */
static PetscErrorCode ComposedPhase(RollerScheme s, PetscReal x, PetscReal *e)
{
  Composed *cp = (Composed *)s->data;
  PetscReal W  = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < cp->n; ++i) W += 2.0 * PetscAtanReal(0.5 * cp->gamma[i] * x);
  *e = PetscAbsReal(W - x);
  PetscFunctionReturn(0);
}

static PetscErrorCode ComposedUsable(RollerScheme s, Roller ctx, const char **why)
{
  PetscBool coriolis;

  PetscFunctionBeginUser;
  *why = NULL;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-coriolis_velocity", &coriolis));
  if (ctx->obstacle.friction > 0) *why = "Coulomb friction cannot change sign in a composition's negative stage (a three-level scheme takes it)";
  else if (ctx->disc.static_solve) *why = "-static is the DMF's one step with A = K";
  else if (ctx->axle.on) *why = "the hub's unknowns (-axle) are the three-level schemes'";
  else if (coriolis) *why = "-coriolis_velocity is the three-level schemes' (this one splits the Coriolis force off exactly)";
  else if (ctx->material.rubber == ROLLER_RUBBER_MAXWELL) *why = "-rubber maxwell's branches are the three-level schemes' (dmf, trapezoidal)";
  PetscFunctionReturn(0);
}

/* With the obstacle the contact's error, not the modes' phase, sets the cost: impacts (every node that enters the
   patch) make the composition first order, and on the rolling scene its mean contact force converges only to 0.11 %
   of the reference while the trapezoidal rule is within 0.006 % at a third of its cost (bench/rolling_schemes.py,
   docs/model.md section 2.1). It stays available by name. */
static PetscErrorCode ComposedByDefault(RollerScheme s, Roller ctx, const char **why)
{
  PetscFunctionBeginUser;
  *why = ctx->obstacle.on ? "with the obstacle, contact makes the composition first order (docs/model.md section 2.1)" : NULL;
  PetscFunctionReturn(0);
}

static PetscErrorCode ComposedView(RollerScheme s, Roller ctx, PetscViewer viewer)
{
  Composed *cp = (Composed *)s->data;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, ", -ts_composition %s:", CompositionTypes[cp->type]));
  for (PetscInt i = 0; i < cp->n; ++i) PetscCall(PetscViewerASCIIPrintf(viewer, " %.6g", (double)cp->gamma[i]));
  PetscCall(PetscViewerASCIIPrintf(viewer, " dt; the Coriolis force split off exactly"));
  PetscFunctionReturn(0);
}

static PetscErrorCode ComposedDestroy(RollerScheme s)
{
  Composed *cp = (Composed *)s->data;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < 2; ++j) {
    PetscCall(VecDestroy(&cp->X[j]));
    PetscCall(VecDestroy(&cp->MX[j]));
    PetscCall(VecDestroy(&cp->KX[j]));
  }
  PetscCall(VecDestroy(&cp->Mv));
  PetscCall(RollerStageWorkDestroy(&cp->w));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSchemeCreate_Composed(RollerScheme s)
{
  Composed *cp;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&cp));
  cp->type = COMPOSITION_SUZUKI;
  Fractions(cp);
  s->data                = cp;
  s->stages              = cp->n;
  s->order               = 4;
  s->ops->setfromoptions = ComposedSetFromOptions;
  s->ops->phase          = ComposedPhase;
  s->ops->usable         = ComposedUsable;
  s->ops->by_default     = ComposedByDefault;
  s->ops->setup          = ComposedSetUp;
  s->ops->step           = ComposedStep;
  s->ops->energy         = ComposedEnergy;
  s->ops->balance        = ComposedBalance;
  s->ops->kept           = ComposedKept;
  s->ops->view           = ComposedView;
  s->ops->destroy        = ComposedDestroy;
  PetscFunctionReturn(0);
}
