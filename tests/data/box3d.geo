// Bad mesh for tests/mesh: a tetrahedral unit cube (Roller needs a 2-D mesh).
//   gmsh -3 -format msh41 box3d.geo -o box3d.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Mesh.MeshSizeMin = 1;
Mesh.MeshSizeMax = 1;
Physical Surface("outer", 2) = {1, 2, 3, 4, 5, 6};
Physical Volume("body", 3) = {1};
