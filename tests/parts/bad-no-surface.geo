// refused: points and a line, no surface
Point(1) = {0, 0.25, 0};
Point(2) = {4, 0.25, 0};
Line(1) = {1, 2};
