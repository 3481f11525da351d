#!/usr/bin/env bash
# Multi-level coarse graining against uniform beds (docs/coarse-graining.md): the knife-bed with
# fine pellets in a box around the knife's path (|y| < HALF_WIDTH, the full length and height),
# shells of intermediate sizes around it and the thesis' 27.5 mm pellets elsewhere, at each fine
# coarse-graining ratio, knife friction 0.4, three beds; then the table of each quantity
# against the uniform bed of the fine size (the coarse-graining study's sweep, or DIR/uniform
# with --uniform) with the 95 % interval of the difference.
#
#   bench/multi_level.sh [--factors "2,1.333"] [--half-width 0.36] [--step 1.25] [--layers 1]
#                        [--pours 3] [--seeds 1,2,3] [--runs-per-bed 1] [--uniform] [--output DIR]
#
# --half-width 0.36 (the default) leaves 0.345 m beside the knife's faces, 1.2 times the depth its
# edge works at below the bed's surface (the margin docs/coarse-graining.md recommends; the runs
# warn below 1.15 times); the tables made before 2026-12-07 used 0.24 and say so in their commands.
# --uniform also runs the uniform beds (otherwise docs/coarse-graining/study.csv, made by
# bench/coarse_graining.sh with the same seeds) and compares bed by bed
# (bench/multi_level_beds.py). --pours: Particles/Coarse graining/Fine region pours of the
# multi-level beds (1: poured once). --runs-per-bed N: N runs on every bed, the Verlet skin
# perturbed by 1 um from one to the next (Simulation/Skin 2.75, 2.751, ... mm of the real
# pellets): the penetration repeats itself, the travel is chaotic, so each run is another sample
# of it; the comparison takes each bed's mean. About 5 minutes for ratio 2 and 40 for 1.333 on two
# cores per run of each bed (--uniform: about 2 minutes more per 13.75 mm run).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=${ABRADE:-$root/build/abrade}
factors="2,1.333" half=0.36 step=1.25 layers=1 pours=3 seeds="1,2,3" per_bed=1 uniform=0 out=""
while (($#)); do
  case $1 in
    --factors) factors=$2; shift 2 ;;
    --half-width) half=$2; shift 2 ;;
    --step) step=$2; shift 2 ;;
    --layers) layers=$2; shift 2 ;;
    --pours) pours=$2; shift 2 ;;
    --runs-per-bed) per_bed=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --uniform) uniform=1; shift ;;
    --output) out=$2; shift 2 ;;
    *) echo "usage: $0 [--factors \"2,1.333\"] [--half-width M] [--step S] [--layers N] [--pours N] [--seeds 1,2,3] [--runs-per-bed N] [--uniform] [--output DIR]" >&2; exit 2 ;;
  esac
done
[[ -x $abrade ]] || { echo "build abrade first: scripts/setup.sh" >&2; exit 2; }
((per_bed == 1 || uniform)) || { echo "--runs-per-bed needs --uniform (the comparison bed by bed)" >&2; exit 2; }
out=${out:-$(mktemp -d /tmp/abrade-multi-level.XXXXXX)}
mkdir -p "$out"
case_file=$root/cases/knife_bed/coarse_graining.prm
source "$root/bench/fine_region_sets.sh"
echo "| part | runtime [s] |" > "$out/runtimes.md"
echo "|---|---|" >> "$out/runtimes.md"
uniform_csv=$root/docs/coarse-graining/study.csv
# the runs of each bed: the skin perturbed by 1 um from one to the next (2.75 mm: cases/knife_bed/real_pellets.prm)
skins=$(python3 -c "import sys; print(','.join(f'{0.00275 + 1e-6 * k:.6f}' for k in range(int(sys.argv[1]))))" "$per_bed")
runs_per_bed=(--vary "Simulation/Skin=$skins")
if ((uniform)); then
  for f in ${factors//,/ }; do
    start=$(date +%s)
    "$abrade" sweep "$case_file" --set "Particles/Coarse graining/Factor=$f" --vary "Wall knife/Interaction/Friction=0.4" \
      "${runs_per_bed[@]}" --seeds "$seeds" --jobs 1 --output "$out/uniform-f$f" --quiet
    echo "| uniform beds, ratio $f | $(( $(date +%s) - start )) |" >> "$out/runtimes.md"
  done
fi
runs=()
for f in ${factors//,/ }; do
  start=$(date +%s)
  fine_region_sets "$f" "$half" "$step" "$layers" "$pours"
  "$abrade" sweep "$case_file" "${fine_sets[@]}" --vary "Wall knife/Interaction/Friction=0.4" "${runs_per_bed[@]}" \
    --seeds "$seeds" --jobs 1 --output "$out/multi-level-f$f" --quiet
  echo "| multi-level, fine ratio $f | $(( $(date +%s) - start )) |" >> "$out/runtimes.md"
  runs+=("$f=$out/multi-level-f$f/study.csv")
done
if ((uniform)); then
  for f in ${factors//,/ }; do
    echo "### Fine ratio $f (knife friction 0.4)"; echo
    python3 "$root/bench/multi_level_beds.py" "$out/uniform-f$f" "multi-level=$out/multi-level-f$f"; echo
  done | tee "$out/comparison.md"
else
  python3 "$root/bench/multi_level_analysis.py" "$uniform_csv" "${runs[@]}" | tee "$out/comparison.md"
fi
