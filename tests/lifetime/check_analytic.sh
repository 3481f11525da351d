#!/usr/bin/env bash
# The lifetime loop against known wear rates (Lifetime/Wear source = analytic):
#  uniform: the flat faces recede by rate x tonnes (to 1e-6), the chisel tip, where the offset
#           bevels meet, by rate x tonnes / sin(half edge angle) (to 1e-4), at every update and
#           across remeshes;
#  edge:    rate 2 um/t x exp(-z / 50 mm): points of the flat faces at three heights recede by the
#           rate at their height times the tonnes (to 2 %, the linear interpolation of the
#           exponential over 10 mm elements).
# Both: the swept volume is the Archard volume of the update within 7 % (what is missing is the
# wear on the border of the clamped top, where vertices cannot move).
#   check_analytic.sh ABRADE TESTDIR OUTDIR
set -euo pipefail
abrade=$1 dir=$2 out=$3
rm -rf "$out"
for c in uniform edge; do
  "$abrade" run "$dir/analytic_$c.prm" --output "$out/$c" --quiet > /dev/null
done
python3 - "$out" <<'PY'
import csv, math, sys, os
out = sys.argv[1]
def rows(case):
    return list(csv.DictReader(open(os.path.join(out, case, "trajectory.csv"))))
sin_half = 0.015 / math.hypot(0.015, 0.04)
worst = {}
def check(case, column, expected, measured, tol):
    err = abs(measured - expected) / expected
    worst[(case, column)] = max(worst.get((case, column), 0), err)
    assert err < tol, f"{case} {column}: {measured} vs analytic {expected} (relative error {err:.2e} > {tol})"
u = rows("uniform")
assert len(u) >= 3 and any(r["remeshed"] == "1" for r in u), "uniform: too few updates or no remesh"
for r in u:
    t = float(r["tonnes"])
    check("uniform", "tip", 1e-6 * t / sin_half, float(r["point_recession"]), 1e-4)
    check("uniform", "face +y", 1e-6 * t, float(r["point_recession_2"]), 1e-6)
    check("uniform", "face -y", 1e-6 * t, float(r["point_recession_3"]), 1e-4)
    assert 0.93 < float(r["swept_over_archard"]) <= 1.0, r["swept_over_archard"]
e = rows("edge")
assert len(e) >= 3 and any(r["remeshed"] == "1" for r in e), "edge: too few updates or no remesh"
for r in e:
    t = float(r["tonnes"])
    for col, z in (("point_recession", 0.06), ("point_recession_2", 0.1), ("point_recession_3", 0.15)):
        check("edge", f"z = {z}", 2e-6 * math.exp(-z / 0.05) * t, float(r[col]), 0.02)
    assert 0.93 < float(r["swept_over_archard"]) <= 1.0, r["swept_over_archard"]
print("ok, largest relative errors:", ", ".join(f"{k[0]} {k[1]} {v:.1e}" for k, v in worst.items()))
PY
