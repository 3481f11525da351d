#!/usr/bin/env bash
# Wall-clock time of the lifetime worked example (cases/knife_bed/lifetime.prm: two beds per
# update) with the beds run side by side on groups of MPI ranks (Lifetime/DEM/Ranks per bed), against
# one process, on this machine.
#
#   bench/lifetime_ensemble.sh [--case FILE.prm] [--set ENTRY=VALUE]... [--updates N] [--repeat N]
#                              [--ways "np1 np1-t1 np2 np2-shared"] [--busy N] [--before BINARY] [--output DIR]
#
# The ways, in turn, N times (default 3; medians reported, as shared machines are noisy):
#   np1        one process, the default threads (all cores)
#   np1-t1     one process, one thread
#   np2        mpirun -np 2, one thread each: the two beds side by side, one rank each
#   np2-shared mpirun -np 2, DEM/Ranks per bed = 2: every bed on both ranks, one after the other
# Each run starts in a fresh directory (its beds settled in the run, as every update settles its
# fresh ones). The script also checks that np2's trajectory.csv is byte-identical to np1's: a
# bed on a group of one rank is the bed of one process. Writes results.md and runs.txt.
#
# --before BINARY: another build of abrade (the code before a change); a way written WAY@before
# runs with it, interleaved with the others (np1@before np1-t1@before np1 np1-t1).
#
# --case: another lifetime case (default cases/knife_bed/lifetime.prm); --set: an entry for
# every run (as abrade run's --set).
#
# --busy N: N processes spin on a core each for the whole benchmark (another user's job). With
# --ways "np1 np1-t1" this asks whether the default threads keep at least 0.8x of one thread's
# speed over a lifetime run's many short cycles (the thread governor carried from each
# simulation to the next, thread_governor.h); cases/lifetime/small.prm has phases of 0.1-0.5 s:
#   bench/lifetime_ensemble.sh --busy 1 --ways "np1 np1-t1"
#   bench/lifetime_ensemble.sh --busy 1 --ways "np1 np1-t1" --case cases/lifetime/small.prm --updates 4
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=${ABRADE:-$root/build/abrade}
updates=1 repeat=3 out="" ways="np1 np1-t1 np2 np2-shared" busy=0 case=$root/cases/knife_bed/lifetime.prm sets=() before=""
while (($#)); do
  case $1 in
    --updates) updates=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --output) out=$2; shift 2 ;;
    --ways) ways=$2; shift 2 ;;
    --busy) busy=$2; shift 2 ;;
    --case) case=$(realpath "$2"); shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    --before) before=$(realpath "$2"); shift 2 ;;
    *) echo "usage: $0 [--case FILE.prm] [--set ENTRY=VALUE]... [--updates N] [--repeat N] [--ways \"np1 np1-t1 np2 np2-shared\"] [--busy N] [--before BINARY] [--output DIR]" >&2; exit 2 ;;
  esac
done
[[ -x $abrade ]] || { echo "build abrade first: scripts/setup.sh" >&2; exit 2; }
out=${out:-$(mktemp -d /tmp/abrade-ensemble.XXXXXX)}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi=(mpirun --oversubscribe --bind-to none -np 2)
: > "$out/runs.txt"
spinners=()
for ((k = 0; k < busy; ++k)); do
  (while :; do :; done) &
  spinners+=($!)
done
trap '((${#spinners[@]})) && kill "${spinners[@]}" 2>/dev/null; true' EXIT

one_run() { # name, round, ranks, --set options...
  local name=$1 round=$2 ranks=$3
  shift 3
  local dir=$out/$name-$round start end launch=() binary=$abrade
  if [[ $name == *@before ]]; then
    [[ -x $before ]] || { echo "$name: give --before BINARY" >&2; exit 2; }
    binary=$before
  fi
  ((ranks == 1)) || launch=("${mpi[@]}")
  rm -rf "$dir"
  start=$(date +%s.%N)
  "${launch[@]}" "$binary" run "$case" --set "Lifetime/Maximum updates=$updates" ${sets[@]+"${sets[@]}"} "$@" --output "$dir" > "$dir.log" 2>&1 ||
    { echo "$name failed: $dir.log" >&2; exit 1; }
  end=$(date +%s.%N)
  echo "$name $round $(python3 -c "print(f'{$end - $start:.2f}')")" >> "$out/runs.txt"
}

for ((round = 1; round <= repeat; ++round)); do
  for way in $ways; do
    case ${way%@before} in
      np1) one_run $way $round 1 ;;
      np1-t1) one_run $way $round 1 --set "Simulation/Threads=1" ;;
      np2) one_run $way $round 2 --set "Simulation/Threads=1" ;;
      np2-shared) one_run $way $round 2 --set "Simulation/Threads=1" --set "Lifetime/DEM/Ranks per bed=2" ;;
      *) echo "unknown way $way" >&2; exit 2 ;;
    esac
  done
  if [[ -d $out/np1-$round && -d $out/np2-$round ]]; then
    cmp -s "$out/np1-$round/trajectory.csv" "$out/np2-$round/trajectory.csv" ||
      { echo "np2's trajectory.csv differs from np1's (round $round)" >&2; exit 1; }
  fi
  echo "round $round of $repeat done" >&2
done

python3 - "$out" "$updates" "$repeat" "$busy" "$(basename "$case")" "${sets[*]-}" <<'PY' | tee "$out/results.md"
import statistics, sys
out, updates, repeat, busy, case, sets = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5], sys.argv[6]
times = {}
for line in open(f"{out}/runs.txt"):
    name, _, seconds = line.split()
    times.setdefault(name, []).append(float(seconds))
med = {k: statistics.median(v) for k, v in times.items()}
print(f"Lifetime case {case}{' ' + sets if sets else ''}, Maximum updates = {updates}, "
      f"medians of {repeat} interleaved runs [s]" + (f", {busy} busy process(es) spinning beside every run" if busy else "") + ":\n")
print("| way | wall clock [s] | each run [s] | speed against its build's np1 | against its np1-t1 |")
print("|---|---|---|---|---|")
for k in [w + s for s in ["@before", ""] for w in ["np1", "np1-t1", "np2", "np2-shared"]]:
    if k in med:
        # against the same build's np1 and np1-t1
        suffix = "@before" if k.endswith("@before") else ""
        each = ", ".join(f"{t:.1f}" for t in times[k])
        print(f"| {k} | {med[k]:.1f} | {each} | " +
              (f"{med['np1' + suffix] / med[k]:.2f}" if "np1" + suffix in med else "-") + " | " +
              (f"{med['np1-t1' + suffix] / med[k]:.2f}" if "np1-t1" + suffix in med else "-") + " |")
if "np1" in med and "np2" in med:
    print("\nnp2's trajectory.csv byte-identical to np1's in every round.")
PY
echo "command: bench/lifetime_ensemble.sh${before:+ --before $before} --case $case ${sets[*]-} --updates $updates --repeat $repeat --ways \"$ways\" --busy $busy" | tee -a "$out/results.md"
