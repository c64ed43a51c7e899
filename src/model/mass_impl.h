/* Private to the massless contact nodes (mass.c, mass_layer.c, mass_transfer.c): the cells around Gamma_C. */
#ifndef ROLLER_MASS_IMPL_H
#define ROLLER_MASS_IMPL_H

#include "model/model.h"

#define ROLLER_MASS_RINGS 4 /* cell rings gathered around Gamma_C: the 2-ring of a node and two enlargements */

/* The cells within ROLLER_MASS_RINGS rings of Gamma_C's vertices, the same on every rank whatever the
   partition: nn nodes per cell (3 P1, 6 P2) */
typedef struct {
  PetscInt   ncell, nn;
  PetscInt  *vert;  /* 3 global vertex numbers per cell */
  PetscInt  *node;  /* nn per cell: the node's first global dof, -1 for a Dirichlet node */
  PetscInt  *outer; /* nn per cell: 1 on Gamma_C */
  PetscReal *x;     /* 2 nn per cell: the node positions */
} RollerMassLayer;

PETSC_INTERN PetscErrorCode RollerMassLayerCreate(Roller, RollerMassLayer *);
PETSC_INTERN PetscErrorCode RollerMassLayerDestroy(RollerMassLayer *);

#endif
