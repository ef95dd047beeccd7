// A two-layer pad 0.2 m wide: a glass-fibre composite plate (physical
// surface "plate") from the strip's top x2 = 0.003 m (C0prime) to
// x2 = 0.013 m, under a polyurethane layer (physical surface "rubber")
// 0.02 m thick, its top (physical curve "top") loaded.  The strip below
// is of the plate's material ([material]).  Lengths in metres.  Mesh size
// 0.0125 m, (b - a) / N at N = 16, at most half a layer's thickness here.
s = 0.003; m = 0.013; t = 0.033; lc = 0.005;
Point(1) = {0, s, 0, lc};
Point(2) = {0.2, s, 0, lc};
Point(3) = {0.2, m, 0, lc};
Point(4) = {0, m, 0, lc};
Point(5) = {0.2, t, 0, lc};
Point(6) = {0, t, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {3, 5};
Line(6) = {5, 6};
Line(7) = {6, 4};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {-3, 5, 6, 7};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Physical Curve("top") = {6};
Physical Surface("plate") = {1};
Physical Surface("rubber") = {2};
