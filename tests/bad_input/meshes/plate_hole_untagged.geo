// A coarse plate with a hole whose hole is in no physical group: Gmsh leaves
// its edges out of the file and deal.II gives them boundary id 0
// (bad_input/gmsh_untagged_face).
//   gmsh -2 plate_hole_untagged.geo -format msh4 -o plate_hole_untagged.msh
DefineConstant[ quads = {1, Name "quadrilaterals (1) or triangles (0)"} ];
h = 0.5;
hh = 0.2;
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
// The hole (curves 5-8) is in no physical group.
Physical Surface(1) = {1};
