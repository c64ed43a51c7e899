/* The contact layer's face (docs/contact.md): the obstacle QP of a step, only built when -obstacle is on.
   Its files and private header: contact_impl.h. */
#ifndef ROLLER_CONTACT_H
#define ROLLER_CONTACT_H

#include <roller_impl.h>
#include "model/model.h"

/* What a time scheme's step (or stage) gives the contact solve besides its right-hand side (docs/contact.md "the
   candidate set"): the step matrix and its factorization, and the level the new one follows, x_cur at t_cur
   (the nodes on the obstacle there are the condensed solver's first active set), with the prediction of the new
   level x_pred = p[0] x_cur + p[1] x_aux, which picks the candidate nodes, and the increment d[0] x_cur +
   d[1] x_aux, whose largest nodal size bounds the change a contact shock can bring. Three-level schemes:
   x_aux = xi^{k-2}, p = (2, -1), d = (1, -1); one-step schemes: x_aux = the velocity, p = (1, h), d = (0, h). */
typedef struct {
  const RollerStepOperator *op;
  PetscReal                 t_cur;
  Vec                       x_cur, x_aux;
  PetscReal                 p[2], d[2];
} RollerContactStage;

PETSC_INTERN PetscErrorCode RollerContactCreate(Roller, RollerContact *);
PETSC_INTERN PetscErrorCode RollerContactHelp(Roller); /* -help without -obstacle: the options block only */
PETSC_INTERN PetscErrorCode RollerContactSolve(Roller, RollerContact, const RollerContactStage *, PetscReal, Vec, Vec);
PETSC_INTERN PetscErrorCode RollerContactPrepare(Roller, RollerContact, const RollerStepOperator *);              /* set-up for an operator (the condensed S) */
PETSC_INTERN PetscErrorCode RollerContactForceVector(RollerContact, Vec);                                         /* E N lambda (+ the friction's) of the last solve: A xi = b + it */
PETSC_INTERN PetscErrorCode RollerContactInfo(Roller, RollerContact, Vec, Vec, Vec, PetscReal, RollerStepInfo *); /* xi, M xi and K xi (or NULL), t */
/* The contact's terms of the energy balance of a solve from the level x_from at t_from, the force of the last solve
   paired with its displacement times weight (contact_energy.c), added to info: obstacle_work, contact_dissipation
   and the contact's parts of the shaft's and the sheet's works */
PETSC_INTERN PetscErrorCode RollerContactEnergyAdd(Roller, RollerContact, Vec, PetscReal, PetscReal, RollerStepInfo *);
PETSC_INTERN PetscErrorCode RollerContactFields(Roller, RollerContact, Vec, Vec, Vec); /* pressure, traction, state: P1 scalar Vecs on the mesh */
PETSC_INTERN PetscBool      RollerContactHasFriction(RollerContact);
PETSC_INTERN PetscErrorCode RollerContactMultipliers(RollerContact, PetscInt *, PetscReal **, PetscReal **); /* the last solve's lambda_N, lambda_T (NULL without friction) of the nc nodes: checkpointed */
/* -rom: the displacement becomes V q (V dense, N x nq, the full model's layout; q a Vec of the reduced layout): the
   Gamma_C rows of V taken before the operators are replaced (contact_reduced.c) */
PETSC_INTERN PetscErrorCode RollerContactSetBasis(Roller, RollerContact, Mat, Vec);
/* -rom_residual: MacNeal's static residual flexibility of the Gamma_C dofs, with a stiffness's factorization (a KSP on
   the full layout) and its reduced V^T K V (dense nq x nq, column-major, every rank); after RollerContactSetBasis */
PETSC_INTERN PetscErrorCode RollerContactSetResidualFlexibility(Roller, RollerContact, KSP, const PetscReal[]);
PETSC_INTERN PetscErrorCode RollerContactResidualEnergy(RollerContact, Vec, Vec, PetscReal *);                                                     /* E^k += its static energy (cur, prev) */
PETSC_INTERN PetscErrorCode RollerContactResidualDissipation(RollerContact, Vec, Vec, PetscReal *, PetscReal *);                                   /* D^k += its update's (cur, prev2), the branches' into the second */
PETSC_INTERN PetscErrorCode RollerContactResidualTrace(RollerContact, PetscReal *);                                                                /* tr R */
PETSC_INTERN PetscErrorCode RollerContactSetResidualBranches(RollerContact, PetscInt, const PetscReal[], const PetscReal[], PetscReal, PetscReal); /* the viscoelastic residual: g, tau, kappa, dt */
PETSC_INTERN PetscErrorCode RollerContactResidualView(Roller, RollerContact, PetscViewer, PetscBool);                                              /* R to a -rom_output file, or from one (load) */
PETSC_INTERN PetscInt       RollerContactNodeCount(RollerContact);                                                                                 /* Gamma_C nodes (0 without contact) */
PETSC_INTERN PetscErrorCode RollerContactResidualLevelsBegin(RollerContact, const Vec[3]);                                                         /* the full levels' u_C, before the reduction */
PETSC_INTERN PetscErrorCode RollerContactResidualLevelsEnd(RollerContact, const Vec[3]);                                                           /* the reduced levels' r = u_C - Phi q, f = R^-1 r */
PETSC_INTERN PetscErrorCode RollerContactResidualFunctionals(RollerContact, Vec, Vec);
PETSC_INTERN PetscErrorCode RollerContactResidualAddFull(RollerContact, Vec, Vec);                                                         /* x (full layout) += E r of the level q */
PETSC_INTERN PetscErrorCode RollerContactResidualRows(RollerContact, Vec, PetscReal **);                                                   /* a functional's Gamma_C rows */
PETSC_INTERN PetscErrorCode RollerContactResidualDot(RollerContact, Vec, const PetscReal[], PetscReal *); /* += rows . r of the level q */ /* keeps w_R, w_alpha's Gamma_C rows (full layout) */
PETSC_INTERN PetscErrorCode RollerContactResidualDots(RollerContact, Vec, PetscReal *, PetscReal *);                                       /* += w_R . r, w_alpha . r of a level */
PETSC_INTERN PetscErrorCode RollerContactCheckReduced(Roller, RollerContact);                                                              /* -contact_solver condensed, no -contact_check */
/* -sheet_mass (contact_sheet.c): the sheet moves by its own forces; its part of E^k, its speed, its state for the
   checkpoint (4 reals: X^k, X^{k-1}, X^{k-2} and its case; NULL for the kinematic sheet) */
PETSC_INTERN PetscBool  RollerContactSheetMoves(RollerContact);
PETSC_INTERN PetscReal  RollerContactSheetEnergy(Roller, RollerContact);
PETSC_INTERN PetscReal  RollerContactSheetSpeed(Roller, RollerContact);
PETSC_INTERN PetscReal *RollerContactSheetState(RollerContact);
PETSC_INTERN PetscBool  RollerContactWantsRow(RollerContact);
/* Dense pieces the steady state of -modes (modes/steady*.c) shares with the step's contact solvers:
   contact_lemke.c: the LCP w = M z + q >= 0, z >= 0, z . w = 0 (M n x n column-major) by Lemke's method;
   *solved false on a secondary ray (no solution found);
   contact_lcp.c: y = G_FF^-1 r on an index set F of a column-major G (m, F, nf, spd: Cholesky else LU, scratch, r, y).
   (The friction law mu(v) they share is the friction layer's, friction/friction.h.) */
PETSC_INTERN PetscErrorCode RollerContactLemke(PetscInt, const PetscReal[], const PetscReal[], PetscReal[], PetscInt *, PetscBool *);
PETSC_INTERN PetscErrorCode RollerContactDenseSolve(const PetscReal[], PetscInt, const PetscInt[], PetscInt, PetscBool, PetscReal[], PetscReal[], PetscReal[]);
PETSC_INTERN PetscErrorCode RollerContactDestroy(RollerContact *);

/* The registry of the per-step QP solvers (-contact_solver NAME, contact_registry.c): a solver is made by
   its create function, which fills the ops and the data of the object it is given (like KSPRegister). */
typedef struct _n_RollerContactSolver *RollerContactSolver;

PETSC_INTERN PetscErrorCode RollerContactSolverRegister(const char[], PetscErrorCode (*)(RollerContactSolver));
PETSC_INTERN PetscErrorCode RollerContactSolversRegisterAll(void);

#endif
