#!/usr/bin/env bash
# The field loop closes: a lifetime run's own worn surface, compared as if it were a scan
# (abrade compare against the design, at the run's tonnage) and calibrated on the
# measured_depths.csv that compare writes, gives the run's own W back: scale 1 +- 0.01 and
# correlation >= 0.99. Four runs: uniform and edge-concentrated analytic rates, one face worn
# 8 mm (where many worn points lie below one design point: compare writes the scan points too and
# calibrate looks them up on the predicted surface), and the small DEM case (also registered on
# the knife's top, z > 0.2 m, which does not wear there).
# Before the lifetime loop and compare shared one definition of wear depth (the distance below
# the design), this gave scale 0.90 and correlation 0.66. On the edge run's scan depths the
# candidate runs are ranked: another pattern (uniform) is told apart from the best, the same
# pattern with other update sizes is not (overlapping correlation intervals).
#   check_round_trip.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$(realpath "$1") src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --quiet --output "$out/uniform" --set "Lifetime/Maximum updates=3" > /dev/null
"$abrade" run "$src/tests/lifetime/analytic_edge.prm" --quiet --output "$out/edge" --set "Lifetime/Maximum updates=3" > /dev/null
"$abrade" run "$src/cases/lifetime/small.prm" --quiet --output "$out/dem" --set "Lifetime/Maximum updates=3" > /dev/null
# one face worn 8 mm: many points of the worn face lie below one design point near the end faces
"$abrade" run "$src/tests/lifetime/analytic_one_face.prm" --quiet --output "$out/one_face" \
  --set "Lifetime/Maximum updates=4" --set "Lifetime/Cycles per update=2000" > /dev/null
round_trip() { # run, label, registration options...
  local run=$1 label=$2; shift 2
  local tonnes
  tonnes=$(python3 -c "import csv,sys; print(list(csv.DictReader(open(sys.argv[1])))[-1]['tonnes'])" "$out/$run/trajectory.csv")
  local last
  last=$(printf "part_%05d.stl" "$(( $(wc -l < "$out/$run/trajectory.csv") - 1 ))")
  "$abrade" compare --predicted "$out/$run/part/$last" --scan "$out/$run/part/$last" \
    --reference "$out/$run/part/part_00000.stl" --tonnes "$tonnes" --output "$out/compare_$label" "$@" > /dev/null 2>&1
  "$abrade" calibrate --run "$out/$run" --measurements "$out/compare_$label/measured_depths.csv" \
    --output "$out/calibrate_$label" > /dev/null
}
round_trip uniform uniform --no-registration
round_trip edge edge --no-registration
round_trip dem dem --no-registration
round_trip one_face one_face --no-registration
round_trip dem dem_registered --register-on -1,-1,0.2,1,1,1
# ranking candidate runs on the edge run's scan depths (the run itself left out: it would match
# them exactly): two runs of the same edge rate with other update sizes (the same pattern) cannot
# be told apart; the uniform rate (another pattern) is told apart from the best
for f in 0.07 0.13; do
  "$abrade" run "$src/tests/lifetime/analytic_edge.prm" --quiet --output "$out/edge_$f" \
    --set "Lifetime/Maximum updates=4" --set "Lifetime/Depth increment fraction=$f" > /dev/null
done
( cd "$out" && "$abrade" calibrate --run uniform --run edge_0.07 --run edge_0.13 \
    --measurements compare_edge/measured_depths.csv --output ranking > ranking.txt )
python3 - "$out" <<'PY'
import json, sys, os
out = sys.argv[1]
lines = []
for label in ("uniform", "edge", "dem", "dem_registered", "one_face"):
    r = json.load(open(os.path.join(out, f"calibrate_{label}", "calibration.json")))["runs"][0]
    assert abs(r["scale"] - 1) <= 0.01, f"{label}: scale {r['scale']}"
    assert r["correlation"] >= 0.99, f"{label}: correlation {r['correlation']}"
    lines.append(f"{label} scale {r['scale']:.4f} correlation {r['correlation']:.4f}")
runs = {r["run"]: r for r in json.load(open(os.path.join(out, "ranking", "calibration.json")))["runs"]}
assert runs["uniform"]["rank"] == 3 and runs["uniform"]["told_apart_from_the_best"], runs["uniform"]
second = "edge_0.07" if runs["edge_0.13"]["rank"] == 1 else "edge_0.13"
assert not runs[second]["told_apart_from_the_best"], runs[second]
lines.append(f"ranking: uniform told apart (correlation {runs['uniform']['correlation']:.3f}), "
             f"{second} not ({runs[second]['correlation']:.5f})")
print("ok: " + "; ".join(lines))
PY
