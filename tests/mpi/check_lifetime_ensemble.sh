#!/usr/bin/env bash
# The beds of a lifetime update side by side under mpirun (Lifetime/Ranks per bed, dem/ensemble.h):
#  1. -np 2 with two beds per update runs each bed on a rank of its own, and gives the serial
#     run's results bit for bit: trajectory.csv and every update's stored wear (each bed's wear
#     at every vertex, in the order of the beds) byte-identical to one process's. A bed lost,
#     swapped or added twice on its way between the ranks changes the stored wear.
#  2. A bed that fails on one rank's group (its settled bed file corrupt) stops both ranks with
#     that bed's message and exit code 2: the other rank does not wait for it for ever.
#   check_lifetime_ensemble.sh ABRADE PRM OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
rm -rf "$out" && mkdir -p "$out"
sets=(--quiet --set "Lifetime/Maximum updates=2" --set "Lifetime/Seeds=1, 2")
"$abrade" run "$prm" --output "$out/np1" "${sets[@]}" > /dev/null
mpirun -np 2 --oversubscribe "$abrade" run "$prm" --output "$out/np2" "${sets[@]}" > /dev/null
grep -q "beds side by side on 2 groups of ranks" "$out/np2/log.txt" || { echo "np2: no ensemble in log.txt"; exit 1; }
cmp "$out/np1/trajectory.csv" "$out/np2/trajectory.csv" || { echo "trajectory.csv differs"; exit 1; }
n=0
for f in "$out"/np1/wear/update_*.wear; do
  cmp "$f" "$out/np2/wear/$(basename "$f")" || { echo "$(basename "$f") differs"; exit 1; }
  n=$((n + 1))
done
((n == 3)) || { echo "expected the pilot's and two updates' stored wear, found $n"; exit 1; }
echo "ok: 2 ranks, 2 beds side by side: trajectory.csv and $n stored wear files byte-identical to 1 process"

# the pilot cycle's second bed (rank 1's) made unreadable
seed=$(sed -n 's/^bed_seeds = [0-9]* \([0-9]*\)$/\1/p' "$out/np1/wear/update_00000.wear")
[[ -n $seed ]] || { echo "no second pilot bed seed in update_00000.wear"; exit 1; }
mkdir -p "$out/fail/beds"
echo "not a bed" > "$out/fail/beds/bed-seed$seed.bed"
set +e
timeout 300 mpirun -np 2 --oversubscribe "$abrade" run "$prm" --output "$out/fail" "${sets[@]}" > "$out/fail.out" 2>&1
code=$?
set -e
((code != 124)) || { echo "a bed failing on one rank hung the other"; exit 1; }
grep -q "bed-seed$seed.bed: not an abrade bed file" "$out/fail.out" || { echo "no bed message:"; cat "$out/fail.out"; exit 1; }
((code == 2)) || { echo "exit $code, expected 2:"; cat "$out/fail.out"; exit 1; }
echo "ok: a bed failing on rank 1 stopped both ranks with its message (exit 2)"
