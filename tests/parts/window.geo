// The band (0, 4) x (0.25, 1) with a rectangular window (1.5, 2.5) x
// (0.5, 0.75), every side a straight named curve, so that the mesh's
// outline is the geometry's exactly (tests/parts_physics.sh's balance of
// forces computes the area and the curves' lengths from these numbers)
Point(1) = {0, 0.25, 0};
Point(2) = {4, 0.25, 0};
Point(3) = {4, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
lc = 0.125;
Point(5) = {1.5, 0.5, 0, lc};
Point(6) = {2.5, 0.5, 0, lc};
Point(7) = {2.5, 0.75, 0, lc};
Point(8) = {1.5, 0.75, 0, lc};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Physical Curve("top") = {3};
Physical Curve("west") = {4};
Physical Curve("east") = {2};
Physical Curve("sill") = {5};
Physical Curve("jamb") = {6};
Physical Curve("lintel") = {7};
Physical Curve("post") = {8};
Physical Surface("block") = {1};
