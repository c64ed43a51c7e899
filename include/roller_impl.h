/* The Roller context: its types, shared by every layer. The functions live in one header per layer
   (docs/architecture.md), each of which includes only this file and the headers of lower layers:

     mesh/       the gmsh annulus, METIS partition, curved P2 boundary                 mesh/mesh.h
     model/      kernels, forcing, FE spaces and operators, the accurate defaults      model/model.h
     verify/     manufactured solutions, the rotation stability check                  verify/verify.h
     contact/    the obstacle QP: Gamma_C nodes, candidates, solvers (a registry)      contact/contact.h
     io/         CSV, HDF5 fields, XDMF index, atomic files                            io/io.h
     integrate/  the DMF step, diagnostics, checkpoint, the driver and its observers   integrate/integrate.h
     app/        the Roller object's life (create, options, set-up, destroy), main */
#ifndef ROLLER_IMPL_H
#define ROLLER_IMPL_H

#include <roller.h>
#include <petsctao.h>
#include <petscsnes.h>
#include <petscds.h>
#include <petscsf.h>

/* A real option checked in its component's options block: finite and ok; one message naming the option, its value
   and what is allowed ("" if any finite value is; PETSC_ERR_USER_INPUT: exit non-zero). */
#define RollerCheckOption(comm, name, value, ok, allowed) \
  do { \
    if (PetscUnlikely(PetscIsInfOrNanReal((PetscReal)(value)) || !(ok))) { \
      char value_[32]; \
      snprintf(value_, sizeof(value_), "%g", (double)(value)); \
      SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s %s: must be finite%s%s", name, value_, (allowed)[0] ? " and " : "", allowed); \
    } \
  } while (0)

typedef enum { ROLLER_IC_REST, ROLLER_IC_BUMP, ROLLER_IC_MMS, ROLLER_IC_MODE } RollerInitialCondition;
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

/* The mass of the Gamma_C dofs: the consistent FE mass M, or massless contact nodes M_red = T^T M T
   (model/mass.c, docs/contact.md "Massless contact nodes"). */
typedef enum { ROLLER_CONTACT_MASS_CONSISTENT, ROLLER_CONTACT_MASS_REDISTRIBUTED } RollerContactMass;
PETSC_EXTERN const char *const RollerContactMasses[];

typedef struct _n_RollerContact  *RollerContact;
typedef struct _n_RollerScheme   *RollerScheme;   /* the time scheme (integrate/scheme*.c, docs/model.md section 2.1) */
typedef struct _n_RollerMonitors *RollerMonitors; /* the observers of the run (integrate/monitor.c) */
typedef struct _n_RollerRom      *RollerRom;      /* -rom: the reduced-order model (src/rom, docs/performance.md) */

/* Indices into ctx->stage for -log_view. */
enum { ROLLER_STAGE_SETUP, ROLLER_STAGE_STEP, ROLLER_STAGE_CONTACT, ROLLER_STAGE_DIAGNOSTICS, ROLLER_STAGE_OUTPUT, ROLLER_STAGE_MODES, ROLLER_NUM_STAGES };

/* The friction and drive columns of a step (docs/friction.md): the tangential force of the sheet on the roller
   along e1 (lab), the torque the shaft exerts, the contact nodes that stick and slip, the cumulative works of
   the shaft and the sheet and the cumulative friction dissipation (E^k - E^0 = shaft_work + sheet_work -
   friction_work - the other dissipations), the step's friction dissipation and the contact's parts of the step's
   shaft and sheet works (the rotation and the motion of the sheet), the largest residual of the Coulomb law over
   the contact nodes, the Coulomb fixed point's iterations and its fallback (0 none, 1 the semismooth Newton
   method failed and Tresca passes took over, 2 Lemke's method took over). Zero without friction, except the
   torque and the works. */
typedef struct {
  PetscReal force, torque;
  PetscInt  stick, slip;
  PetscReal shaft_work, sheet_work, work;
  PetscReal dissipation, shaft_step, sheet_step, residual;
  PetscInt  iterations, fallback;
} RollerStepFriction;

/* The axle's columns of a step (docs/model.md section 8): the hub's lab-vertical displacement, its lab angular velocity,
   the drive's torque on it, the sheet's speed. Without -axle: 0, theta'(t), the shaft's torque, -sheet_speed. */
typedef struct {
  PetscReal y, hub_rate, drive_torque, sheet_speed;
} RollerStepAxle;

/* What the diagnostics of one step give (docs/model.md section 6, CSV columns and extras). */
typedef struct {
  PetscReal R, alpha, energy;
  PetscInt  contact_nodes;
  PetscReal contact_force, gap_min;
  PetscInt  qp_iterations;
  PetscReal kkt_residual;
  /* the discrete energy balance of the step (docs/model.md section 2, "Dampings and the energy balance"):
     E^k - E^{k-1} = load_work + obstacle_work - contact_dissipation - damping_dissipation - viscous_dissipation */
  PetscReal          load_work, obstacle_work, contact_dissipation, damping_dissipation, viscous_dissipation;
  PetscInt           contact_flips, contact_reversals; /* Gamma_C nodes whose state (on the obstacle or not) changed from
                                                 t_{k-1} to t_k; of these, those back in their state of t_{k-2} */
  RollerStepFriction friction;
  RollerStepAxle     axle;
} RollerStepInfo;

/* The context, split by lifetime and owner (docs/architecture.md). Each part is filled by the component
   that owns it, from its own options block. */

/* Mesh (src/mesh): the annulus, its labels "inner" (Gamma_D) and "outer" (Gamma_C) */
typedef struct {
  PetscReal r_inner, r_outer, h;
  PetscBool h_set;                    /* -mesh_h given; otherwise chosen from -ts_phase_error (model/accuracy.c) */
  PetscReal h_contact, contact_layer; /* graded toward Gamma_C: edge h_c within distance L of it (0: uniform; mesh/generate.c) */
  PetscBool h_contact_set;            /* -mesh_h_contact given (0 then asks for a uniform mesh); otherwise chosen for contact scenes */
  char      file[PETSC_MAX_PATH_LEN];
  PetscBool partition_view;
  PetscBool curved;          /* P2 geometry with Gamma_D, Gamma_C on their circles (mesh/geometry.c) */
  DM        dm;              /* the distributed mesh and the displacement space */
  DM        dm_view;         /* the straight-sided mesh written to HDF5/XDMF (dm itself unless curved) */
  PetscReal boundary_length; /* |Gamma_C| of the discrete (polygonal or curved) outer circle */
  /* -r_inner, -r_outer given (checked against a mesh file's radii), -mesh_gmsh_verbose, -mesh_view_info (mesh/mesh.c);
     h (and h_contact, contact_layer) from the -restart checkpoint (integrate/checkpoint.c) */
  PetscBool radii_set[2], gmsh_verbose, view_info, h_restart;
} RollerMesh;

/* The rubber's damping (-rubber, docs/model.md section 1.1): Kelvin-Voigt (-viscosity) or a generalized Maxwell solid
   (Prony series) of deviatoric branches, the bulk elastic (model/rubber.c) */
typedef enum { ROLLER_RUBBER_KELVIN_VOIGT, ROLLER_RUBBER_MAXWELL } RollerRubber;
PETSC_EXTERN const char *const RollerRubbers[];
#define ROLLER_MAX_BRANCHES 16

/* Material (set once): plane-strain Lame constants from E, nu (the relaxed, static moduli); with -rubber maxwell the
   branches: shear moduli g_i mu (g_i relative to the relaxed shear modulus mu) relaxing with times tau_i, fitted to the
   loss factor loss_factor over the band [band[0], band[1]] (cycles per unit time; fit_error: the largest relative error
   of the fitted loss factor over the band) or given (loss_factor 0) */
typedef struct {
  PetscReal    young, poisson, density, lambda, mu;
  PetscReal    viscosity; /* tau of Kelvin-Voigt damping sigma = C:(eps + tau eps_t) */
  RollerRubber rubber;
  PetscInt     nbranch;
  PetscReal    tau[ROLLER_MAX_BRANCHES], g[ROLLER_MAX_BRANCHES];
  PetscReal    band[2], loss_factor, fit_error;
} RollerMaterial;

/* The driving rotation theta(t) = omega (t - t0) + a cos(b (t - t0)) from t0 = -theta_start on, theta = a before; with
   -drive_ramp T the speed rises smoothly from 0 to omega over [t0, t0 + T], and -drive_ripple adds the motor's ripple
   ripple s(t) sin(2 pi f (t - t0)) (s the ramp's speed fraction) at -drive_ripple_frequency f (model/forcing.c). With -axle
   this is the motor's angle; without, the hub's. */
typedef struct {
  PetscReal omega, a, b, start;
  PetscReal ramp, ripple, ripple_frequency;
} RollerRotation;

/* -friction_table (friction/law.c): n points (v_i, mu_i) of the friction coefficient mu(|v|), 0 <= v_1 < ... < v_n,
   and the slopes s_i of their monotone cubic interpolant; n = 0 without it */
typedef struct {
  PetscInt   n;
  PetscReal *v, *mu, *s;
} RollerFrictionTable;

/* The obstacle (the sheet): height g(t) = min(speed t, depth) - r_outer, lab-frame position X(t) = sheet_speed t
   along e1, and Coulomb friction mu(v) = mu + (mu_s - mu) exp(-|v|/v_c) (friction = 0: frictionless; decay = 0:
   constant mu), or the interpolant of a table (then friction = mu_n, its value beyond the last speed, and
   friction_static = mu_1, its value at rest; decay 0) */
typedef struct {
  PetscBool           on;
  PetscReal           speed, depth, sheet_speed;
  PetscReal           friction, friction_static, friction_decay;
  RollerFrictionTable table;
  PetscReal           sheet_mass, sheet_resistance; /* -sheet_mass: the sheet moves by its own forces (contact/contact_sheet.c); 0: kinematic */
} RollerObstacle;

/* The axle and drive (-axle, model/axle.c, docs/model.md section 8): the hub a rigid body that translates (mass,
   vertical spring preloaded to the nip force per unit width, ramped in over nip_ramp, and a stiff horizontal spring: the
   bracket) and turns (inertia), driven through a torsional spring and damper by the motor, whose angle is the
   frame's theta(t). Off: the hub is clamped to theta(t), as before. hub: the rigid hub's coupling with the body and its
   state (model/axle.h), NULL when off. */
typedef struct {
  PetscBool            on;
  PetscReal            mass, inertia, stiffness, stiffness_x, nip_force, nip_ramp;
  PetscReal            drive_stiffness, drive_damping;
  PetscReal            kick, kick_time; /* -drive_kick: an angular impulse on the hub at one level, the nearest to kick_time */
  struct _n_RollerHub *hub;
} RollerAxle;

/* The discretization choices (model/fe.c) */
typedef struct {
  PetscInt               degree;      /* Lagrange degree, 1 (the paper), 2 or 3 */
  PetscBool              degree_set;  /* -degree given (else P3 without -obstacle, P2 with: RollerChooseMeshSize) */
  PetscBool              clamp_outer; /* xi = 0 on Gamma_C too (Theorem 1 setting) */
  RollerCoriolisVelocity coriolis;
  PetscReal              damping;       /* eta of the DMF functional */
  PetscBool              static_solve;  /* -static: the rest state at the obstacle of t = max_time in one step, A = K */
  RollerContactMass      contact_mass;  /* -contact_mass (model/mass.c) */
  PetscBool              schur;         /* on several ranks, SPD step matrices by substructuring (model/solver_schur.c) */
  PetscInt               schur_ranks;   /* on groups of at most this many ranks, each group a copy (PCREDUNDANT) */
  PetscInt               redundant_max; /* the others: up to this many unknowns factored whole on every rank, larger ones by MUMPS (model/solver.c) */
} RollerDiscretization;

/* Operators fixed at set-up (model/operators.c): mass M, stiffness K (the step matrices are the time scheme's,
   RollerStepOperator), all on the free (non-Dirichlet) dofs; loads of the rigid-body parts of f: L_euler = M-load
   of R(-pi/2) x, L_centrifugal = M-load of x (exact integrals, docs/model.md section 2); the boundary
   functionals R = w_R . xi, alpha = w_alpha . xi. With -contact_mass redistributed M is M_red = T^T M T, G is
   T^T G T and the loads are T^T L (model/mass.c). */
typedef struct {
  Mat       M, K;
  Mat       Kd; /* with -rubber maxwell: the deviatoric stiffness at the relaxed shear modulus, int 2 mu dev eps[u] : dev eps[v] (else NULL) */
  Mat       G;  /* the gyroscopic matrix int rho N^T R(pi/2) N: only for the centred Coriolis velocity (its step matrix) */
  Vec       L_euler, L_centrifugal;
  Vec       coordinates; /* nodal positions x_n of every free dof pair */
  PetscReal I0;          /* x . M x, the rigid body's polar moment over rho (the shaft torque, integrate/diagnostics.c) */
  Vec       w_R, w_alpha;
  /* -rom (src/rom): M, K, the loads, w_R, w_alpha and the state are the reduced model's; R90 its R(-pi/2) on M products
     (NULL: the nodal one), V its basis in the full space (the modes' shapes), M_full the full model's M (their
     classification); reduced: PETSC_TRUE then */
  Mat       R90, V, M_full;
  PetscBool reduced;
} RollerOperators;

/* A step matrix of a time scheme (model/solver.c): A = c_M M + c_K K + c_D K_d (- c_G G with the centred Coriolis term,
   which makes it non-symmetric: LU), factored once; c_D K_d: the Maxwell branches (ops.Kd; 0 without them). A scheme
   has one or a fixed few (integrate/scheme*.c); the contact layer keeps its condensation S = E^T A^{-1} E per
   operator, by id. */
typedef struct {
  Mat                     A, A0, G; /* A0 = c_M M + c_K K + c_D K_d and G: only with the centred Coriolis term (A = A0 - c_G G, re-made when theta' varies) */
  KSP                     ksp;
  PetscReal               c_M, c_K, c_D;
  PetscInt                id;
  struct _n_RollerBorder *border; /* -axle: the hub's unknowns eliminated, A_eff = A - C Dz C^T (model/axle.h); NULL otherwise */
} RollerStepOperator;

/* Time stepping (integrate/timestep.c) */
typedef struct {
  PetscReal      dt, max_time;
  PetscBool      dt_set;                     /* -ts_dt given (or from the checkpoint); otherwise chosen from -ts_phase_error (model/accuracy.c) */
  PetscBool      dt_restart, scheme_restart; /* dt, the scheme from the -restart checkpoint (integrate/checkpoint.c) */
  PetscReal      phase_error;                /* -ts_phase_error: the accuracy target that sets the default dt and h */
  PetscBool      view;                       /* -ts_view: print the chosen discretization and why */
  PetscInt       max_steps;
  PetscReal      max_wall;       /* -ts_max_wall: stop with a checkpoint before this many seconds of the process (0: none) */
  PetscLogDouble wall_start;     /* the process's start (integrate/timestep.c) */
  PetscBool      quiet, monitor; /* -quiet: no progress line; -ts_monitor: a line every step */
  char           scheme[64];     /* -ts_scheme (empty: the one that meets -ts_phase_error with the fewest solves) */
  RollerScheme  *schemes;        /* every registered scheme, set from options; the run's is chosen at set-up */
  PetscInt       nschemes;
} RollerTimeParams;

/* The lowest radial breathing and torsional angular frequencies of the annulus (model/accuracy.c) and the radii
   they were computed for (0: not yet): computed once, shared by the default h and the default dt */
typedef struct {
  PetscReal r_inner, r_outer, breathing, torsion;
} RollerModes;

/* The integrator state: during a step, cur = xi^{k-1}, prev = xi^{k-2}, prev2 = xi^{k-3} (extrapolated Coriolis)
   and next receives xi^k; after it the levels move up one (next is then free, a scratch vector between steps).
   K xi of the last three levels, M xi^k, and the velocity of the newest level (the one-step schemes' own state;
   (xi^k - xi^{k-1})/dt for the three-level ones); the right-hand side, the external load F^{k-1} of the last step
   (its work closes the energy balance, integrate/diagnostics.c) and a work vector. */
typedef struct {
  Vec       next, cur, prev, prev2, Kcur, Kprev, Kprev2, Mcur, velocity, rhs, load, work;
  PetscInt  step;
  PetscReal time;
  /* the cumulative works of the CSV (shaft, sheet, friction dissipation) up to step work_step, the angular momentum of
     level momentum_step and of the level before (checkpointed), the step ctx->info describes (-1: not made yet; it is
     made when an observer asks: integrate/diagnostics.c) */
  PetscReal works[3], momentum[2];
  PetscInt  work_step, momentum_step, info_step;
} RollerState;

/* Modes (src/modes, docs/squeal.md): -modes solves the quadratic eigenproblem of the scene instead of stepping;
   the frame of the linearization, the eigenvalue CSV and the shapes' HDF5 file */
typedef enum { ROLLER_FRAME_ROTATING, ROLLER_FRAME_LAB } RollerFrame;
PETSC_EXTERN const char *const RollerFrames[];
/* The steady state's slip speed along Gamma_C (RollerSteadyAngularDerivative): box (candidate j and its upstream
   neighbour, the slip at their midpoint), upwind (the same two points, the slip at j), upwind2 (three points at j) */
typedef enum { ROLLER_SLIP_BOX, ROLLER_SLIP_UPWIND, ROLLER_SLIP_UPWIND2 } RollerSlipDifference;
PETSC_EXTERN const char *const RollerSlipDifferences[];
typedef struct {
  PetscBool            on;
  RollerFrame          frame;
  PetscInt             nev;
  PetscReal            stick_eps;        /* the stick nodes' regularized cone, a slip speed (docs/squeal.md 4.4); 0: rigid stick */
  PetscReal            stick_margin;     /* a stick node with |T| > (1 - margin) mu N is linearized as slipping (docs/squeal.md 4.4.2); 0: none */
  RollerSlipDifference slip_difference;  /* the steady slip along Gamma_C (docs/squeal.md 3, 4.4.4) */
  PetscBool            branch_transport; /* -rubber maxwell in the lab: the branches transported (B_L), or frozen (docs/squeal.md 1.2) */
  char                 csv[PETSC_MAX_PATH_LEN], output[PETSC_MAX_PATH_LEN], steady_csv[PETSC_MAX_PATH_LEN];
  /* the result, sorted by frequency: n eigenvalues re + i im (im >= 0), their order, wave (RollerWave), error and rubber loss factor */
  PetscInt   n, *order, *wave, dofs;        /* dofs: the size of the eigenproblem */
  PetscReal *re, *im, *error, *rubber_loss; /* rubber_loss: the rubber's loss factor of the shape at its frequency (modes/branches.c) */
  PetscReal  skew_defect[2];                /* the damped lab frame's ||A + A^T||/||A|| of A_L and B_L (-1: not built) */
} RollerEigen;

/* A component's own state in the checkpoint (RollerCheckpointAddVec, RollerCheckpointAddReals in
   integrate/checkpoint.c): a vector whose points have positions (restarted on any number of ranks by matching
   them), or n reals that every rank holds */
#define ROLLER_CHECKPOINT_ITEMS (3 + 4 * ROLLER_MAX_BRANCHES + 16) /* the scheme's kept vectors (Maxwell: 4 a branch) and the components' state */
typedef struct {
  char       name[64];
  Vec       *v;              /* the address of a vector (followed when a step swaps it), or NULL: the reals below */
  Vec        where;          /* the positions of v's points, (x, y) per point, v having the same number of points */
  char       where_name[64]; /* its dataset ("nodes": the displacement's free nodes, ops.coordinates) */
  PetscInt   n;
  PetscReal *values;
  PetscBool  optional; /* a checkpoint without it restarts with the values as they are (a start, not a state) */
} RollerCheckpointItem;

/* Checkpoint and restart (integrate/checkpoint*.c) */
typedef struct {
  char                 file[PETSC_MAX_PATH_LEN], restart[PETSC_MAX_PATH_LEN];
  PetscInt             every;
  PetscInt             nitems;
  RollerCheckpointItem items[ROLLER_CHECKPOINT_ITEMS];
} RollerCheckpoint;

/* Initial state and verification (integrate/initial.c, verify/mms.c) */
typedef struct {
  RollerInitialCondition type;
  PetscReal              amplitude;
  RollerMMSType          mms;
  DM                     dm;       /* the manufactured body force's own DM and DS (verify/mms.c) */
  PetscViewer            mms_view; /* -mms_view: where the errors at the end go (NULL: stdout) */
  PetscViewerFormat      mms_format;
  char                   mode_file[PETSC_MAX_PATH_LEN]; /* -initial_condition mode: the -modes_output file and the mode's row */
  PetscInt               mode_index;
} RollerInitial;

struct _n_Roller {
  MPI_Comm             comm;
  RollerMesh           mesh;
  RollerMaterial       material;
  RollerRotation       rotation;
  RollerObstacle       obstacle;
  RollerAxle           axle;
  RollerDiscretization disc;
  RollerOperators      ops;
  RollerTimeParams     ts;
  RollerModes          modes;
  RollerEigen          eig;
  RollerState          state;
  RollerCheckpoint     ck;
  RollerInitial        init;
  RollerContact        contact;
  RollerScheme         scheme; /* the run's time scheme, one of ts.schemes */
  RollerRom            rom;    /* -rom: the reduced model (NULL without) */
  RollerMonitors       monitors;
  RollerStepInfo       info;
  PetscLogStage        stage[ROLLER_NUM_STAGES];
};

#endif
