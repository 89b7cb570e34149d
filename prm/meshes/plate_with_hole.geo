// A plate [0, 2] x [0, 1] with a hole of radius 0.2 about (1, 0.5), in 2D, for
// the scene prm/plate_with_hole.prm (doc/gmsh.md).
//
//   gmsh -2 plate_with_hole.geo -format msh4 -o plate_with_hole.msh
//   gmsh -2 plate_with_hole.geo -setnumber quads 0 -format msh4 \
//        -o plate_with_hole_triangles.msh
//
// Physical tags, which deal.II reads as boundary ids:
//   1 = bottom y = 0 (on the foundation), 2 = left x = 0 (clamped),
//   3 = right x = 2 (pulled), 4 = top y = 1 (pressed), 5 = the hole (free,
//   curved), and 1 for the surface (the cells' material id).
DefineConstant[ quads = {1, Name "quadrilaterals (1) or triangles (0)"} ];
h = 0.1;   // element size on the outer boundary
hh = 0.05; // on the hole
Point(1) = {0, 0, 0, h};
Point(2) = {2, 0, 0, h};
Point(3) = {2, 1, 0, h};
Point(4) = {0, 1, 0, h};
Point(5) = {1, 0.5, 0, hh};   // the centre of the hole
Point(6) = {1.2, 0.5, 0, hh};
Point(7) = {1, 0.7, 0, hh};
Point(8) = {0.8, 0.5, 0, hh};
Point(9) = {1, 0.3, 0, hh};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 8};
Circle(7) = {8, 5, 9};
Circle(8) = {9, 5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
If (quads)
  Recombine Surface {1};
  Mesh.RecombineAll = 1;
EndIf
Physical Curve(1) = {1};
Physical Curve(2) = {4};
Physical Curve(3) = {2};
Physical Curve(4) = {3};
Physical Curve(5) = {5, 6, 7, 8};
Physical Surface(1) = {1};
