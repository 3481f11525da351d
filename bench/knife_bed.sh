#!/usr/bin/env bash
# Throughput of abrade against LIGGGHTS on the knife-bed case, on this machine, in one run.
#
#   bench/knife_bed.sh [--knife-edge H] [--threads "1 2"] [--repeat N] [--output DIR]
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
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=$root/build/abrade
edge=0 threads="1 2" out="" repeat=3
while (($#)); do
  case $1 in
    --knife-edge) edge=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --output) out=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    *) echo "usage: $0 [--knife-edge H] [--threads \"1 2\"] [--repeat N] [--output DIR]" >&2; exit 2 ;;
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

# One round: LIGGGHTS (serial: one core), then abrade on each thread count. Each run appends
# "code threads particles steps seconds" to runs.txt.
: > "$out/runs.txt"
for ((rep = 1; rep <= repeat; ++rep)); do
  mkdir -p "$out/liggghts-$rep"
  cp "$root/bench/liggghts/knife_bed.in" "$out/liggghts-$rep/"
  ( cd "$out/liggghts-$rep" && liggghts -in knife_bed.in -var knife "$out/walls/knife.stl" -log log.liggghts -screen screen.log )
  awk '/^Loop time of/ { n++; if (n > 1) { s += $9; t += $4; a = $12 } } END { print "liggghts 1", a, s, t }' \
    "$out/liggghts-$rep/log.liggghts" >> "$out/runs.txt"
  for n in $threads; do
    "$abrade" run "$case" --quiet --output "$out/abrade-$n-$rep" --set "Simulation/Threads=$n" --set "$knife_set" \
      --set "Output/Snapshot interval=0" --set "Output/Write particles=false" \
      --set "Particles/Settling/Bed file=$out/bed.bed" >/dev/null
    python3 - "$out/abrade-$n-$rep/summary.json" "$n" >> "$out/runs.txt" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); r = s["results"]
ph = [r["phases"][p] for p in ("penetration", "travel")]
steps = sum(p["steps"] for p in ph)
seconds = sum(p["steps"] * r["particles"] / p["particle_steps_per_second"] for p in ph)
print("abrade", sys.argv[2], r["particles"], steps, f"{seconds:.4f}")
PY
  done
done

# medians per code and thread count
mapfile -t rows < <(python3 - "$out/runs.txt" "$threads" <<'PY'
import statistics, sys
runs = [l.split() for l in open(sys.argv[1]) if l.strip()]
def rate(r): return int(r[2]) * int(r[3]) / float(r[4])
def med(code, n):
    sel = [r for r in runs if r[0] == code and r[1] == str(n)]
    return sel[0], statistics.median(rate(r) for r in sel), statistics.median(float(r[4]) for r in sel), len(sel)
print("code,threads,particles,steps,median_loop_seconds,median_particle_steps_per_second,per_core_ratio_vs_liggghts,runs")
l, lr, ls, k = med("liggghts", 1)
print(f"liggghts,1,{l[2]},{l[3]},{ls:.3f},{lr:.4g},1,{k}")
for n in sys.argv[2].split():
    a, ar, as_, k = med("abrade", int(n))
    print(f"abrade,{n},{a[2]},{a[3]},{as_:.3f},{ar:.4g},{ar / int(n) / lr:.2f},{k}")
PY
)
printf '%s\n' "${rows[@]}" > "$out/results.csv"
cmd="bench/knife_bed.sh --knife-edge $edge --threads \"$threads\" --repeat $repeat"
{
  echo "Knife-bed throughput, knife phases (penetration + travel), knife mesh of $triangles triangles"
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d)"
  echo
  echo "| code | threads | particles | steps | median loop s | median particle-steps/s | ratio per core vs LIGGGHTS | runs |"
  echo "|---|---|---|---|---|---|---|---|"
  for r in "${rows[@]:1}"; do IFS=, read -r c t p s l r q k <<<"$r"; echo "| $c | $t | $p | $s | $l | $r | $q | $k |"; done
  echo
  echo "command: $cmd"
} | tee "$out/results.md"
echo "files: $out"
