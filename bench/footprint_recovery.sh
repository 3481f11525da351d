#!/usr/bin/env bash
# Can W and the wear footprint be recovered from a scan of a worn knife, with one DEM run of
# candidates (issue 34)? Truth from the code itself, through the independent scan path:
#  1. truth: the knife-bed reference knife (cases/knife_bed/lifetime.prm, three beds) with
#     W = 3e-14 and Lifetime/Smoothing radius = 13.75 mm, to its end of life (DEM);
#  2. the candidate: the same case at the default footprint (27.5 mm) and W = 2e-14, to its end
#     of life (DEM): its stored wear (wear/update_*.wear) is replayed without the DEM at the
#     footprints 8.15, 12.2, 18.3, 41.25 and 61.9 mm (Lifetime/Wear source = replay: seconds each);
#  3. scans: the truth's worn surface after updates 8 and 12 (1.51 and 2.35 Mt), sampled as a
#     scanner would (8000 points, 0.3 mm noise, turned 3 degrees, shifted 3, -2 and 5 cm;
#     scripts/make-synthetic-field-data.py), registered on the unworn top (z > 0.3 m) by
#     `abrade compare`; a third table with the deepest scan point only;
#  4. `abrade calibrate` of the six candidates on each scan, on both scans together and on the
#     single point: W and the footprint with their intervals, or "not identifiable";
#  5. a second round: DEM candidates at the first round's fit (both scans; --round2 R,W sets it)
#     and 1.25x either side, replays of the middle one at 1.25^2 either side, calibrated again;
#     the lifetime (DEM) with the second round's calibration of both scans, against the truth's;
#  6. the replay's own error: the candidate replayed at the truth's footprint and W against the
#     truth's DEM run.
# Writes DIR/recovery.md. Runs whose summary.json is there already are not run again (the second
# round's are named by their footprints, the life by its calibration's numbers).
#
#   bench/footprint_recovery.sh [--output DIR] [--jobs 2] [--round2 R,W]
#
# Takes about 45 minutes on 2 cores (six DEM lifetimes, one thread each, two at a time).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=${ABRADE:-$root/build/abrade}
out=footprint-recovery jobs=2 round2=
while (($#)); do
  case $1 in
    --output) out=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --round2) round2=$2; shift 2 ;;
    *) echo "usage: $0 [--output DIR] [--jobs N] [--round2 R,W]" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"
out=$(cd "$out" && pwd)
case_file="$root/cases/knife_bed/lifetime.prm"
life() { # dir, sets...: a lifetime run of the knife-bed case, unless done
  local dir=$1; shift
  [ -f "$out/$dir/summary.json" ] && return 0
  "$abrade" run "$case_file" --quiet --output "$out/$dir" --set "Lifetime/Seeds=1,2,3" --set "Simulation/Threads=1" \
    "$@" > "$out/$dir.log" 2>&1 || { echo "$dir failed: $out/$dir.log" >&2; return 1; }
}
parallel() { # commands, $jobs at a time
  local pids=()
  for c in "$@"; do
    eval "$c" & pids+=($!)
    if ((${#pids[@]} >= jobs)); then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
  done
  for p in "${pids[@]}"; do wait "$p"; done
}

# 1-2. the truth and the candidate (DEM)
parallel 'life truth --set "Wall knife/Wear/Archard/Coefficient=3e-14" --set "Lifetime/Smoothing radius=0.01375"' \
         'life candidate --set "Wall knife/Wear/Archard/Coefficient=2e-14" --set "Lifetime/Smoothing radius=0.0275"'
footprints="0.00815 0.0122 0.0183 0.04125 0.0619"
runs=(--run "$out/candidate")
for r in $footprints; do
  life "replay_$r" --set "Lifetime/Smoothing radius=$r" --set "Lifetime/Wear source=replay" \
    --set "Lifetime/Replay/Run=$out/candidate"
  runs+=(--run "$out/replay_$r")
done
# 6. the replay's own error: at the truth's footprint and W
life replay_truth --set "Wall knife/Wear/Archard/Coefficient=3e-14" --set "Lifetime/Smoothing radius=0.01375" \
  --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/candidate"

# 3. the scans
for u in 8 12; do
  python3 "$root/scripts/make-synthetic-field-data.py" "$out/truth" $u "$out/scan$u" --noise 0.0003 --angle 3 \
    --shift 0.03,-0.02,0.05 --seed $u > /dev/null
  t=$(python3 -c "import csv,sys; print(list(csv.DictReader(open(sys.argv[1])))[$u - 1]['tonnes'])" "$out/truth/trajectory.csv")
  "$abrade" compare --predicted "$out/candidate/part/part_00003.stl" --scan "$out/scan$u/scan_mm.ply" \
    --reference "$out/candidate/part/part_00000.stl" --register-on -1,-1,0.3,1,1,1 --tonnes "$t" \
    --output "$out/compare$u" > "$out/compare$u.log" 2>&1
done
(cat "$out/compare8/measured_depths.csv"; tail -n +2 "$out/compare12/measured_depths.csv") > "$out/both_scans.csv"
python3 - "$out/compare8/measured_depths.csv" "$out/one_point.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
w = csv.DictWriter(open(sys.argv[2], "w", newline=""), fieldnames=list(rows[0]))
w.writeheader(), w.writerow(max(rows, key=lambda r: float(r["depth"])))
PY

# 4. calibrate on each scan, both, and the single point
for m in scan8:compare8/measured_depths.csv scan12:compare12/measured_depths.csv both:both_scans.csv one_point:one_point.csv; do
  name=${m%%:*} file=${m#*:}
  "$abrade" calibrate "${runs[@]}" --measurements "$out/$file" --output "$out/calibration_$name" > "$out/calibration_$name.log" 2>&1
done

# 5. a second round: the replays are off by their own error (the geometry feedback they leave
#    out, growing with the distance from their DEM run), so DEM candidates at the first round's
#    fit (both scans; or --round2 R,W) and 1.25x either side, replays of the middle one at
#    1.25^2 either side, and the calibration again; then the lifetime with it (DEM)
if [ -z "$round2" ]; then
  python3 -c "import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))['footprint']['identifiable'] else 1)" \
    "$out/calibration_both/calibration.json" || { echo "round 1 (both scans) not identifiable" >&2; exit 1; }
  round2=$(python3 -c "import json,sys; f = json.load(open(sys.argv[1]))['footprint']; \
print('%.3g,%.3g' % (f['smoothing_radius'], f['wear_coefficient']))" "$out/calibration_both/calibration.json")
fi
r1=${round2%%,*} w1=${round2#*,}
radius() { python3 -c "print('%.4g' % ($r1 * 1.25 ** $1))"; }
parallel "life dem2_$(radius 0) --set \"Wall knife/Wear/Archard/Coefficient=$w1\" --set \"Lifetime/Smoothing radius=$(radius 0)\"" \
         "life dem2_$(radius -1) --set \"Wall knife/Wear/Archard/Coefficient=$w1\" --set \"Lifetime/Smoothing radius=$(radius -1)\"" \
         "life dem2_$(radius 1) --set \"Wall knife/Wear/Archard/Coefficient=$w1\" --set \"Lifetime/Smoothing radius=$(radius 1)\""
runs2=(--run "$out/dem2_$(radius 0)" --run "$out/dem2_$(radius -1)" --run "$out/dem2_$(radius 1)")
for k in -2 2; do
  life "replay2_$(radius $k)" --set "Lifetime/Smoothing radius=$(radius $k)" --set "Lifetime/Wear source=replay" \
    --set "Lifetime/Replay/Run=$out/dem2_$(radius 0)"
  runs2+=(--run "$out/replay2_$(radius $k)")
done
for m in scan8:compare8/measured_depths.csv scan12:compare12/measured_depths.csv both:both_scans.csv; do
  name=${m%%:*} file=${m#*:}
  "$abrade" calibrate "${runs2[@]}" --measurements "$out/$file" --output "$out/calibration2_$name" \
    > "$out/calibration2_$name.log" 2>&1
done
python3 -c "import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))['footprint']['identifiable'] else 1)" \
  "$out/calibration2_both/calibration.json" || { echo "round 2 (both scans) not identifiable" >&2; exit 1; }
# (the life's directory named by the calibration's numbers: another calibration, another run)
tag=$(python3 -c "import json,sys; f = json.load(open(sys.argv[1]))['footprint']; \
print('%.5g_%.5g' % (f['smoothing_radius'], f['wear_coefficient']))" "$out/calibration2_both/calibration.json")
life "life2_both_$tag" --set "Lifetime/Calibration=$out/calibration2_both/calibration.json"
ln -sfn "life2_both_$tag" "$out/life2_both"

python3 - "$out" <<'PY'
import csv, json, math, os, sys
out = sys.argv[1]
def life(d):
    return json.load(open(os.path.join(out, d, "summary.json")))["results"]["lifetime"]
def mt(x):
    return "%.2f" % (x / 1e6)
def joint(f):
    jr = f["joint_region"]
    a = math.log(0.01375 / f["smoothing_radius"])
    e = math.log(3e-14 / f["wear_coefficient"]) - f["dlnw_dlnr"] * a
    q = (a / jr["scale_log_r_below" if a < 0 else "scale_log_r_above"]) ** 2 + (e / jr["scale_log_w"]) ** 2
    return "%s (%.1f / %.1f)" % ("yes" if q <= jr["level"] else "no", q, jr["level"])
truth = life("truth")
L = truth["predicted_tonnes_to_end_of_life"]
md = ["# W and the footprint recovered from a scan (bench/footprint_recovery.sh)", "",
      "Truth: W 3e-14, footprint 13.75 mm, life %s Mt (%s ... %s). Round 1: the candidate at W 2e-14, 27.5 mm (DEM), "
      "replayed at 8.15, 12.2, 18.3, 41.25, 61.9 mm. Round 2: DEM candidates at the first round's fit and 1.25x "
      "either side, replays at 1.25^2 either side." % (mt(L), mt(truth["predicted_tonnes_low"]), mt(truth["predicted_tonnes_high"])), "",
      "| measurements | round | footprint [mm] (95 %) | W at it [1e-14] (95 %, the footprint's uncertainty in it) | "
      "truth in the joint region (Q / level) | life with the calibration, DEM [Mt] (95 %) |",
      "|---|---|---|---|---|---|"]
for rnd, prefix in ((1, "calibration_"), (2, "calibration2_")):
    for name in ("scan8", "scan12", "both", "one_point"):
        path = os.path.join(out, prefix + name, "calibration.json")
        if not os.path.exists(path):
            continue
        c = json.load(open(path))
        f = c["footprint"]
        if not f["identifiable"]:
            md.append("| %s | %d | not identifiable | %.3g (at the assumed %.4g mm) | | |" % (
                name, rnd, 1e14 * f["wear_coefficient"], 1e3 * f["smoothing_radius"]))
            continue
        lived = ""
        if rnd == 2 and name == "both" and os.path.exists(os.path.join(out, "life2_both", "summary.json")):
            x = life("life2_both")
            lived = "%s (%s ... %s)" % (mt(x["predicted_tonnes_to_end_of_life"]), mt(x["predicted_tonnes_low"]),
                                        mt(x["predicted_tonnes_high"]))
        md.append("| %s | %d | %.1f (%.1f ... %.1f) | %.2f (%.2f ... %.2f) | %s | %s |" % (
            name, rnd, 1e3 * f["smoothing_radius"], 1e3 * f["smoothing_radius_low"], 1e3 * f["smoothing_radius_high"],
            1e14 * f["wear_coefficient"], 1e14 * f["wear_coefficient_low"], 1e14 * f["wear_coefficient_high"], joint(f),
            lived))
rt = life("replay_truth")
md += ["", "The replay's own error (the candidate's wear replayed at 13.75 mm and W 3e-14, against the truth's DEM run): "
       "life %s Mt (%s ... %s) against %s Mt." % (mt(rt["predicted_tonnes_to_end_of_life"]), mt(rt["predicted_tonnes_low"]),
                                                 mt(rt["predicted_tonnes_high"]), mt(L))]
open(os.path.join(out, "recovery.md"), "w").write("\n".join(md) + "\n")
print("\n".join(md))
PY
