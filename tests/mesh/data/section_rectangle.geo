// Meridian section of a cylinder (radius 18 mm, height 8 mm) with the four curves the rectangle
// generator names, a material surface and a pinned corner: the example of docs/section_meshes.md.
// Mesh with: gmsh section_rectangle.geo -2 -order 2 -format msh41 -o section.msh
R = 18.0;
H = 8.0;
lc = 2.0;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};
Point(3) = {R, H, 0, lc};
Point(4) = {0, H, 0, lc};
Line(1) = {1, 2};  // z = 0
Line(2) = {2, 3};  // r = R
Line(3) = {3, 4};  // z = H
Line(4) = {4, 1};  // r = 0
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("axis") = {4};
Physical Curve("lateral") = {2};
Physical Curve("bottom") = {1};
Physical Curve("top") = {3};
Physical Surface("tissue") = {1};
Physical Point("pin") = {1};
