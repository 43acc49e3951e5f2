// A hex-dominant test mesh: a quadrangle-dominant 2D mesh of a plate with a hole (recombination
// leaves a few triangles), extruded in two layers. Quads become hexahedra, triangles prisms.
lc = 0.45;
Mesh.RecombinationAlgorithm = 0;  // "simple": leaves triangles where quads do not fit
Point(1) = {0, 0, 0, lc}; Point(2) = {3, 0, 0, lc}; Point(3) = {3, 2, 0, lc}; Point(4) = {0, 2, 0, lc};
Point(5) = {1.0, 0.7, 0, lc}; Point(6) = {2.1, 0.8, 0, lc}; Point(7) = {1.4, 1.4, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 5};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7};
Plane Surface(1) = {1, 2};
Recombine Surface {1};
Extrude {0, 0, 0.6} { Surface{1}; Layers{2}; Recombine; }
Physical Volume("slab") = {1};
Physical Surface("bottom") = {1};
