#!/usr/bin/env bash
# Throughput of abrade against LIGGGHTS on the knife-bed case, on this machine, in one run.
#
#   bench/knife_bed.sh [--knife-edge H] [--threads "1 2"] [--output DIR]
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
edge=0 threads="1 2" out=""
while (($#)); do
  case $1 in
    --knife-edge) edge=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --output) out=$2; shift 2 ;;
    *) echo "usage: $0 [--knife-edge H] [--threads \"1 2\"] [--output DIR]" >&2; exit 2 ;;
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

# LIGGGHTS (serial: one core)
mkdir -p "$out/liggghts"
cp "$root/bench/liggghts/knife_bed.in" "$out/liggghts/"
( cd "$out/liggghts" && liggghts -in knife_bed.in -var knife "$out/walls/knife.stl" -log log.liggghts -screen screen.log )
read -r lig_steps lig_atoms lig_seconds < <(awk '/^Loop time of/ { n++; if (n > 1) { s += $9; t += $4; a = $12 } }
                                              END { print s, a, t }' "$out/liggghts/log.liggghts")
lig_rate=$(python3 -c "print('%.4g' % ($lig_steps * $lig_atoms / $lig_seconds))")

rows=("code,threads,particles,steps,loop_seconds,particle_steps_per_second,per_core_ratio_vs_liggghts")
rows+=("liggghts,1,$lig_atoms,$lig_steps,$lig_seconds,$lig_rate,1")
for n in $threads; do
  "$abrade" run "$case" --quiet --output "$out/abrade-$n" --set "Simulation/Threads=$n" --set "$knife_set" \
    --set "Output/Snapshot interval=0" --set "Output/Write particles=false" >/dev/null
  rows+=("$(python3 - "$out/abrade-$n/summary.json" "$n" "$lig_rate" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); n = int(sys.argv[2]); lig = float(sys.argv[3])
ph = [s["results"]["phases"][p] for p in ("penetration", "travel")]
steps = sum(p["steps"] for p in ph)
seconds = sum(p["steps"] * s["results"]["particles"] / p["particle_steps_per_second"] for p in ph)
rate = steps * s["results"]["particles"] / seconds
print(f'abrade,{n},{s["results"]["particles"]},{steps},{seconds:.3f},{rate:.4g},{rate / n / lig:.2f}')
PY
)")
done

printf '%s\n' "${rows[@]}" > "$out/results.csv"
cmd="bench/knife_bed.sh --knife-edge $edge --threads \"$threads\""
{
  echo "Knife-bed throughput, knife phases (penetration + travel), knife mesh of $triangles triangles"
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d)"
  echo
  echo "| code | threads | particles | steps | loop s | particle-steps/s | ratio per core vs LIGGGHTS |"
  echo "|---|---|---|---|---|---|---|"
  for r in "${rows[@]:1}"; do IFS=, read -r c t p s l r q <<<"$r"; echo "| $c | $t | $p | $s | $l | $r | $q |"; done
  echo
  echo "command: $cmd"
} | tee "$out/results.md"
echo "files: $out"
