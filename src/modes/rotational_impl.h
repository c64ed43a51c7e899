/* Private to the rotational operators of the damped lab frame (rotational.c: the cell terms; rotational_edges.c: the
   edge terms, serial and across ranks; rotational_element.c: the pointwise pieces both use). docs/squeal.md
   section 1.1. */
#ifndef ROLLER_ROTATIONAL_IMPL_H
#define ROLLER_ROTATIONAL_IMPL_H

#include "modes/modes.h"

/* rotational_element.c: the isoparametric map at tabulation point q: x, J, J^-1, the map's second derivatives X2, det J */
PETSC_INTERN void RollerRotGeometry(PetscTabulation, PetscInt, const PetscScalar[], PetscReal[], PetscReal[], PetscReal[], PetscReal[], PetscReal *);
/* the physical gradients (and, if given, Hessians) of the basis functions at point q */
PETSC_INTERN void RollerRotDerivatives(PetscTabulation, PetscInt, const PetscReal[], const PetscReal[], PetscReal[], PetscReal[]);
/* sigma[G] : H */
PETSC_INTERN PetscReal RollerRotStressProduct(Roller, const PetscReal[], const PetscReal[]);
/* the coordinate element (P1 or P2) of a cell from its number of coordinates */
PETSC_INTERN PetscErrorCode RollerRotCoordinateElement(PetscInt, PetscFE[2], PetscFE *);
/* rotational_edges.c: adds the edge terms S + B/2 to a matrix (dm, fe, the coordinate elements) */
PETSC_INTERN PetscErrorCode RollerRotEdgeTerms(Roller, DM, PetscFE, PetscFE[2], Mat);

#endif
