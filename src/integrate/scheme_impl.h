/* Private to the scheme*.c files: the time scheme as a component (docs/model.md section 2.1), like the contact
   solvers: registered by name (-ts_scheme NAME, scheme.c), each one file that fills the ops of the object it is
   given. Every scheme Roller offers keeps the DMF's properties: each step (or stage) a convex QP on factored
   matrices, so contact stays the bound-constrained problem in rotated contact coordinates; an exact discrete
   energy identity without contact; unconditional stability for the stiff modes.
     scheme.c           the registry, the options block, the default (the scheme that meets -ts_phase_error at the
                        least cost), the step count and dt rule, -ts_view, the dispatch
     scheme_newmark.c   the three-level schemes: dmf (Newmark beta = 1/2, the paper's) and trapezoidal (beta = 1/4)
     scheme_maxwell.c   their generalized Maxwell branches (-rubber maxwell)
     scheme_stage.c     the one-step trapezoidal stage with the rotational terms split off (Strang)
     scheme_composed.c  its symmetric compositions: fourth order (Suzuki, Yoshida) */
#ifndef ROLLER_SCHEME_IMPL_H
#define ROLLER_SCHEME_IMPL_H

#include "integrate/integrate.h"

#define ROLLER_SCHEME_MAX_OPERATORS 4

/* A scheme's operations. setfromoptions (optional) reads its own options inside the scheme's options block;
   phase: the phase error per step of an undamped mode of angular frequency w, as a function of x = w dt
   (|W dt - x|, W the scheme's frequency), for the default dt and -ts_view; usable (optional): why the scheme cannot
   run this scene (a static string) or NULL; by_default (optional): why the default should not take it although its
   phase error would (an error the phase-error rule does not see), or NULL; setup builds the step matrices (after the operators M, K) and whatever
   the scheme keeps from the levels (and state.velocity, eta^0 for a one-step scheme); step advances
   (ctx->state.step, .time and the levels cur, prev, prev2 move up one; state.Mcur = M xi^k and state.velocity
   follow); energy: E^k of the newest level; balance: the terms of E^k - E^{k-1} of the last step (docs/model.md
   section 2), added to info; 
   level (NULL: (xi^k - xi^{k-1})/dt); kept: the addresses of the vectors the scheme keeps beyond the levels (the
   checkpoint's, so that a restart repeats the run to the last bit; addresses because a step swaps the vectors), at
   most ROLLER_SCHEME_KEPT. */
typedef struct {
  PetscErrorCode (*setfromoptions)(RollerScheme, Roller, PetscOptionItems *);
  PetscErrorCode (*phase)(RollerScheme, PetscReal, PetscReal *);
  PetscErrorCode (*usable)(RollerScheme, Roller, const char **);
  PetscErrorCode (*by_default)(RollerScheme, Roller, const char **); /* why the default should not take it (it may be named) */
  PetscErrorCode (*setup)(RollerScheme, Roller);
  PetscErrorCode (*step)(RollerScheme, Roller);
  PetscErrorCode (*energy)(RollerScheme, Roller, PetscReal *);
  PetscErrorCode (*balance)(RollerScheme, Roller, RollerStepInfo *);
  PetscErrorCode (*kept)(RollerScheme, Roller, PetscInt *, Vec *[], const char *[]); /* the fields' addresses: the levels swap */
  PetscErrorCode (*view)(RollerScheme, Roller, PetscViewer);
  PetscErrorCode (*destroy)(RollerScheme);
} RollerSchemeOps;

struct _n_RollerScheme {
  char              *name;
  RollerSchemeOps    ops[1];
  void              *data;
  PetscInt           stages; /* step solves per step: the cost model of the default choice */
  PetscInt           order;  /* the order of the phase error without contact */
  PetscInt           nop;    /* the step matrices */
  RollerStepOperator op[ROLLER_SCHEME_MAX_OPERATORS];
};

PETSC_INTERN PetscFunctionList RollerSchemeList;

/* scheme.c */
PETSC_INTERN PetscErrorCode RollerSchemeCreate(const char[], RollerScheme *);
PETSC_INTERN PetscErrorCode RollerSchemeDestroy(RollerScheme *);
PETSC_INTERN PetscErrorCode RollerSchemeAddOperator(RollerScheme, Roller, PetscReal, PetscReal, PetscReal, Mat, PetscReal, RollerStepOperator **); /* c_M, c_K, c_D, G, c_G */

/* scheme_stage.c: a stage of the one-step scheme. Its velocity v and M v (V, MV: the step's working copies, committed
   at the step's end), scratch, the loads at t0 and t1 (L0 at time tL0 is reused when the next stage starts there),
   and the energy terms it adds up over a step's stages (the contact's in contact). */
typedef struct {
  Vec            V, MV, dv, Delta, L0, L1;
  PetscReal      tL0;
  PetscReal      load_work, damping_dissipation, viscous_dissipation;
  RollerStepInfo contact;
} RollerStageWork;

PETSC_INTERN PetscErrorCode RollerStageWorkCreate(Roller, RollerStageWork *);
PETSC_INTERN PetscErrorCode RollerStageWorkDestroy(RollerStageWork *);
PETSC_INTERN PetscErrorCode RollerSchemeStage(Roller, RollerStageWork *, RollerStepOperator *, PetscReal, PetscReal, PetscReal, PetscReal, PetscBool, Vec, Vec, Vec, Vec, Vec, Vec); /* h, t0, t1, delta, refresh M v, x0, M x0, K x0 -> x1, M x1, K x1 */

/* scheme_hub.c: the hub's part of a three-level step (-axle, model/axle.h): after the body's right-hand side (op,
   beta, t_{k-1}, the Coriolis velocity's coefficients, rhs, load, scratch), after the solve (the new body level), after
   the levels moved up (the new cur); q's terms of the energy and the balance (beta) */
PETSC_INTERN PetscErrorCode RollerHubSetUp(Roller);

PETSC_INTERN PetscErrorCode RollerHubStepEnd(Roller, RollerStepOperator *, PetscReal, Vec);
PETSC_INTERN PetscErrorCode RollerHubShift(Roller, Vec);
PETSC_INTERN PetscErrorCode RollerHubEnergy(Roller, PetscReal, PetscReal *);
PETSC_INTERN PetscErrorCode RollerHubBalance(Roller, PetscReal, RollerStepInfo *);
/* scheme_maxwell.c: the Maxwell branches of the three-level schemes (-rubber maxwell; NULL without) */
typedef struct _n_RollerMaxwell *RollerMaxwell;
PETSC_INTERN PetscErrorCode      RollerMaxwellCreate(Roller, PetscReal, RollerMaxwell *);   /* beta */
PETSC_INTERN PetscReal           RollerMaxwellStiffness(RollerMaxwell);                     /* c_D of the step matrix (0 for NULL) */
PETSC_INTERN Vec                 RollerMaxwellKdCur(RollerMaxwell);                         /* K_d xi^k */
PETSC_INTERN PetscErrorCode      RollerMaxwellRightHandSide(RollerMaxwell, PetscBool, Vec); /* second difference?, b */
PETSC_INTERN PetscErrorCode      RollerMaxwellNewLevel(RollerMaxwell, Roller);
PETSC_INTERN PetscReal           RollerMaxwellDissipation(RollerMaxwell, Roller);
PETSC_INTERN PetscErrorCode      RollerMaxwellEnergyAdd(RollerMaxwell, Roller, PetscReal *);
PETSC_INTERN PetscErrorCode      RollerMaxwellKept(RollerMaxwell, PetscInt *, Vec *[], const char *[]);
PETSC_INTERN PetscErrorCode      RollerMaxwellDestroy(RollerMaxwell *);
PETSC_INTERN PetscErrorCode      RollerMaxwellHubRightHandSide(RollerMaxwell, Roller, Vec, PetscReal[3]); /* -axle: b, b_q */
PETSC_INTERN PetscErrorCode      RollerHubStepBegin(Roller, RollerStepOperator *, RollerMaxwell, PetscReal, PetscReal, const PetscReal[3], Vec, Vec, Vec);

/* The schemes' create functions, for RollerSchemesRegisterAll */
PETSC_INTERN PetscErrorCode RollerSchemeCreate_DMF(RollerScheme);
PETSC_INTERN PetscErrorCode RollerSchemeCreate_Trapezoidal(RollerScheme);
PETSC_INTERN PetscErrorCode RollerSchemeCreate_Composed(RollerScheme);

#endif
