// refused: the bottom of an overhang bulges below C0prime between its points
Point(1) = {-1, 0.25, 0};
Point(2) = {0, 0.25, 0};
Point(3) = {4, 0.25, 0};
Point(4) = {4, 1, 0};
Point(5) = {-1, 1, 0};
Point(6) = {-0.5, 0.5, 0};
Circle(1) = {1, 6, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
