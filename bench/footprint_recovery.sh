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
#  5. the lifetime with each identifiable calibration (DEM, Lifetime/Calibration), against the
#     truth's life; the same by replaying the candidate (no DEM);
#  6. the replay's own error: the candidate replayed at the truth's footprint and W against the
#     truth's DEM run.
# Writes DIR/recovery.md. Runs whose summary.json is there already are not run again.
#
#   bench/footprint_recovery.sh [--output DIR] [--jobs 2]
#
# Takes about 25 minutes on 2 cores (four DEM lifetimes, one thread each, two at a time).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=${ABRADE:-$root/build/abrade}
out=footprint-recovery jobs=2
while (($#)); do
  case $1 in
    --output) out=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    *) echo "usage: $0 [--output DIR] [--jobs N]" >&2; exit 2 ;;
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
    --set "Lifetime/Replay run=$out/candidate"
  runs+=(--run "$out/replay_$r")
done
# 6. the replay's own error: at the truth's footprint and W
life replay_truth --set "Wall knife/Wear/Archard/Coefficient=3e-14" --set "Lifetime/Smoothing radius=0.01375" \
  --set "Lifetime/Wear source=replay" --set "Lifetime/Replay run=$out/candidate"

# 3. the scans
for u in 8 12; do
  python3 "$root/scripts/make-synthetic-field-data.py" "$out/truth" $u "$out/scan$u" --noise 0.0003 --angle 3 \
    --shift 0.03,-0.02,0.05 --seed $u > /dev/null
  t=$(python3 -c "import csv,sys; print(list(csv.DictReader(open(sys.argv[1])))[$u - 1]['tonnes'])" "$out/truth/trajectory.csv")
  "$abrade" compare --predicted "$out/candidate/knife/knife_00003.stl" --scan "$out/scan$u/scan_mm.ply" \
    --reference "$out/candidate/knife/knife_00000.stl" --register-on -1,-1,0.3,1,1,1 --tonnes "$t" \
    --output "$out/compare$u" > "$out/compare$u.log" 2>&1
done
(cat "$out/compare8/measured_depths.csv"; tail -n +2 "$out/compare12/measured_depths.csv") > "$out/both_scans.csv"
python3 - "$out/compare8/measured_depths.csv" "$out/one_point.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
w = csv.DictWriter(open(sys.argv[2], "w", newline=""), fieldnames=list(rows[0]))
w.writeheader(), w.writerow(max(rows, key=lambda r: float(r["depth"])))
PY

# 4-5. calibrate, and the lifetime with each calibration
for m in scan8:compare8/measured_depths.csv scan12:compare12/measured_depths.csv both:both_scans.csv one_point:one_point.csv; do
  name=${m%%:*} file=${m#*:}
  "$abrade" calibrate "${runs[@]}" --measurements "$out/$file" --output "$out/calibration_$name" > "$out/calibration_$name.log" 2>&1
done
calibrated=()
for name in scan8 scan12 both; do
  if python3 -c "import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))['footprint']['identifiable'] else 1)" \
       "$out/calibration_$name/calibration.json"; then
    calibrated+=("life life_$name --set \"Lifetime/Calibration=$out/calibration_$name/calibration.json\"")
    life "replayed_life_$name" --set "Lifetime/Calibration=$out/calibration_$name/calibration.json" \
      --set "Lifetime/Wear source=replay" --set "Lifetime/Replay run=$out/candidate"
  fi
done
parallel "${calibrated[@]}"

# 7. a second round: the replays are off by their own error (the geometry feedback: it grows
#    with the distance from the DEM candidate's footprint), so a DEM candidate at the first
#    round's fit (both scans), replayed around it at 1.25x steps, and the calibration again
if python3 -c "import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))['footprint']['identifiable'] else 1)" \
     "$out/calibration_both/calibration.json"; then
  read -r r1 w1 < <(python3 -c "import json,sys; f = json.load(open(sys.argv[1]))['footprint']; \
print('%.3g %.3g' % (f['smoothing_radius'], f['wear_coefficient']))" "$out/calibration_both/calibration.json")
  life candidate2 --set "Wall knife/Wear/Archard/Coefficient=$w1" --set "Lifetime/Smoothing radius=$r1"
  runs2=(--run "$out/candidate2")
  for k in -2 -1 1 2; do
    r=$(python3 -c "print('%.4g' % ($r1 * 1.25 ** $k))")
    life "replay2_$k" --set "Lifetime/Smoothing radius=$r" --set "Lifetime/Wear source=replay" \
      --set "Lifetime/Replay run=$out/candidate2"
    runs2+=(--run "$out/replay2_$k")
  done
  for m in scan8:compare8/measured_depths.csv scan12:compare12/measured_depths.csv both:both_scans.csv; do
    name=${m%%:*} file=${m#*:}
    "$abrade" calibrate "${runs2[@]}" --measurements "$out/$file" --output "$out/calibration2_$name" \
      > "$out/calibration2_$name.log" 2>&1
  done
  if python3 -c "import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))['footprint']['identifiable'] else 1)" \
       "$out/calibration2_both/calibration.json"; then
    life life2_both --set "Lifetime/Calibration=$out/calibration2_both/calibration.json"
  fi
fi

python3 - "$out" <<'PY'
import csv, json, math, os, sys
out = sys.argv[1]
def life(d):
    return json.load(open(os.path.join(out, d, "summary.json")))["results"]["lifetime"]
def mt(x):
    return "%.2f" % (x / 1e6)
truth = life("truth")
L = truth["predicted_tonnes_to_end_of_life"]
md = ["# W and the footprint recovered from a scan (bench/footprint_recovery.sh)", "",
      "Truth: W 3e-14, footprint 13.75 mm, life %s Mt (%s ... %s). Candidate: W 2e-14, 27.5 mm (DEM), "
      "replayed at 8.15, 12.2, 18.3, 41.25, 61.9 mm." % (mt(L), mt(truth["predicted_tonnes_low"]), mt(truth["predicted_tonnes_high"])), "",
      "| measurements | candidates | footprint [mm] (95 %) | W at it [1e-14] (95 %, the footprint's uncertainty in it) | "
      "truth in the joint region (Q / level) | life, DEM [Mt] (95 %) | life, replay [Mt] (95 %) |",
      "|---|---|---|---|---|---|---|"]
def joint(f):
    a = math.log(0.01375 / f["smoothing_radius"])
    e = math.log(3e-14 / f["wear_coefficient"]) - f["dlnw_dlnr"] * a
    q = a * a / f["log_smoothing_radius_standard_error"] ** 2 + e * e / f["log_wear_coefficient_standard_error"] ** 2
    return "%s (%.1f / %.1f)" % ("yes" if q <= f["joint_region"]["level"] else "no", q, f["joint_region"]["level"])
def lives_of(*dirs):
    out_ = []
    for d in dirs:
        if d and os.path.exists(os.path.join(out, d, "summary.json")):
            x = life(d)
            out_.append("%s (%s ... %s)" % (mt(x["predicted_tonnes_to_end_of_life"]), mt(x["predicted_tonnes_low"]),
                                            mt(x["predicted_tonnes_high"])))
        else:
            out_.append("")
    return out_
rows = [(n, "calibration_" + n, "27.5 mm (DEM) + 5 replays", ("life_" + n, "replayed_life_" + n))
        for n in ("scan8", "scan12", "both", "one_point")]
rows += [(n, "calibration2_" + n, "round 2: %s (DEM) + 4 replays", ("life2_" + n if n == "both" else "", ""))
         for n in ("scan8", "scan12", "both")]
for name, cal, what, lives in rows:
    path = os.path.join(out, cal, "calibration.json")
    if not os.path.exists(path):
        continue
    c = json.load(open(path))
    f = c["footprint"]
    if "%s" in what:
        what = what % ("%.1f mm" % (1e3 * [r for r in c["runs"] if r["run"].endswith("candidate2")][0]["smoothing_radius"]))
    if not f["identifiable"]:
        md.append("| %s | %s | not identifiable | %.3g (at the assumed 27.5 mm) | | | |" % (
            name, what, 1e14 * c["runs"][0]["archard_coefficient"]))
        continue
    dem, replay = lives_of(*lives)
    md.append("| %s | %s | %.1f (%.1f ... %.1f) | %.2f (%.2f ... %.2f) | %s | %s | %s |" % (
        name, what, 1e3 * f["smoothing_radius"], 1e3 * f["smoothing_radius_low"], 1e3 * f["smoothing_radius_high"],
        1e14 * f["wear_coefficient"], 1e14 * f["wear_coefficient_low"], 1e14 * f["wear_coefficient_high"], joint(f),
        dem, replay))
rt = life("replay_truth")
md += ["", "The replay's own error (the candidate's wear replayed at 13.75 mm and W 3e-14, against the truth's DEM run): "
       "life %s Mt (%s ... %s) against %s Mt." % (mt(rt["predicted_tonnes_to_end_of_life"]), mt(rt["predicted_tonnes_low"]),
                                                 mt(rt["predicted_tonnes_high"]), mt(L))]
open(os.path.join(out, "recovery.md"), "w").write("\n".join(md) + "\n")
print("\n".join(md))
PY
