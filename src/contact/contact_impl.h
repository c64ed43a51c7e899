/* Private to the contact*.c files: the obstacle QP of docs/model.md section 2 and its solvers.

     min 1/2 xi^T A xi - b^T xi   s.t.  (x_n + xi_n) . n^k >= g^k  at every Lagrange node x_n of Gamma_C

   contact.c            the Gamma_C nodes (gathered redundantly on every rank, in angle order), the candidate
                        set of a step, the dispatch with the penetration check, KKT residual, info, -contact_check
   contact_condensed.c  the default: the QP condensed onto the multipliers of the candidates with
                        S = E^T A^{-1} E computed once; exact active-set solver (or TAO) for the small problem
   contact_primal.c     the primal problem in rotated coordinates z = Q^T xi (Q: 2x2 blocks (t^k, n^k) at the
                        candidates): SNES VI and TAO
   contact_pcg.c        the paper's projected Polak-Ribiere nonlinear CG (its section 3.3), the baseline

   Every rank holds the same copy of the Gamma_C data (node list, positions, S, multipliers) and makes the
   same decisions on it, so the candidate set and the condensed problem do not depend on the partition.
   docs/contact.md describes the method, the options and the KKT residual. */
#ifndef ROLLER_CONTACT_IMPL_H
#define ROLLER_CONTACT_IMPL_H

#include "contact/contact.h"

typedef enum { CONTACT_CONDENSED, CONTACT_VI, CONTACT_TAO, CONTACT_PCG, CONTACT_NUM_SOLVERS } RollerContactSolverType;
PETSC_INTERN const char *const RollerContactSolverTypes[];

typedef enum { CONTACT_QP_ACTIVESET, CONTACT_QP_TAO } RollerContactQPType;
PETSC_INTERN const char *const RollerContactQPTypes[];

/* What one solver returns besides the displacement: the multiplier of every Gamma_C node (0 off the
   candidate set) and its iteration count. */
typedef struct {
  PetscReal *lambda;
  PetscInt   its;
} RollerContactResult;

typedef struct _n_RollerContactCondensed *RollerContactCondensed;

/* The primal problem in rotated coordinates (contact_primal.c, used by vi, tao and pcg): xi = Q z, with
   A_hat = Q^T A Q, b_hat = Q^T b, and the bound z_q >= lower at the normal component of every candidate. */
typedef struct {
  Mat       Q, Ahat;
  Vec       z, bhat, lower, upper, r;
  PetscReal fscale; /* force scale of the tolerances: max(||b||_2, ||A||_inf ||z_0||_2) */
  PetscReal Anorm;  /* ||A||_inf */
  Vec      *work;   /* 4 work vectors (projected CG, J0) */
  SNES      snes;
  Tao       tao;
  KSP       ksp; /* the step factorization: A_hat^{-1} = Q^T A^{-1} Q, TAO's quasi-Newton J0 */
} RollerContactPrimal;

struct _n_RollerContact {
  MPI_Comm comm;

  /* options */
  RollerContactSolverType solver;
  RollerContactQPType     qp;
  PetscBool               check, monitor, tao_j0;
  PetscReal               margin;   /* extra reach of the candidate set (length) */
  PetscReal               rtol;     /* relative tolerance of vi, tao and the condensed TAO */
  PetscReal               pcg_rtol; /* stopping tolerance of the projected CG, relative to the force scale */
  PetscInt                pcg_max_it, max_resolves;

  /* Gamma_C nodes, the same on every rank, sorted by angle: node i has its x dof at global index gidx[i]
     (y at gidx[i] + 1) and position xc[2i], xc[2i+1]; the redundant vectors hold 2 nc entries in this order */
  PetscInt   nc;
  PetscInt  *gidx;
  PetscBool *is_vertex; /* a mesh vertex (P2: the others are edge midpoints) */
  PetscReal *xc;
  PetscInt   nown;      /* nodes owned by this rank: */
  PetscInt  *own_node;  /*   their indices in the sorted list */
  PetscInt  *own_off;   /*   the local offset of their x dof in a global Vec */
  PetscInt  *own_point; /*  their mesh point (vertex, or edge for a P2 midpoint) */
  VecScatter scatter;   /* global Vec -> redundant Vec of the Gamma_C dofs */
  Vec        red, red1, red2;

  /* the step: time, rotation, obstacle height, contact basis (t^k, n^k), candidate set, bounds */
  PetscReal  t, theta, g, normal[2], tangent[2];
  PetscInt   ncand;
  PetscInt  *cand;        /* candidate node indices, ascending */
  PetscBool *is_cand;     /* nc flags */
  PetscReal *lower;       /* nc lower bounds g^k - x_n . n^k of the normal displacement q_n */
  PetscReal *gap;         /* nc gaps of a solution (scratch) */
  PetscBool *on_obstacle; /* nc: gap^{k-1}_n <= tol, the nodes on the obstacle at the previous level, from
                             xi^{k-1} (checkpointed state, so a restart takes the same decisions) */

  /* the accepted solution of the step: multipliers, iterations, re-solves; the right-hand side it solved */
  RollerContactResult result;
  PetscBool           solved;
  PetscInt            resolves;
  Vec                 b, force, work;

  /* -contact_check: a second solution and its multipliers; the largest differences and residuals seen */
  Vec                 xi_check;
  RollerContactResult check_result;
  PetscReal           check_max_diff[CONTACT_NUM_SOLVERS], check_max_kkt[CONTACT_NUM_SOLVERS];
  PetscInt            check_steps;

  RollerContactCondensed condensed;
  RollerContactPrimal    primal;
  PetscBool              primal_ready;
};

/* contact.c */
PETSC_INTERN PetscErrorCode RollerContactGather(RollerContact, Vec, Vec);
PETSC_INTERN PetscErrorCode RollerContactForce(RollerContact, const PetscReal[], Vec);
PETSC_INTERN PetscReal      RollerContactGapTolerance(Roller);

/* contact_condensed.c */
PETSC_INTERN PetscErrorCode RollerContactCondensedCreate(Roller, RollerContact);
PETSC_INTERN PetscErrorCode RollerContactCondensedSolve(Roller, RollerContact, Vec, Vec, RollerContactResult *);
PETSC_INTERN PetscErrorCode RollerContactCondensedDestroy(RollerContact);

/* contact_primal.c */
PETSC_INTERN PetscErrorCode RollerContactPrimalSetUpStep(Roller, RollerContact, Vec);
PETSC_INTERN PetscErrorCode RollerContactPrimalFinish(Roller, RollerContact, Vec, RollerContactResult *);
PETSC_INTERN PetscErrorCode RollerContactVISolve(Roller, RollerContact, Vec, Vec, RollerContactResult *);
PETSC_INTERN PetscErrorCode RollerContactTaoSolve(Roller, RollerContact, Vec, Vec, RollerContactResult *);
PETSC_INTERN PetscErrorCode RollerContactPrimalDestroy(RollerContact);

/* contact_pcg.c */
PETSC_INTERN PetscErrorCode RollerContactPCGSolve(Roller, RollerContact, Vec, Vec, RollerContactResult *);

#endif
