// The roller: an annulus r_inner < |x| < r_outer, meshed with triangles of edge length about h.
// Override the parameters on the command line:
//   gmsh -2 -format msh41 -setnumber h 0.025 meshes/annulus.geo -o annulus.msh
// Physical groups: curve "inner" (Gamma_D), curve "outer" (Gamma_C), surface "body".
DefineConstant[ r_inner = 0.25, r_outer = 0.5, h = 0.0125 ];

Point(1) = {0, 0, 0, h};
Point(2) = {r_inner, 0, 0, h};
Point(3) = {-r_inner, 0, 0, h};
Point(4) = {r_outer, 0, 0, h};
Point(5) = {-r_outer, 0, 0, h};
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
Mesh.CharacteristicLengthFromPoints = 1;
Mesh.CharacteristicLengthExtendFromBoundary = 1;
