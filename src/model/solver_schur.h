/* The substructured Cholesky of a step matrix on several ranks (solver_schur.c): its context and set-up pieces. */
#pragma once
#include "model/model.h"

typedef struct {
  Mat          F, Gt, S;      /* the interior's factor, G_r^T (interface x interior, factor order), S's factor */
  Vec          bI, yI, xI;    /* interior vectors in the factor's order */
  Vec          xg, tg;        /* interface vectors (every rank holds all of them) */
  PetscInt    *row;           /* row[p]: the local row of the factor's p-th interior unknown */
  PetscInt    *grow, nglocal; /* the local rows of this rank's interface part, its offset in the interface */
  PetscInt     goff, ng;
  PetscScalar *Sa; /* S's storage, column-major */
  struct {         /* the factor's rows (MatGetRowIJ: a row's entries above the diagonal, then 1/D_k), for a
                       backward substitution that reads the factor in one descending stream, twice as fast as PETSc 3.18's MatBackwardSolve */
    const PetscInt    *i, *j;
    const PetscScalar *a;
    PetscBool          on;
  } rows;
} SchurCtx;

PETSC_INTERN PetscErrorCode RollerSchurInterface(Mat, SchurCtx *, PetscInt **, PetscBool **);                       /* solver_schur_split.c */
PETSC_INTERN PetscErrorCode RollerSchurInteriorFactor(Mat, SchurCtx *, const PetscBool[], PetscInt *, PetscInt **); /* solver_schur_split.c */

/* The position of the global row c in the interface, or a negative number. */
static inline PetscInt RollerSchurInInterface(PetscInt ng, const PetscInt gl[], PetscInt c)
{
  PetscInt loc;

  PetscCallAbort(PETSC_COMM_SELF, PetscFindInt(c, ng, gl, &loc));
  return loc;
}
