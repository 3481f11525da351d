#!/usr/bin/env python3
"""A lifetime run's cross-sections, against what the run says by other paths.

  check_sections.py RUN_DIR [--part-height METRES]

- every outline of knife/profile_*.csv and knife/section_worst.csv (the design as update 0,
  then each update) is closed: each segment end is the end of exactly one other segment (a cut
  that misses the triangles whose corners lie on the plane leaves it open -- the middle of a
  regular mesh);
- section_worst.csv is cut (from the updates' STL files) at the x of summary.json's
  end_of_life_where, and when the life ended by the depth, its last outline's lowest point is
  the deepest point of the last update (trajectory.csv deepest_z, found on the surface in
  memory), and when by the gauged edge, its lowest point's rise above the design's is the
  gauge's reading (edge_recession): the two paths agree to the STL's single precision;
- the picture's window (lifetime.gp, the set xrange / yrange before section_worst.png) holds
  that place, is zoomed (its height under half of --part-height) and holds the whole wear
  (the last outline's lowest point and the design's).
Exit 1 with the reason on a failure."""
import argparse, csv, json, math, os, re, sys


def blocks(path):
    out = {}
    for line in open(path):
        w = line.split()
        if not w or w[0].startswith("#"):
            continue
        out.setdefault(int(w[0]), []).append(tuple(float(v) for v in w[1:5]))
    return out


def closed(segments, tol):
    ends = [(s[0], s[1]) for s in segments] + [(s[2], s[3]) for s in segments]
    key = lambda p: (round(p[0] / tol), round(p[1] / tol))
    count = {}
    for p in ends:
        count[key(p)] = count.get(key(p), 0) + 1
    return all(c % 2 == 0 for c in count.values())


def fail(text):
    print("FAIL:", text)
    sys.exit(1)


ap = argparse.ArgumentParser()
ap.add_argument("run")
ap.add_argument("--part-height", type=float, default=0)
a = ap.parse_args()
knife = os.path.join(a.run, "knife")
files = sorted(f for f in os.listdir(knife) if f.endswith(".csv") and (f.startswith("profile_") or f == "section_worst.csv"))
if "section_worst.csv" not in files:
    fail("no knife/section_worst.csv")
for f in files:
    b = blocks(os.path.join(knife, f))
    if 0 not in b:
        fail(f + ": no design outline (update 0)")
    for u, segments in b.items():
        if not closed(segments, 2e-6):
            fail("%s: the outline of update %d is not closed (%d segments)" % (f, u, len(segments)))
    print("%s: %d outlines, each closed" % (f, len(b)))

life = json.load(open(os.path.join(a.run, "summary.json")))["results"]["lifetime"]
where = life["end_of_life_where"]
worst = blocks(os.path.join(knife, "section_worst.csv"))
last = max(worst)
lowest = min(min(s[1], s[3]) for s in worst[last])
rows = list(csv.DictReader(open(os.path.join(a.run, "trajectory.csv"))))
if int(rows[-1]["update"]) != last:
    fail("section_worst.csv ends at update %d, trajectory.csv at %s" % (last, rows[-1]["update"]))
if life["end_of_life_criterion"] == "maximum depth":
    deepest_z = float(rows[-1]["deepest_z"])
    print("lowest point of the last outline %.7f m, the deepest vertex %.7f m" % (lowest, deepest_z))
    if abs(lowest - deepest_z) > 2e-6:
        fail("the section through the deepest point misses it: lowest z %.7f m, deepest_z %.7f m" % (lowest, deepest_z))
if life["end_of_life_criterion"] == "maximum edge recession":
    # the height gauge: the rise of the section's lowest point above the design's, from the cut
    # of the STL files against the gauge's reading on the surface in memory
    design_lowest = min(min(s[1], s[3]) for s in worst[0])
    gauged = float(rows[-1]["edge_recession"])
    print("rise of the lowest point %.7f m, the gauge %.7f m" % (lowest - design_lowest, gauged))
    if abs(lowest - design_lowest - gauged) > 2e-6:
        fail("the section through the gauge's station reads %.7f m, the gauge %.7f m" % (lowest - design_lowest, gauged))

gp = open(os.path.join(a.run, "lifetime.gp")).read()
m = re.search(r"set output 'knife/section_worst.png'.*?set xrange \[([^:]+):([^\]]+)\]\nset yrange \[([^:]+):([^\]]+)\]", gp, re.S)
if not m:
    fail("lifetime.gp draws no knife/section_worst.png")
y0, y1, z0, z1 = (float(v) / 1000 for v in m.groups())
print("window y %.4f..%.4f, z %.4f..%.4f m; the place (%.4f, %.4f) m" % (y0, y1, z0, z1, where[1], where[2]))
if not (y0 <= where[1] <= y1 and z0 <= where[2] <= z1):
    fail("the window does not hold where the life ended")
design_lowest = min(min(s[1], s[3]) for s in worst[0])
if not (z0 <= min(lowest, design_lowest) and z1 >= max(lowest, design_lowest)):
    fail("the window does not hold the wear (the design's lowest point and the last one's)")
if a.part_height > 0 and z1 - z0 > 0.5 * a.part_height:
    fail("the window is not zoomed: %.3f m high for a part %.3f m high" % (z1 - z0, a.part_height))
print("ok")
