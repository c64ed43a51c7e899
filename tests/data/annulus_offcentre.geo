// Bad mesh for tests/mesh: a correctly named annulus whose centre is (0.1, 0), not the origin.
//   gmsh -2 -format msh22 annulus_offcentre.geo -o annulus_offcentre.msh
h = 0.1;
c = 0.1;
Point(1) = {c, 0, 0, h};
Point(2) = {c + 0.25, 0, 0, h};
Point(3) = {c - 0.25, 0, 0, h};
Point(4) = {c + 0.5, 0, 0, h};
Point(5) = {c - 0.5, 0, 0, h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 2};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 4};
Curve Loop(1) = {3, 4};
Curve Loop(2) = {1, 2};
Plane Surface(1) = {1, 2};
Physical Curve("inner", 1) = {1, 2};
Physical Curve("outer", 2) = {3, 4};
Physical Surface("body", 3) = {1};
