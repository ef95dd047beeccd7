// The band of rectangle.geo and a physical curve "ghost" from (1, 1.5)
// to (3, 1.5) above it, of no surface
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
Point(5) = {1, 1.5, 0};
Point(6) = {3, 1.5, 0};
Line(5) = {5, 6};
Physical Curve("ghost") = {5};
Physical Surface("body") = {1};
