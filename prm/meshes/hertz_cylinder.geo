// The right half of a half-cylinder of radius 1 (per unit thickness) that
// rests on the plane y = 0 with its curved side, its flat side at y = 1:
// the quarter disk x >= 0, y <= 1 of the circle about (0, 1). Quadrilaterals
// of size h near the first contact point (0, 0), growing to 25 h away from it.
// Physical tags (boundary ids): 0 = symmetry line x = 0, 1 = flat side
// y = 1 (the load), 2 = the curved side (contact).
//   gmsh -2 -format msh2 -setnumber h 0.004 hertz_cylinder.geo -o FILE.msh
If (!Exists(h))
  h = 0.004;
EndIf
Point(1) = {0, 1, 0};   // centre
Point(2) = {0, 0, 0};   // first contact point
Point(3) = {1, 1, 0};
Line(1) = {1, 2};       // symmetry line
Circle(2) = {2, 1, 3};  // curved side
Line(3) = {3, 1};       // flat side
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
Mesh.Algorithm = 6;               // frontal-Delaunay
Mesh.RecombinationAlgorithm = 1;  // Blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrilaterals
Physical Curve(0) = {1};
Physical Curve(1) = {3};
Physical Curve(2) = {2};
Physical Surface(0) = {1};
