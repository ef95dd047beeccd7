// Kirsch's hole: the block (0, 4) x (0.25, 4.25) with a circular hole of
// radius r = 0.1 centred at (2, 2.25), r/20 of the block's width and
// height; the mesh size at the hole is r/4 (divided by mesh.refine)
Point(1) = {0, 0.25, 0};
Point(2) = {4, 0.25, 0};
Point(3) = {4, 4.25, 0};
Point(4) = {0, 4.25, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
r = 0.1; lc = r / 4;
Point(5) = {2, 2.25, 0, lc};
Point(6) = {2 + r, 2.25, 0, lc};
Point(7) = {2, 2.25 + r, 0, lc};
Point(8) = {2 - r, 2.25, 0, lc};
Point(9) = {2, 2.25 - r, 0, lc};
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 8};
Circle(7) = {8, 5, 9};
Circle(8) = {9, 5, 6};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Physical Curve("hole") = {5, 6, 7, 8};
Physical Curve("top") = {3};
Physical Curve("west") = {4};
Physical Surface("block") = {1};
