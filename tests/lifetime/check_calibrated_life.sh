#!/usr/bin/env bash
# A lifetime run that takes a calibration back (Lifetime/Calibration; lifetime/wear_calibration.h),
# through the independent scan path. Truth: the small DEM case with W = 3e-14, three beds, one
# update; its worn surface written as a scan (abrade compare). A candidate at the case's
# W = 2e-14 on the same beds is calibrated on that scan (abrade calibrate), and the case is run
# again with Lifetime/Calibration = that calibration.json:
#  - the calibration finds W = 3e-14 (within 1 %: the same beds, Archard wear is linear in W);
#  - the calibrated run uses it (summary.json wear_coefficient) and predicts the truth's life
#    (within 0.1 %: one update's life goes exactly as 1 / W), and the truth lies in its interval;
#  - its interval's component `calibration` is calibration.json's relative standard error of W,
#    the total is the beds' and the calibration's in quadrature, and t lies between t(infinity)
#    and t at the smaller of the two degrees of freedom (Welch-Satterthwaite);
#  - a run with another footprint (Smoothing radius) than the calibrated run's is warned about;
#  - a missing calibration file, one that is not JSON, one without runs, and an analytic rate
#    with a calibration are refused with exit 2, naming the file or the parameter.
#   check_calibrated_life.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
case_file="$src/cases/lifetime/small.prm"
run() { # output, sets...
  local dir=$1; shift
  "$abrade" run "$case_file" --quiet --output "$out/$dir" --set "Lifetime/Seeds=1,2,3" \
    --set "Lifetime/Maximum updates=1" "$@" > /dev/null
}
run truth --set "Wall knife/Wear/Archard/Coefficient=3e-14"
tonnes=$(python3 -c "import csv,sys; print(list(csv.DictReader(open(sys.argv[1])))[-1]['tonnes'])" "$out/truth/trajectory.csv")
"$abrade" compare --predicted "$out/truth/knife/knife_00001.stl" --scan "$out/truth/knife/knife_00001.stl" \
  --reference "$out/truth/knife/knife_00000.stl" --tonnes "$tonnes" --no-registration --output "$out/scan" > /dev/null 2>&1
run candidate
"$abrade" calibrate --run "$out/candidate" --measurements "$out/scan/measured_depths.csv" --output "$out/calibration" > /dev/null
run calibrated --set "Lifetime/Calibration=$out/calibration/calibration.json"
run other_footprint --set "Lifetime/Calibration=$out/calibration/calibration.json" --set "Lifetime/Smoothing radius=0.04"

refused() { # what, expected text, sets...
  local what=$1 text=$2; shift 2
  set +e
  "$abrade" run "$case_file" --quiet --output "$out/refused" --set "Lifetime/Maximum updates=1" "$@" > "$out/refused.log" 2>&1
  local rc=$?
  set -e
  rm -rf "$out/refused"
  [ "$rc" = 2 ] || { echo "$what: exit $rc, not 2"; cat "$out/refused.log"; exit 1; }
  grep -q -- "$text" "$out/refused.log" || { echo "$what: the message does not say '$text'"; cat "$out/refused.log"; exit 1; }
}
refused "missing file" "$out/none.json" --set "Lifetime/Calibration=$out/none.json"
echo "W = 3e-14" > "$out/not_json.json"
refused "not JSON" "not_json.json: not a calibration.json" --set "Lifetime/Calibration=$out/not_json.json"
echo '{"runs": []}' > "$out/no_runs.json"
refused "no runs" "no calibrated run" --set "Lifetime/Calibration=$out/no_runs.json"
refused "analytic rate" "Calibration" --set "Lifetime/Wear source=analytic" --set "Lifetime/Analytic wear rate=1e-6" \
  --set "Lifetime/Tonnes per cycle=1" --set "Lifetime/Calibration=$out/calibration/calibration.json"

python3 - "$out" <<'PY'
import json, math, os, sys
out = sys.argv[1]
def life(run):
    return json.load(open(os.path.join(out, run, "summary.json")))["results"]["lifetime"]
cal = json.load(open(os.path.join(out, "calibration", "calibration.json")))["runs"][0]
w = cal["archard_coefficient"]
assert abs(w / 3e-14 - 1) < 0.01, w
truth, candidate, calibrated = life("truth"), life("candidate"), life("calibrated")
assert calibrated["wear_coefficient"] == w and calibrated["calibration"]["wear_coefficient"] == w, calibrated
assert cal["smoothing_radius"] == candidate["smoothing_radius"] > 0, (cal, candidate["smoothing_radius"])
L, Lt = calibrated["predicted_tonnes_to_end_of_life"], truth["predicted_tonnes_to_end_of_life"]
assert abs(L / (Lt * 3e-14 / w) - 1) < 1e-3, (L, Lt, w)
iv = calibrated["interval"]
s_cal = math.hypot(cal["scale_standard_error_fit"], cal["scale_standard_error_replicates"]) / cal["scale"]
assert s_cal > 0 and abs(iv["components"]["calibration"] / s_cal - 1) < 1e-9, (iv, s_cal)
beds = math.hypot(iv["components"]["beds"], iv["components"]["extrapolation"])
assert abs(iv["relative_sd"] / math.hypot(beds, s_cal) - 1) < 1e-9, iv
t = math.log(calibrated["predicted_tonnes_high"] / L) / iv["relative_sd"]
t_small = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447}[int(min(cal["degrees_of_freedom"], 6))]
assert 1.959 < t <= t_small + 1e-3, (t, t_small, iv["degrees_of_freedom"])
assert calibrated["predicted_tonnes_low"] < Lt < calibrated["predicted_tonnes_high"], (calibrated, Lt)
assert life("truth")["interval"]["components"]["calibration"] == 0
other = life("other_footprint")
assert any("was fitted with a footprint" in x for x in other["warnings"]), other["warnings"]
assert not any("was fitted with a footprint" in x for x in calibrated["warnings"]), calibrated["warnings"]
print(f"ok: calibrated W = {w:.5g} (truth 3e-14) +- {100 * s_cal:.3g} %; life {L:.5g} t against the truth's {Lt:.5g} "
      f"(interval {calibrated['predicted_tonnes_low']:.4g} ... {calibrated['predicted_tonnes_high']:.4g}; beds "
      f"{100 * beds:.3g} %, calibration {100 * s_cal:.3g} %); another footprint warned; bad calibrations refused")
PY
