#!/usr/bin/env bash
# Wear on the edge line only, followed to 30 mm of tip recession (issue 32's tip check), on
# tests/lifetime/analytic_tip.prm's knife (30 mm chisel, 40 mm bevel, 10 mm mesh):
#  the rate:   1 um/t on a band 3 mm high that follows the tip up (z < 3 mm + the tip's
#              recession at the bevel planes' speed, 1 um/t / sin(20.6 deg)), given as a volume
#              (Analytic wear is = volume: the knife must lose rate x tonnes x worn area in every
#              update, as it must lose the DEM's Archard volume);
#  the filter: as the loop receives a DEM's wear on the edge line, spread over the particle's
#              footprint (Lifetime/Smoothing radius, volume-conserving): at the mesh size (10 mm)
#              and at half of it (5 mm), the smallest the documentation allows.
# Checks, for both: the recession limit reached, not extrapolated; no update halved, folded,
# built as a set or filled inside its old surface; the knife meshed anew before a step at least
# once; every update removed the volume worn (1e-4) and the worn volume at the end is the summed
# wear (1e-6); the gauge's recession only grows, and at the end it is the tip of the worn
# knife's exported surface cut at the gauge's section (computed here from the STL, 1e-5 m).
# Unfiltered (a band narrower than a cell carried by the tip's vertices alone) the tip blunts
# into a flat that Gmsh cannot remesh at about 11 mm (docs/lifetime.md): a smoothing radius
# below half the mesh size is warned about (checked here on one update).
#   check_tip_recession.sh ABRADE TESTDIR OUTDIR
set -euo pipefail
abrade=$1 dir=$2 out=$3
rm -rf "$out"
tip=(--set "Lifetime/Analytic wear rate=1e-6*(z < 0.003 + 1e-6*t/0.3511)" --set "Lifetime/Analytic wear is=volume"
     --set "Lifetime/Maximum depth=0" --set "Lifetime/Maximum recession=0.03" --set "Lifetime/Maximum updates=80")
for r in 0.01 0.005; do
  "$abrade" run "$dir/analytic_tip.prm" "${tip[@]}" --set "Lifetime/Smoothing radius=$r" \
    --output "$out/filter_$r" --quiet > /dev/null
done
"$abrade" run "$dir/analytic_tip.prm" "${tip[@]}" --set "Lifetime/Smoothing radius=0.004" \
  --set "Lifetime/Maximum updates=1" --output "$out/narrow" --quiet > /dev/null || true
grep -q "Smoothing radius (0.004 m) is below half the Knife/Mesh size" "$out/narrow/log.txt" ||
  { echo "narrow: no warning about a smoothing radius below half the mesh size"; exit 1; }
python3 - "$out" <<'PY'
import csv, glob, json, os, struct, sys
out = sys.argv[1]
def tip_of_stl(path, x):
    """The lowest point of the surface's cut with the plane at x (binary STL)."""
    data = open(path, "rb").read()
    n = struct.unpack("<I", data[80:84])[0]
    lowest = float("inf")
    for k in range(n):
        v = struct.unpack("<9f", data[84 + 50 * k + 12:84 + 50 * k + 48])
        corners = [v[0:3], v[3:6], v[6:9]]
        for a in range(3):
            p, q = corners[a], corners[(a + 1) % 3]
            if (p[0] - x) * (q[0] - x) < 0:
                s = (x - p[0]) / (q[0] - p[0])
                lowest = min(lowest, p[2] + s * (q[2] - p[2]))
    return lowest
for r in ("0.01", "0.005"):
    case = os.path.join(out, "filter_" + r)
    s = json.load(open(os.path.join(case, "summary.json")))
    assert s["status"] == "completed", (case, s["status"])
    l = s["results"]["lifetime"]
    assert l["end_of_life_criterion"] == "maximum recession", (case, l["end_of_life_criterion"])
    assert not l["extrapolated"], f"{case}: the life was extrapolated ({l['end_of_life_method']})"
    assert l["remeshes_inside_worn_surface"] == 0, f"{case}: filled inside its worn surface"
    assert abs(l["worn_over_archard"] - 1) < 1e-6, f"{case}: worn/Archard {l['worn_over_archard']}"
    log = open(os.path.join(case, "log.txt")).read()
    for bad in ("retried with", "built anew", "would fold;", "could not be remeshed"):
        assert bad not in log, f"{case}: the log says '{bad}'"
    assert "meshed anew before its vertices moved" in log, f"{case}: never meshed anew before a step"
    rows = list(csv.DictReader(open(os.path.join(case, "trajectory.csv"))))
    worst = max(abs(float(row["swept_over_archard"]) - 1) for row in rows)
    assert worst < 1e-4, f"{case}: an update's swept volume {worst:.1e} off the volume worn"
    recession = [float(row["point_recession"]) for row in rows]
    assert all(b >= a for a, b in zip(recession, recession[1:])), f"{case}: the recession went back: {recession}"
    assert recession[-1] >= 0.03, f"{case}: the last update's recession {recession[-1]}"
    last = sorted(glob.glob(os.path.join(case, "knife", "knife_*.stl")))[-1]
    cut = tip_of_stl(last, 0.075)
    assert abs(cut - recession[-1]) < 1e-5, f"{case}: gauge {recession[-1]} m, the STL's tip {cut} m"
    print(f"filter {r} m: 30 mm of tip recession reached at {l['predicted_tonnes_to_end_of_life']:.0f} t in "
          f"{len(rows)} updates, {l['remeshes']} remeshes, swept/Archard within {worst:.0e}; the worn "
          f"STL's tip {1e3 * cut:.4f} mm, the gauge's {1e3 * recession[-1]:.4f} mm")
PY
