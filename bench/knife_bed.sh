#!/usr/bin/env bash
# Throughput of abrade against LIGGGHTS on the knife-bed case, on this machine, in one run.
#
#   bench/knife_bed.sh [--knife-edge H] [--threads "1 2"] [--ranks "2"] [--repeat N] [--busy N] [--output DIR]
#
# Shared machines are noisy (we have seen +-30 % between identical runs), so the codes run in
# turn N times (default 3) and the medians are reported; abrade's runs share one settled bed.
#
# Both codes run the same case (cases/knife_bed/knife_bed.prm and bench/liggghts/knife_bed.in:
# same material, bed region, time step, knife mesh and motion); the knife mesh is written by
# `abrade export-walls`, so both see the same triangles (H = 0: the 16-triangle reference knife;
# H > 0: refined to edges <= H). Prints particle-steps per second for the knife phases
# (penetration and travel) of each code, the ratio abrade / LIGGGHTS per core, and the command
# that reproduces the figures. Writes results.md and results.csv into the output directory.
#
# --threads: abrade on one MPI rank with each of these OpenMP thread counts; --ranks: abrade and
# LIGGGHTS under `mpirun -np N` (one thread per rank) for each N > 1, for the strong scaling.
# Per core = rate / (ranks x threads); strong-scaling efficiency = rate(N) / (N rate(1)).
# A thread count written "2fixed" runs with Simulation/Adapt threads = false (every thread works
# on every step, as before the thread governor).
#
# --busy N: a busy machine. The script starts N processes that spin on a core each for the whole
# benchmark (LIGGGHTS and abrade alike run beside them), as another user's job would; the
# question is whether the default thread count keeps at least 0.8x the one-thread throughput:
#   bench/knife_bed.sh --busy 1 --threads "1 2 2fixed" --ranks 1
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=${ABRADE:-$root/build/abrade} # (ABRADE: another build, e.g. a copy taken before rebuilding)
# ABRADE_BASELINE: a second build (a copy taken before a change) run on one rank with each thread
# count in every round, between LIGGGHTS and abrade, reported as code "baseline": a change's
# speed against the code before it, interleaved on the same machine state.
baseline=${ABRADE_BASELINE:-}
edge=0 threads="1 2" ranks="2" out="" repeat=3 busy=0
while (($#)); do
  case $1 in
    --knife-edge) edge=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --ranks) ranks=$2; shift 2 ;;
    --output) out=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --busy) busy=$2; shift 2 ;;
    *) echo "usage: $0 [--knife-edge H] [--threads \"1 2\"] [--ranks \"2\"] [--repeat N] [--busy N] [--output DIR]" >&2; exit 2 ;;
  esac
done
[[ -x $abrade ]] || { echo "build abrade first: scripts/setup.sh" >&2; exit 2; }
command -v liggghts >/dev/null || { echo "liggghts not installed: scripts/install-deps.sh" >&2; exit 2; }
out=${out:-$(mktemp -d /tmp/abrade-bench.XXXXXX)}
mkdir -p "$out"
case=$root/cases/knife_bed/knife_bed.prm
knife_set="Wall knife/Maximum edge length=$edge"

"$abrade" export-walls "$case" --set "$knife_set" --output "$out/walls" >/dev/null
triangles=$(python3 -c "import struct,sys; f=open(sys.argv[1],'rb'); f.read(80); print(struct.unpack('<I', f.read(4))[0])" "$out/walls/knife.stl")

# One round: LIGGGHTS (one core, then N ranks), then abrade on each thread count and each rank
# count. Each run appends "code ranks threads particles steps seconds" to runs.txt.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi=(mpirun --oversubscribe --bind-to none)
: > "$out/runs.txt"
liggghts_run() { # ranks, directory
  mkdir -p "$2"
  cp "$root/bench/liggghts/knife_bed.in" "$2/"
  if (($1 == 1)); then
    ( cd "$2" && liggghts -in knife_bed.in -var knife "$out/walls/knife.stl" -log log.liggghts -screen screen.log )
  else
    ( cd "$2" && "${mpi[@]}" -np "$1" -x OMP_NUM_THREADS=1 liggghts -in knife_bed.in -var knife "$out/walls/knife.stl" \
        -log log.liggghts -screen screen.log )
  fi
  awk -v r="$1" '/^Loop time of/ { n++; if (n > 1) { s += $9; t += $4; a = $12 } } END { print "liggghts", r, 1, a, s, t }' \
    "$2/log.liggghts" >> "$out/runs.txt"
}
abrade_run() { # ranks, threads (N or Nfixed), directory[, binary, code name]
  local launch=() n=${2%fixed} adapt=true bin=${4:-$abrade} code=${5:-abrade}
  [[ $2 == *fixed ]] && adapt=false
  (($1 > 1)) && launch=("${mpi[@]}" -np "$1" -x OMP_NUM_THREADS="$n")
  OMP_NUM_THREADS=$n "${launch[@]}" "$bin" run "$case" --quiet --output "$3" --set "Simulation/Threads=$n" \
    --set "Simulation/Adapt threads=$adapt" \
    --set "$knife_set" --set "Output/Snapshot interval=0" --set "Output/Write particles=false" \
    --set "Particles/Settling/Bed file=$out/bed.bed" >/dev/null
  python3 - "$3/summary.json" "$1" "$2" "$code" >> "$out/runs.txt" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); r = s["results"]
ph = [r["phases"][p] for p in ("penetration", "travel")]
steps = sum(p["steps"] for p in ph)
seconds = sum(p["steps"] * r["particles"] / p["particle_steps_per_second"] for p in ph)
print(sys.argv[4], sys.argv[2], sys.argv[3], r["particles"], steps, f"{seconds:.4f}")
PY
}
"$abrade" run "$case" --quiet --output "$out/bed" --set Job=bed --set "$knife_set" \
  --set "Particles/Settling/Bed file=$out/bed.bed" >/dev/null # the shared settled bed
busy_pids=()
trap '((${#busy_pids[@]})) && kill "${busy_pids[@]}" 2>/dev/null' EXIT
for ((b = 0; b < busy; ++b)); do
  bash -c 'while :; do :; done' &
  busy_pids+=($!)
done
for ((rep = 1; rep <= repeat; ++rep)); do
  liggghts_run 1 "$out/liggghts-1-$rep"
  for n in $ranks; do (( n > 1 )) && liggghts_run "$n" "$out/liggghts-$n-$rep"; done
  [[ -n $baseline ]] && for t in $threads; do abrade_run 1 "$t" "$out/baseline-1x$t-$rep" "$baseline" baseline; done
  for t in $threads; do abrade_run 1 "$t" "$out/abrade-1x$t-$rep"; done
  for n in $ranks; do (( n > 1 )) && abrade_run "$n" 1 "$out/abrade-${n}x1-$rep"; done
done

# medians per code, ranks and threads
mapfile -t rows < <(python3 - "$out/runs.txt" <<'PY'
import statistics, sys
runs = [l.split() for l in open(sys.argv[1]) if l.strip()]
def rate(r): return int(r[3]) * int(r[4]) / float(r[5])
configs = []
for r in runs:
    if (r[0], r[1], r[2]) not in configs: configs.append((r[0], r[1], r[2]))
med = {}
for c in configs:
    sel = [r for r in runs if (r[0], r[1], r[2]) == c]
    med[c] = (sel[0], statistics.median(rate(r) for r in sel), statistics.median(float(r[5]) for r in sel), len(sel))
ref = med[("liggghts", "1", "1")][1]
print("code,ranks,threads,particles,steps,median_loop_seconds,median_particle_steps_per_second,"
      "per_core_ratio_vs_liggghts_1_core,strong_scaling_efficiency,runs")
for c in configs:
    r, rt, sec, k = med[c]
    cores = int(c[1]) * int(c[2].replace("fixed", ""))
    base = med.get((c[0], "1", "1"))
    eff = rt / cores / base[1] if base else float("nan")
    print(f"{c[0]},{c[1]},{c[2]},{r[3]},{r[4]},{sec:.3f},{rt:.4g},{rt / cores / ref:.2f},{eff:.2f},{k}")
PY
)
printf '%s\n' "${rows[@]}" > "$out/results.csv"
cmd="${baseline:+ABRADE_BASELINE=$baseline }bench/knife_bed.sh --knife-edge $edge --threads \"$threads\" --ranks \"$ranks\" --repeat $repeat --busy $busy"
{
  echo "Knife-bed throughput, knife phases (penetration + travel), knife mesh of $triangles triangles"
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d)$( ((busy)) && echo ", $busy busy process(es) spinning beside every run")"
  echo
  echo "| code | MPI ranks | threads | particles | steps | median loop s | median particle-steps/s | per core vs LIGGGHTS on 1 core | strong-scaling efficiency | runs |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  for r in "${rows[@]:1}"; do IFS=, read -r c n t p s l r q e k <<<"$r"; echo "| $c | $n | $t | $p | $s | $l | $r | $q | $e | $k |"; done
  echo
  echo "command: $cmd"
} | tee "$out/results.md"
echo "files: $out"
