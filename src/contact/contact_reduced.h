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
typedef struct {
  PetscReal    *R;
  PetscReal    *wc;
  PetscReal    *u0;    /* 3 x 2 nc during the set-up: the initial levels' Gamma_C displacements (NULL from rest) */
  PetscInt      nslot; /* the vectors that carry a residual (r, f_C: 4 nc reals each), by object id */
  PetscObjectId id[ROLLER_RESIDUAL_SLOTS];
  PetscReal    *slot[ROLLER_RESIDUAL_SLOTS];
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
PETSC_INTERN PetscErrorCode RollerContactResidualGatherFull(RollerContact, Vec, PetscReal[]); /* Gamma_C rows of a full-layout Vec */
PETSC_INTERN PetscErrorCode RollerContactResidualOf(RollerContact, Vec, PetscReal **);        /* a level's (r, f_C), or NULL */
PETSC_INTERN PetscErrorCode RollerContactResidualKeep(RollerContact, Vec, PetscReal **);      /* ... kept for the Vec (made if none), zeroed */

#endif
