// Full cylinder (radius 2 mm, height 1.5 mm) with its axis embedded as a curve and a point on
// the rim: everything a case needs to hold a body between frictionless platens without
// symmetry planes. Meshed coarsely (about 100 tetrahedra).
SetFactory("OpenCASCADE");
R = 2.0;
H = 1.5;
Cylinder(1) = {0, 0, 0, 0, 0, H, R};
Point(100) = {0, 0, 0};
Point(101) = {0, 0, H};
Line(100) = {100, 101};
BooleanFragments{ Volume{1}; Delete; }{ Line{100}; Delete; }
Mesh.MeshSizeMax = 0.9;
Mesh.MeshSizeMin = 0.9;
e = 1e-6;
bottom() = Surface In BoundingBox{-R - e, -R - e, -e, R + e, R + e, e};
top() = Surface In BoundingBox{-R - e, -R - e, H - e, R + e, R + e, H + e};
lateral() = Surface{:};
lateral() -= {bottom(), top()};
Physical Surface("bottom") = {bottom()};
Physical Surface("top") = {top()};
Physical Surface("lateral") = {lateral()};
Physical Curve("axis") = Curve In BoundingBox{-e, -e, -e, e, e, H + e};
Physical Point("rim") = Point In BoundingBox{R - e, -e, -e, R + e, e, e};
Physical Volume("domain") = {1};
