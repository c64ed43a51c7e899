/* Private to the contact*.c files: the reduced model's contact (-rom; contact_reduced.c, contact_residual.c,
   contact_residual_levels.c), included by contact_impl.h. */
#ifndef ROLLER_CONTACT_REDUCED_H
#define ROLLER_CONTACT_REDUCED_H

/* -rom_residual (MacNeal, contact_residual.c): the static residual flexibility R = E^T (K^-1 - V K_r^-1 V^T) E of the
   Gamma_C dofs (2 nc x 2 nc column-major, every rank; NULL without it). A solve's displacement is Phi q + R f_C, f_C
   its nodal force: the residual r = R f_C of a level is kept by its Vec's id (RollerContactReducedResidual). wc: the
   Gamma_C rows of the functionals w_R, w_alpha (2 x 2 nc), for r's part of R and alpha. */
#define ROLLER_RESIDUAL_SLOTS 16
#define ROLLER_GATHER_CACHE   6
/* -rom: the gather of q on every rank, and the last gathers Phi q within the current window (a step gathers its few levels about ten times), by the Vec's
   id and state: a level read again is copied, not recomputed (contact_reduced.c) */
typedef struct {
  VecScatter       qscatter; /* reduced Vec -> qall on every rank */
  Vec              qall;
  PetscInt         wstamp;                  /* the window's count: RollerContactReducedWindow */
  PetscObjectId    id[ROLLER_GATHER_CACHE]; /* 0: empty */
  PetscObjectState state[ROLLER_GATHER_CACHE];
  PetscInt         stamp[ROLLER_GATHER_CACHE], next;
  PetscReal       *val[ROLLER_GATHER_CACHE]; /* 2 nc: the window's entries */
} RollerContactGatherCache;
/* With the Maxwell rubber the residual is viscoelastic (contact_residual_branches.c): a level's slot holds, after r and
   f_C, its coefficients a (r = R a), and per branch b_i and w_i = R b_i; hist is the new level's r before its force,
   from the level two back (from); kappa the branches' deviatoric share of the residual's stiffness. */
typedef struct {
  PetscReal       *R;
  PetscReal       *wc;
  PetscReal       *u0;    /* 3 x 2 nc during the set-up: the initial levels' Gamma_C displacements (NULL from rest) */
  PetscInt         nslot; /* the vectors that carry a residual ((2 + (nb ? 1 + 2 nb : 0)) x 2 nc reals each), by object id */
  PetscObjectId    id[ROLLER_RESIDUAL_SLOTS];
  PetscReal       *slot[ROLLER_RESIDUAL_SLOTS];
  PetscInt         nb;                                                      /* branches (0: the elastic residual) */
  PetscReal        kappa, g[ROLLER_MAX_BRANCHES], rho[ROLLER_MAX_BRANCHES]; /* rho_i = dt/tau_i (the midpoint rule over 2 dt) */
  PetscReal        cinv;                                                    /* 1/C: the flexibility of a step's force, R/C */
  PetscReal       *hist;                                                    /* 2 nc */
  const PetscReal *from;                                                    /* the slot of the level two back (NULL: at rest) */
} RollerContactResidual;

PETSC_INTERN PetscErrorCode RollerContactReducedGather(RollerContact, Vec, Vec);
PETSC_INTERN PetscErrorCode RollerContactReducedForce(RollerContact, const PetscReal[], const PetscReal[], Vec);
PETSC_INTERN void           RollerContactReducedWindow(Roller, RollerContact);
PETSC_INTERN PetscErrorCode RollerContactReducedColumns(RollerContact, Mat, PetscInt, PetscReal[]);
PETSC_INTERN PetscErrorCode RollerContactReducedDestroy(RollerContact);
PETSC_INTERN PetscErrorCode RollerContactReducedResidual(RollerContact, const RollerContactResult *, Vec); /* r = R f_C on xi */
PETSC_INTERN void           RollerContactReducedAddFlexibility(RollerContact, PetscInt, PetscReal[]);      /* S's column j += R's */
PETSC_INTERN PetscErrorCode RollerContactReducedAddResidual(RollerContact, Vec, Vec);                      /* a gather's red += r of q */
PETSC_INTERN PetscErrorCode RollerContactResidualDestroy(RollerContact);
PETSC_INTERN PetscErrorCode RollerContactResidualGatherFull(RollerContact, Vec, PetscReal[]);                                         /* Gamma_C rows of a full-layout Vec */
PETSC_INTERN PetscErrorCode RollerContactResidualOf(RollerContact, Vec, PetscReal **);                                                /* a level's (r, f_C), or NULL */
PETSC_INTERN PetscErrorCode RollerContactResidualKeep(RollerContact, Vec, PetscReal **);                                              /* ... kept for the Vec (made if none), zeroed */
PETSC_INTERN PetscErrorCode RollerContactResidualBegin(RollerContact, const PetscReal[]);                                             /* before a step's solve: the level two back's slot, R h/C */
PETSC_INTERN PetscErrorCode RollerContactResidualAddHistory(RollerContact, Vec);                                                      /* a free solution's gather += R h/C */
PETSC_INTERN PetscInt       RollerContactResidualSize(RollerContact);                                                                 /* a slot's reals */
PETSC_INTERN void           RollerContactResidualBranchesUpdate(RollerContact, PetscReal[]);                                          /* a, b_i, w_i of a new level from r, f_C and from */
PETSC_INTERN void           RollerContactResidualLevelEnergy(RollerContact, const PetscReal[], PetscReal *);                          /* e = 1/2 a . r + kappa/2 sum g_i (a - b_i) . (r - w_i) */
PETSC_INTERN void           RollerContactResidualBranchDissipation(RollerContact, const PetscReal[], const PetscReal[], PetscReal *); /* of the branches' update between two levels */

#endif
