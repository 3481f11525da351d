#!/usr/bin/env bash
# The stored wear and its replay (Lifetime/Wear source = replay; lifetime/stored_wear.h): a
# lifetime run keeps every update's unfiltered wear with the surface it fell on, and a run of
# the same case replays it without the DEM. Checked against DEM runs of the small case (three
# beds, three updates), not against the replay's own arithmetic:
#  - the replay at the stored footprint is the stored run again, byte for byte (trajectory,
#    beds and their rates, life and interval);
#  - at another footprint (15 mm against the default 27.5 mm) its first update is the DEM
#    run's at that footprint (the same beds on the same unworn knife: every column of the
#    trajectory within 1e-9); every later update replays the stored update whose worn volume
#    before it is the largest not above the replay's (checked from the two trajectories and
#    the beds in life_beds.csv);
#  - the DEM from update 2's tonnes on (Replay/DEM from) after the replay's first update at 15 mm
#    is the DEM run at 15 mm again, byte for byte (trajectory and beds), where the replay alone
#    differs from it; a DEM that draws beds the replay used (the replay in larger steps than the
#    stored run) says so once, not as a fault of the DEM's cycles;
#  - with another W in the case (4e-14 against the stored 2e-14) its first update is the DEM
#    run's at that W (the wear scaled by their ratio);
#  - past the stored run's worn volume, and where a stored update's beds serve twice, a
#    warning says so;
#  - calibrate warns when the footprint is fitted on replays without a DEM candidate near it,
#    and names a replay among the best and its neighbours that it could not leave out;
#  - several runs joined (Replay/Run = a, b, c): one-update runs of one bed each, the stored
#    run's three beds made apart, replayed together store the stored run's pilot and first
#    update byte for byte (the DEM's own three-bed run: an independent path), and their first
#    update is the stored run's trajectory row (also with the runs in another order than the
#    seeds); runs of three updates, which part after the first, are joined to it (said), and
#    the replay goes beyond them at their mean worn volume after it; a bed two joined runs share
#    is refused; a stored run of fixed cycles (no pilot) replayed is said to serve twice from the
#    replay's second update on, not its first (the pilot is not an update), and a replay of that
#    replay in smaller steps, whose first two updates take its stored update 1, is said so;
#  - a replay of a replay at its footprint is that replay again (carried volumes that round
#    below zero were refused as corrupt before); a user's own files in the output's wear/ stay;
#  - a missing directory, one without stored wear, another knife's (another height, another
#    bevel: the same extent within the mesh size), other particles (coarse graining), a
#    corrupt stored file and a replay into its own stored run are refused with exit 2, naming
#    them.
#   check_replay.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
updates=3
source "$(dirname "$0")/small_case_runs.sh"
replay() { local dir=$1; shift; run "$dir" --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/stored" "$@"; }
run stored
replay same
for s in 1 2 3; do run "bed$s" --set "Lifetime/Seeds=$s" --set "Lifetime/Maximum updates=1"; done
run joined --set "Lifetime/Maximum updates=1" --set "Lifetime/Wear source=replay" \
  --set "Lifetime/Replay/Run=$out/bed1, $out/bed2,$out/bed3"
for f in wear/update_00000.wear wear/update_00001.wear; do
  cmp "$out/stored/$f" "$out/joined/$f" || { echo "one-bed runs joined: their $f is not the three-bed run's"; exit 1; }
done
cmp <(head -2 "$out/stored/trajectory.csv") "$out/joined/trajectory.csv" || { echo "one-bed runs joined: update 1 differs"; exit 1; }
grep -q '"replayed_runs"' "$out/joined/summary.json" || { echo "summary.json does not list the joined runs"; exit 1; }
# a stored run of fixed cycles has no pilot: its first update serves the replay's pilot and first
# update, and is said to be used twice only when a second update takes it again
run fixed --set "Lifetime/Cycles per update=100000" --set "Lifetime/Maximum updates=1"
run fixed_replayed --set "Lifetime/Maximum updates=2" --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/fixed"
python3 - "$out/fixed_replayed/summary.json" <<'PY'
import json, sys
w = [x for x in json.load(open(sys.argv[1]))["results"]["lifetime"]["warnings"] if "more than one update" in x]
assert len(w) == 1 and w[0].startswith("update 2,"), w
PY
# a replay of that replay (whose stored pilot holds the beds it borrowed, the seeds' own) in
# smaller steps takes its stored update 1 in its updates 1 and 2: said (its first update, on the
# seeds' own beds, is a use, not a pilot)
run fixed_replayed_again --set "Lifetime/Maximum updates=2" --set "Lifetime/Depth increment fraction=0.02" \
  --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/fixed_replayed"
python3 - "$out/fixed_replayed_again/summary.json" <<'PY'
import json, sys
w = [x for x in json.load(open(sys.argv[1]))["results"]["lifetime"]["warnings"] if "more than one update" in x]
assert len(w) == 1 and w[0].startswith("update 2,") and "stored update 1's" in w[0], w
PY
# in another order than the seeds: the same run (its pilot found, the first update as long)
run joined_213 --set "Lifetime/Maximum updates=1" --set "Lifetime/Wear source=replay" \
  --set "Lifetime/Replay/Run=$out/bed2,$out/bed1,$out/bed3"
# runs of several updates part after the first (each knife worn its own way): joined to there,
# said, and the stored runs' worn volume after it is where the replay goes beyond them
run other --set "Lifetime/Seeds=4"
run joined_parted --set "Lifetime/Seeds=1,2,3,4" --set "Lifetime/Wear source=replay" \
  --set "Lifetime/Replay/Run=$out/stored,$out/other"
python3 - "$out" <<'PY'
import csv, json, os, sys
out = sys.argv[1]
def rows(run):
    return list(csv.DictReader(open(os.path.join(out, run, "trajectory.csv"))))
a, b = rows("stored")[0], rows("joined_213")[0]
for k in ("tonnes", "worn_volume"):
    assert abs(float(a[k]) - float(b[k])) <= 1e-9 * abs(float(a[k])), ("beds in another order", k, a[k], b[k])
w = json.load(open(os.path.join(out, "joined_parted", "summary.json")))["results"]["lifetime"]["warnings"]
assert any("joined runs end at update 1" in x for x in w), w
beyond = [x for x in w if "than the stored run" in x]
first = rows("stored")[0], rows("other")[0]
worn = sum(float(r["worn_volume"]) for r in first) / 2 * 1e6
assert beyond and ("did (%.4g cm^3)" % worn) in beyond[0], (beyond, worn)
print("replay: joined runs in another order the same first update; runs parted after update 1 joined to it, beyond at %.4g cm^3" % worn)
PY
run dem_r15 --set "Lifetime/Smoothing radius=0.015"
replay replay_r15 --set "Lifetime/Smoothing radius=0.015"
# the DEM from the tonnes of update 2 on (Replay/DEM from): the replay's first update at 15 mm is
# the DEM run's there bit for bit, so from it the DEM's own cycles on the same beds are that run
# again, byte for byte; a replay that kept replaying, or went over to the DEM an update late, is
# the replay's trajectory from update 2 on and differs
t1=$(python3 -c "import csv,sys; print(repr(float(list(csv.DictReader(open(sys.argv[1])))[0]['tonnes']) * (1 - 1e-9)))" \
  "$out/dem_r15/trajectory.csv")
replay dem_from_r15 --set "Lifetime/Smoothing radius=0.015" --set "Lifetime/Replay/DEM from=$t1"
for f in trajectory.csv life_beds.csv; do
  cmp "$out/dem_r15/$f" "$out/dem_from_r15/$f" || { echo "the DEM from update 2 after a replay is not the DEM run: $f"; exit 1; }
done
! cmp -s "$out/replay_r15/trajectory.csv" "$out/dem_from_r15/trajectory.csv" || { echo "the replay at 15 mm is the DEM run: the check cannot tell"; exit 1; }
grep -q '"dem_from_tonnes"' "$out/dem_from_r15/summary.json" || { echo "summary.json does not say where the DEM took over"; exit 1; }
# a replay in larger steps (Depth increment fraction 0.3) has used the stored update 3's beds by
# its update 2; the DEM from its update 3 draws the same beds (update 3's of the same seeds):
# said, as the interval counts them twice
replay big_steps --set "Lifetime/Depth increment fraction=0.3" --set "Lifetime/Maximum updates=2"
t2=$(python3 -c "import csv,sys; print(repr(float(list(csv.DictReader(open(sys.argv[1])))[1]['tonnes']) * (1 - 1e-9)))" \
  "$out/big_steps/trajectory.csv")
replay big_steps_dem --set "Lifetime/Depth increment fraction=0.3" --set "Lifetime/Replay/DEM from=$t2"
python3 - "$out/big_steps_dem/summary.json" <<'PY'
import json, sys
w = json.load(open(sys.argv[1]))["results"]["lifetime"]
assert sum("were replayed before" in x for x in w["warnings"]) == 1 and w["dem_warnings"] == 0, (w["warnings"], w["dem_warnings"])
PY
run dem_w4 --set "Wall knife/Wear/Archard/Coefficient=4e-14"
replay replay_w4 --set "Wall knife/Wear/Archard/Coefficient=4e-14"
replay beyond --set "Lifetime/Maximum updates=5"
# a replay of a replay (its carried wear stored again) at its footprint: the same run again
run replay_of_replay --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/replay_r15" \
  --set "Lifetime/Smoothing radius=0.015"
cmp -s "$out/replay_r15/trajectory.csv" "$out/replay_of_replay/trajectory.csv" || { echo "a replay of a replay differs"; exit 1; }
# a user's own files in the output directory's wear/ stay
mkdir -p "$out/keep/wear" && echo "mine" > "$out/keep/wear/notes.txt"
"$abrade" run "$case_file" --quiet --output "$out/keep" --set "Lifetime/Seeds=1,2,3" --set "Lifetime/Maximum updates=1" \
  --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/stored" > /dev/null
[ -f "$out/keep/wear/notes.txt" ] && [ -f "$out/keep/wear/update_00001.wear" ] || { echo "wear/ of the output directory not kept"; exit 1; }

for f in trajectory.csv life_beds.csv; do
  cmp -s "$out/stored/$f" "$out/same/$f" || { echo "the replay at the stored footprint differs in $f"; exit 1; }
done
python3 - "$out" <<'PY'
import csv, json, os, sys
out = sys.argv[1]
def rows(run):
    return list(csv.DictReader(open(os.path.join(out, run, "trajectory.csv"))))
def life(run):
    return json.load(open(os.path.join(out, run, "summary.json")))["results"]["lifetime"]
def beds(run):
    seen = {}
    for r in csv.DictReader(open(os.path.join(out, run, "life_beds.csv"))):
        seen.setdefault(int(r["update"]), []).append(int(r["bed_seed"]))
    return seen
a, b = life("stored"), life("same")
for key in ("predicted_tonnes_to_end_of_life", "predicted_tonnes_low", "predicted_tonnes_high"):
    assert a[key] == b[key], (key, a[key], b[key])
assert b["wear_source"] == "replay" and a["wear_source"] == "dem", (a["wear_source"], b["wear_source"])
for dem, rep in (("dem_r15", "replay_r15"), ("dem_w4", "replay_w4")):
    d, r = rows(dem)[0], rows(rep)[0]
    for k in d:
        x, y = float(d[k]), float(r[k])
        assert abs(x - y) <= 1e-9 * max(abs(x), abs(y), 1e-30), (dem, k, x, y)
# every later update replays the stored update that began with the most volume worn off, but
# not more than the replay's knife had lost (the nearest state; the worn volume before an
# update read from the trajectories, 0 before the first)
def worn_before(run):
    v = [0.0] + [float(r["worn_volume"]) for r in rows(run)]
    return {k + 1: v[k] for k in range(len(v) - 1)}
stored_beds, stored_worn = beds("stored"), worn_before("stored")
replay_beds = beds("replay_r15")
assert replay_beds[1] == beds("dem_r15")[1] == stored_beds[1], (replay_beds, stored_beds)
for k, w in worn_before("replay_r15").items():
    if k == 1:
        continue
    near = max((j for j in stored_worn if stored_worn[j] <= w * (1 + 1e-9)), key=lambda j: stored_worn[j])
    assert replay_beds[k] == stored_beds[near], (k, w, near, replay_beds[k], stored_beds)
d, r = life("dem_r15"), life("replay_r15")
assert r["smoothing_radius"] == d["smoothing_radius"] == 0.015, (r["smoothing_radius"], d["smoothing_radius"])
L = r["predicted_tonnes_to_end_of_life"] # (three updates of the small case: extrapolated, not compared; the
                                         # replay's accuracy is measured on the knife-bed, docs/field.md)
w = life("beyond")["warnings"]
assert any("than the stored run" in x for x in w) and any("more than one update" in x for x in w), w
print("replay: same footprint byte for byte; at 15 mm update 1 = the DEM's, life %.4g t (DEM %.4g t, %.4g ... %.4g; "
      "extrapolated from three updates); "
      "at W 4e-14 update 1 = the DEM's" % (L, d["predicted_tonnes_to_end_of_life"], d["predicted_tonnes_low"],
                                           d["predicted_tonnes_high"]))
PY

# a footprint fitted on replays is warned about (their own error is in its interval only as far
# as leaving each out shows it), and not as resting on replays where none lies within 1.25^2 of
# the fit: the scan is the DEM run's at 15 mm; the candidates at 10, 15, 27.5 and 55 mm all
# replays of the 27.5 mm run, then the DEM runs at 15 and 27.5 mm with replays at 8 and 55 mm
# (the fit then holds 15 mm; the replay at 8 mm is the best's neighbour and cannot be left out,
# the rest holding no minimum without it: said so, by its footprint)
replay replay_r10 --set "Lifetime/Smoothing radius=0.01"
replay replay_r8 --set "Lifetime/Smoothing radius=0.008"
replay replay_r55 --set "Lifetime/Smoothing radius=0.055"
t=$(python3 -c "import csv,sys; print(list(csv.DictReader(open(sys.argv[1])))[-1]['tonnes'])" "$out/dem_r15/trajectory.csv")
"$abrade" compare --predicted "$out/dem_r15/part/part_0000$updates.stl" --scan "$out/dem_r15/part/part_0000$updates.stl" \
  --reference "$out/dem_r15/part/part_00000.stl" --tonnes "$t" --no-registration --output "$out/scan" > /dev/null 2>&1
for set in replays:replay_r15:same:replay_r10 dem:dem_r15:stored:replay_r8; do
  IFS=: read -r name r15 r27 small <<< "$set"
  "$abrade" calibrate --run "$out/$r27" --run "$out/$small" --run "$out/$r15" --run "$out/replay_r55" \
    --measurements "$out/scan/measured_depths.csv" --output "$out/fit_$name" > "$out/fit_$name.log" 2>&1
done
python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
fit = {k: json.load(open(os.path.join(out, "fit_" + k, "calibration.json")))["footprint"] for k in ("replays", "dem")}
assert fit["replays"]["identifiable"] and fit["dem"]["identifiable"], fit
assert any("rests on replayed candidates" in w for w in fit["replays"].get("warnings", [])), fit["replays"]
assert fit["dem"]["replays_not_assessed"] == [0.008], fit["dem"]
assert all("among the best and its neighbours (8 mm)" in w for w in fit["dem"].get("warnings", [])), fit["dem"]
assert fit["dem"]["smoothing_radius_low"] < 0.015 < fit["dem"]["smoothing_radius_high"], fit["dem"]
print("replay: a footprint fitted on replays alone (%.3g mm; the truth 15 mm) warned about; with the DEM runs at 15 "
      "and 27.5 mm and replays beyond 1.25^2 (%.3g mm, %.3g ... %.3g) not" % (1e3 * fit["replays"]["smoothing_radius"], 1e3 * fit["dem"]["smoothing_radius"],
                                      1e3 * fit["dem"]["smoothing_radius_low"], 1e3 * fit["dem"]["smoothing_radius_high"]))
PY

refused "no directory given" "Replay/Run" --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run="
refused "missing directory" "$out/none" --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/none"
mkdir -p "$out/empty"
refused "a bed twice" "is in another of the runs too" --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/bed1,$out/stored"
refused "no stored wear" "holds no stored wear" --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/empty"
refused "another part" "another part" --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/stored" --set "Part/Height=0.3"
refused "another bevel" "another part" --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/stored" --set "Part/Bevel height=0.08"
refused "other particles" "Coarse graining/Factor" --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/stored" \
  --set "Particles/Coarse graining/Factor=1.5"
set +e
"$abrade" run "$case_file" --quiet --output "$out/stored" --set "Lifetime/Maximum updates=1" --set "Lifetime/Wear source=replay" \
  --set "Lifetime/Replay/Run=$out/stored" > "$out/refused.log" 2>&1
rc=$?
set -e
[ "$rc" = 2 ] && grep -q "own output directory" "$out/refused.log" || { echo "a replay into its own stored run: exit $rc"; cat "$out/refused.log"; exit 1; }
cp -r "$out/stored" "$out/corrupt"
sed -i '0,/^tonnes_start/s/^tonnes_start = .*/tonnes_start = 1/' "$out/corrupt/wear/update_00001.wear"
refused "corrupt stored wear" "update_00001.wear" --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$out/corrupt"
echo "replay: refusals exit 2"
