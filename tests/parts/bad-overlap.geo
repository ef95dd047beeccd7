// The band of rectangle.geo with a square "insert" (1.5, 2.5) x (0.4, 0.8)
// drawn inside it, not cut from it: the two surfaces overlap
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
Point(5) = {1.5, 0.4, 0};
Point(6) = {2.5, 0.4, 0};
Point(7) = {2.5, 0.8, 0};
Point(8) = {1.5, 0.8, 0};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Physical Surface("body") = {1};
Physical Surface("insert") = {2};
