#!/usr/bin/env bash
# The lifetime loop checks a multi-level bed's fine box once (fine_region_margin.cc): the small
# lifetime case with 13.75 mm pellets in |y| < 0.06 m (0.045 m beside the knife, well under the
# depth it works at) and two beds: the margin warned once in the loop's log (a warning for each of
# the box's two faces beside the knife, the first bed's), and none of it among the
# DEM's cycle warnings (trajectory.csv's dem_warnings; before, each bed made added it there).
# Then the same beds loaded by a case that pours its fine region twice: each saved bed named once
# as made by another case (bed_preparation.cc's check_bed_pours), in the loop's log and
# summary.json and not among the cycle warnings (before, each bed loaded added one there; the base
# seeds' beds are loaded in the first update only, later updates make fresh beds).
# Last, the first run replayed (Lifetime/Wear source = replay) by the same case: its own run again,
# byte for byte (before, a multi-level run's stored wear, made by the finest particles, factor
# 1.25, was refused as made by other particles than the case's Factor 2).
#   check_lifetime_fine_region.sh ABRADE CASE OUTDIR
set -euo pipefail
abrade=$1 case_file=$2 out=$3
rm -rf "$out" "$out-loaded" "$out-replay"
run() { # OUTDIR POURS [--set ...]
  local dir=$1 pours=$2
  shift 2
  "$abrade" run "$case_file" --output "$dir" --quiet --set "Particles/Generation/Radius=0.01375" \
    --set "Particles/Generation/Count=4800" --set "Particles/Coarse graining/Factor=2" \
    --set "Particles/Coarse graining/Fine region min=-0.39, -0.06, 0.01" --set "Particles/Coarse graining/Fine region max=0.39, 0.06, 0.6" \
    --set "Particles/Coarse graining/Fine region factor=1.25" --set "Particles/Coarse graining/Fine region pours=$pours" \
    --set "Lifetime/Maximum updates=1" --set "Lifetime/Seeds=1,2" --set "Simulation/Threads=1" "$@"
}
no_cycle_warnings() {
  python3 - "$1/trajectory.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert rows and all(float(r["dem_warnings"]) == 0 for r in rows), (sys.argv[1], [r["dem_warnings"] for r in rows])
PY
}
run "$out" 1
warned=$(grep -c "warning: Particles/Coarse graining/Fine region: wall knife's path comes 0.045 m" "$out/log.txt" || true)
[[ $warned == 2 ]] || { echo "the margin warning $warned times in the lifetime's log (twice wanted: the first bed's two faces)"; exit 1; }
# the face the margin wants (0.149 m out) leaves the shells and a bulk particle (0.142 m) no room
# before the fill box's face at 0.24 m: the advice is to extend the fine region to it; the box
# reaches the fill box's faces in x and z already, so extended in y it would leave the bulk no
# room: a warning says so
extend=$(grep -c "extend the fine region to the fill box's face at y = [-]*0.24 m (a face at [-]*0.1[0-9]* m would leave its shells and a bulk particle less than the 0.142 m" "$out/log.txt" || true)
[[ $extend == 2 ]] || { echo "the advice to extend the fine region to the fill box's faces $extend times (twice wanted)"; exit 1; }
grep -q "^warning: Particles/Coarse graining/Fine region: extended to the fill box's faces as advised, the fine region and its shells would fill the fill box" "$out/log.txt" ||
  { echo "no warning that the advised box leaves the bulk no room"; exit 1; }
no_cycle_warnings "$out"

mkdir -p "$out-loaded/beds" && cp "$out"/beds/bed-seed[12].bed "$out-loaded/beds/"
run "$out-loaded" 2
for seed in 1 2; do
  n=$(grep -c "^warning: .*beds/bed-seed$seed.bed: its [0-9]* particles are the case's [0-9]*: it was poured once" "$out-loaded/log.txt" || true)
  [[ $n == 1 ]] || { echo "bed-seed$seed.bed named $n times as poured by another case (once wanted)"; exit 1; }
done
no_cycle_warnings "$out-loaded"
python3 - "$out-loaded/summary.json" <<'PY'
import json, sys
w = json.load(open(sys.argv[1]))["results"]["lifetime"]["warnings"]
for seed in (1, 2):
    assert sum(f"beds/bed-seed{seed}.bed: its" in t for t in w) == 1, (seed, w)
PY

run "$out-replay" 1 --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out"
for f in trajectory.csv life_beds.csv; do
  cmp -s "$out/$f" "$out-replay/$f" || { echo "the multi-level run replayed differs in $f"; exit 1; }
done
echo "ok: the fine box's margin warned once, a loaded bed of another case named once; neither counted among the DEM's cycle warnings; the run replayed is itself again"
