#!/usr/bin/env bash
# The beds of a lifetime update side by side under mpirun (Lifetime/DEM/Ranks per bed, dem/ensemble.h),
# on the small case made to exercise everything a bed hands on: DEM warnings (an overlap limit
# of 8 %, On error = continue), a particle radius that differs from bed to bed (uniform sizes:
# the last bed's largest is the filter's), the tonnes from the payload (Tonnes per cycle = 0).
#  1. -np 2 with two beds per update runs each bed on a rank of its own and gives the serial
#     run's results bit for bit: trajectory.csv, life_beds.csv, every update's stored wear (each
#     bed's wear at every vertex, in the order of the beds) and the warnings, as one process.
#  2. -np 3 with two beds: bed 1 on ranks 0-1, bed 2 on rank 2; the pilot cycle's bed 1 is that
#     of -np 2 with one bed, bed 2 that of one process (a bed on g ranks is the bed of -np g).
#  3. A bed whose file cannot be written by its group's first rank (rank 0 of ranks 0-1 under
#     -np 3), and a bed file that rank 1 (a group of its own under -np 2) finds corrupt: every
#     rank stops with that bed's message, none waits for ever.
#   check_lifetime_ensemble.sh ABRADE PRM OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
rm -rf "$out" && mkdir -p "$out"
mpi=(timeout 300 mpirun --oversubscribe)
sets=(--quiet --set "Lifetime/Maximum updates=2" --set "Simulation/Maximum overlap fraction=0.08"
      --set "Simulation/On error=continue" --set "Particles/Generation/Size distribution=uniform"
      --set "Particles/Generation/Minimum radius=0.022" --set "Particles/Generation/Maximum radius=0.0275"
      --set "Lifetime/Tonnes per cycle=0" --set "Simulation/Payload height=0.2")
two=(--set "Lifetime/Seeds=1, 2")
"$abrade" run "$prm" --output "$out/np1" "${sets[@]}" "${two[@]}" > /dev/null 2>&1
"${mpi[@]}" -np 2 "$abrade" run "$prm" --output "$out/np2" "${sets[@]}" "${two[@]}" > /dev/null 2>&1
grep -q "beds side by side on 2 groups of ranks" "$out/np2/log.txt" || { echo "np2: no ensemble in log.txt"; exit 1; }
for f in trajectory.csv life_beds.csv; do
  cmp "$out/np1/$f" "$out/np2/$f" || { echo "$f differs"; exit 1; }
done
n=0
for f in "$out"/np1/wear/update_*.wear; do
  cmp "$f" "$out/np2/wear/$(basename "$f")" || { echo "$(basename "$f") differs"; exit 1; }
  n=$((n + 1))
done
((n == 3)) || { echo "expected the pilot's and two updates' stored wear, found $n"; exit 1; }
# what is handed on was there to hand on: warnings of both beds, in the same words and order
grep "^warning: .*seed " "$out/np1/log.txt" > "$out/np1.warnings" || true
grep "^warning: .*seed " "$out/np2/log.txt" > "$out/np2.warnings" || true
grep -q "seed 2: " "$out/np1.warnings" || { echo "no warning of the second bed to hand on"; exit 1; }
cmp "$out/np1.warnings" "$out/np2.warnings" || { echo "the warnings differ"; exit 1; }
echo "ok: 2 ranks, 2 beds side by side: trajectory.csv, life_beds.csv, $n stored wear files and $(wc -l < "$out/np1.warnings") warnings as 1 process's"

# 2. groups of 2 and 1
"${mpi[@]}" -np 3 "$abrade" run "$prm" --output "$out/np3" "${sets[@]}" "${two[@]}" > /dev/null 2>&1
"${mpi[@]}" -np 2 "$abrade" run "$prm" --output "$out/np2-one" "${sets[@]}" --set "Lifetime/Seeds=1" \
  --set "Lifetime/Maximum updates=1" > /dev/null 2>&1
bed() { grep -a "^volume_bed_$2 = " "$1/wear/update_00000.wear"; }
[[ $(bed "$out/np3" 1) == $(bed "$out/np2-one" 1) ]] || { echo "-np 3: bed 1 is not -np 2's"; exit 1; }
[[ $(bed "$out/np3" 2) == $(bed "$out/np1" 2) ]] || { echo "-np 3: bed 2 is not 1 process's"; exit 1; }
[[ $(bed "$out/np3" 1) != $(bed "$out/np1" 1) ]] || { echo "-np 3: bed 1 on 2 ranks is bitwise 1 process's (not spread?)"; exit 1; }
echo "ok: 3 ranks, 2 beds: bed 1 as on 2 ranks, bed 2 as on 1"

# 3. failures on one group
expect_stop() { # name, ranks, expected exit code, expected text
  local code
  set +e
  "${mpi[@]}" -np "$2" "$abrade" run "$prm" --output "$out/$1" "${sets[@]}" "${two[@]}" > "$out/$1.out" 2>&1
  code=$?
  set -e
  ((code != 124)) || { echo "$1: a bed failing on one group hung the others"; exit 1; }
  grep -q "$4" "$out/$1.out" || { echo "$1: no '$4' in:"; cat "$out/$1.out"; exit 1; }
  ((code == $3)) || { echo "$1: exit $code, expected $3:"; cat "$out/$1.out"; exit 1; }
  echo "ok: $1 stopped every rank with the bed's message (exit $code)"
}
seeds=$(sed -n 's/^bed_seeds = //p' "$out/np1/wear/update_00000.wear")
first=${seeds% *} second=${seeds#* }
mkdir -p "$out/unwritable/beds/bed-seed$first.bed.tmp" # rank 0 cannot write bed 1's file
expect_stop unwritable 3 3 "cannot write .*bed-seed$first.bed"
mkdir -p "$out/corrupt/beds"
echo "not a bed" > "$out/corrupt/beds/bed-seed$second.bed" # rank 1's bed
expect_stop corrupt 2 2 "bed-seed$second.bed: not an abrade bed file"
