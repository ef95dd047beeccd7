// The band of rectangle.geo, and a square "island" (5, 6) x (0.5, 1.5)
// beside it that touches it nowhere: a surface apart
Point(1) = {0, 0.25, 0};
Point(2) = {4, 0.25, 0};
Point(3) = {4, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point(5) = {5, 0.5, 0};
Point(6) = {6, 0.5, 0};
Point(7) = {6, 1.5, 0};
Point(8) = {5, 1.5, 0};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Physical Surface("body") = {1};
Physical Surface("island") = {2};
