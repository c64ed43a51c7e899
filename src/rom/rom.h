/* The reduced-order transient (-rom, docs/performance.md "Reduced-order transient"): the co-rotating roller's linear
   bulk on the modes of the roller clamped at the shaft below a cutoff, plus the static responses to the rigid-body
   loads (one M-orthonormal basis V, V^T K V diagonal), stepped by the same three-level schemes, driver, CSV and
   energy balance as the full model on those coordinates.
     rom.c        the options (-rom, -rom_modes, -rom_cutoff), the default cutoff, -ts_view, set-up and destroy
     rom_basis.c  the basis: SLEPc's modes of (K, M), the static load responses, their Ritz diagonalization
     rom_reduce.c the reduced operators (M, K, R(-pi/2), the loads, the functionals) and state put in the context
     rom_io.c     -rom_output / -rom_input: the basis (and the residual flexibility) saved and reused, refused by name
                  when made for another model */
#ifndef ROLLER_ROM_H
#define ROLLER_ROM_H

#include <roller_impl.h>
#include <slepceps.h>
#include "model/model.h"

PETSC_INTERN PetscErrorCode RollerRomSetFromOptions(Roller); /* creates ctx->rom with -rom */
PETSC_INTERN PetscErrorCode RollerRomSetUp(Roller);          /* after the operators, the initial state and the contact nodes */
PETSC_INTERN PetscErrorCode RollerRomDestroy(Roller);

/* Private to rom*.c */
struct _n_RollerRom {
  PetscInt       modes_req;                                             /* -rom_modes (0: from the cutoff) */
  PetscReal      cutoff;                                                /* -rom_cutoff in cycles per unit time (0: the default) */
  PetscReal      w_cut;                                                 /* the cutoff used, angular */
  PetscInt       nmodes;                                                /* modes kept */
  PetscInt       nq;                                                    /* reduced coordinates: the modes and the static responses */
  PetscReal     *lambda;                                                /* nq: V^T K V (diagonal) */
  PetscReal      offdiag;                                               /* max |V^T K V - diag| / max lambda, max |V^T M V - I|: the basis' round-off */
  Mat            V;                                                     /* N x nq dense, M-orthonormal */
  PetscBool      residual;                                              /* -rom_residual: MacNeal's static residual flexibility at Gamma_C (contact_residual.c) */
  PetscBool      residual_branches;                                     /* -rom_residual_branches: with -rubber maxwell the residual is viscoelastic (contact_residual_branches.c) */
  PetscReal      kappa;                                                 /* its branches' share of the residual's stiffness (computed, or the -rom_input file's) */
  EPS            eps;                                                   /* the modes' eigensolver: its ST holds K's factorization until the set-up ends */
  char           input[PETSC_MAX_PATH_LEN], output[PETSC_MAX_PATH_LEN]; /* -rom_input, -rom_output ("" off) */
  PetscLogDouble t_modes, t_reduce, t_residual;
};

PETSC_INTERN PetscErrorCode RollerRomBasis(Roller, RollerRom);
PETSC_INTERN PetscErrorCode RollerRomColumnsGet(Mat, Vec **); /* the columns of a dense matrix as Vecs on its storage */
PETSC_INTERN PetscErrorCode RollerRomColumnsRestore(Mat, Vec **);
PETSC_INTERN PetscErrorCode RollerRomGram(Mat, Mat, PetscReal[]); /* A^T B of two dense N x n, on every rank */
PETSC_INTERN PetscErrorCode RollerRomReduce(Roller, RollerRom);
PETSC_INTERN PetscErrorCode RollerRomSave(Roller, RollerRom, const char[]);
PETSC_INTERN PetscErrorCode RollerRomLoad(Roller, RollerRom, const char[]);
PETSC_INTERN PetscErrorCode RollerRomLoadResidual(Roller, RollerRom, const char[]);

#endif
