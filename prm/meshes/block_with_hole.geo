// A block [0, 2] x [0, 1] x [0, 0.5] with a cylindrical hole of radius 0.2
// along z about the axis through (1, 0.5), for the scene
// prm/block_with_hole.prm (doc/gmsh.md): the plate of plate_with_hole.geo
// extruded in z.
//
//   gmsh -3 block_with_hole.geo -format msh4 -o block_with_hole.msh
//   gmsh -3 block_with_hole.geo -setnumber hexes 0 -format msh4 \
//        -o block_with_hole_tets.msh
//
// Physical tags, which deal.II reads as boundary ids:
//   1 = bottom y = 0 (on the foundation), 2 = left x = 0 (clamped),
//   3 = right x = 2 (pulled), 4 = top y = 1 (pressed), 5 = the hole (free,
//   curved), 6 = the faces z = 0 and z = 0.5 (rollers in z), and 1 for the
//   volume (the cells' material id).
DefineConstant[ hexes = {1, Name "hexahedra (1) or tetrahedra (0)"} ];
h = 0.125;  // element size on the outer boundary
hh = 0.07;  // on the hole
Point(1) = {0, 0, 0, h};
Point(2) = {2, 0, 0, h};
Point(3) = {2, 1, 0, h};
Point(4) = {0, 1, 0, h};
Point(5) = {1, 0.5, 0, hh};
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
// The lateral surfaces come in the order of the base's curves: out[2] from
// curve 1, ..., out[9] from curve 8; out[0] is the top, out[1] the volume.
If (hexes)
  Recombine Surface {1};
  Mesh.RecombineAll = 1;
  out[] = Extrude {0, 0, 0.5} { Surface{1}; Layers{4}; Recombine; };
Else
  out[] = Extrude {0, 0, 0.5} { Surface{1}; Layers{4}; };
EndIf
Physical Surface(1) = {out[2]};
Physical Surface(2) = {out[5]};
Physical Surface(3) = {out[3]};
Physical Surface(4) = {out[4]};
Physical Surface(5) = {out[6], out[7], out[8], out[9]};
Physical Surface(6) = {1, out[0]};
Physical Volume(1) = {out[1]};
