/* The modes layer (docs/squeal.md): the quadratic eigenproblem of the annulus by SLEPc's PEP.
     pep.c        (lambda^2 M + lambda C + K) x = 0 for any (M, C, K): TOAR, shift-and-invert, pairs sorted by frequency
     operators.c  M, C, K of the free rotating annulus in the co-rotating or the lab (Eulerian) frame
     rotational.c the lab frame's damping of the objective rate: A_L = a(L u, v) (cells and edges), B_L = (L u, v)
                  (rotational_edges.c its edge terms, rotational_element.c the pointwise pieces both use)
     classify.c   the circumferential order n and the travelling direction of a mode shape
     steady.c     the steady rolling/sliding state pressed by the sheet (lab frame), one static contact problem
     steady_coulomb.c  its contact law: normal LCP and tangential stick/slip active set, alternated
     squeal.c     the linearization about it: contact, friction (non-symmetric), velocity weakening (damping)
     axle_modes.c with -axle: the hub's (Y, phi) bordering M, C, K; the steady state at -nip_force
     modes.c      -modes: the options, the solve, the eigenvalue CSV and the shapes (io/output_modes.c) */
#ifndef ROLLER_MODES_H
#define ROLLER_MODES_H

#include <roller_impl.h>
#include <slepcpep.h>
#include "model/model.h"
#include "io/io.h"
#include "friction/friction.h"

/* pep.c: the converged eigenpairs with im >= 0 (one of each conjugate pair), sorted by frequency im, then re. */
typedef struct _n_RollerPEP *RollerPEP;
PETSC_INTERN PetscErrorCode RollerPEPCreate(MPI_Comm, Mat, Mat, Mat, PetscInt, PetscBool, const PetscReal[2], RollerPEP *); /* M, C, K, nev (-pep_* may override), pivoting LU, the band [r_lo, r_hi] of decay rates whose overdamped eigenvalues are left out (or NULL) */
PETSC_INTERN PetscErrorCode RollerPEPSolve(RollerPEP, PetscInt *);                                                          /* the number of pairs kept */
PETSC_INTERN PetscErrorCode RollerPEPGetPair(RollerPEP, PetscInt, PetscReal *, PetscReal *, Vec, Vec);                      /* re, im, x_re, x_im (vectors may be NULL) */
PETSC_INTERN PetscErrorCode RollerPEPGetError(RollerPEP, PetscInt, PetscReal *);                                            /* backward error of pair i */
PETSC_INTERN PetscErrorCode RollerPEPDestroy(RollerPEP *);

/* operators.c: the (M, C, K) of the linearized free annulus in ctx->eig.frame (docs/squeal.md section 1) */
PETSC_INTERN PetscErrorCode RollerModeOperators(Roller, Mat *, Mat *, Mat *);

/* branches.c: the Maxwell branches' augmented state (xi, z_1, ..., z_n) (docs/squeal.md section 1.2): the frame's
   (M, C, K) replaced by the augmented ones (unchanged without -rubber maxwell); the xi part of an augmented vector (the
   leading local entries), an augmented vector of xi and zero branches */
PETSC_INTERN PetscErrorCode RollerBranchOperators(Roller, Mat, Mat *, Mat *, Mat *);    /* the bordered K_d of -axle, NULL: the clamped body */
PETSC_INTERN PetscErrorCode RollerBranchSteadyStiffness(Roller, Mat, PetscBool, Mat *); /* the lab K of the steady state (the branches transported) */
PETSC_INTERN PetscErrorCode RollerBranchRestrict(Vec, Vec);
PETSC_INTERN PetscErrorCode RollerBranchExtend(Vec, Vec);
PETSC_INTERN PetscBool      RollerBranchRelaxationBand(Roller, PetscReal[2]);                 /* the decay rates [r_lo, r_hi] of the relaxation spectrum */
PETSC_INTERN PetscErrorCode RollerBranchLossFactor(Roller, Vec, Vec, PetscReal, PetscReal *); /* the rubber's loss factor of the shape xr + i xi at w */

/* rotational.c: the damped lab frame's forms of the rotational rate L u = d_phi u - J u (docs/squeal.md section 1.1) */
PETSC_INTERN PetscErrorCode RollerAssembleRotationalElastic(Roller, Mat *, PetscReal *); /* A_L = a(L u, v): cells + edges; the cells' skewness defect */
PETSC_INTERN PetscErrorCode RollerAssembleRotationalMass(Roller, Mat *);                 /* B_L = (L u, v) = D + G */
PETSC_INTERN PetscErrorCode RollerSkewPart(Mat, PetscReal *);                            /* A <- (A - A^T)/2; ||A + A^T|| / ||A|| */

/* classify.c: the dominant circumferential order n >= 0 and the wave (forward: travelling with the rotation) of
   the mode x_re + i x_im, e^{lambda t}, im >= 0; from the mass-weighted Fourier spectrum over the nodes */
typedef enum { ROLLER_WAVE_FORWARD, ROLLER_WAVE_BACKWARD, ROLLER_WAVE_STANDING } RollerWave;
PETSC_EXTERN const char *const          RollerWaves[];
typedef struct _n_RollerModeClassifier *RollerModeClassifier;
PETSC_INTERN PetscErrorCode             RollerModeClassifierCreate(Roller, RollerModeClassifier *);
PETSC_INTERN PetscErrorCode             RollerModeClassify(RollerModeClassifier, Vec, Vec, PetscInt *, RollerWave *);
PETSC_INTERN PetscErrorCode             RollerModeClassifierDestroy(RollerModeClassifier *);

/* steady.c: the steady rolling/sliding state in the lab frame (docs/squeal.md section 3): the Gamma_C nodes within
   reach of the sheet (sorted by angle; x dof at dof[j], y at dof[j] + 1; positions xy), their normal and tangential
   forces, mu(v), mu'(v), slip speeds, gaps and states (0 off the sheet, 1 stick, 2 slip), the state u; the
   scatter to the candidates */
typedef struct {
  PetscInt             n, *dof, *state, iterations, alternations, active_set;
  PetscReal           *xy, *normal, *tangent, *mu, *dmu, *slip, *gap;
  RollerSlipDifference difference;
  Vec                  u, red;
  VecScatter           scatter;
} RollerSteady;
PETSC_INTERN PetscErrorCode RollerSteadySolve(Roller, Mat, RollerSteady *);                                                                    /* with K_lab */
PETSC_INTERN PetscErrorCode RollerSteadyKSPCreate(Roller, Mat, KSP *);                                                                         /* K_lab's direct solver, for repeated solves */
PETSC_INTERN PetscErrorCode RollerSteadySolveWith(Roller, KSP, RollerSteady *);                                                                /* with that solver (factored once) */
PETSC_INTERN PetscErrorCode RollerSteadyAngularDerivative(const RollerSteady *, PetscReal, PetscInt, PetscInt[3], PetscReal[3], PetscReal[3]); /* the slip's d_phi and point weights, upstream for omega */
PETSC_INTERN PetscErrorCode RollerSteadyDestroy(RollerSteady *, PetscBool);
PETSC_INTERN PetscErrorCode RollerSteadyReport(Roller, const RollerSteady *); /* printed, and -modes_steady_csv */
/* steady_coulomb.c: Coulomb on the candidates' dual data w = G x + d (n, G, d, friction, mu; N, T, state in/out as a
   warm start; the number of normal/tangential alternations, the most stick/slip active-set iterations of one of them) */
PETSC_INTERN PetscErrorCode RollerSteadyCoulomb(MPI_Comm, PetscInt, const PetscReal[], const PetscReal[], PetscBool, const PetscReal[], PetscReal[], PetscReal[], PetscInt[], PetscInt *, PetscInt *);

/* squeal.c: the linearization about the steady state: the reduced (M, C, K) on the dofs but the contact nodes'
   normal ones (and after them, on the last rank, one multiplier per stick node: their number), and the map of a
   reduced vector's first part back to the full space */
PETSC_INTERN PetscErrorCode RollerSquealOperators(Roller, const RollerSteady *, Mat, Mat, Mat, Mat *, Mat *, Mat *, IS *, PetscInt *);

/* axle_modes.c, axle_steady.c: -modes with -axle (docs/squeal.md section 3.1): the hub's lab-frame (Y, phi) appended to
   M, C, K on the last rank (the body's indices unchanged); the steady state at the hub's height that gives -nip_force (and q = Y, phi
   of it, the body's state with the hub's rigid motion); an augmented vector's parts and one with the body's layout */
PETSC_INTERN PetscErrorCode RollerAxleModeOperators(Roller, Mat *, Mat *, Mat *, Mat *); /* and the branches' bordered K_d, or NULL */
PETSC_INTERN PetscErrorCode RollerAxleSteadySolve(Roller, Mat, RollerSteady *, PetscReal[2]);
PETSC_INTERN PetscErrorCode RollerAxleRigidFields(Roller, Vec[2]); /* e2, J x on the free nodes */
PETSC_INTERN PetscErrorCode RollerAxleModeSplit(Vec, Vec, PetscReal[2]);
PETSC_INTERN PetscErrorCode RollerAxleModeRelative(Roller, Vec, const PetscReal[2], Vec); /* the body's shape less the hub's rigid motion */
PETSC_INTERN PetscErrorCode RollerAxleModeVec(Vec, Vec *);

/* modes.c */
PETSC_INTERN PetscErrorCode RollerModesSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerModesSolve(Roller);   /* fills ctx->eig's result; the CSV, the shapes */
PETSC_INTERN PetscErrorCode RollerModesDestroy(Roller); /* frees the result */

#endif
