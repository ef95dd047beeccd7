// The band of rectangle.geo as two halves (0, 2) and (2, 4) that share
// the points of the line x1 = 2 but each have a line of their own there
// (lines 3 and 7): the mesh has a seam, which no triangle crosses
Point(1) = {0, 0.25, 0};
Point(2) = {2, 0.25, 0};
Point(3) = {2, 1, 0};
Point(4) = {0, 1, 0};
Point(5) = {4, 0.25, 0};
Point(6) = {4, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {2, 5};
Line(6) = {5, 6};
Line(7) = {6, 3};
Line(8) = {3, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{2} = 5;
Transfinite Curve{8} = 7;
Physical Surface("left") = {1};
Physical Surface("right") = {2};
