/* The rigid hub on its axle and drive (-axle, docs/model.md section 10), private to the model, integrate and contact
   layers. The body's displacement xi lives on the free nodes as without -axle (the frame is the motor's, theta(t));
   the hub's motion q = (u1, u2, phi) moves the Gamma_D nodes rigidly, xi = u + phi J x there (J x = (-x2, x1), the
   translation u in the frame's components, phi the hub's rotation against the motor), so the step's unknowns are
   (xi, q) with the bordered matrices
     M_aug = [[M, C_M], [C_M^T, D_M]] (rho) + diag(m, m, I),  K_aug = [[K, C_K], [C_K^T, D_K]] + diag(k, k, k_d),
   C_M = M_fG R_G, C_K = K_fG R_G the couplings of the free rows with Gamma_D's rigid fields R_G, D_* = R_G^T *_GG R_G. The
   hub translates only along the lab's vertical: u = Y n(theta(t)), n = R(theta)^T e2 (a constraint, q = Z p with
   Z = [[n, 0], [0, 1]]). Each step eliminates q (model/solver.c: A_eff = A - C Dz C^T, Dz = Z (Z^T D Z)^{-1} Z^T, its
   inverse by Woodbury from the one factorization of A). */
#ifndef ROLLER_AXLE_H
#define ROLLER_AXLE_H

#include <roller_impl.h>

/* The hub's coupling with the body, computed once at set-up from M, K, the rigid loads and a product with the whole
   body's mass (model/axle.c). The rigid fields r_1 = e1, r_2 = e2, r_3 = J x; R = R(-pi/2). Per unit density. */
typedef struct {
  Vec       CM[3], CK[3];  /* M_fG r_G, K_fG r_G (free rows, nonzero near Gamma_D) */
  Vec       RCM[3];        /* R CM: the rotational loads' pairing C_M . R a = -RCM . a */
  Vec       cx;            /* M_fG x_G: the load of R(-pi/2) r(e_phi) = x on Gamma_D */
  PetscReal DM[9], DK[9];  /* r_G^T M_GG r_G, r_G^T K_GG r_G (row-major 3 x 3) */
  PetscReal dx[3];         /* r_G^T M_GG x_G */
  PetscReal le[3], lc[3];  /* r_G^T (M R(-pi/2) x)_G, r_G^T (M x)_G: the rigid loads on the hub's rows */
  PetscReal mass, inertia; /* the body's mass int 1 and polar moment int |x|^2 (per unit density) */
  Vec       CD[3], RF[3];  /* -rubber maxwell: K_d,fG r_G = -K_d r_f, and the rigid fields r_f themselves (NULL otherwise) */
  PetscReal DD[9];         /* r_G^T K_d,GG r_G */
} RollerHubCoupling;

/* The hub's levels (like ctx->state's: cur = q^{k-1} during a step, then q^k), the products P = (CM . xi, CK . xi,
   RCM . xi, CD . xi) of the body's levels, the Maxwell branches' hub parts zeta_i (the branch field z_i on Gamma_D is the
   rigid field of zeta_i: tau_i zeta_i' = q - zeta_i; indexed like the branches' levels, integrate/scheme_maxwell.c),
   and what a step keeps for its diagnostics. */
typedef struct {
  PetscReal next[3], cur[3], prev[3], prev2[3];
  PetscReal P[3][12]; /* the products of the levels cur, prev, prev2 */
  PetscReal zeta[2][ROLLER_MAX_BRANCHES][3];
  PetscReal bq[3], Dz[9]; /* the step's q right-hand side and Z (Z^T D_A Z)^-1 Z^T */
  PetscReal load[3];      /* the q rows of the step's load F^{k-1} (rotation, preload, anchor) */
  PetscReal reaction[3];  /* the guide's reaction on q of the last step (the constraint's force) */
  PetscReal delta[3];     /* Dz b_q - q^k: C delta completes the body's equation for M xi^k */
  PetscReal anchor[2];    /* 1 once the spring is anchored (the end of -nip_ramp), and Y there (checkpointed) */
  PetscBool jump;         /* anchored at the last step: its balance adds the spring's quadratic energy */
} RollerHubState;

typedef struct _n_RollerHub RollerHub;
struct _n_RollerHub {
  RollerHubCoupling c;
  RollerHubState    s;
};

/* The border of a step matrix (model/solver.c): C = c_M CM + c_K CK, Y = A^{-1} C, C^T Y, and the eliminated hub's
   W = Z (Z^T (D_A - C^T Y) Z)^{-1} Z^T of the current step (A_eff^{-1} = A^{-1} + Y W Y^T). */
struct _n_RollerBorder {
  Vec       C[3], Y[3];
  PetscReal CtY[9], W[9];
};

/* axle.c */
PETSC_INTERN PetscErrorCode RollerAxleSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerAxleSetUp(Roller);           /* after the operators M, K */
PETSC_INTERN PetscErrorCode RollerRigidFields(Roller, Vec[3]); /* e1, e2, J x on the free nodes (new Vecs) */
PETSC_INTERN PetscErrorCode RollerAxleDestroy(Roller);
PETSC_INTERN void           RollerAxleFrame(Roller, PetscReal, PetscReal[2]);                       /* n(theta(t)) */
PETSC_INTERN void           RollerAxleSprings(Roller, PetscReal[9]);                                /* the springs on q */
PETSC_INTERN void           RollerAxleForce(Roller, PetscReal, PetscReal[3]);                       /* the preload and the anchor's force on q at t */
PETSC_INTERN PetscReal      RollerAxleNipForce(Roller, PetscReal);                                  /* the preload at t (ramped) */
PETSC_INTERN void           RollerAxleProject(Roller, PetscReal, const PetscReal[9], PetscReal[9]); /* Z (Z^T D Z)^{-1} Z^T at t */

/* solver.c */
PETSC_INTERN PetscErrorCode RollerStepOperatorSetBorder(Roller, RollerStepOperator *);
PETSC_INTERN PetscErrorCode RollerStepOperatorUpdateBorder(Roller, RollerStepOperator *, PetscReal, const PetscReal[9]); /* t, D_A */
PETSC_INTERN PetscErrorCode RollerBorderDestroy(struct _n_RollerBorder **);

/* small dense helpers (axle.c) */
PETSC_INTERN void      RollerMat3Vec(const PetscReal[9], const PetscReal[3], PetscReal[3]);
PETSC_INTERN PetscReal RollerDot3(const PetscReal[3], const PetscReal[3]);

#endif
