// A bearing block (pillow block), the left half of a cast-iron block
// 0.2 m wide and 0.125 m high, cut by its plane of symmetry x1 = 0.1 m:
// the half block (0, 0.1) x (0.005, 0.125) above the strip, its bore of
// radius 0.03 m centred on the symmetry plane at x2 = 0.07 m.  The shaft
// presses on the lower quarter of the bore (the physical curve "seat");
// the upper quarter is free, the symmetry plane ("symmetry") a roller.
// Lengths in metres.  Mesh size 0.00625 m, (b - a) / N at N = 16.
s = 0.005; h = 0.125; c = 0.07; r = 0.03; lc = 0.00625;
Point(1) = {0, s, 0, lc};
Point(2) = {0.1, s, 0, lc};
Point(3) = {0.1, c - r, 0, lc / 2};
Point(4) = {0.1, c, 0, lc};
Point(5) = {0.1 - r * Sqrt(0.5), c - r * Sqrt(0.5), 0, lc / 2};
Point(6) = {0.1 - r, c, 0, lc / 2};
Point(7) = {0.1, c + r, 0, lc / 2};
Point(8) = {0.1, h, 0, lc};
Point(9) = {0, h, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Circle(3) = {3, 4, 5};
Circle(4) = {5, 4, 6};
Circle(5) = {6, 4, 7};
Line(6) = {7, 8};
Line(7) = {8, 9};
Line(8) = {9, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8};
Plane Surface(1) = {1};
Physical Curve("seat") = {3, 4};
Physical Curve("symmetry") = {2, 6};
Physical Surface("block") = {1};
