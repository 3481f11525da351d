// The bucket of cases/bucket/bucket.geo as first drawn, with a CAD defect kept for a test
// (test_part_files, PoorMeshNamesTheSliverFace): the lip and the teeth fused with the shell
// before the front-top quarter is cut away leave a 1 mm wide sliver face on the lip's top beside
// the shell's end, and a poor mesh there at any mesh size.
//
// A small excavator-like bucket with three teeth and a pin through two lugs, drawn as a CAD tool
// would hand it over (in millimetres, its own coordinates): x forward (the teeth point along
// +x), y across the bucket, z up; the shell's axis along y through the origin. A test part for
// a user's own part (issue 36), not a product: a 270-degree shell (radius 350, 20 thick, 600
// wide) open at the front top, two side plates, a cutting lip with three teeth, and two lugs at
// the top back with a 45 mm pin bore on one axis (CAD faces of cylinders come split in halves).
// Made into bucket.step by
//   abrade convert bucket.geo --output bucket.step
SetFactory("OpenCASCADE");

R  = 350;  // the shell's outer radius
T  = 20;   // shell thickness
W  = 600;  // width inside the side plates
S  = 20;   // side plate thickness
L  = 160;  // the lip's length forward of the shell
LT = 30;   // lip thickness
TL = 90;   // tooth length beyond the lip
TW = 60;   // tooth width
P  = 22.5; // pin bore radius

// the shell: a ring about y, without its front-top quarter (x > 0, z > 0)
Cylinder(1) = {0, 0, 0, 0, W, 0, R};
Cylinder(2) = {0, -1, 0, 0, W + 2, 0, R - T};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
// the side plates: discs at either end
Cylinder(4) = {0, -S, 0, 0, S, 0, R};
Cylinder(5) = {0, W, 0, 0, S, 0, R};
// the lip: a plate forward from the shell's front end (x from R - T, z from -LT to 0)
Box(6) = {R - T, -S, -LT, L + T, W + 2 * S, LT};
// three teeth on the lip's front edge
For i In {0 : 2}
  Box(7 + i) = {R + L, W / 2 - TW / 2 + (i - 1) * 220, -LT, TL, TW, LT};
EndFor
// two lugs on the back top, a pin bore through both (axis along y at x = -120, z = R + 70)
Box(10) = {-200, 140, R - 30, 160, 30, 150};
Box(11) = {-200, W - 170, R - 30, 160, 30, 150};
BooleanUnion(20) = { Volume{3}; Delete; }{ Volume{4, 5, 6, 7, 8, 9, 10, 11}; Delete; };
Box(21) = {0, -S - 1, 0, R + 1, W + 2 * S + 2, R + 1};
BooleanDifference(22) = { Volume{20}; Delete; }{ Volume{21}; Delete; };
Cylinder(23) = {-120, -S - 1, R + 70, 0, W + 2 * S + 2, 0, P};
BooleanDifference(24) = { Volume{22}; Delete; }{ Volume{23}; Delete; };
