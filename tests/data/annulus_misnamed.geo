// Bad mesh for tests/mesh: the roller annulus, but its physical groups are named Gamma_D, Gamma_C, Omega
// instead of inner, outer, body.
//   gmsh -2 -format msh41 annulus_misnamed.geo -o annulus_misnamed.msh
h = 0.1;
Point(1) = {0, 0, 0, h};
Point(2) = {0.25, 0, 0, h};
Point(3) = {-0.25, 0, 0, h};
Point(4) = {0.5, 0, 0, h};
Point(5) = {-0.5, 0, 0, h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 2};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 4};
Curve Loop(1) = {3, 4};
Curve Loop(2) = {1, 2};
Plane Surface(1) = {1, 2};
Physical Curve("Gamma_D", 1) = {1, 2};
Physical Curve("Gamma_C", 2) = {3, 4};
Physical Surface("Omega", 3) = {1};
