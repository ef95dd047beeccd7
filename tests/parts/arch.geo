// A curved outline: the half disc of radius 2 on [0, 4] x {0.25}, by OpenCASCADE
SetFactory("OpenCASCADE");
Disk(1) = {2, 0.25, 0, 2};
Rectangle(2) = {-1, 0.25, 0, 6, 3};
BooleanIntersection{ Surface{1}; Delete; }{ Surface{2}; Delete; }
