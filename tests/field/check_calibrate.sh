#!/usr/bin/env bash
# abrade calibrate against synthetic measurements made with a known W (or rate):
#  1. W: the small DEM lifetime case run with W = 3e-14 gives the wear depth (below the design)
#     at four followed points per update (trajectory.csv, computed inside the run); calibrating the same case run
#     with W = 2e-14 on them must recover 3e-14 to 3 % (the two runs' DEM cycles agree while
#     their geometries do; the roundings of the update sizes part them after two updates, and
#     one bed's wear then differs by about 1 %: DEM noise, not in the fit's interval).
#  2. pattern: measurements from an analytic run with rate 2 um/t exp(-z / 50 mm); candidates
#     with the right pattern at half the magnitude (1 um/t exp(-z / 50 mm)) and with a wrong one
#     (exp(-z / 150 mm)): the right pattern ranks first with correlation > 0.999 and scale 2 (1 %).
#  3. the same measurements with 3 % Gaussian noise: the 95 % interval of the scale holds 2 and
#     is narrower than +-10 %.
#   check_calibrate.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$(realpath "$1") src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
points="0.075, 0, 0; 0.05, 0.0075, 0.02; 0.1, -0.0075, 0.02; 0.075, 0.015, 0.06"
dem() { "$abrade" run "$src/cases/lifetime/small.prm" --quiet --output "$out/$1" --set "Lifetime/Maximum updates=4" \
          --set "Lifetime/Recession points=$points" --set "Wall knife/Wear/Archard/Coefficient=$2" > /dev/null; }
dem truth_w 3e-14
dem run_w 2e-14
analytic() { "$abrade" run "$src/tests/lifetime/analytic_edge.prm" --quiet --output "$out/$1" \
               --set "Lifetime/Analytic/Wear rate=$2" --set "Lifetime/Maximum updates=4" > /dev/null; }
analytic truth_pattern "2e-6*exp(-z/0.05)"
analytic right_pattern "1e-6*exp(-z/0.05)"
analytic wrong_pattern "1e-6*exp(-z/0.15)"
python3 - "$out" "$points" <<'PY'
import csv, sys, os
out, points = sys.argv[1], [[float(v) for v in p.split(",")] for p in sys.argv[2].split(";")]
def table(run, name, pts):
    rows = list(csv.DictReader(open(os.path.join(out, run, "trajectory.csv"))))
    with open(os.path.join(out, name), "w") as f:
        f.write("x,y,z,tonnes,depth\n")
        for r in rows:
            for k, p in enumerate(pts):
                col = "point_depth" if k == 0 else f"point_depth_{k + 1}"
                f.write(f"{p[0]},{p[1]},{p[2]},{r['tonnes']},{r[col]}\n")
table("truth_w", "w.csv", points)
table("truth_pattern", "pattern.csv", [[0.075, 0.015, 0.06], [0.075, 0.015, 0.1], [0.075, -0.015, 0.15]])
import random
random.seed(5)
lines = open(os.path.join(out, "pattern.csv")).read().splitlines()
with open(os.path.join(out, "noisy.csv"), "w") as f:
    f.write(lines[0] + "\n")
    for l in lines[1:]:
        v = l.split(",")
        v[-1] = str(float(v[-1]) * (1 + random.gauss(0, 0.03)))
        f.write(",".join(v) + "\n")
PY
"$abrade" calibrate --run "$out/run_w" --measurements "$out/w.csv" --output "$out/cal_w"
( cd "$out" && "$abrade" calibrate --run wrong_pattern --run right_pattern --measurements pattern.csv --output cal_pattern )
"$abrade" calibrate --run "$out/right_pattern" --measurements "$out/noisy.csv" --output "$out/cal_noisy"
python3 - "$out" <<'PY'
import json, sys, os
out = sys.argv[1]
w = json.load(open(os.path.join(out, "cal_w", "calibration.json")))["runs"][0]
assert abs(w["archard_coefficient"] / 3e-14 - 1) < 0.03, w
p = json.load(open(os.path.join(out, "cal_pattern", "calibration.json")))["runs"]
assert p[0]["run"] == "right_pattern" and p[0]["correlation"] > 0.999, p
assert abs(p[0]["scale"] / 2 - 1) < 0.01, p[0]
assert p[1]["correlation"] < p[0]["correlation"], p
n = json.load(open(os.path.join(out, "cal_noisy", "calibration.json")))["runs"][0]
assert n["scale_low"] <= 2 <= n["scale_high"] and n["scale_high"] - n["scale_low"] < 0.4, n
print(f"ok: W = {w['archard_coefficient']:.5g} ({w['archard_coefficient_low']:.4g} ... {w['archard_coefficient_high']:.4g}), "
      f"pattern: right {p[0]['correlation']:.5f} (scale {p[0]['scale']:.4f}), wrong {p[1]['correlation']:.5f}; "
      f"3 % noise: scale {n['scale']:.4f} ({n['scale_low']:.4f} ... {n['scale_high']:.4f})")
PY
