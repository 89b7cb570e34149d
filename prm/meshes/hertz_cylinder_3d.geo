// A slice of thickness 0.1 of the half-cylinder of hertz_cylinder.geo (right
// half, radius 1, resting on the plane y = 0 along the line x = y = 0):
// the quarter disk extruded in z by one layer of hexahedra. Quadrilaterals of
// size h near the contact line, growing to 25 h away from it.
// Physical tags (boundary ids): 0 = symmetry plane x = 0, 1 = flat side
// y = 1 (the load), 2 = the curved side (contact), 3 = the faces z = 0 and
// z = 0.1 (rollers u_z = 0: plane strain).
//   gmsh -3 -format msh2 -setnumber h 0.004 hertz_cylinder_3d.geo -o FILE.msh
If (!Exists(h))
  h = 0.004;
EndIf
Point(1) = {0, 1, 0};
Point(2) = {0, 0, 0};
Point(3) = {1, 1, 0};
Line(1) = {1, 2};
Circle(2) = {2, 1, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = 25 * h;
Field[2].DistMin = 0.2;
Field[2].DistMax = 0.8;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
out[] = Extrude {0, 0, 0.1} { Surface{1}; Layers{1}; Recombine; };
// out[0]: the top surface z = 0.1, out[1]: the volume, out[2..4]: the
// surfaces extruded from the lines 1, 2, 3.
Physical Surface(0) = {out[2]};
Physical Surface(1) = {out[4]};
Physical Surface(2) = {out[3]};
Physical Surface(3) = {1, out[0]};
Physical Volume(0) = {out[1]};
