// A bolt-on grab knife, drawn as a CAD tool would hand it over: in millimetres, in assembly
// coordinates (lying on the drawing board: its length along x from x = 1500, its height along y
// from the edge at y = 800, its thickness along z from 0 to 30). The plate of the knife-bed
// reference knife (400 x 500 x 30 mm, a 40 mm chisel bevel) with four 22 mm bolt holes 60 mm
// below its top. Gmsh script, OpenCASCADE kernel; made into edge.step by
//   abrade convert edge.geo --output edge.step
SetFactory("OpenCASCADE");

L = 400;  // length of the edge
H = 500;  // height
T = 30;   // plate thickness
B = 40;   // bevel height (the chisel's two faces meet at the edge, in the middle)
D = 22;   // bolt hole diameter
x0 = 1500;
y0 = 800;

// the cross-section at x = x0: y up from the edge, z across the plate
Point(1) = {x0, y0, T / 2};
Point(2) = {x0, y0 + B, T};
Point(3) = {x0, y0 + H, T};
Point(4) = {x0, y0 + H, 0};
Point(5) = {x0, y0 + B, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
plate[] = Extrude {L, 0, 0} { Surface{1}; };

// four bolt holes through the plate
For i In {0 : 3}
  Cylinder(10 + i) = {x0 + 50 + i * 100, y0 + H - 60, -1, 0, 0, T + 2, D / 2};
EndFor
BooleanDifference(20) = { Volume{plate[1]}; Delete; }{ Volume{10 : 13}; Delete; };
