#!/usr/bin/env bash
# A lifetime run that takes a calibration back (Lifetime/Calibration; lifetime/wear_calibration.h),
# through the independent scan path. Truth: the small DEM case with W = 3e-14, three beds, one
# update; its worn surface written as a scan (abrade compare). A candidate at the case's
# W = 2e-14 on the same beds is calibrated on that scan (abrade calibrate), and the case is run
# again with Lifetime/Calibration = that calibration.json:
#  - the calibration finds W = 3e-14 (within 1 %: the same beds, Archard wear is linear in W);
#  - the calibrated run uses it (summary.json wear_coefficient; its report says the
#    calibration's share of the interval) and predicts the truth's life
#    (within 0.1 %: one update's life goes exactly as 1 / W), and the truth lies in its interval;
#  - its interval's component `calibration` is calibration.json's relative standard error of W,
#    the total is the beds' and the calibration's in quadrature, its degrees of freedom are
#    Welch-Satterthwaite's and its t the Student quantile at them (computed here by integrating
#    the density); with one bed an update there is no interval, calibration or not;
#  - a run with another footprint (Smoothing radius) than the calibrated run's is warned about,
#    and so is one whose calibration was fitted at another particle size (a calibration.json
#    with coarse-graining factor 1.5, and one with 1.5 times the particle, each alone): the
#    calibration records the calibrated run's largest particle and factor;
#  - W and the footprint together: candidates at footprints 15 and 55 mm beside the default
#    27.5 mm (the truth's): calibrate fits the footprint within its interval of the truth's and
#    the lifetime run with that calibration takes both (its Smoothing radius the fitted one,
#    the footprint's share in the component) and its interval holds the truth's life; on a
#    single measured depth the footprint is not identifiable, said so, and W is given for the
#    first run's footprint;
#  - a missing calibration file, one that is not JSON, one without runs, one of another wear
#    field (Oka's coefficient is not Archard's), one whose W is 1e-3 (not the case's units), one
#    with a negative standard error or one larger than W, and an analytic rate with a
#    calibration are refused with exit 2, naming the file or the parameter.
#   check_calibrated_life.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
updates=1
source "$(dirname "$0")/small_case_runs.sh"
run truth --set "Wall knife/Wear/Archard/Coefficient=3e-14"
tonnes=$(python3 -c "import csv,sys; print(list(csv.DictReader(open(sys.argv[1])))[-1]['tonnes'])" "$out/truth/trajectory.csv")
"$abrade" compare --predicted "$out/truth/part/part_00001.stl" --scan "$out/truth/part/part_00001.stl" \
  --reference "$out/truth/part/part_00000.stl" --tonnes "$tonnes" --no-registration --output "$out/scan" > /dev/null 2>&1
run candidate
"$abrade" calibrate --run "$out/candidate" --measurements "$out/scan/measured_depths.csv" --output "$out/calibration" > /dev/null
run calibrated --set "Lifetime/Calibration=$out/calibration/calibration.json"
run other_footprint --set "Lifetime/Calibration=$out/calibration/calibration.json" --set "Lifetime/Smoothing radius=0.04"
"$abrade" run "$case_file" --quiet --output "$out/one_bed" --set "Lifetime/Seeds=1" --set "Lifetime/Maximum updates=1" \
  --set "Lifetime/Calibration=$out/calibration/calibration.json" > /dev/null

run cand_r15 --set "Lifetime/Smoothing radius=0.015"
run cand_r55 --set "Lifetime/Smoothing radius=0.055"
"$abrade" calibrate --run "$out/candidate" --run "$out/cand_r15" --run "$out/cand_r55" \
  --measurements "$out/scan/measured_depths.csv" --output "$out/calibration_footprint" > /dev/null
run calibrated_footprint --set "Lifetime/Calibration=$out/calibration_footprint/calibration.json"
python3 - "$out/scan/measured_depths.csv" "$out/one_depth.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
deepest = max(rows, key=lambda r: float(r["depth"]))
with open(sys.argv[2], "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader(), w.writerow(deepest)
PY
"$abrade" calibrate --run "$out/candidate" --run "$out/cand_r15" --run "$out/cand_r55" \
  --measurements "$out/one_depth.csv" --output "$out/calibration_one_depth" > /dev/null 2>&1

refused "missing file" "$out/none.json" --set "Lifetime/Calibration=$out/none.json"
echo "W = 3e-14" > "$out/not_json.json"
refused "not JSON" "not_json.json: not a calibration.json" --set "Lifetime/Calibration=$out/not_json.json"
echo '{"runs": []}' > "$out/no_runs.json"
refused "no runs" "no calibrated run" --set "Lifetime/Calibration=$out/no_runs.json"
variant() { # name, python expression changing the best run r
  python3 - "$out/calibration/calibration.json" "$out/$1.json" "$2" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); r = j["runs"][0]; exec(sys.argv[3]); json.dump(j, open(sys.argv[2], "w"))
PY
}
variant other_factor 'r["coarse_graining_factor"] = 1.5'
run other_factor --set "Lifetime/Calibration=$out/other_factor.json"
variant other_size 'r["particle_radius"] *= 1.5'
run other_size --set "Lifetime/Calibration=$out/other_size.json"
variant object 'j["runs"] = {"best": r}'
refused "runs not a list" "not a list" --set "Lifetime/Calibration=$out/object.json"
variant oka 'r["wear_field"] = "oka_volume"'
refused "another wear field" "another law's coefficient" --set "Lifetime/Calibration=$out/oka.json"
variant tiny 'r["archard_coefficient"] = 1e-3'
refused "W in other units" "not the same law or units" --set "Lifetime/Calibration=$out/tiny.json"
variant negative 'r["scale_standard_error_fit"] = -0.1'
refused "negative standard error" "negative" --set "Lifetime/Calibration=$out/negative.json"
variant vague 'r["scale_standard_error_fit"] = 10 * r["scale"]'
refused "standard error above W" "uncertain by more than itself" --set "Lifetime/Calibration=$out/vague.json"
refused "analytic rate" "Calibration" --set "Lifetime/Wear source=analytic" --set "Lifetime/Analytic/Wear rate=1e-6" \
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
# the particle size W holds for: recorded by the run and the calibration, another one warned about
assert cal["particle_radius"] == candidate["particle_radius"] > 0 and cal["coarse_graining_factor"] == 1, cal
for run in ("other_factor", "other_size"):
    assert any("particle size they were fitted at" in w for w in life(run)["warnings"]), (run, life(run)["warnings"])
assert not any("particle size they were fitted at" in w for w in calibrated["warnings"]), calibrated["warnings"]
# the report says the calibration's share of the interval (and the footprint's, where fitted)
for run, words in (("calibrated", "the calibration's share (W "), ("calibrated_footprint", " and the footprint ")):
    assert words in open(os.path.join(out, run, "report.html")).read(), (run, words)
L, Lt = calibrated["predicted_tonnes_to_end_of_life"], truth["predicted_tonnes_to_end_of_life"]
assert abs(L / (Lt * 3e-14 / w) - 1) < 1e-3, (L, Lt, w)
iv = calibrated["interval"]
s_cal = math.hypot(cal["scale_standard_error_fit"], cal["scale_standard_error_replicates"]) / cal["scale"]
assert s_cal > 0 and abs(iv["components"]["calibration"] / s_cal - 1) < 1e-9, (iv, s_cal)
beds = math.hypot(iv["components"]["beds"], iv["components"]["extrapolation"])
assert abs(iv["relative_sd"] / math.hypot(beds, s_cal) - 1) < 1e-9, iv
# Welch-Satterthwaite: the beds' part has sum(n - 1) = 2 degrees of freedom (three beds, one update)
own = life("candidate")["interval"]
dof_ws = (beds ** 2 + s_cal ** 2) ** 2 / (beds ** 4 / own["degrees_of_freedom"] + s_cal ** 4 / cal["degrees_of_freedom"])
assert own["degrees_of_freedom"] == 2 and abs(iv["degrees_of_freedom"] / dof_ws - 1) < 1e-9, (iv, dof_ws)
def t975(nu):  # the Student quantile, by Simpson's rule on the density and bisection
    c = math.exp(math.lgamma((nu + 1) / 2) - math.lgamma(nu / 2)) / math.sqrt(nu * math.pi)
    def cdf(x, n=4000):
        h = x / n
        f = lambda y: c * (1 + y * y / nu) ** (-(nu + 1) / 2)
        return 0.5 + h / 3 * (f(0) + f(x) + sum((4 if k % 2 else 2) * f(k * h) for k in range(1, n)))
    lo, hi = 1.0, 20.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if cdf(mid) < 0.975 else (lo, mid)
    return 0.5 * (lo + hi)
t = math.log(calibrated["predicted_tonnes_high"] / L) / iv["relative_sd"]
assert abs(t / t975(dof_ws) - 1) < 1e-5, (t, t975(dof_ws), dof_ws)
assert abs(t975(2) - 4.302653) < 1e-5  # (the quantile routine itself)
alone = life("one_bed")
assert "predicted_tonnes_low" not in alone and any("one bed per update" in x for x in alone["warnings"]), alone
assert abs(alone["interval"]["components"]["calibration"] / s_cal - 1) < 1e-9, alone["interval"]
assert life("truth")["interval"]["components"]["calibration"] == 0
other = life("other_footprint")
assert any("was fitted with a footprint" in x for x in other["warnings"]), other["warnings"]
assert not any("was fitted with a footprint" in x for x in calibrated["warnings"]), calibrated["warnings"]
# W and the footprint together
fp = json.load(open(os.path.join(out, "calibration_footprint", "calibration.json")))["footprint"]
assert fp["identifiable"], fp
assert fp["smoothing_radius_low"] < 0.0275 < fp["smoothing_radius_high"], fp
both = life("calibrated_footprint")
assert abs(both["smoothing_radius"] / fp["smoothing_radius"] - 1) < 1e-9, (both["smoothing_radius"], fp)
assert both["wear_coefficient"] == fp["wear_coefficient"] and both["calibration"]["footprint_fitted"], both["calibration"]
assert both["calibration"]["footprint_relative_sd"] > 0
assert abs(both["interval"]["components"]["calibration"] - both["calibration"]["relative_sd"]) < 1e-12
assert both["predicted_tonnes_low"] < Lt < both["predicted_tonnes_high"], (both, Lt)
one = json.load(open(os.path.join(out, "calibration_one_depth", "calibration.json")))["footprint"]
assert not one["identifiable"] and "degenerate" in one["reason"] and one["smoothing_radius"] == 0.0275, one
print(f"ok: footprint fitted {1e3 * fp['smoothing_radius']:.4g} mm ({1e3 * fp['smoothing_radius_low']:.4g} ... "
      f"{1e3 * fp['smoothing_radius_high']:.4g}; truth 27.5), W {fp['wear_coefficient']:.4g} at it; the life with both "
      f"{both['predicted_tonnes_to_end_of_life']:.5g} t ({both['predicted_tonnes_low']:.4g} ... "
      f"{both['predicted_tonnes_high']:.4g}); one depth: not identifiable")
print(f"ok: calibrated W = {w:.5g} (truth 3e-14) +- {100 * s_cal:.3g} %; life {L:.5g} t against the truth's {Lt:.5g} "
      f"(interval {calibrated['predicted_tonnes_low']:.4g} ... {calibrated['predicted_tonnes_high']:.4g}; beds "
      f"{100 * beds:.3g} %, calibration {100 * s_cal:.3g} %); another footprint warned; bad calibrations refused")
PY
