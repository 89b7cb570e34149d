// A half-cylinder of radius 1 (per unit thickness) resting with its curved
// side on the plane y = 0, its flat side at y = 1: the half disk y <= 1 of
// the circle about (0, 1). Quadrilaterals of size h near the first contact
// point (0, 0), growing to 25 h away from it.
// Physical tags (boundary ids): 1 = flat side y = 1, 2 = the curved side.
//   gmsh -2 -format msh2 -setnumber h 0.008 cattaneo_mindlin.geo -o FILE.msh
If (!Exists(h))
  h = 0.008;
EndIf
Point(1) = {0, 1, 0};    // centre
Point(2) = {-1, 1, 0};
Point(3) = {0, 0, 0};    // first contact point
Point(4) = {1, 1, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};        // flat side
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {3};
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
Physical Curve(1) = {3};
Physical Curve(2) = {1, 2};
Physical Surface(0) = {1};
