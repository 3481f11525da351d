#!/usr/bin/env bash
# Runs a small sweep of the regression case over a grid (knife friction x coarse-graining
# factor, 2 seeds: 8 runs) and checks its products: one row per combination with finite means;
# the plots and surfaces exist; one bed per seed and particle size (the friction reuses them);
# the per-metre wear against the prescribed motion (the knife moves 1.5 m/s x 0.1 s = 0.15 m in
# penetration: wear / wear per metre must give that path, from the job's wall positions); the
# wear shares of the height bands and of the faces each sum to one; each combination's total wear
# against the first's, pair by pair on the same seeds (computed again from the runs' tables).
#   check_sweep.sh ABRADE PRM OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
rm -rf "$out"
"$abrade" sweep "$prm" --vary "Wall knife/Interaction/Friction=0,0.4" --vary "Particles/Coarse graining/Factor=1,1.25" \
  --seeds 1,2 --edge-height 0.005 --output "$out" --quiet
rows=$(tail -n +2 "$out/study.csv" | wc -l)
[[ $rows -eq 4 ]] || { echo "study.csv has $rows rows, expected 4"; exit 1; }
cut -d, -f1,2 "$out/study.csv" | tail -n +2 | tr '\n' ' ' | grep -q "^0,1 0,1.25 0.4,1 0.4,1.25 $" || { echo "unexpected values"; cat "$out/study.csv"; exit 1; }
if grep -qiE "nan|inf" "$out/study.csv"; then echo "non-finite values:"; cat "$out/study.csv"; exit 1; fi
for f in plots/wear_total.png plots/edge_share.png plots/contacts_travel.png plots/wear_by_height.png plots/force.png \
         plots/layer_velocity.png surfaces/knife_0_1_seed1.vtp surfaces/knife_0.4_1.25_seed2.vtp study.md; do
  [[ -s "$out/$f" ]] || { echo "missing $f"; exit 1; }
done
[[ $(ls "$out/beds" | wc -l) -eq 4 ]] || { echo "expected one bed per seed and factor"; ls "$out/beds"; exit 1; }
python3 - "$out" <<'PY'
import csv, glob, os, sys
out = sys.argv[1]
import json
edge_shares = {}
for d in [d for d in glob.glob(os.path.join(out, "runs", "*")) if os.path.isdir(d)]:
    # the path from the summed wall positions against the prescribed speed x the steps taken
    res = json.load(open(os.path.join(d, "summary.json")))["results"]
    prescribed = 1.5 * res["phases"]["penetration"]["steps"] * res["time_step"]
    w = {r["phase"]: r for r in csv.DictReader(open(os.path.join(d, "walls", "knife_wear.csv")))}
    path = float(w["penetration"]["path_length"])
    assert abs(path - prescribed) < 1e-9, f"{d}: penetration path {path} m, the motion prescribes {prescribed} m"
    assert abs(prescribed - 0.15) < 1.5 * res["time_step"] * 1.5, prescribed
    rows = list(csv.DictReader(open(os.path.join(d, "walls", "knife_wear_profile.csv"))))
    total = [float(w["archard_volume"]) for w in csv.DictReader(open(os.path.join(d, "walls", "knife_wear.csv"))) if w["phase"] == "total"][0]
    for kind in ("height", "face"):
        s = sum(float(w["archard_volume"]) for w in rows if w["kind"] == kind)
        assert abs(s - total) <= 1e-9 * total, f"{d}: the {kind} rows sum to {s}, the wear table says {total}"
    # each phase's column: its height and face rows sum to that phase's wear in the wear table,
    # and a row's phase columns to the row's total
    phase_wear = {w["phase"]: float(w["archard_volume"]) for w in csv.DictReader(open(os.path.join(d, "walls", "knife_wear.csv")))}
    phase_columns = [c for c in rows[0] if c.startswith("archard_volume_")]
    assert sorted(c[len("archard_volume_"):] for c in phase_columns) == sorted(p for p in phase_wear if p != "total"), phase_columns
    for c in phase_columns:
        want = phase_wear[c[len("archard_volume_"):]]
        for kind in ("height", "face"):
            s = sum(float(w[c]) for w in rows if w["kind"] == kind)
            assert abs(s - want) <= 1e-9 * total, f"{d}: the {kind} rows of {c} sum to {s}, the wear table says {want}"
    for w in rows:
        if w["kind"] in ("height", "face"):
            s = sum(float(w[c]) for c in phase_columns)
            assert abs(s - float(w["archard_volume"])) <= 1e-9 * total, (d, w)
    # a phase's filtered peak: the filter is linear with weights >= 0 but for one factor per
    # field that conserves its volume (within about 1e-4 of the run's here), so no phase's peak
    # is above the run's and the phases' peaks add up to at least the run's, to 1 %; the phases'
    # peaks are their own (where both phases wear, one at least is below the run's)
    for w in rows:
        if w["kind"] == "filtered_peak":
            run_peak, phase_peaks = float(w["archard_volume"]), [float(w[c]) for c in phase_columns]
            assert all(0 < p <= run_peak * 1.01 for p in phase_peaks), (d, w)
            assert sum(phase_peaks) >= run_peak * 0.99, (d, w)
            assert min(phase_peaks) < run_peak * (1 - 1e-6), (d, w)
    # each phase's share within --edge-height (0.005 m: half the lowest 10 mm band) of the edge
    edge = {}
    for c in phase_columns:
        bands = [w for w in rows if w["kind"] == "height"]
        below = sum(float(w[c]) * min(max((0.005 - float(w["lower"])) / (float(w["upper"]) - float(w["lower"])), 0), 1) for w in bands)
        edge[c[len("archard_volume_"):]] = below / sum(float(w[c]) for w in bands)
    edge_shares[os.path.basename(d)] = edge
    peaks = [float(w["archard_volume"]) for w in rows if w["kind"] == "filtered_peak"]
    assert len(peaks) == 2 and all(p > 0 for p in peaks), f"{d}: filtered peaks {peaks}"
for r in csv.DictReader(open(os.path.join(out, "study.csv"))):
    assert abs(float(r["wear_penetration_mean"]) / float(r["wear_per_m_penetration_mean"]) - 0.15) < 1e-3
    # the phases' edge shares: the means over the seeds of each run's, from its profile
    name = r["Wall knife/Interaction/Friction"] + "_" + r["Particles/Coarse graining/Factor"]
    for phase in ("penetration", "travel"):
        want = sum(edge_shares[f"{name}-seed{s}"][phase] for s in (1, 2)) / 2
        assert abs(float(r[f"edge_share_{phase}_mean"]) - want) < 1e-8, (name, phase, r[f"edge_share_{phase}_mean"], want)
        assert 0.05 < want < 0.95, (name, phase, want) # the height cuts the wear (a check that can fail)
# each combination's total wear against the first's, pair by pair on the same seeds: the
# geometric mean of the per-seed ratios and its t-interval (1 degree of freedom), again here
# from the runs' own wear tables
import math
def total(d):
    return next(float(w["archard_volume"]) for w in csv.DictReader(open(os.path.join(out, "runs", d, "walls", "knife_wear.csv")))
                if w["phase"] == "total")
study = list(csv.DictReader(open(os.path.join(out, "study.csv"))))
first = study[0]
assert float(first["wear_total_ratio"]) == 1 and first["wear_total_ratio_significant"] == "0", first
for r in study[1:]:
    name = r["Wall knife/Interaction/Friction"] + "_" + r["Particles/Coarse graining/Factor"]
    logs = [math.log(total(f"{name}-seed{s}") / total(f"0_1-seed{s}")) for s in (1, 2)]
    m, h = sum(logs) / 2, 12.70620474 * abs(logs[0] - logs[1]) / 2
    for key, want in (("wear_total_ratio", math.exp(m)), ("wear_total_ratio_low", math.exp(m - h)),
                      ("wear_total_ratio_high", math.exp(m + h))):
        assert abs(float(r[key]) / want - 1) < 1e-6, (name, key, r[key], want)
print("ok: per-metre wear over the prescribed path, profile rows sum to the total")
PY
echo "ok: sweep wrote study.csv (2 x 2 combinations), plots, surfaces and 4 beds"
