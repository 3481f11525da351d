#!/usr/bin/env python3
"""A lifetime run's cross-sections, against what the run says by other paths.

  check_sections.py RUN_DIR [--part-height METRES]

- every outline of part/profile_*.csv and part/section_worst.csv (the design as update 0,
  then each update) is closed: each segment end is the end of exactly one other segment (a cut
  that misses the triangles whose corners lie on the plane leaves it open -- the middle of a
  regular mesh);
- section_worst.csv is cut (from the updates' STL files) in the plane its first line names,
  through summary.json's end_of_life_where (none: trajectory.csv's deepest point); the place
  lies on the last outline (on the design's for a followed point), and when the gauged edge
  ended the life, the section's lowest point rises above the design's by the gauge's reading
  (edge_recession): the STL's cut and the run's surfaces in memory agree to 2e-6 m;
- the picture's window (lifetime.gp, the set xrange / yrange before section_worst.png) holds
  that place (and for the edge both lowest points), zoomed (its height under half of
  --part-height).
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
knife = os.path.join(a.run, "part")
files = sorted(f for f in os.listdir(knife) if f.endswith(".csv") and (f.startswith("profile_") or f == "section_worst.csv"))
if "section_worst.csv" not in files:
    fail("no part/section_worst.csv")
for f in files:
    b = blocks(os.path.join(knife, f))
    if 0 not in b:
        fail(f + ": no design outline (update 0)")
    for u, segments in b.items():
        if not closed(segments, 2e-6):
            fail("%s: the outline of update %d is not closed (%d segments)" % (f, u, len(segments)))
    print("%s: %d outlines, each closed" % (f, len(b)))

life = json.load(open(os.path.join(a.run, "summary.json")))["results"]["lifetime"]
rows = list(csv.DictReader(open(os.path.join(a.run, "trajectory.csv"))))
where = life["end_of_life_where"] or [float(rows[-1]["deepest_" + c]) for c in "xyz"]
criterion = life["end_of_life_criterion"]
worst_file = os.path.join(knife, "section_worst.csv")
worst = blocks(worst_file)
# the plane: "# section AXIS AT: ..." on the first line, through the place
m = re.match(r"# section ([xyz]) (\S+):", open(worst_file).readline())
if not m:
    fail("section_worst.csv does not say its plane")
axis = "xyz".index(m.group(1))
iu, iv = (axis + 1) % 3, (axis + 2) % 3
if abs(float(m.group(2)) - where[axis]) > 1e-9:
    fail("section_worst.csv is cut at %s = %s m, the place is at %.10g m" % (m.group(1), m.group(2), where[axis]))
last = max(worst)
if int(rows[-1]["update"]) != last:
    fail("section_worst.csv ends at update %d, trajectory.csv at %s" % (last, rows[-1]["update"]))


def distance_to(outline, p):
    best = float("inf")
    for u0, v0, u1, v1 in outline:
        du, dv = u1 - u0, v1 - v0
        l2 = du * du + dv * dv
        t = 0 if l2 == 0 else max(0.0, min(1.0, ((p[0] - u0) * du + (p[1] - v0) * dv) / l2))
        best = min(best, math.hypot(u0 + t * du - p[0], v0 + t * dv - p[1]))
    return best


# the place on its outline: a followed point on the design's (it recedes from there), every
# other place on the last update's (the deepest vertex, the gauge's lowest point); the cut of
# the exported surfaces against the run's own surfaces in memory
place = (where[iu], where[iv])
on = worst[0] if criterion == "maximum recession" else worst[last]
d = distance_to(on, place)
print("the place (%s, %s) = (%.5f, %.5f) m lies %.2g m from the %s outline" %
      ("xyz"[iu], "xyz"[iv], place[0], place[1], d, "design's" if on is worst[0] else "last"))
if d > 2e-6:
    fail("the section misses the place that ended the life by %.3g m" % d)
lowest = min(min(s[1], s[3]) for s in worst[last])
if criterion == "maximum edge recession":
    # the height gauge: the rise of the section's lowest point above the design's, from the cut
    # of the STL files against the gauge's reading on the surface in memory
    design_lowest = min(min(s[1], s[3]) for s in worst[0])
    gauged = float(rows[-1]["edge_recession"])
    print("rise of the lowest point %.7f m, the gauge %.7f m" % (lowest - design_lowest, gauged))
    if abs(lowest - design_lowest - gauged) > 2e-6:
        fail("the section through the gauge's station reads %.7f m, the gauge %.7f m" % (lowest - design_lowest, gauged))

gp = open(os.path.join(a.run, "lifetime.gp")).read()
m = re.search(r"set output 'part/section_worst.png'.*?set xrange \[([^:]+):([^\]]+)\]\nset yrange \[([^:]+):([^\]]+)\]", gp, re.S)
if not m:
    fail("lifetime.gp draws no part/section_worst.png")
y0, y1, z0, z1 = (float(v) / 1000 for v in m.groups())
print("window %s %.4f..%.4f, %s %.4f..%.4f m" % ("xyz"[iu], y0, y1, "xyz"[iv], z0, z1))
if not (y0 <= place[0] <= y1 and z0 <= place[1] <= z1):
    fail("the window does not hold where the life ended")
if criterion == "maximum edge recession":
    design_lowest = min(min(s[1], s[3]) for s in worst[0])
    if not (z0 <= min(lowest, design_lowest) and z1 >= max(lowest, design_lowest)):
        fail("the window does not hold the gauge's reading (the design's lowest point and the last one's)")
if a.part_height > 0 and z1 - z0 > 0.5 * a.part_height:
    fail("the window is not zoomed: %.3f m high for a part %.3f m high" % (z1 - z0, a.part_height))
print("ok")
