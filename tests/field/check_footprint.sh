#!/usr/bin/env bash
# W and the wear footprint fitted together (abrade calibrate, field/footprint_fit.h), on a
# pattern whose width the footprint sets: wear in a 4 mm band at the knife's lowest point, given
# as a volume and spread by the footprint filter (Lifetime/Smoothing radius). Truth: 3e-6 per
# tonne at a 10 mm footprint, 3,000 t in two updates; its worn surface, compared as a scan,
# with 0.1 mm of noise on each depth. Candidates at 2e-6 with footprints 5, 10, 20 and 40 mm,
# the assumed one (20 mm) first, each update removing the truth's volume (2,250 cycles: the
# candidate at 10 mm is the truth at 1.5 times its tonnes; with the truth's 1,500 cycles the
# band, which follows the lowest point, wears another shape in smaller steps, and the fit,
# noise-free, put the footprint at 8.8 mm, 7.5 ... 9.9):
#  - the footprint fitted holds the truth's 10 mm in its 95 % interval, which is narrower than
#    +-40 %, the scale at it holds 1.5 within its own interval (the footprint's uncertainty in
#    it), and the truth lies in the joint region of the two (footprint.png);
#  - the candidates' scales differ by 1.65x between 5 and 40 mm (W and the footprint are
#    degenerate in a depth: why both must be fitted);
#  - on the deepest point alone the footprint is not identifiable (said why) and the scale is
#    given for the first run's footprint.
# The candidates run to 4,500 t: the fitted scales of the other footprints reach past them and
# are extrapolated linearly (calibrate warns).
#   check_footprint.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
cat > "$out/band.prm" <<PRM
include $src/tests/lifetime/analytic_edge.prm
subsection Lifetime
  subsection Analytic
    set Wear rate = 3e-6*(z < zlow + 0.004)
    set Wear is   = volume
  end
  set Smoothing radius   = 0.01
  set Maximum updates    = 2
  set Cycles per update  = 1500
  set Maximum depth      = 0.02
end
PRM
"$abrade" run "$out/band.prm" --quiet --output "$out/truth" > /dev/null
"$abrade" compare --predicted "$out/truth/part/part_00002.stl" --scan "$out/truth/part/part_00002.stl" \
  --reference "$out/truth/part/part_00000.stl" --tonnes 3000 --no-registration --output "$out/scan" > /dev/null 2>&1
for r in 0.005 0.01 0.02 0.04; do
  "$abrade" run "$out/band.prm" --quiet --output "$out/r$r" --set "Lifetime/Smoothing radius=$r" \
    --set "Lifetime/Analytic/Wear rate=2e-6*(z < zlow + 0.004)" --set "Lifetime/Cycles per update=2250" > /dev/null &
done
wait
# the measured depths with a gauge's noise (0.1 mm, seeded)
python3 - "$out/scan/measured_depths.csv" "$out/measured.csv" "$out/one_depth.csv" <<'PY'
import csv, random, sys
rows = list(csv.DictReader(open(sys.argv[1])))
random.seed(34)
for r in rows:
    r["depth"] = repr(float(r["depth"]) + random.gauss(0, 1e-4))
for path, chosen in ((sys.argv[2], rows), (sys.argv[3], [max(rows, key=lambda r: float(r["depth"]))])):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader(), w.writerows(chosen)
PY
runs=(--run "$out/r0.02" --run "$out/r0.005" --run "$out/r0.01" --run "$out/r0.04")
"$abrade" calibrate "${runs[@]}" --measurements "$out/measured.csv" --output "$out/fit" > /dev/null
"$abrade" calibrate "${runs[@]}" --measurements "$out/one_depth.csv" --output "$out/one" > /dev/null 2>&1
python3 - "$out" <<'PY'
import csv, json, math, os, sys
out = sys.argv[1]
fit = json.load(open(os.path.join(out, "fit", "calibration.json")))
fp = fit["footprint"]
assert fp["identifiable"], fp
assert fp["smoothing_radius_low"] < 0.01 < fp["smoothing_radius_high"], fp
assert fp["smoothing_radius_high"] / fp["smoothing_radius_low"] < 1.4 / 0.6, fp
scales = {r["run"].split("/")[-1]: r for r in fit["runs"]}
assert scales["r0.04"]["scale"] / scales["r0.005"]["scale"] > 1.5, scales
# the scale at the fitted footprint (wear_coefficient: the scale for analytic runs): its own
# interval (the footprint's uncertainty in it) holds the truth's 1.5, and so does the joint
# region (r, scale), whose outline (footprint_region.csv) is on its level
assert fp["wear_coefficient_low"] < 1.5 < fp["wear_coefficient_high"], fp
jr = fp["joint_region"]
a = math.log(0.01 / fp["smoothing_radius"])
e = math.log(1.5 / fp["wear_coefficient"]) - fp["dlnw_dlnr"] * a
q = (a / jr["scale_log_r_below" if a < 0 else "scale_log_r_above"]) ** 2 + (e / jr["scale_log_w"]) ** 2
assert q <= jr["level"], (q, fp)
outline = list(csv.DictReader(open(os.path.join(out, "fit", "footprint_region.csv"))))
assert len(outline) > 10 and os.path.getsize(os.path.join(out, "fit", "footprint.png")) > 1000
one = json.load(open(os.path.join(out, "one", "calibration.json")))["footprint"]
assert not one["identifiable"] and "degenerate" in one["reason"] and one["smoothing_radius"] == 0.02, one
print(f"ok: footprint {1e3 * fp['smoothing_radius']:.3g} mm ({1e3 * fp['smoothing_radius_low']:.3g} ... "
      f"{1e3 * fp['smoothing_radius_high']:.3g}; truth 10), scale {fp['wear_coefficient']:.3g} at it ({fp['wear_coefficient_low']:.3g} ... "
      f"{fp['wear_coefficient_high']:.3g}; truth 1.5), the truth in the joint region ({q:.2g} <= {fp['joint_region']['level']:.3g}); the "
      f"candidates' scales {scales['r0.005']['scale']:.3g} (5 mm) ... {scales['r0.04']['scale']:.3g} (40 mm); one depth: "
      f"not identifiable")
PY
