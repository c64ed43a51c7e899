/* Private to the contact*.c files: the obstacle QP of docs/model.md section 2 and its solvers.

     min 1/2 xi^T A xi - b^T xi   s.t.  (x_n + xi_n) . n^k >= g^k  at every Lagrange node x_n of Gamma_C

   No circle of calls between these files (tests/architecture.py).
   The core (no file of it names a solver):
   contact.c             create, options, destroy; the dispatch of a step
   contact_report.c      KKT residual, -contact_check, -contact_monitor, the CSV's contact columns
   contact_pressure.c    the contact pressure and friction traction output fields
   contact_energy.c      the contact terms of the energy balance, flips and reversals
   contact_candidates.c  the step's basis and bounds, the candidate set, the penetrating nodes it gains
   contact_nodes.c       the Gamma_C nodes (gathered redundantly on every rank, in angle order), gaps, force
   contact_reduced.c     -rom: the basis' Gamma_C rows Phi, the window's gathers Phi q, the force Phi^T f, S's columns
   contact_residual.c    -rom_residual: MacNeal's residual flexibility R, S + R, each level's residual R f_C, its energy
   contact_residual_levels.c  the residual in the fields, functionals and -rom_output file; the initial levels' remainder
   contact_residual_branches.c  the residual of the Maxwell rubber: its branches as standard linear solids
                         (their types and functions: contact_reduced.h)
   Friction (only with -friction > 0; docs/friction.md), a part of the condensed solver; the law mu(v) and Coulomb's
   law on dense data by the semismooth Newton method are the friction layer's (friction/law.c, friction/coulomb.c),
   which calls nothing here. Contact calls the friction files (create, solve, info, state); they call back none of
   contact.c, contact_report.c, contact_condensed.c: only the dense solvers (contact_boxqp.c, contact_lcp.c,
   contact_lemke.c, contact_anderson.c), the friction layer and the nodes' gather (contact_nodes.c):
   contact_friction.c    the slips, the Coulomb solve with its Tresca fixed point and fallbacks, the law's residual
   contact_friction_newton.c  Coulomb by the semismooth Newton method with velocity weakening, the fixed points' steps
   contact_boxqp.c       the Tresca step's dual: a small dense box-constrained QP (active set, TAO, SNES VI)
   contact_lemke.c       Coulomb as one LCP, Lemke's method (the last fallback)
   contact_anderson.c    Anderson acceleration of the friction's fixed points (mu(v), the Tresca steps)
   The registry and the solvers (each file one solver, using the core):
   contact_registry.c    RollerContactSolverRegister, RegisterAll, the solver object's create/setup/destroy and
                         RollerContactSolveWith: a solve with the re-solve loop that makes it free of penetration
   contact_condensed.c   the default: the QP condensed onto the multipliers of the candidates with
                         S = E^T A^{-1} E computed once; its small LCP in contact_lcp.c (active set or TAO)
   contact_primal.c      not a solver: the primal problem in rotated coordinates z = Q^T xi (Q: 2x2 blocks
                         (t^k, n^k) at the candidates) shared by
   contact_vi.c, contact_tao.c, contact_pcg.c   SNES VI, TAO, the paper's projected CG (its section 3.3)

   Every rank holds the same copy of the Gamma_C data (node list, positions, S, multipliers) and makes the
   same decisions on it, so the candidate set and the condensed problem do not depend on the partition.
   docs/contact.md describes the method, the options, the KKT residual and how to add a solver. */
#ifndef ROLLER_CONTACT_IMPL_H
#define ROLLER_CONTACT_IMPL_H

#include "contact/contact.h"
#include "friction/friction.h"

/* What one solver returns besides the displacement: the multiplier of every Gamma_C node (0 off the
   candidate set) and its iteration count. */
typedef struct {
  PetscReal *lambda;
  PetscReal *lambda_t; /* with friction: the tangential multipliers (force lambda_t t^k), NULL otherwise */
  PetscInt   its;
} RollerContactResult;

typedef struct _n_RollerContactFriction *RollerContactFriction;

/* The solvers of a Tresca step's box QP (contact_boxqp.c), and lemke: Coulomb as one LCP (contact_lemke.c) */
typedef enum { ROLLER_BOXQP_ACTIVESET, ROLLER_BOXQP_TAO, ROLLER_BOXQP_VI, ROLLER_BOXQP_LEMKE } RollerBoxQPType;
PETSC_INTERN const char *const RollerBoxQPTypes[];

/* A solver's operations. setfromoptions (optional) reads its own options inside the contact options block;
   setup (optional) is called once before its first solve, when the Gamma_C nodes are known; prepare (optional)
   when a scheme has made a step matrix; solve finds the minimizer xi with the step matrix c->step.op and the
   bounds of the current candidate set (c->step) and its multipliers; destroy frees
   what the data holds (the data itself is freed by RollerContactSolverDestroy). */
typedef struct {
  PetscErrorCode (*setfromoptions)(RollerContactSolver, PetscOptionItems *);
  PetscErrorCode (*setup)(RollerContactSolver, Roller, RollerContact);
  PetscErrorCode (*prepare)(RollerContactSolver, Roller, RollerContact, const RollerStepOperator *); /* optional: work for a step matrix */
  PetscErrorCode (*solve)(RollerContactSolver, Roller, RollerContact, Vec, Vec, RollerContactResult *);
  PetscErrorCode (*destroy)(RollerContactSolver);
} RollerContactSolverOps;

struct _n_RollerContactSolver {
  char                  *name; /* its name in the registry */
  RollerContactSolverOps ops[1];
  void                  *data; /* the solver's own (freed by RollerContactSolverDestroy) */
  PetscBool              setupcalled;
};

PETSC_INTERN PetscFunctionList RollerContactSolverList;

/* The parts of the contact context, by lifetime and owner. */

/* Options (contact.c), read once */
typedef struct {
  char              solver[64]; /* -contact_solver: a name in the registry */
  PetscBool         check;
  PetscReal         margin; /* extra reach of the candidate set (length) */
  PetscReal         rtol;   /* relative tolerance of vi, tao and the condensed TAO */
  PetscInt          max_resolves;
  PetscViewer       monitor; /* -contact_monitor, NULL when off */
  PetscViewerFormat monitor_format;
  PetscBool         monitor_header; /* the CSV header line is written */
  RollerBoxQPType   friction_qp;    /* -contact_friction_qp: the Tresca QP solver, or lemke (Coulomb as one LCP) */
  PetscReal         friction_rtol;  /* the Coulomb fixed point's tolerance on lambda_N and mu(v) */
  PetscInt          friction_max_it;
  PetscBool         friction_newton; /* -contact_friction_newton: Coulomb by the semismooth Newton method first */
} RollerContactOptions;

#include "contact_reduced.h"

/* Gamma_C nodes (contact_nodes.c), fixed at creation, the same on every rank, sorted by angle: node i has its
   x dof at global index gidx[i] (y at gidx[i] + 1) and position xc[2i], xc[2i+1]; the redundant vectors hold
   2 nc entries in this order */
typedef struct {
  PetscInt   nc;
  PetscInt  *gidx;
  PetscBool *is_vertex; /* a mesh vertex (P2: the others are edge midpoints) */
  PetscReal *xc;
  PetscInt   nown;      /* nodes owned by this rank: */
  PetscInt  *own_node;  /*   their indices in the sorted list */
  PetscInt  *own_off;   /*   the local offset of their x dof in a global Vec */
  PetscInt  *own_point; /*   their mesh point (vertex, or edge for a P2 midpoint) */
  VecScatter scatter;   /* global Vec -> redundant Vec of the Gamma_C dofs */
  Vec        red, red1, red2;
  /* -rom (contact_reduced.c): the displacement is V q; the Gamma_C rows of V, phi (2 nc x nq, row-major, on every
     rank), gather u_C = phi q and spread f_q = phi^T f_C; within a step only the rows of the window's nodes (those
     the obstacle can reach) are computed, the others' displacement reads 0 */
  PetscInt                 nq;
  PetscReal               *phi;
  PetscInt                 nwin, *win; /* the window's nodes; windowed false: all of them */
  PetscBool                windowed;
  RollerContactGatherCache gather;   /* the last gathers Phi q (-rom) */
  RollerContactResidual    residual; /* -rom_residual (contact_residual.c) */
} RollerContactNodes;

/* The step (contact_candidates.c): time, rotation, obstacle height, contact basis (t^k, n^k), candidate set,
   bounds, the gaps of the last solve and the re-solves it took */
typedef struct {
  const RollerStepOperator *op; /* the step matrix of this solve (the scheme's) */
  PetscReal                 t, theta, g, normal[2], tangent[2];
  PetscInt                  ncand;
  PetscInt                 *cand;        /* candidate node indices, ascending */
  PetscBool                *is_cand;     /* nc flags */
  PetscReal                *lower;       /* nc lower bounds g^k - x_n . n^k of the normal displacement q_n */
  PetscReal                *gap;         /* nc gaps of a solution (scratch) */
  PetscBool                *on_obstacle; /* nc: gap^{k-1}_n <= tol, the nodes on the obstacle at the previous level, from
                             xi^{k-1} (checkpointed state, so a restart takes the same decisions) */
  PetscInt                  resolves;
  const PetscReal          *Yg; /* -axle: the Gamma_C rows of the step matrix's border Y (3 columns of 2 nc), NULL otherwise */
} RollerContactStep;

/* -axle: the hub's part of S_eff = E^T A_eff^{-1} E = S + Yg W Yg^T between the components u of node i and v of node j
   (model/axle.h: the step's W) is a^T W b with a = u . Yg(i), b = v . Yg(j) (RollerContactBorderRow, 3 reals each, once
   per node and direction: a step's G takes m^2 pairs); 0 without the hub. */
static inline void RollerContactBorderRow(const RollerContactStep *st, const PetscReal u[2], PetscInt i, PetscInt n, PetscReal a[3])
{
  for (PetscInt k = 0; k < 3; ++k) a[k] = st->Yg ? u[0] * st->Yg[k * n + 2 * i] + u[1] * st->Yg[k * n + 2 * i + 1] : 0.0;
}

static inline PetscReal RollerContactBorderPair(const RollerContactStep *st, const PetscReal a[3], const PetscReal b[3])
{
  PetscReal r = 0.0;

  if (!st->Yg) return 0.0;
  for (PetscInt k = 0; k < 3; ++k)
    for (PetscInt l = 0; l < 3; ++l) r += a[k] * st->op->border->W[3 * k + l] * b[l];
  return r;
}

/* The accepted solution of the step: multipliers and iterations, the right-hand side it solved; work vectors
   of its KKT residual */
typedef struct {
  RollerContactResult result;
  PetscBool           solved;
  Vec                 b, force, work;
} RollerContactAccepted;

/* -contact_check: a second solution and its multipliers; per solver, the largest differences and residuals */
typedef struct {
  Vec                 xi;
  RollerContactResult result;
  PetscReal          *max_diff, *max_kkt;
  PetscInt            steps;
} RollerContactCheck;

/* The sheet's own motion (-sheet_mass, contact_sheet.c): its mass and resistance per unit width, the levels X^k,
   X^{k-1}, X^{k-2} after the last step and its case X[3] (1 or -1: sliding along +-e1, 0: held), the resistance's
   dissipation in the last step. mass 0: the kinematic sheet of -sheet_speed. */
typedef struct {
  PetscReal mass, resistance;
  PetscReal X[4];
  PetscReal dissipation;
  PetscBool held_at_bound; /* the last step: no case consistent, held with the force it needed (coulomb_fallback 4) */
  PetscInt  bound_steps;   /* the run's such steps */
} RollerContactSheet;

struct _n_RollerContact {
  MPI_Comm              comm;
  RollerContactSheet    sheet;
  RollerContactOptions  opt;
  RollerContactNodes    nodes;
  RollerContactStep     step;
  RollerContactAccepted acc;
  RollerContactCheck    check;
  PetscInt              nsolvers;
  RollerContactSolver  *solvers;  /* every registered solver, in registration order (set up when first used) */
  RollerContactSolver   solver;   /* the one of -contact_solver */
  RollerContactFriction friction; /* NULL without friction (-friction 0) */
};

/* contact_sheet.c (RollerContactSheetMoves, Energy, Speed, State: contact.h) */
PETSC_INTERN PetscErrorCode RollerContactSheetSetUp(Roller, RollerContact);
PETSC_INTERN void           RollerContactSheetFree(Roller, RollerContact, PetscReal *, PetscReal *); /* dX without friction, compliance dt^2/m */
PETSC_INTERN PetscErrorCode RollerContactSheetAccept(Roller, RollerContact, const PetscReal[], PetscBool *);
PETSC_INTERN PetscErrorCode RollerContactSheetHoldAtBound(Roller, RollerContact);

/* contact_registry.c */
PETSC_INTERN PetscErrorCode RollerContactSolveWith(Roller, RollerContact, RollerContactSolver, Vec, Vec, RollerContactResult *);
PETSC_INTERN PetscErrorCode RollerContactSolverCreate(const char[], RollerContactSolver *);
PETSC_INTERN PetscErrorCode RollerContactSolverSetUp(RollerContactSolver, Roller, RollerContact);
PETSC_INTERN PetscErrorCode RollerContactSolverDestroy(RollerContactSolver *);

/* contact_nodes.c */
PETSC_INTERN PetscErrorCode RollerContactNodesCreate(Roller, RollerContact);
PETSC_INTERN PetscErrorCode RollerContactNodesDestroy(RollerContact);
PETSC_INTERN PetscErrorCode RollerContactGather(RollerContact, Vec, Vec);
PETSC_INTERN PetscErrorCode RollerContactGaps(RollerContact, Vec, PetscReal[], PetscReal *);
PETSC_INTERN void           RollerContactObstacleAt(Roller, PetscReal, PetscReal[2], PetscReal *);
PETSC_INTERN PetscErrorCode RollerContactGapsAt(Roller, RollerContact, Vec, PetscReal, PetscReal[]);
PETSC_INTERN PetscErrorCode RollerContactForce(RollerContact, const PetscReal[], const PetscReal[], Vec);

/* contact_reduced.c (-rom) */
PETSC_INTERN PetscReal RollerContactGapTolerance(Roller);

/* contact_candidates.c */
PETSC_INTERN PetscErrorCode RollerContactSetTime(Roller, RollerContact, PetscReal);
PETSC_INTERN PetscErrorCode RollerContactSetUpStep(Roller, RollerContact, const RollerContactStage *, PetscReal);
PETSC_INTERN PetscErrorCode RollerContactAddPenetrating(Roller, RollerContact, PetscInt *);

/* contact_report.c */
PETSC_INTERN PetscErrorCode RollerContactKKT(Roller, RollerContact, Vec, Vec, Vec, const PetscReal[], PetscReal *, PetscReal *); /* xi, M xi and K xi or NULL, lambda */
PETSC_INTERN PetscErrorCode RollerContactCheckStep(Roller, RollerContact, Vec, Vec);
PETSC_INTERN PetscErrorCode RollerContactCheckSummary(RollerContact);

/* contact_energy.c */
PETSC_INTERN PetscErrorCode RollerContactFlips(Roller, RollerContact, const PetscReal[], RollerStepInfo *);

/* contact_primal.c: the rotated primal problem of vi, tao and pcg, each of which holds one in its data:
   xi = Q z, A_hat = Q^T A Q, b_hat = Q^T b, and the bound z_q >= lower at the normal component of every
   candidate. */
typedef struct {
  Mat       Q, Ahat;
  Vec       z, bhat, lower, upper, r;
  PetscReal fscale; /* force scale of the tolerances: max(||b||_2, ||A||_inf ||z_0||_2) */
  PetscReal Anorm;  /* ||A||_inf */
  Vec      *work;   /* 4 work vectors (projected CG, J0) */
  KSP       ksp;    /* the step factorization: A_hat^{-1} = Q^T A^{-1} Q, TAO's quasi-Newton J0 */
} RollerContactPrimal;

PETSC_INTERN PetscErrorCode RollerContactPrimalSetUp(Roller, RollerContact, RollerContactPrimal *);
PETSC_INTERN PetscErrorCode RollerContactPrimalSetUpStep(Roller, RollerContact, RollerContactPrimal *, Vec);
PETSC_INTERN PetscErrorCode RollerContactPrimalFinish(Roller, RollerContact, RollerContactPrimal *, Vec, RollerContactResult *);
PETSC_INTERN PetscErrorCode RollerContactPrimalDestroy(RollerContactPrimal *);

/* contact_tao.c: the QP  f(x) = 1/2 x^T H x + sign c^T x  of a TAO solve (the tao solver's, and the condensed
   TAO's in contact_lcp.c): its objective-gradient callback and its Hessian callback (H is TAO's matrix). */
typedef struct {
  Mat       H;
  Vec       c;
  PetscReal sign;
} RollerContactTaoQP;

PETSC_INTERN PetscErrorCode RollerContactTaoQPObjective(Tao, Vec, PetscReal *, Vec, void *);
PETSC_INTERN PetscErrorCode RollerContactTaoQPHessian(Tao, Vec, Mat, Mat, void *);

/* contact_lcp.c: the small dense LCP of the condensed solver, its arrays sized for nc; with lo and up (the
   friction's box QP, contact_boxqp.c) the bounds lo <= lam <= up instead of lam >= 0 */
typedef struct {
  PetscReal *G, *Gff, *d, *lam, *mu, *mu2, *w;
  PetscReal *lo, *up;
  PetscInt  *F;
  PetscBool *act;
  /* -contact_condensed_qp tao: a sequential TAO on the same problem (the friction's box QP also a SNES VI),
     on work objects rebuilt when the size changes */
  Tao                tao;
  SNES               snes;
  Mat                tG;
  Vec                tx, tlb, tub, td;
  PetscInt           tao_m;
  RollerContactTaoQP tqp; /* 1/2 lam^T G lam + d^T lam on tG, td */
} RollerContactLCP;

PETSC_INTERN PetscErrorCode RollerContactLCPCreate(PetscInt, RollerContactLCP *);
PETSC_INTERN PetscErrorCode RollerContactLCPActiveSet(RollerContactLCP *, PetscInt, PetscReal, PetscBool[], PetscReal[], PetscInt *);
PETSC_INTERN PetscErrorCode RollerContactLCPTao(RollerContactLCP *, PetscInt, PetscReal, PetscReal, PetscReal[], PetscInt *);
PETSC_INTERN PetscErrorCode RollerContactLCPDestroy(RollerContactLCP *);
PETSC_INTERN PetscErrorCode RollerContactLCPWork(RollerContactLCP *, PetscInt);
PETSC_INTERN void           RollerContactLCPSlack(RollerContactLCP *, PetscInt, const PetscReal[], PetscReal[]);

/* contact_boxqp.c: min 1/2 x^T G x + d^T x over lo <= x <= up on the arrays of a RollerContactLCP created with
   RollerContactBoxQPCreate (size n); state[] (-1 at lo, 0 free, 1 at up) warm-starts the active set */
PETSC_INTERN PetscErrorCode RollerContactBoxQPCreate(PetscInt, RollerContactLCP *);
PETSC_INTERN PetscErrorCode RollerContactBoxQPSolve(RollerContactLCP *, RollerBoxQPType, PetscInt, PetscReal, PetscReal, PetscInt[], PetscReal[], PetscInt *);
PETSC_INTERN PetscErrorCode RollerContactBoxQPDestroy(RollerContactLCP *);

/* contact_anderson.c: Anderson acceleration of a fixed point x = g(x) of up to cap unknowns */
#define ROLLER_ANDERSON_MAX 8
typedef struct {
  PetscInt   cap, depth, n, k, next; /* capacity, history length, unknowns, stored differences, the next slot */
  PetscBool  have;                   /* a previous (f, g) is stored */
  PetscReal  fnorm;                  /* ||f||^2 of the last iterate */
  PetscReal *dF, *dG, *f, *g;        /* depth x n differences of f = g - x and of g; the last f and g */
} RollerContactAnderson;

PETSC_INTERN PetscErrorCode RollerContactAndersonCreate(PetscInt, PetscInt, RollerContactAnderson *);
PETSC_INTERN void           RollerContactAndersonReset(RollerContactAnderson *, PetscInt);
PETSC_INTERN PetscErrorCode RollerContactAndersonStep(RollerContactAnderson *, PetscReal[], const PetscReal[]);
PETSC_INTERN PetscErrorCode RollerContactAndersonDestroy(RollerContactAnderson *);

/* contact_friction.c: the friction part of the condensed solver (created only with -friction > 0) */
struct _n_RollerContactFriction {
  const RollerObstacle *law;                      /* mu(v) (friction/law.c) */
  PetscBool             varies;                   /* mu depends on the slip speed */
  PetscReal             range[2];                 /* the least and the largest mu(v) */
  RollerContactLCP      box;                      /* the Tresca dual, sized 2 nc */
  PetscInt             *state;                    /* 2 nc: its active bounds, warm start of the next Tresca step */
  PetscReal            *lam_n;                    /* nc: lambda_N of the last iterate */
  PetscReal            *mu_n;                     /* nc: mu(v) of the candidates at the last iterate */
  PetscReal            *x;                        /* 2 nc: the box QP's solution */
  PetscInt             *node_state;               /* nc: 0 off the sheet, 1 stick, 2 slip, of the accepted step */
  PetscReal            *g, *y;                    /* 2 nc: a fixed point's image (lambda_N, mu(v)) and its iterate */
  PetscReal            *warm;                     /* 2 nc: (lambda_N, lambda_T) of every node after the last solve, the Newton's first iterate */
  RollerContactAnderson aa;                       /* the acceleration of the fixed points on mu(v) and (lambda_N, mu) */
  PetscReal            *M, *q, *z;                /* Lemke's LCP of 4 m unknowns (allocated when first needed, for lemke_cap) */
  PetscInt              lemke_cap, its, fallback; /* Lemke's allocation; the last solve's iterations and fallback */
  struct {
    PetscInt steps, newton_failures, lemke_steps, lagged_steps;
  } count; /* the run's Coulomb solves and their fallbacks */
};

/* The sheet's tangent t = (n_y, -n_x) at time t (n its outward normal, RollerContactObstacleAt). */
static inline void RollerContactSheetTangent(Roller ctx, PetscReal t, PetscReal tan[2])
{
  PetscReal n[2], g;

  RollerContactObstacleAt(ctx, t, n, &g);
  tan[0] = n[1];
  tan[1] = -n[0];
}

/* The lab position along tan of the Gamma_C node i, x_i + u_i (xc the reference positions, u a gathered field). */
static inline PetscReal RollerContactAlong(const PetscReal xc[], const PetscScalar u[], PetscInt i, const PetscReal tan[2])
{
  return (xc[2 * i] + PetscRealPart(u[2 * i])) * tan[0] + (xc[2 * i + 1] + PetscRealPart(u[2 * i + 1])) * tan[1];
}

/* The frictionless multipliers lam as the first iterate x = (lambda_N, lambda_T = 0) of a Coulomb solve on m nodes. */
static inline void RollerContactFrictionStart(PetscInt m, const PetscReal lam[], PetscReal x[])
{
  for (PetscInt a = 0; a < m; ++a) {
    x[a]     = lam[a];
    x[m + a] = 0.0;
  }
}

/* contact_friction_newton.c */
PETSC_INTERN void           RollerContactFrictionUpdate(RollerContactFriction, PetscInt, PetscReal, PetscReal *, PetscReal *, PetscReal *);
PETSC_INTERN PetscErrorCode RollerContactFrictionNext(RollerContactFriction, PetscInt, PetscBool);
PETSC_INTERN PetscErrorCode RollerContactFrictionLaggedMu(Roller, RollerContact, PetscInt);
PETSC_INTERN PetscErrorCode RollerContactFrictionNewton(Roller, RollerContact, PetscInt, PetscBool *);

/* contact_friction.c */
PETSC_INTERN PetscErrorCode RollerContactFrictionCreate(Roller, RollerContact);
PETSC_INTERN PetscErrorCode RollerContactFrictionRemember(RollerContact); /* the last solve's multipliers, before a new solve */
PETSC_INTERN PetscErrorCode RollerContactFrictionSolve(Roller, RollerContact, const PetscReal[], RollerContactLCP *, RollerContactResult *);
PETSC_INTERN PetscErrorCode RollerContactFrictionInfo(Roller, RollerContact, const PetscReal[], RollerStepInfo *);
PETSC_INTERN PetscErrorCode RollerContactFrictionState(RollerContact, PetscReal[]);
PETSC_INTERN PetscErrorCode RollerContactFrictionDestroy(MPI_Comm, RollerContactFriction *); /* prints the run's fallbacks */

/* The solvers' create functions, for RollerContactSolversRegisterAll */
PETSC_INTERN PetscErrorCode RollerContactSolverCreate_Condensed(RollerContactSolver);
PETSC_INTERN PetscErrorCode RollerContactSolverCreate_VI(RollerContactSolver);
PETSC_INTERN PetscErrorCode RollerContactSolverCreate_Tao(RollerContactSolver);
PETSC_INTERN PetscErrorCode RollerContactSolverCreate_PCG(RollerContactSolver);

#endif
