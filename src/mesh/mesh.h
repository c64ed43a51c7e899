/* The mesh layer: ctx->mesh.dm becomes the distributed annulus with labels "inner" (Gamma_D) and "outer"
   (Gamma_C), each marking faces and their closure (vertices) with value 1. With a mesh file, r_inner and
   r_outer are measured from it.
     mesh.c       gmsh annulus (file or generated), labels, validation, the mesh options (-mesh_*, -r_*, -partition_view)
     generate.c   the in-process gmsh annulus (C API): uniform, or graded toward Gamma_C (-mesh_h_contact)
     partition.c  METIS partition of the cell graph, distribution
     geometry.c   curved (isoparametric P2) boundary */
#ifndef ROLLER_MESH_H
#define ROLLER_MESH_H

#include <roller_impl.h>

PETSC_INTERN PetscErrorCode RollerMeshSetFromOptions(Roller);
PETSC_INTERN PetscErrorCode RollerMeshCreate(Roller);
PETSC_INTERN PetscErrorCode RollerMeshCheckOrientation(Roller, const char *);      /* counter-clockwise, no inverted or degenerate cell */
PETSC_INTERN PetscErrorCode RollerMeshGenerate(Roller, PetscBool, char[], char[]); /* verbose; temporary dir, msh file */
PETSC_INTERN PetscErrorCode RollerMeshDistribute(Roller);
PETSC_INTERN PetscErrorCode RollerMeshMeasure(Roller);
PETSC_INTERN PetscErrorCode RollerMeshOwnedMask(DM, PetscBool **); /* PETSC_TRUE at the points this rank owns */
PETSC_INTERN PetscErrorCode RollerGeometrySetUp(Roller);           /* curved boundary with -degree 2 */

#endif
