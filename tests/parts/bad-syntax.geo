// refused: gmsh cannot parse it
Point(1) = {0, 0.25, 0};
Line(1) = {1, 2, ;
