#!/usr/bin/env bash
# The same case gives the same bits with any number of threads: Simulation/Shares (default 4)
# fixes how a step's work is cut and summed, Simulation/Threads only how many threads work on
# the shares. Before, the shares followed the thread count (0: the machine's cores), and the
# knife-bed's first lifetime update took 458,999 cycles on one thread and 595,951 on two.
# Checked on a DEM job's wall forces (every force sample) and a lifetime run's trajectory and
# life (one update of the small DEM case), each with 1, 2 and 0 (= OMP_NUM_THREADS=3) threads.
#   check_same_bits_any_threads.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$(realpath "$1") src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
for t in 1 2 0; do
  OMP_NUM_THREADS=3 "$abrade" run "$src/tests/regression/knife_bed_small.prm" --quiet --output "$out/dem_$t" \
    --set "Simulation/Threads=$t" > /dev/null
  OMP_NUM_THREADS=3 "$abrade" run "$src/cases/lifetime/small.prm" --quiet --output "$out/life_$t" \
    --set "Simulation/Threads=$t" --set "Lifetime/Maximum updates=1" > /dev/null
done
for t in 2 0; do
  for f in knife_forces.csv container_forces.csv; do
    cmp "$out/dem_1/walls/$f" "$out/dem_$t/walls/$f" || { echo "FAIL: $f differs between 1 and $t threads"; exit 1; }
  done
  cmp "$out/life_1/trajectory.csv" "$out/life_$t/trajectory.csv" ||
    { echo "FAIL: trajectory.csv differs between 1 and $t threads"; exit 1; }
done
python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
lives = [json.load(open(f"{out}/life_{t}/summary.json"))["results"]["lifetime"]["predicted_tonnes_to_end_of_life"] for t in (1, 2, 0)]
assert lives[0] == lives[1] == lives[2], lives
print(f"ok: the same forces, trajectory and life ({lives[0]:.6g} t) on 1, 2 and 3 threads")
PY
