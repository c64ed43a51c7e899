/* The model layer (docs/model.md sections 1-4, 6.2):
     material.c     -young, -poisson, -density, -rubber, -viscosity, the Lame constants, the material constants of the kernels
     rubber.c       -rubber maxwell: the branches (fitted to a loss factor over a band, or given), G*(w), -ts_view
     forcing.c      the rotation theta(t) (-omega, -theta_a, -theta_b), the obstacle height g(t), R(-pi/2)
     fe.c           the discretization options, the PetscFE space and Dirichlet boundary, one DM per operator
     operators.c    M, K, G, the rigid-body loads, the load assembly, the nodal positions
     mass.c         -contact_mass, the massless contact nodes M_red = T^T M T and their loads T^T L
     mass_transfer.c, mass_layer.c  T: the weights of each Gamma_C node, from the cells around Gamma_C
     solver.c       the step matrices A = c_M M + c_K K of the time schemes, factored once; the defaults of every direct solve
     functionals.c  w_R, w_alpha and |Gamma_C| (boundary integrals on Gamma_C); the orders of the radial displacement
     accuracy.c     the default h from -ts_phase_error, the breathing and torsional frequencies (the time schemes' dt)
     kernels.h      pointwise FE kernels, the one kernel signature, the material constants */
#ifndef ROLLER_MODEL_H
#define ROLLER_MODEL_H

#include <roller_impl.h>
#include "mesh/mesh.h"
#include "model/axle.h"

/* material.c */
PETSC_INTERN PetscErrorCode RollerMaterialSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerLameFromYoung(PetscReal, PetscReal, PetscReal *, PetscReal *);
PETSC_INTERN PetscErrorCode RollerMaterialSetConstants(Roller, PetscDS); /* (lambda, mu), set once */

/* rubber.c: the generalized Maxwell solid (-rubber maxwell, docs/model.md section 1.1) */
PETSC_INTERN void           RollerRubberModulus(PetscInt, const PetscReal[], const PetscReal[], PetscReal, PetscReal, PetscReal *, PetscReal *);                 /* n, tau, g, s = sr + i si -> G*(s)/mu */
PETSC_INTERN void           RollerRubberInstantaneous(const RollerMaterial *, PetscReal *, PetscReal *);                                                         /* lambda, mu of the unrelaxed solid */
PETSC_INTERN PetscErrorCode RollerRubberFit(PetscReal, PetscReal, PetscReal, PetscReal, PetscReal, PetscInt, PetscInt *, PetscReal[], PetscReal[], PetscReal *); /* eta, tau_kv, f1, f2, tol, nmax -> n, tau, g, err */
PETSC_INTERN PetscErrorCode RollerRubberSetUp(Roller, const PetscBool[4], PetscInt, PetscInt, const PetscReal[], PetscInt, const PetscReal[]);
PETSC_INTERN PetscErrorCode RollerRubberView(Roller, PetscInt, const PetscReal[], const char *const[]); /* -ts_view, with G', eta at nw angular frequencies */

/* forcing.c: theta and its derivatives, the obstacle height, R(-pi/2) */
PETSC_INTERN PetscErrorCode RollerRotationSetFromOptions(Roller);
PETSC_INTERN void           RollerTheta(Roller, PetscReal, PetscReal *, PetscReal *, PetscReal *);
PETSC_INTERN PetscReal      RollerSheetPosition(Roller, PetscReal);
PETSC_INTERN PetscReal      RollerObstacleHeight(Roller, PetscReal);
PETSC_INTERN PetscErrorCode RollerApplyRotate90(Roller, Vec, Vec);    /* nodal, or the reduced model's ops.R90 (-rom) */
PETSC_INTERN PetscErrorCode RollerApplyRotation(Vec, PetscReal, Vec); /* cos(phi) x + sin(phi) R(-pi/2) x, nodal */

/* fe.c */
PETSC_INTERN PetscErrorCode RollerDiscretizationSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerDiscretizationSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerOperatorDMCreate(Roller, PetscFE, DM *); /* a clone of ctx->mesh.dm with an empty DS of its own */
PETSC_INTERN PetscErrorCode RollerUnconstrainedDMCreate(Roller, DM *);     /* the same space without the Dirichlet boundary (axle.c) */

/* operators.c */
PETSC_INTERN PetscErrorCode RollerOperatorsSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerAddLoad(DM, Vec);                                                                         /* b += the residual kernel's load on an operator's DM */
PETSC_INTERN PetscErrorCode RollerAssembleMatrix(Roller, const char *, PetscPointJac, PetscPointJac, PetscPointJac, Mat *); /* g0, g1, g3 on its own DM */
PETSC_INTERN PetscErrorCode RollerAssembleLoad(Roller, PetscPointFunc, Vec *);                                              /* (f0, v) on its own DM */

/* mass.c, mass_transfer.c */
PETSC_INTERN PetscErrorCode RollerMassSetFromOptions(Roller);  /* after the obstacle's options: the default follows -obstacle */
PETSC_INTERN PetscErrorCode RollerMassTransfer(Roller, Mat *); /* T, or NULL for -contact_mass consistent */
PETSC_INTERN PetscErrorCode RollerMassTransferCreate(Roller, Mat *);
PETSC_INTERN PetscErrorCode RollerMassReduce(Mat, PetscReal, Mat *);  /* B <- T^T B T, symmetric (+1) or skew (-1) */
PETSC_INTERN PetscErrorCode RollerMassReduceLoad(Mat, Vec);           /* L <- T^T L */
PETSC_INTERN PetscErrorCode RollerMassReducePattern(Mat, Mat, Mat *); /* G <- T^T G T (skew) on A's pattern, widened */

/* solver.c: the step matrices of the time schemes */
PETSC_INTERN PetscErrorCode RollerStepOperatorCreate(Roller, PetscReal, PetscReal, PetscReal, Mat, PetscReal, PetscInt, RollerStepOperator *); /* c_M, c_K, c_D, G or NULL, c_G, id */
PETSC_INTERN PetscErrorCode RollerStepOperatorUpdateGyroscopic(RollerStepOperator *, PetscReal);
PETSC_INTERN PetscErrorCode RollerStepOperatorSolve(Roller, const RollerStepOperator *, Vec, Vec, PetscReal); /* b, x, t (for the message) */
PETSC_INTERN PetscErrorCode RollerStepOperatorDestroy(RollerStepOperator *);
PETSC_INTERN PetscErrorCode RollerDirectSolverDefaults(KSP, PCType); /* preonly + factorization: ND serial, MUMPS parallel */
PETSC_INTERN PetscErrorCode RollerSchurPCSet(PC);                    /* solver_schur.c: the substructured Cholesky of an SPD MPIAIJ matrix */

/* functionals.c */
PETSC_INTERN PetscErrorCode RollerComputeBoundaryFunctionals(Roller);
PETSC_INTERN PetscErrorCode RollerComputeOrderFunctionals(Roller, PetscInt, Vec[]); /* 2 N vectors: orders 1..N, cos and sin */

/* accuracy.c: the default -mesh_h from the accuracy target -ts_phase_error, the modes that set it and dt */
PETSC_INTERN PetscErrorCode RollerModeFrequencies(Roller, PetscReal *, PetscReal *);
PETSC_INTERN PetscReal      RollerEndTime(Roller, PetscReal);                                          /* -ts_max_time, at least one period of w */
PETSC_INTERN PetscErrorCode RollerRadialModes(Roller, PetscInt, PetscReal[], PetscReal[], PetscInt *); /* nmax, w_j, a_j (sum 1), n */
PETSC_INTERN PetscErrorCode RollerChooseMeshSize(Roller);

#endif
