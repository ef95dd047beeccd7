/* part_geometry.h: the gmsh geometry of the part that the scene tests
   load (tests/scene_files.h for test_scene.c and test_scene_errors.c,
   test_scene_write.c, test_scene_keys.c, the fuzzing harness): the band
   (0, 4) x (0.25, 1), which joins the strip of a = 0, b = 4, C0prime =
   0.25 along its bottom [0, 4] x {0.25}, one straight curve ending on the
   grid x_i of every N.  Three layers: (0.25, 0.5) below, (0.5, 0.75) with
   a bore of radius 0.1 centred at (2, 0.625), (0.75, 1) above, whose
   right upper corner is cut by a chamfer from (4, 0.875) to (3.875, 1).
   PART_GEO_BODY is the body without names; PART_GEO_NAMES names every
   curve and surface that the tests' scenes use:
     top    the top side x2 = 1, for x1 in (0, 3.875)
     bore   the four arcs of the bore (curved: no roller)
     seat   the left side x1 = 0, its three pieces
     new    the right side x1 = 4 of the lower layer (vertical: a roller
            holds u1)
     slot   the right side of the middle layer (vertical)
     PART_GEO_NAME40, a name of 40 characters: the chamfer (inclined: no
            roller)
     rubber the lower layer, ply the middle one, stiff the upper one.
   The mesh size is the scene's (b - a) / N, the bore's points 0.05. */
#ifndef CONTACTOPT_TEST_PART_GEOMETRY_H
#define CONTACTOPT_TEST_PART_GEOMETRY_H

/* the name of 40 characters, as "[boundary.%040d]" writes 0 */
#define PART_GEO_NAME40 "0000000000000000000000000000000000000000"

#define PART_GEO_BODY \
  "// the scene tests' part (tests/part_geometry.h)\n" \
  "Point(1) = {0, 0.25, 0};\nPoint(2) = {4, 0.25, 0};\n" \
  "Point(3) = {4, 0.5, 0};\nPoint(4) = {0, 0.5, 0};\n" \
  "Point(5) = {4, 0.75, 0};\nPoint(6) = {0, 0.75, 0};\n" \
  "Point(7) = {4, 0.875, 0};\nPoint(8) = {3.875, 1, 0};\n" \
  "Point(9) = {0, 1, 0};\n" \
  "Line(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\n" \
  "Line(4) = {4, 1};\nLine(5) = {3, 5};\nLine(6) = {5, 6};\n" \
  "Line(7) = {6, 4};\nLine(8) = {5, 7};\nLine(9) = {7, 8};\n" \
  "Line(10) = {8, 9};\nLine(11) = {9, 6};\n" \
  "r = 0.1; lc = 0.05;\n" \
  "Point(10) = {2, 0.625, 0, lc};\nPoint(11) = {2 + r, 0.625, 0, lc};\n" \
  "Point(12) = {2, 0.625 + r, 0, lc};\nPoint(13) = {2 - r, 0.625, 0, lc};\n" \
  "Point(14) = {2, 0.625 - r, 0, lc};\n" \
  "Circle(12) = {11, 10, 12};\nCircle(13) = {12, 10, 13};\n" \
  "Circle(14) = {13, 10, 14};\nCircle(15) = {14, 10, 11};\n" \
  "Curve Loop(1) = {1, 2, 3, 4};\nCurve Loop(2) = {-3, 5, 6, 7};\n" \
  "Curve Loop(3) = {12, 13, 14, 15};\nCurve Loop(4) = {-6, 8, 9, 10, 11};\n" \
  "Plane Surface(1) = {1};\nPlane Surface(2) = {2, 3};\n" \
  "Plane Surface(3) = {4};\n"

#define PART_GEO_NAMES \
  "Physical Curve(\"top\") = {10};\n" \
  "Physical Curve(\"bore\") = {12, 13, 14, 15};\n" \
  "Physical Curve(\"seat\") = {4, 7, 11};\n" \
  "Physical Curve(\"new\") = {2};\n" \
  "Physical Curve(\"slot\") = {5};\n" \
  "Physical Curve(\"" PART_GEO_NAME40 "\") = {9};\n" \
  "Physical Surface(\"rubber\") = {1};\n" \
  "Physical Surface(\"ply\") = {2};\n" \
  "Physical Surface(\"stiff\") = {3};\n"

/* the whole geometry */
#define PART_GEO PART_GEO_BODY PART_GEO_NAMES
#endif
