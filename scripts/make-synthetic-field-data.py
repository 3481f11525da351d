#!/usr/bin/env python3
"""Synthetic field data for the compare/calibrate worked example (cases/field/).

Field measurements of worn knives are not public (shared/reference/cases.md); this script makes
stand-ins from a lifetime run whose W plays the unknown true value:
  - scan_mm.ply:       a point cloud sampled on the run's worn knife after update U, in
                       millimetres, turned and shifted as a scanner would leave it, with noise;
  - measurements.csv:  the recession of the run's followed points at every update's tonnage
                       (its trajectory.csv), with noise, as a table of named locations;
  - locations.csv:     where the locations are (knife frame, metres).
Usage: make-synthetic-field-data.py RUN_DIR UPDATE OUT_DIR [--noise M] [--angle DEG]
                                   [--shift X,Y,Z] [--seed N]
  --noise: the scan's noise, standard deviation per coordinate [m] (default 0.0002)
  --angle: the scanner's turn about (1, 1, 2) [degrees] (default 20)
  --shift: the scanner's shift [m] (default 0.12,-0.04,0.3)
"""
import argparse, csv, math, os, random, struct, sys

parser = argparse.ArgumentParser()
parser.add_argument("run"), parser.add_argument("update", type=int), parser.add_argument("out")
parser.add_argument("--noise", type=float, default=0.0002)
parser.add_argument("--angle", type=float, default=20)
parser.add_argument("--shift", default="0.12,-0.04,0.3")
parser.add_argument("--seed", type=int, default=2026)
args = parser.parse_args()
run, update, out = args.run, args.update, args.out
random.seed(args.seed)
os.makedirs(out, exist_ok=True)

def read_stl(path):
    data = open(path, "rb").read()
    n = struct.unpack_from("<I", data, 80)[0]
    tris = []
    for k in range(n):
        v = struct.unpack_from("<12f", data, 84 + 50 * k)
        tris.append((v[3:6], v[6:9], v[9:12]))
    return tris

def area(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    x = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    return 0.5 * math.sqrt(sum(t * t for t in x))

# a scanner's view: turned about (1, 1, 2) and shifted (by default 20 degrees, (120, -40, 300) mm)
axis = [1 / math.sqrt(6), 1 / math.sqrt(6), 2 / math.sqrt(6)]
th = math.radians(args.angle)
c, s = math.cos(th), math.sin(th)
# Rodrigues' formula, written out
ux, uy, uz = axis
R = [[c + ux * ux * (1 - c), ux * uy * (1 - c) - uz * s, ux * uz * (1 - c) + uy * s],
     [uy * ux * (1 - c) + uz * s, c + uy * uy * (1 - c), uy * uz * (1 - c) - ux * s],
     [uz * ux * (1 - c) - uy * s, uz * uy * (1 - c) + ux * s, c + uz * uz * (1 - c)]]
shift = [float(x) for x in args.shift.split(",")]

# the part's folder: part/part_NNNNN.stl, or knife/knife_NNNNN.stl in an earlier abrade's run
part = "part" if os.path.isdir(os.path.join(run, "part")) or not os.path.isdir(os.path.join(run, "knife")) else "knife"
tris = read_stl(os.path.join(run, part, f"{part}_{update:05d}.stl"))
areas = [area(*t) for t in tris]
total = sum(areas)
points = []
n_points = 8000
for _ in range(n_points):
    r = random.uniform(0, total)
    k = 0
    while r > areas[k]:
        r -= areas[k]
        k += 1
    a, b, cc = tris[k]
    u, v = random.random(), random.random()
    if u + v > 1:
        u, v = 1 - u, 1 - v
    p = [a[i] + u * (b[i] - a[i]) + v * (cc[i] - a[i]) + random.gauss(0, args.noise) for i in range(3)]
    q = [sum(R[i][j] * p[j] for j in range(3)) + shift[i] for i in range(3)]
    points.append([1000 * x for x in q])
with open(os.path.join(out, "scan_mm.ply"), "w") as f:
    f.write("ply\nformat ascii 1.0\ncomment synthetic scan (scripts/make-synthetic-field-data.py), millimetres\n")
    f.write(f"element vertex {len(points)}\nproperty float x\nproperty float y\nproperty float z\nend_header\n")
    for p in points:
        f.write(f"{p[0]:.3f} {p[1]:.3f} {p[2]:.3f}\n")

# measurements at the run's followed points
prm = open(os.path.join(run, "parameters.prm")).read()
import re
pts = re.search(r"set Recession points\s*=\s*(.*)", prm).group(1)
pts = [[float(x) for x in p.split(",")] for p in pts.split(";")]
names = [f"P{k + 1}" for k in range(len(pts))]
with open(os.path.join(out, "locations.csv"), "w") as f:
    f.write("name,x,y,z\n")
    for n, p in zip(names, pts):
        f.write(f"{n},{p[0]},{p[1]},{p[2]}\n")
rows = list(csv.DictReader(open(os.path.join(run, "trajectory.csv"))))
with open(os.path.join(out, "measurements.csv"), "w") as f:
    f.write("location,tonnes,depth_mm\n")
    for r in rows:
        for k, n in enumerate(names):
            col = "point_depth" if k == 0 else f"point_depth_{k + 1}"
            d = 1000 * float(r[col]) * (1 + random.gauss(0, 0.05))  # 5 % gauge scatter
            f.write(f"{n},{round(float(r['tonnes']))},{d:.3f}\n")
print(f"wrote {out}/scan_mm.ply ({len(points)} points, update {update}: {rows[update - 1]['tonnes']} t), "
      f"{out}/measurements.csv ({len(rows) * len(names)} rows), {out}/locations.csv")
