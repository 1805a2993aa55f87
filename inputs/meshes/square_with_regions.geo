// Unit square [0,1] x [0,1] split at x = 0.5 into two regions, for the Gmsh reader tests.
// Regenerate the mesh with:  gmsh -2 -format msh4 square_with_regions.geo -o square_with_regions.msh
// The left part is meshed with triangles, the right part with quadrangles. The right part's
// curve loop runs clockwise on purpose, so Gmsh writes its cells clockwise and the reader's
// re-orientation is exercised.
h = 0.25;
Point(1) = {0, 0, 0, h};
Point(2) = {0.5, 0, 0, h};
Point(3) = {1, 0, 0, h};
Point(4) = {1, 1, 0, h};
Point(5) = {0.5, 1, 0, h};
Point(6) = {0, 1, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {7, -4, -3, -2};
Plane Surface(2) = {2};
Recombine Surface {2};
Physical Surface("left_part") = {1};
Physical Surface("right_part") = {2};
Physical Curve("left") = {6};
Physical Curve("right") = {3};
Physical Curve("bottom") = {1, 2};
Physical Curve("top") = {4, 5};
Physical Curve("middle") = {7};
Physical Point("origin") = {1};
