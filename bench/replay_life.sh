#!/bin/bash
# The knife-bed's life at one pellet size without the geometry feedback, bed by bed
# (docs/coarse-graining.md, "The real-size life by replay"): each bed's wear on the design (one
# update of fixed cycles, Lifetime/Cycles per update, Maximum updates = 1: the DEM's only cycle)
# is replayed to the end of life (Lifetime/Wear source = replay: the part wears on, its wear
# carried onto the worn surface, no DEM). The life of the beds' mean rate is the harmonic mean of
# the single-bed lives (at 27.5 mm 7.05 Mt against 7.07 Mt from a replay of the three beds
# together); its 95 % interval is the t interval of the mean rate 1/life over the beds (the
# beds' scatter only: fresh beds, not one bed reused at every update).
#
#   bench/replay_life.sh [--real] [--beds DIR] [--seeds "1 2 3"] [--jobs N] [--smoothing R] [--replays-only]
#                        [--output DIR]
#
# --real: the real pellets (6.875 mm) in the fine region |y| < 0.36 m, as the coarse-graining
#   study's real-size beds (bench/multi_level.sh --factors 1 --half-width 0.36 --pours 3);
#   without it the thesis' 27.5 mm pellets (Particles/Coarse graining/Factor = 4), uniform.
# --beds DIR: saved beds DIR/bed-seedN.bed (e.g. a sweep's DIR/beds) copied into each run, so
#   that a real-size bed (about 50 minutes of pours on one core) is not poured again; without
#   it each run pours its own.
# --smoothing R: the replays' Lifetime/Smoothing radius [m] (default 0: the radius of the
#   particles at the part, 6.875 mm with --real, 27.5 mm without); the stored wear is unfiltered.
# --replays-only: the replays and the lives again from the one-update runs already in DIR
#   (e.g. at another --smoothing; their output goes to DIR/replay-seedN, replaced).
# A real-size bed's cycle takes about 33 minutes on one core; a 27.5 mm one seconds.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
abrade=${ABRADE:-$here/build/abrade}
case_file=$here/cases/knife_bed/lifetime_coarse_graining.prm
real=0 beds="" seeds="1 2 3" jobs=2 out=replay-life smoothing=0 replays_only=0
while [ $# -gt 0 ]; do
  case $1 in
    --real) real=1; shift ;;
    --beds) beds=$(cd "$2" && pwd); shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --smoothing) smoothing=$2; shift 2 ;;
    --replays-only) replays_only=1; shift ;;
    --output) out=$2; shift 2 ;;
    *) echo "usage: $0 [--real] [--beds DIR] [--seeds \"1 2 3\"] [--jobs N] [--smoothing R] [--replays-only] [--output DIR]" >&2
       exit 2 ;;
  esac
done
sets=(--set "Simulation/Threads=1")
if [ $real = 1 ]; then
  sets+=(--set "Particles/Coarse graining/Fine region min=-0.97, -0.36, 0.03"
         --set "Particles/Coarse graining/Fine region max=0.97, 0.36, 0.85" --set "Particles/Coarse graining/Fine region factor=1"
         --set "Particles/Coarse graining/Fine region step=1.25" --set "Particles/Coarse graining/Fine region layer thickness=1"
         --set "Particles/Coarse graining/Fine region pours=3" --set "Simulation/Skin=0.00275")
fi
mkdir -p "$out"; out=$(cd "$out" && pwd)

# 1. each bed's wear on the design: one update of fixed cycles (the cycles only size that
#    update's step; the replay takes the wear per cycle)
one_update() {
  local s=$1 dir=$out/bed-seed$1
  mkdir -p "$dir/beds"
  if [ -n "$beds" ]; then cp "$beds/bed-seed$s.bed" "$dir/beds/"; fi
  "$abrade" run "$case_file" "${sets[@]}" --set "Lifetime/Seeds=$s" --set "Lifetime/Cycles per update=200000" \
    --set "Lifetime/Maximum updates=1" --output "$dir" > "$dir.log" 2>&1
}
if [ $replays_only = 0 ]; then
  running=0
  for s in $seeds; do
    one_update "$s" &
    running=$((running + 1))
    if [ $running -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
  done
  wait
fi

# 2. each bed's wear replayed to the end of life
for s in $seeds; do
  rm -rf "$out/replay-seed$s"
  "$abrade" run "$case_file" "${sets[@]}" --set "Lifetime/Seeds=$s" --set "Lifetime/Smoothing radius=$smoothing" \
    --set "Lifetime/Wear source=replay" \
    --set "Lifetime/Replay/Run=$out/bed-seed$s" --set "Lifetime/Maximum updates=80" --output "$out/replay-seed$s" \
    > "$out/replay-seed$s.log" 2>&1
done

# 3. the lives, the life of the mean rate and its interval
python3 - "$out" $seeds <<'EOF'
import json, statistics, sys
from math import sqrt
out, seeds = sys.argv[1], sys.argv[2:]
# two-sided 95 % t quantiles by degrees of freedom (1 ... 30; beyond, the normal's 1.96 is within 4 %)
t95 = dict(enumerate([12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
                      2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
                      2.052, 2.048, 2.045, 2.042], start=1))
lives = []
print("| bed seed | life [Mt] | end of life |")
print("|---|---|---|")
for s in seeds:
    j = json.load(open(f"{out}/replay-seed{s}/summary.json"))["results"]["lifetime"]
    life = j["predicted_tonnes_to_end_of_life"]
    lives.append(life)
    print(f"| {s} | {life / 1e6:.3f} | {j['end_of_life_method']} |")
rates = [1 / l for l in lives]
mean = statistics.mean(rates)
life = 1 / mean
line = f"life of the mean rate (harmonic mean of the lives): {life / 1e6:.3f} Mt"
if len(rates) > 1:
    half = t95.get(len(rates) - 1, 1.96) * statistics.stdev(rates) / sqrt(len(rates))
    upper = f"{1 / (mean - half) / 1e6:.2f}" if mean > half else "unbounded"
    line += f", 95 % interval {1 / (mean + half) / 1e6:.2f} ... {upper} Mt ({len(rates)} beds, the beds' scatter only)"
print(line)
EOF
