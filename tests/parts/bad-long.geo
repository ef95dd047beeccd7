// refused: a name of 70 characters
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
Physical Curve("a123456789b123456789c123456789d123456789e123456789f123456789g123456789") = {3};
