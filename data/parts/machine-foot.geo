// A machine foot: a steel column 0.08 m wide on a base plate 0.28 m wide
// and 0.02 m thick, whose flange overhangs the strip (0, 0.2) by 0.04 m on
// each side.  The base plate's underside is the strip's top x2 = 0.004 m
// (C0prime): on (0, 0.2) it joins the strip; the overhangs, outside
// [a, b], are the free physical curve "ledge".  The column's top
// (physical curve "top") carries the machine.  Lengths in metres.  Mesh
// size 0.0125 m, (b - a) / N at N = 16, finer at the column's re-entrant
// corners.
s = 0.004; t = 0.024; h = 0.204; lc = 0.0125; lf = lc / 2;
Point(1) = {-0.04, s, 0, lc};
Point(2) = {0, s, 0, lc};
Point(3) = {0.2, s, 0, lc};
Point(4) = {0.24, s, 0, lc};
Point(5) = {0.24, t, 0, lc};
Point(6) = {0.14, t, 0, lf};
Point(7) = {0.14, h, 0, lc};
Point(8) = {0.06, h, 0, lc};
Point(9) = {0.06, t, 0, lf};
Point(10) = {-0.04, t, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 9};
Line(9) = {9, 10};
Line(10) = {10, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
Plane Surface(1) = {1};
Physical Curve("ledge") = {1, 3};
Physical Curve("top") = {7};
Physical Surface("foot") = {1};
