// refused: the bottom is split at x1 = 1.1, between the nodes x_4 = 1 and x_5 = 1.25 (N = 16)
Point(1) = {0, 0.25, 0};
Point(2) = {1.1, 0.25, 0};
Point(3) = {4, 0.25, 0};
Point(4) = {4, 1, 0};
Point(5) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
