/* The time scheme as a component (docs/model.md section 2.1): the registry (-ts_scheme NAME, like the contact
   solvers'), the options block, the default and its dt, -ts_view, and the dispatch of a run's steps.

   The default: every usable scheme gets the dt that keeps the time error of R below -ts_phase_error P/2 at the end
   time T, the phase errors (T/dt) phase(w dt) of the radial modes R carries weighted by their amplitudes
   (docs/model.md section 6.2), and the run takes the one whose steps cost the fewest solves, stages x T/dt. A scheme is usable if it honours every option given:
   the one-step schemes split the Coriolis force off exactly (no -coriolis_velocity) and cannot take friction
   (docs/model.md section 2.1), -static is the DMF's. */
#include "scheme_impl.h"
#include "model/model.h"

PetscFunctionList RollerSchemeList  = NULL;
static PetscBool  RegisterAllCalled = PETSC_FALSE;

static PetscErrorCode SchemesFinalize(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&RollerSchemeList));
  RegisterAllCalled = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* The built-in schemes, in the order of -help and of the cost comparison of -ts_view. */
PetscErrorCode RollerSchemesRegisterAll(void)
{
  PetscFunctionBeginUser;
  if (RegisterAllCalled) PetscFunctionReturn(0);
  RegisterAllCalled = PETSC_TRUE;
  PetscCall(PetscRegisterFinalize(SchemesFinalize));
  PetscCall(RollerSchemeRegister("dmf", RollerSchemeCreate_DMF));
  PetscCall(RollerSchemeRegister("trapezoidal", RollerSchemeCreate_Trapezoidal));
  PetscCall(RollerSchemeRegister("composed", RollerSchemeCreate_Composed));
  PetscFunctionReturn(0);
}

/* Adds (or replaces) a scheme under name; the built-in ones are registered first. */
PetscErrorCode RollerSchemeRegister(const char name[], PetscErrorCode (*create)(RollerScheme))
{
  PetscFunctionBeginUser;
  PetscCall(RollerSchemesRegisterAll());
  PetscCall(PetscFunctionListAdd(&RollerSchemeList, name, create));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSchemeCreate(const char name[], RollerScheme *scheme)
{
  PetscErrorCode (*create)(RollerScheme) = NULL;
  RollerScheme s;

  PetscFunctionBeginUser;
  PetscCall(RollerSchemesRegisterAll());
  PetscCall(PetscFunctionListFind(RollerSchemeList, name, &create));
  PetscCheck(create, PETSC_COMM_SELF, PETSC_ERR_ARG_UNKNOWN_TYPE, "Unknown time scheme %s (registered: see -help, -ts_scheme)", name);
  PetscCall(PetscNew(&s));
  PetscCall(PetscStrallocpy(name, &s->name));
  s->stages = 1;
  s->order  = 2;
  PetscCall((*create)(s));
  PetscCheck(s->ops->step && s->ops->phase && s->ops->energy && s->ops->balance, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Time scheme %s lacks an operation", name);
  *scheme = s;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSchemeDestroy(RollerScheme *scheme)
{
  RollerScheme s = *scheme;

  PetscFunctionBeginUser;
  if (!s) PetscFunctionReturn(0);
  if (s->ops->destroy) PetscCall((*s->ops->destroy)(s));
  for (PetscInt k = 0; k < s->nop; ++k) PetscCall(RollerStepOperatorDestroy(&s->op[k]));
  PetscCall(PetscFree(s->data));
  PetscCall(PetscFree(s->name));
  PetscCall(PetscFree(s));
  *scheme = NULL;
  PetscFunctionReturn(0);
}

/* A step matrix c_M M + c_K K + c_D K_d (- c_G G) of the scheme, factored, and made known to the contact solver. */
PetscErrorCode RollerSchemeAddOperator(RollerScheme s, Roller ctx, PetscReal c_M, PetscReal c_K, PetscReal c_D, Mat G, PetscReal c_G, RollerStepOperator **op)
{
  PetscFunctionBeginUser;
  PetscCheck(s->nop < ROLLER_SCHEME_MAX_OPERATORS, ctx->comm, PETSC_ERR_SUP, "Time scheme %s: at most %d step matrices", s->name, ROLLER_SCHEME_MAX_OPERATORS);
  PetscCall(RollerStepOperatorCreate(ctx, c_M, c_K, c_D, G, c_G, s->nop, &s->op[s->nop]));
  if (ctx->axle.on) PetscCall(RollerStepOperatorSetBorder(ctx, &s->op[s->nop])); /* the hub eliminated (model/axle.h) */
  if (ctx->contact) PetscCall(RollerContactPrepare(ctx, ctx->contact, &s->op[s->nop]));
  *op = &s->op[s->nop++];
  PetscFunctionReturn(0);
}

/* Every registered scheme is created (cheap) so that the one block lists all their options; the run's is chosen
   at set-up (RollerSchemeChoose), when the mesh's radii are known. */
PetscErrorCode RollerSchemeSetFromOptions(Roller ctx)
{
  const char **names;
  int          n;

  PetscFunctionBeginUser;
  PetscCall(RollerSchemesRegisterAll());
  PetscCall(PetscFunctionListGet(RollerSchemeList, &names, &n));
  PetscCall(PetscCalloc1(n, &ctx->ts.schemes));
  for (ctx->ts.nschemes = 0; names[ctx->ts.nschemes]; ++ctx->ts.nschemes) PetscCall(RollerSchemeCreate(names[ctx->ts.nschemes], &ctx->ts.schemes[ctx->ts.nschemes])); /* n counts the NULL that ends names */
  PetscCall(PetscFree(names));
  PetscOptionsBegin(ctx->comm, NULL, "Roller: time scheme (docs/model.md section 2.1)", NULL);
  PetscCall(PetscOptionsFList("-ts_scheme", "Time scheme: dmf (the paper's, Newmark beta = 1/2), trapezoidal (beta = 1/4), composed (fourth order, Suzuki's composition of the trapezoidal step); default: the one that meets -ts_phase_error with the fewest solves (-ts_view)", "RollerSchemeRegister", RollerSchemeList,
                              ctx->ts.scheme, ctx->ts.scheme, sizeof(ctx->ts.scheme), NULL));
  for (PetscInt k = 0; k < ctx->ts.nschemes; ++k)
    if (ctx->ts.schemes[k]->ops->setfromoptions) PetscCall((*ctx->ts.schemes[k]->ops->setfromoptions)(ctx->ts.schemes[k], ctx, PetscOptionsObject));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

#define SCHEME_MODES 30

/* The radial modes R carries (RollerRadialModes: w_j, amplitudes a_j summing to 1) and, with -theta_b, the forcing;
   the time over which each one's phase error grows: T, or, damped, the time its error a_j e^(-zeta_j w_j t) phi_j(t)
   peaks at, 1/(zeta_j w_j) (its value there is that at t = 1/(e zeta_j w_j) without the decay), zeta_j = tau w_j/2 +
   eta/(2 rho w_j) the modal damping ratio of -viscosity and -damping. */
typedef struct {
  PetscInt  n;
  PetscReal w[SCHEME_MODES + 1], a[SCHEME_MODES + 1], T[SCHEME_MODES + 1];
} Modes;

/* The time error of R that a step dt makes, relative to its swing (R goes from 0 to twice its static value): every
   mode's phase error (T_j/dt) phase(w_j dt), at most 2 (a mode out of phase), weighted by its amplitude, the modes'
   errors summed in quadrature (they peak at different times): E_R = sqrt(sum_j (a_j min(2, phi_j))^2)/2. For the DMF
   at the paper's scene it is 1.24 times the first mode's phi_1/2, the former rule (docs/model.md section 6.2). */
static PetscErrorCode ErrorR(RollerScheme s, const Modes *md, PetscReal dt, PetscReal *err)
{
  PetscReal sum = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < md->n; ++j) {
    PetscReal e;

    PetscCall((*s->ops->phase)(s, md->w[j] * dt, &e));
    sum += PetscSqr(md->a[j] * PetscMin(2.0, md->T[j] / dt * e));
  }
  *err = 0.5 * PetscSqrtReal(sum);
  PetscFunctionReturn(0);
}

/* The dt whose time error of R by T is P/2 (half of the target: the other half is R's spatial error): E_R grows
   from 0 with dt, so the first crossing is bracketed by a geometric scan and bisected. */
static PetscErrorCode SchemeTimeStep(RollerScheme s, const Modes *md, PetscReal P, PetscReal *dt)
{
  PetscReal lo = 0.0, hi = 1e-5 / md->w[0], e;

  PetscFunctionBeginUser;
  for (;;) {
    PetscCall(ErrorR(s, md, hi, &e));
    if (e > 0.5 * P || hi * md->w[0] > 2 * PETSC_PI) break;
    lo = hi;
    hi *= 1.05;
  }
  for (PetscInt it = 0; it < 200 && hi - lo > 1e-14 * hi; ++it) {
    const PetscReal mid = 0.5 * (lo + hi);

    PetscCall(ErrorR(s, md, mid, &e));
    if (e > 0.5 * P) hi = mid;
    else lo = mid;
  }
  *dt = lo;
  PetscFunctionReturn(0);
}

/* Why the scheme cannot run this scene (NULL: it can). */
static PetscErrorCode SchemeUsable(RollerScheme s, Roller ctx, const char **why)
{
  PetscFunctionBeginUser;
  *why = NULL;
  if (s->ops->usable) PetscCall((*s->ops->usable)(s, ctx, why));
  PetscFunctionReturn(0);
}

/* The run's scheme (-ts_scheme, or the cheapest usable one) and, unless -ts_dt is given, its dt; -ts_view says
   which and why. Called after the mesh is read, so that the radii of a mesh file count. */
PetscErrorCode RollerSchemeChoose(Roller ctx)
{
  PetscReal w_b, w_t, w, T, dt[16], cost[16], e;
  PetscInt  best = -1;
  Modes     md;

  PetscFunctionBeginUser;
  PetscCall(RollerModeFrequencies(ctx, &w_b, &w_t));
  PetscCall(RollerRadialModes(ctx, SCHEME_MODES, md.w, md.a, &md.n));
  if (ctx->rotation.b > 0) { /* the forcing of theta, as strong as the first mode */
    md.w[md.n] = ctx->rotation.b;
    md.a[md.n] = 1.0;
    md.n++;
  }
  w = PetscMax(w_b, ctx->rotation.b);
  T = RollerEndTime(ctx, w);
  for (PetscInt j = 0; j < md.n; ++j) {
    const PetscReal zeta = 0.5 * ctx->material.viscosity * md.w[j] + 0.5 * ctx->disc.damping / (ctx->material.density * md.w[j]);

    md.T[j] = zeta > 0 ? PetscMin(T, 1.0 / (PetscExpReal(1.0) * zeta * md.w[j])) : T;
  }
  PetscCheck(ctx->ts.nschemes <= 16, ctx->comm, PETSC_ERR_SUP, "At most 16 registered time schemes");
  for (PetscInt k = 0; k < ctx->ts.nschemes; ++k) {
    RollerScheme s = ctx->ts.schemes[k];
    const char  *why;
    PetscBool    named;

    PetscCall(SchemeTimeStep(s, &md, ctx->ts.phase_error, &dt[k]));
    cost[k] = s->stages * PetscCeilReal(T / dt[k] - 1e-9); /* at the target, also when -ts_dt is given */
    PetscCall(SchemeUsable(s, ctx, &why));
    PetscCall(PetscStrcmp(s->name, ctx->ts.scheme, &named));
    if (named) {
      PetscCheck(!why, ctx->comm, PETSC_ERR_ARG_INCOMP, "-ts_scheme %s: %s", s->name, why);
      best = k;
      continue; /* the others' dt and cost still computed: -ts_view lists them */
    }
    if (!why && s->ops->by_default) PetscCall((*s->ops->by_default)(s, ctx, &why));
    if (!ctx->ts.scheme[0] && !why && (best < 0 || cost[k] < cost[best])) best = k;
  }
  PetscCheck(best >= 0, ctx->comm, PETSC_ERR_ARG_WRONG, "-ts_scheme %s: no such scheme (see -help)", ctx->ts.scheme);
  ctx->scheme = ctx->ts.schemes[best];
  if (!ctx->ts.dt_set) { /* a whole number of steps to -ts_max_time, none longer than the rule's */
    const PetscReal n = PetscCeilReal(ctx->ts.max_time / dt[best] - 1e-9);

    ctx->ts.dt = n >= 1 ? ctx->ts.max_time / n : dt[best];
  }
  PetscCall(ErrorR(ctx->scheme, &md, ctx->ts.dt, &e));
  PetscCall(PetscInfo(NULL, "-ts_scheme %s, -ts_dt %g: time error of R by T = %g estimated %g, target %g/2\n", ctx->scheme->name, (double)ctx->ts.dt, (double)T, (double)e, (double)ctx->ts.phase_error));
  if (ctx->ts.view) {
    PetscCall(PetscPrintf(ctx->comm, "roller: P%" PetscInt_FMT "%s, %s -mesh_h %g, -ts_scheme %s (%s; order %" PetscInt_FMT ", %" PetscInt_FMT " solve%s a step), -ts_dt %g (%s)", ctx->disc.degree, ctx->mesh.curved ? " curved" : "",
                          ctx->mesh.file[0] ? "mesh file, not" : (ctx->mesh.h_set ? (ctx->mesh.h_restart ? "from the checkpoint" : "given") : "from -ts_phase_error:"), (double)ctx->mesh.h, ctx->scheme->name,
                          ctx->ts.scheme_restart ? "from the checkpoint" : (ctx->ts.scheme[0] ? "given" : "the fewest solves"), ctx->scheme->order, ctx->scheme->stages, ctx->scheme->stages > 1 ? "s" : "", (double)ctx->ts.dt,
                          ctx->ts.dt_restart ? "from the checkpoint" : (ctx->ts.dt_set ? "given" : "from -ts_phase_error")));
    if (ctx->scheme->ops->view) PetscCall((*ctx->scheme->ops->view)(ctx->scheme, ctx, PETSC_VIEWER_STDOUT_(ctx->comm)));
    PetscCall(PetscPrintf(ctx->comm, "\nroller: radial modes carrying R%s: w = %g (%.3f of R), %g (%.3f), %g (%.3f), ...; torsional mode w_t = %g (period %g); end time %g; R's time error, the modes' phase errors (T/dt) phase(w dt) weighted: %.3g (target -ts_phase_error/2 = %g)\n",
                          ctx->material.rubber == ROLLER_RUBBER_MAXWELL ? " (the instantaneous moduli' modes: the fastest the rubber's reach)" : "", (double)md.w[0], (double)md.a[0], (double)md.w[1], (double)md.a[1], (double)md.w[2], (double)md.a[2], (double)w_t, (double)(2 * PETSC_PI / w_t), (double)T, (double)e,
                          (double)(0.5 * ctx->ts.phase_error)));
    {
      const PetscReal   wm[2]   = {w_t, w_b};
      const char *const what[2] = {"the (instantaneous) torsional mode", "the (instantaneous) breathing mode"};

      PetscCall(RollerRubberView(ctx, 2, wm, what));
    }
    PetscCall(PetscPrintf(ctx->comm, "roller: solves to reach t = %g at the target:", (double)T));
    for (PetscInt k = 0; k < ctx->ts.nschemes; ++k) {
      const char *why;

      PetscCall(SchemeUsable(ctx->ts.schemes[k], ctx, &why));
      if (why) PetscCall(PetscPrintf(ctx->comm, " %s %.0f (dt %.3g): not usable, %s", ctx->ts.schemes[k]->name, (double)cost[k], (double)dt[k], why));
      else {
        if (ctx->ts.schemes[k]->ops->by_default) PetscCall((*ctx->ts.schemes[k]->ops->by_default)(ctx->ts.schemes[k], ctx, &why));
        PetscCall(PetscPrintf(ctx->comm, " %s %.0f (dt %.3g)%s%s", ctx->ts.schemes[k]->name, (double)cost[k], (double)dt[k], why ? ": not the default, " : "", why ? why : ""));
      }
      if (k + 1 < ctx->ts.nschemes) PetscCall(PetscPrintf(ctx->comm, ";"));
    }
    PetscCall(PetscPrintf(ctx->comm, "\n"));
    if (ctx->mesh.h_contact > 0) {
      const PetscReal v = PetscAbsReal(ctx->rotation.omega) * ctx->mesh.r_outer; /* speed of Gamma_C past the obstacle */

      PetscCall(PetscPrintf(ctx->comm, "roller: mesh graded toward Gamma_C: -mesh_h_contact %g within -mesh_contact_layer %g, -mesh_h %g in the bulk; dt is set by the bulk modes above, not by h_c", (double)ctx->mesh.h_contact, (double)ctx->mesh.contact_layer,
                            (double)ctx->mesh.h));
      if (v > 0) PetscCall(PetscPrintf(ctx->comm, "; element passing f_e = omega r_C / h_c = %g (period %g = %.1f steps)", (double)(v / ctx->mesh.h_contact), (double)(ctx->mesh.h_contact / v), (double)(ctx->mesh.h_contact / (v * ctx->ts.dt))));
      PetscCall(PetscPrintf(ctx->comm, "\n"));
    }
  }
  /* the schemes the run does not take */
  for (PetscInt k = 0; k < ctx->ts.nschemes; ++k)
    if (k != best) PetscCall(RollerSchemeDestroy(&ctx->ts.schemes[k]));
  PetscFunctionReturn(0);
}

/* The chosen scheme's step matrices (after M and K) and its start. */
/* The scheme's step matrices and what it keeps (RollerSchemeKept: the checkpoint registers them). */
PetscErrorCode RollerSchemeSetUp(Roller ctx)
{
  PetscFunctionBeginUser;
  if (ctx->scheme->ops->setup) PetscCall((*ctx->scheme->ops->setup)(ctx->scheme, ctx));
  PetscFunctionReturn(0);
}

/* The addresses of the vectors the scheme keeps beyond the levels (at most ROLLER_SCHEME_KEPT) and their names. */
PetscErrorCode RollerSchemeKept(Roller ctx, PetscInt *n, Vec *kept[], const char *names[])
{
  PetscFunctionBeginUser;
  *n = 0;
  if (ctx->scheme->ops->kept) PetscCall((*ctx->scheme->ops->kept)(ctx->scheme, ctx, n, kept, names));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSchemeStep(Roller ctx)
{
  PetscFunctionBeginUser;
  PetscCall((*ctx->scheme->ops->step)(ctx->scheme, ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSchemeEnergy(Roller ctx, PetscReal *energy)
{
  PetscFunctionBeginUser;
  PetscCall((*ctx->scheme->ops->energy)(ctx->scheme, ctx, energy));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSchemeBalance(Roller ctx, RollerStepInfo *info)
{
  PetscFunctionBeginUser;
  PetscCall((*ctx->scheme->ops->balance)(ctx->scheme, ctx, info));
  PetscFunctionReturn(0);
}

const char *RollerSchemeName(Roller ctx)
{
  return ctx->scheme ? ctx->scheme->name : "";
}

PetscErrorCode RollerSchemesDestroy(Roller ctx)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < ctx->ts.nschemes; ++k) PetscCall(RollerSchemeDestroy(&ctx->ts.schemes[k]));
  PetscCall(PetscFree(ctx->ts.schemes));
  ctx->ts.nschemes = 0;
  ctx->scheme      = NULL;
  PetscFunctionReturn(0);
}
