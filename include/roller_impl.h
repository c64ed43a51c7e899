/* The Roller context and the functions the source files share. One concern per file:
     options.c        parameters, validation, -help                      (docs/model.md section 6)
     accuracy.c       the default dt and h from -ts_phase_error           (docs/model.md section 6.2)
     mesh.c           gmsh annulus (C API or file), labels, validation
     partition.c      METIS partition of the cell graph, distribution
     geometry.c       curved (isoparametric P2) boundary
     discretization.c PetscFE spaces, Dirichlet boundary, M, K, A, loads   (docs/model.md sections 2-3)
     kernels.h        pointwise FE kernels
     forcing.c        theta(t), the explicit Euler/centrifugal/Coriolis load (docs/model.md section 1)
     step.c           one DMF step                                        (docs/model.md section 2)
     contact*.c       the obstacle QP in rotated contact coordinates       (docs/model.md section 2)
     diagnostics.c    R, alpha, energy                                    (docs/model.md section 4)
     driver.c         the time loop, monitors, progress line
     output.c         HDF5 fields (output_csv.c the CSV, output_xdmf.c the XDMF index, output.h)
     output_files.c   .part files renamed on success, stale outputs, writable paths
     checkpoint.c     checkpoint and restart, signals */
#ifndef ROLLER_IMPL_H
#define ROLLER_IMPL_H

#include <roller.h>
#include <petsctao.h>
#include <petscsnes.h>
#include <petscds.h>
#include <petscsf.h>

typedef enum { ROLLER_IC_REST, ROLLER_IC_BUMP, ROLLER_IC_MMS } RollerInitialCondition;
PETSC_EXTERN const char *const RollerInitialConditions[];

/* Manufactured solutions used to verify the discretization (docs/validation.md). */
typedef enum { ROLLER_MMS_NONE, ROLLER_MMS_LINEAR, ROLLER_MMS_SINE } RollerMMSType;
PETSC_EXTERN const char *const RollerMMSTypes[];

/* The velocity in the explicit Coriolis term of f^{k-1}: the paper's backward difference
   (xi^{k-1} - xi^{k-2})/dt (first order in time when theta' != 0), the second-order extrapolation
   (3 xi^{k-1} - 4 xi^{k-2} + xi^{k-3})/(2 dt), or the implicit centred (xi^k - xi^{k-2})/(2 dt), which
   does no work and is unconditionally stable but makes A non-symmetric (docs/model.md, docs/stability.md). */
typedef enum { ROLLER_CORIOLIS_BACKWARD, ROLLER_CORIOLIS_EXTRAPOLATED, ROLLER_CORIOLIS_CENTERED } RollerCoriolisVelocity;
PETSC_EXTERN const char *const RollerCoriolisVelocities[];

typedef struct _n_RollerContact *RollerContact;
typedef struct _n_RollerOutput  *RollerOutput;

/* Indices into ctx->stage for -log_view. */
enum { ROLLER_STAGE_SETUP, ROLLER_STAGE_STEP, ROLLER_STAGE_CONTACT, ROLLER_STAGE_DIAGNOSTICS, ROLLER_STAGE_OUTPUT, ROLLER_NUM_STAGES };

/* What the diagnostics of one step give (docs/model.md section 6, CSV columns and extras). */
typedef struct {
  PetscReal R, alpha, energy;
  PetscInt  contact_nodes;
  PetscReal contact_force, gap_min;
  PetscInt  qp_iterations;
  PetscReal kkt_residual;
} RollerStepInfo;

struct _n_Roller {
  MPI_Comm comm;

  /* Geometry and mesh */
  PetscReal r_inner, r_outer, mesh_h;
  PetscBool mesh_h_set; /* -mesh_h given; otherwise chosen from -ts_phase_error (accuracy.c) */
  char      mesh_file[PETSC_MAX_PATH_LEN];
  PetscBool partition_view;
  DM        dm;
  DM        dm_view;         /* the straight-sided mesh written to HDF5/XDMF (ctx->dm itself unless curved) */
  PetscBool curved;          /* P2 geometry with Gamma_D, Gamma_C on their circles (geometry.c) */
  PetscReal boundary_length; /* |Gamma_C| of the discrete (polygonal or curved) outer circle */

  /* Discretization */
  PetscInt               degree;      /* Lagrange degree, 1 (the paper) or 2 */
  PetscBool              clamp_outer; /* xi = 0 on Gamma_C too (Theorem 1 setting) */
  RollerCoriolisVelocity coriolis;

  /* Material */
  PetscReal young, poisson, density, lambda, mu;

  /* Driving rotation theta(t) = omega t + a cos(b t) */
  PetscReal omega, theta_a, theta_b;

  /* Obstacle g(t) = min(speed t, depth) - r_outer, damping eta */
  PetscBool obstacle;
  PetscReal obstacle_speed, obstacle_depth, damping;
  PetscBool static_solve; /* -static: the rest state at the obstacle of t = max_time in one step, A = K */

  /* Time */
  PetscReal dt, max_time;
  PetscBool dt_set;              /* -ts_dt given; otherwise chosen from -ts_phase_error (accuracy.c) */
  PetscReal phase_error;         /* -ts_phase_error: the accuracy target that sets the default dt and h */
  PetscBool discretization_view; /* print the chosen discretization and why */
  PetscInt  max_steps;
  PetscBool quiet;

  /* Checkpoint and restart */
  char     checkpoint[PETSC_MAX_PATH_LEN], restart[PETSC_MAX_PATH_LEN];
  PetscInt checkpoint_every;

  /* Initial state and verification */
  RollerInitialCondition ic;
  PetscReal              ic_amplitude;
  RollerMMSType          mms;

  /* Operators: mass M, stiffness K, step matrix A = rho/dt^2 M + K/2 (+ eta/(2 dt) M), all on the
     free (non-Dirichlet) dofs; loads of the rigid-body parts of f: L_euler = M-load of R(-pi/2) x,
     L_centrifugal = M-load of x (exact integrals, docs/model.md section 2). */
  Mat M, K, A;
  Mat G, A0; /* centred Coriolis only: the gyroscopic matrix and the symmetric part of A */
  Vec L_euler, L_centrifugal;
  Vec coordinates; /* nodal positions x_n of every free dof pair */
  KSP ksp;

  /* History: xi^k (xi), xi^{k-1} (xi1), xi^{k-2} (xi2), xi^{k-3} (xi3, extrapolated Coriolis only);
     K xi of the last two levels; work */
  Vec       xi, xi1, xi2, xi3, Kxi1, Kxi2, rhs, work;
  PetscInt  step;
  PetscReal time;

  /* Boundary functionals: R = w_R . xi, alpha = w_alpha . xi (exact integrals over discrete Gamma_C) */
  Vec w_R, w_alpha;

  RollerContact  contact;
  RollerOutput   output;
  RollerStepInfo info;

  PetscLogStage stage[ROLLER_NUM_STAGES];
};

/* options.c */
PETSC_INTERN PetscErrorCode RollerLameFromYoung(PetscReal, PetscReal, PetscReal *, PetscReal *);

/* mesh.c, partition.c: ctx->dm becomes the distributed annulus with labels "inner" (Gamma_D) and
   "outer" (Gamma_C), each marking faces and their closure (vertices) with value 1. With a mesh file,
   ctx->r_inner and ctx->r_outer are measured from it. */
PETSC_INTERN PetscErrorCode RollerMeshCreate(Roller);
PETSC_INTERN PetscErrorCode RollerMeshDistribute(Roller);
PETSC_INTERN PetscErrorCode RollerMeshMeasure(Roller);
PETSC_INTERN PetscErrorCode RollerMeshOwnedMask(DM, PetscBool **); /* PETSC_TRUE at the points this rank owns */
PETSC_INTERN PetscErrorCode RollerGeometrySetUp(Roller);           /* geometry.c: curved boundary with -degree 2 */

/* discretization.c */
PETSC_INTERN PetscErrorCode RollerDiscretizationSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerDirectSolverDefaults(KSP, PCType); /* preonly + factorization: ND serial, MUMPS parallel */
PETSC_INTERN PetscErrorCode RollerSetConstants(Roller, PetscReal, PetscReal, PetscReal, PetscReal);
PETSC_INTERN PetscErrorCode RollerUpdateGyroscopic(Roller, PetscReal);
PETSC_INTERN PetscErrorCode RollerOperatorsSetUp(Roller);
PETSC_INTERN PetscErrorCode RollerComputeBoundaryFunctionals(Roller);

/* forcing.c: theta and its derivatives; the load rho (f^{k-1}, v) of docs/model.md section 2 */
PETSC_INTERN void           RollerTheta(Roller, PetscReal, PetscReal *, PetscReal *, PetscReal *);
PETSC_INTERN PetscReal      RollerObstacleHeight(Roller, PetscReal);
PETSC_INTERN PetscErrorCode RollerApplyRotate90(Vec, Vec);
PETSC_INTERN PetscErrorCode RollerAddMMSLoad(Roller, PetscReal, Vec);
PETSC_INTERN PetscErrorCode RollerMMSExact(Roller, PetscReal, Vec);

/* step.c */
PETSC_INTERN PetscErrorCode RollerInitialState(Roller);
PETSC_INTERN PetscErrorCode RollerStep(Roller);

/* contact.c: the obstacle QP (only built when -obstacle is on) */
PETSC_INTERN PetscErrorCode RollerContactCreate(Roller, RollerContact *);
PETSC_INTERN PetscErrorCode RollerContactHelp(Roller); /* -help without -obstacle: the options block only */
PETSC_INTERN PetscErrorCode RollerContactSolve(Roller, RollerContact, PetscReal, Vec, Vec);
PETSC_INTERN PetscErrorCode RollerContactInfo(Roller, RollerContact, Vec, PetscReal, RollerStepInfo *);
PETSC_INTERN PetscErrorCode RollerContactPressure(Roller, RollerContact, Vec); /* into a P1 scalar Vec on the mesh */
PETSC_INTERN PetscErrorCode RollerContactDestroy(RollerContact *);

/* accuracy.c: the default -mesh_h and -ts_dt from the accuracy target -ts_phase_error */
PETSC_INTERN PetscErrorCode RollerModeFrequencies(Roller, PetscReal *, PetscReal *);
PETSC_INTERN PetscErrorCode RollerChooseMeshSize(Roller);
PETSC_INTERN PetscErrorCode RollerChooseTimeStep(Roller);

/* stability.c */
PETSC_INTERN PetscErrorCode RollerCheckRotation(Roller);

/* checkpoint.c */
PETSC_INTERN PetscErrorCode RollerCheckpointWrite(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerCheckpointRead(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerCheckpointDiscretization(Roller, const char *);
PETSC_INTERN PetscErrorCode RollerSignalsInstall(void);
PETSC_INTERN PetscErrorCode RollerSignalCaught(Roller, PetscInt *);

/* diagnostics.c */
PETSC_INTERN PetscErrorCode RollerComputeStepInfo(Roller);
PETSC_INTERN PetscErrorCode RollerComputeErrors(Roller, PetscReal, PetscReal *, PetscReal *);

/* series.c: the diagnostics time series written into the HDF5 output */
typedef struct _n_RollerSeries *RollerSeries;
PETSC_INTERN PetscErrorCode     RollerSeriesAppend(Roller, RollerSeries *);
PETSC_INTERN PetscErrorCode     RollerSeriesWrite(Roller, RollerSeries, PetscViewer);
PETSC_INTERN PetscErrorCode     RollerSeriesDestroy(RollerSeries *);

/* output_files.c: output that must not look complete before it is (CSV, HDF5, XDMF, checkpoint) */
PETSC_INTERN PetscErrorCode RollerJoinPath(char[], size_t, const char[], const char[], const char[]);
PETSC_INTERN PetscErrorCode RollerRenameFile(MPI_Comm, const char[], const char[]);
PETSC_INTERN PetscErrorCode RollerRemoveStale(MPI_Comm, const char[]);
PETSC_INTERN PetscErrorCode RollerCheckWritable(MPI_Comm, const char[], const char[]);

/* output.c, output_csv.c, output_xdmf.c */
PETSC_INTERN PetscErrorCode RollerOutputCreate(Roller, RollerOutput *);
PETSC_INTERN PetscErrorCode RollerOutputStep(Roller, RollerOutput);
PETSC_INTERN PetscErrorCode RollerOutputDestroy(Roller, RollerOutput *);

#endif
