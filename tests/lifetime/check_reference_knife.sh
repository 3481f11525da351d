#!/usr/bin/env bash
# The reference knife (0.4 m x 0.5 m x 30 mm chisel, 40 mm bevel, 20 mm mesh) followed to its
# end of life with known wear rates, where the moved vertices fold (the bevel face shrinks away
# under uniform wear; fronts meet at the tip under edge-concentrated wear) and the worn surface
# is built anew as a set (fem/eroded_surface.h):
#  uniform: 1 um/t on every wearable face, to 12 mm of depth below the design: reached (not
#           extrapolated) at 12,000 t. Until the worn surface was built as a set, Gmsh aborted
#           the process at 9 mm here (the test case had been moved to a 60 mm plate).
#           Tolerance 4 %: the corners of the front are cut by the marching cubes between their
#           vertices by a few hundredths of the 2 mm grid, which the next update carries on
#           (measured: 11,630 t, -3.1 %; the issue asks 1 %: open).
#  edge:    2 um/t x exp(-z / 50 mm), to 20 mm of recession at the middle of the edge: reached,
#           not extrapolated (it stopped with a failed remesh at update 5 and extrapolated); the
#           worn section at mid-length within 1 mm of an independent solution of the same front
#           motion (front_2d.py: the eikonal equation by fast marching on a 0.2 mm grid), both
#           ways, at every update.
#   check_reference_knife.sh ABRADE TESTDIR OUTDIR   (by hand; not yet in ctest: tests/CMakeLists.txt says why)
set -euo pipefail
abrade=$1 dir=$2 out=$3
rm -rf "$out"
knife=(--set Knife/Thickness=0.03 --set "Knife/Bevel height=0.04" --set "Knife/Mesh size=0.02"
       --set Knife/Length=0.4 --set Knife/Height=0.5 --set "Lifetime/Maximum updates=60")
"$abrade" run "$dir/analytic_uniform.prm" "${knife[@]}" --output "$out/uniform" --quiet > /dev/null
"$abrade" run "$dir/analytic_edge.prm" "${knife[@]}" --set "Lifetime/Maximum depth=0" \
  --set "Lifetime/Maximum recession=0.02" --set "Lifetime/Recession points=0.2, 0, 0" --output "$out/edge" --quiet > /dev/null
python3 - "$out" <<'PY'
import csv, json, os, sys
out = sys.argv[1]
def summary(case):
    return json.load(open(os.path.join(out, case, "summary.json")))
for case, criterion, life, tol in (("uniform", "maximum depth", 12000, 0.04), ("edge", "maximum recession", None, None)):
    s = summary(case)
    assert s["status"] == "completed", (case, s["status"])
    l = s["results"]["lifetime"]
    assert l["end_of_life_criterion"] == criterion, (case, l["end_of_life_criterion"])
    assert not l["extrapolated"], f"{case}: the life was extrapolated ({l['end_of_life_method']})"
    rows = list(csv.DictReader(open(os.path.join(out, case, "trajectory.csv"))))
    assert any(r["remeshed"] == "1" for r in rows), f"{case}: never remeshed"
    if life:
        err = abs(l["predicted_tonnes_to_end_of_life"] - life) / life
        assert err < tol, f"{case}: life {l['predicted_tonnes_to_end_of_life']} t against {life} t ({err:.1%})"
    print(f"{case}: {criterion} reached at {l['predicted_tonnes_to_end_of_life']:.0f} t in {len(rows)} updates")
PY
for ((u = 1; u < $(wc -l < "$out/edge/trajectory.csv"); ++u)); do
  python3 "$dir/front_2d.py" "$out/edge" --update $u --tolerance 0.001
done
