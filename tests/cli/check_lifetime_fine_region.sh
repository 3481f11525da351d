#!/usr/bin/env bash
# The lifetime loop checks a multi-level bed's fine box once (fine_region_margin.cc): the small
# lifetime case with 13.75 mm pellets in |y| < 0.06 m (0.045 m beside the knife, well under the
# depth it works at) and two beds: the margin warned once in the loop's log (a warning for each of
# the box's two faces beside the knife, the first bed's), and none of it among the
# DEM's cycle warnings (trajectory.csv's dem_warnings; before, each bed made added it there).
#   check_lifetime_fine_region.sh ABRADE CASE OUTDIR
set -euo pipefail
abrade=$1 case_file=$2 out=$3
rm -rf "$out"
"$abrade" run "$case_file" --output "$out" --quiet --set "Particles/Generation/Radius=0.01375" \
  --set "Particles/Generation/Count=4800" --set "Particles/Coarse graining/Factor=2" \
  --set "Particles/Coarse graining/Fine region min=-0.39, -0.06, 0.01" --set "Particles/Coarse graining/Fine region max=0.39, 0.06, 0.6" \
  --set "Particles/Coarse graining/Fine region factor=1.25" --set "Particles/Coarse graining/Fine region pours=1" \
  --set "Lifetime/Maximum updates=1" --set "Lifetime/Seeds=1,2" --set "Simulation/Threads=1"
warned=$(grep -c "warning: Particles/Coarse graining/Fine region: wall knife's path comes 0.045 m" "$out/log.txt" || true)
[[ $warned == 2 ]] || { echo "the margin warning $warned times in the lifetime's log (twice wanted: the first bed's two faces)"; exit 1; }
python3 - "$out/trajectory.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert rows and all(float(r["dem_warnings"]) == 0 for r in rows), [r["dem_warnings"] for r in rows]
PY
echo "ok: the fine box's margin warned once, not counted among the DEM's cycle warnings"
