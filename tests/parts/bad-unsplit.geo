// refused: the part (-1, 5) x (0.25, 1) overhangs, its bottom not split at a and b
Point(1) = {-1, 0.25, 0};
Point(2) = {5, 0.25, 0};
Point(3) = {5, 1, 0};
Point(4) = {-1, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
