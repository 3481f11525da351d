#!/bin/bash
# The knife-bed's life at one pellet size without the geometry feedback, bed by bed
# (docs/coarse-graining.md, "The real-size life by replay"): each bed's wear on the design (one
# update of fixed cycles, Lifetime/Cycles per update, Maximum updates = 1: the DEM's only cycle,
# one bed per run) is replayed to the end of life (Lifetime/Wear source = replay: the part wears
# on, its wear carried onto the worn surface, no DEM), alone and with all the beds together (their
# stored wear joined by the replay, Lifetime/Replay/Run = a, b, ...: byte for byte what one run
# of them all stores). The life is the beds together's; its 95 % interval the jackknife's over the beds
# (each left out once, t with beds - 1 degrees of freedom): the beds' scatter only. Not the
# harmonic mean of the single-bed lives: the gauge reads the worst station, which differs from
# bed to bed at the real size (the harmonic mean 0.90 of the life there, 1.00 at 27.5 mm).
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
#   (e.g. at another --smoothing; the replays go to DIR/replay-rR/, replaced).
# A real-size bed's cycle took 65 minutes with three at once on two shared cores (about 33 on a
# core of its own, inferred); a 27.5 mm one a minute. A replay takes seconds.
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
  source "$here/bench/fine_region_sets.sh"
  fine_region_sets 1 0.36 1.25 1 3 # (bench/multi_level.sh --factors 1's defaults)
  sets+=("${fine_sets[@]}" --set "Simulation/Skin=0.00275")
fi
mkdir -p "$out"; out=$(cd "$out" && pwd)

# 1. each bed's wear on the design: one update of fixed cycles (the cycles only size that
#    update's step; the replay takes the wear per cycle)
one_update() {
  local s=$1 dir=$out/bed-seed$1
  mkdir -p "$dir/beds"
  if [ -n "$beds" ]; then cp "$beds/bed-seed$s.bed" "$dir/beds/"; fi
  "$abrade" run "$case_file" "${sets[@]}" --set "Lifetime/Seeds=$s" --set "Lifetime/Cycles per update=200000" \
    --set "Lifetime/Maximum updates=1" --output "$dir" > "$dir.log" 2>&1 || { echo "bed seed $s failed: $dir.log" >&2; return 1; }
}
if [ $replays_only = 0 ]; then
  pids=()
  for s in $seeds; do
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
    one_update "$s" & pids+=($!)
  done
  failed=0
  for p in "${pids[@]}"; do wait "$p" || failed=1; done
  [ $failed = 0 ] || exit 1
fi

# 2. the replays: each bed alone, all of them together, and all but one (the jackknife)
replays=$out/replay-r$smoothing
rm -rf "$replays" && mkdir -p "$replays"
replay() { # NAME STORED_RUN SEEDS
  "$abrade" run "$case_file" "${sets[@]}" --set "Lifetime/Seeds=$3" --set "Lifetime/Smoothing radius=$smoothing" \
    --set "Lifetime/Wear source=replay" --set "Lifetime/Replay/Run=$2" --set "Lifetime/Maximum updates=80" \
    --output "$replays/$1" > "$replays/$1.log" 2>&1 || { echo "replay $1 failed: $replays/$1.log" >&2; exit 1; }
}
joined() { # NAME SEEDS...: the one-bed runs of those beds replayed together (Replay/Run = a, b, ...:
           # their stored wear joined as one run of those beds stores it)
  local name=$1 runs=""
  shift
  for s in "$@"; do runs+="${runs:+,}$out/bed-seed$s"; done
  replay "$name" "$runs" "$(echo "$@" | tr ' ' ,)"
}
for s in $seeds; do replay "seed$s" "$out/bed-seed$s" "$s"; done
n_beds=$(echo $seeds | wc -w)
if [ "$n_beds" -gt 1 ]; then
  joined all $seeds
  for s in $seeds; do joined "without$s" $(for t in $seeds; do [ "$t" = "$s" ] || echo "$t"; done); done
fi

# 3. the lives: each bed's, the beds together's with the jackknife's interval
python3 - "$replays" $seeds <<'EOF'
import json, statistics, sys
from math import sqrt
replays, seeds = sys.argv[1], sys.argv[2:]
# two-sided 95 % t quantiles by degrees of freedom (1 ... 30; beyond, the normal's 1.96 is within 4 %)
t95 = dict(enumerate([12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
                      2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
                      2.052, 2.048, 2.045, 2.042], start=1))
def life(name):
    j = json.load(open(f"{replays}/{name}/summary.json"))["results"]["lifetime"]
    if j.get("predicted_tonnes_to_end_of_life") is None:
        sys.exit(f"{replays}/{name}: no predicted life")
    return j["predicted_tonnes_to_end_of_life"], j["end_of_life_method"]
print("| beds | life [Mt] | end of life |")
print("|---|---|---|")
for s in seeds:
    l, how = life(f"seed{s}")
    print(f"| {s} | {l / 1e6:.3f} | {how} |")
if len(seeds) > 1:
    whole, how = life("all")
    print(f"| {', '.join(seeds)} together | {whole / 1e6:.3f} | {how} |")
    n = len(seeds)
    left = [life(f"without{s}")[0] for s in seeds]
    se = sqrt((n - 1) / n * sum((l - statistics.mean(left)) ** 2 for l in left))
    half = t95.get(n - 1, 1.96) * se
    print(f"life of the {n} beds together: {whole / 1e6:.3f} Mt, 95 % interval {(whole - half) / 1e6:.2f} ... "
          f"{(whole + half) / 1e6:.2f} Mt (jackknife over the beds, {n - 1} degrees of freedom: the beds' scatter only)")
EOF
