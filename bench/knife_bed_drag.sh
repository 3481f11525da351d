#!/usr/bin/env bash
# The knife-bed in both codes, each from its own beds: the mean knife force in penetration
# (vertical) and in travel (the drag, against the travel direction) over several beds per code,
# with the standard error of each mean and the difference in units of its standard error. One
# bed per seed: LIGGGHTS' insert/pack with seed S (bench/liggghts/knife_bed.in), abrade's random
# placement with Particles/Generation/Seed = S; both settle for 0.573 s, then the same knife
# mesh moves down 0.4 m and along 1.2 m at 1.5 m/s. (The same bed in both codes:
# tests/peer/check_knife_bed_liggghts.sh.)
#
#   bench/knife_bed_drag.sh [--seeds "1 2 3 4 5"] [--friction 0.4] [--output DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=${ABRADE:-$root/build/abrade} # (ABRADE: another build, e.g. a copy taken before rebuilding)
seeds="1 2 3 4 5" mu=0.4 out=""
while (($#)); do
  case $1 in
    --seeds) seeds=$2; shift 2 ;;
    --friction) mu=$2; shift 2 ;;
    --output) out=$2; shift 2 ;;
    *) echo "usage: $0 [--seeds \"1 2 3 4 5\"] [--friction MU] [--output DIR]" >&2; exit 2 ;;
  esac
done
[[ -x $abrade ]] || { echo "build abrade first: scripts/setup.sh" >&2; exit 2; }
command -v liggghts >/dev/null || { echo "liggghts not installed: scripts/install-deps.sh" >&2; exit 2; }
out=${out:-$(mktemp -d /tmp/abrade-drag.XXXXXX)}
mkdir -p "$out"
case=$root/cases/knife_bed/knife_bed.prm
"$abrade" export-walls "$case" --output "$out/walls" > /dev/null
: > "$out/forces.txt" # code seed mean_fz_penetration mean_fx_travel
for s in $seeds; do
  d=$out/liggghts-$s
  mkdir -p "$d" && cp "$root/bench/liggghts/knife_bed.in" "$d/"
  # (LIGGGHTS' seeds must be primes > 10000: seed S is the S-th prime from the input's own seed)
  prime=$(python3 -c "import sys
def is_prime(n): return n > 1 and all(n % k for k in range(2, int(n ** 0.5) + 1))
n, found = 49979687, 0
while True:
    if is_prime(n):
        found += 1
        if found == int(sys.argv[1]): break
    n += 1
print(n)" "$s")
  ( cd "$d" && liggghts -in knife_bed.in -var knife "$out/walls/knife.stl" -var mu_k "$mu" -var seed "$prime" \
      -var thermo_every 10 -log log.liggghts -screen screen.log )
  awk -v s="$s" '/^ *Step/ { section++; first = 1; next }
      NF == 7 && $1 ~ /^[0-9]+$/ { if (first) { first = 0; next }
                                   if (section == 2) { np++; fz += $6 } if (section == 3) { nt++; fx += $4 } }
      END { printf "liggghts %s %.6g %.6g\n", s, fz / np, fx / nt }' "$d/log.liggghts" >> "$out/forces.txt"
  "$abrade" run "$case" --quiet --output "$out/abrade-$s" --set "Particles/Generation/Seed=$s" \
    --set "Wall knife/Interaction/Friction=$mu" --set "Output/Snapshot interval=0" \
    --set "Output/Write particles=false" --set "Particles/Settling/Bed file=" > /dev/null
  python3 - "$out/abrade-$s/summary.json" "$s" >> "$out/forces.txt" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))["results"]["phases"]
print("abrade", sys.argv[2], p["penetration"]["walls"]["knife"]["mean_force"][2], p["travel"]["walls"]["knife"]["mean_force"][0])
PY
done
python3 - "$out/forces.txt" "$mu" <<'PY' | tee "$out/results.md"
import statistics, sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip()]
def stats(code, k):
    v = [float(r[k]) for r in rows if r[0] == code]
    return statistics.mean(v), statistics.stdev(v) / len(v) ** 0.5 if len(v) > 1 else float("nan"), v
print(f"Knife-bed, each code from its own beds (seeds {', '.join(sorted({r[1] for r in rows}))}), knife friction {sys.argv[2]}\n")
print("| quantity | abrade mean +- s.e. [N] | LIGGGHTS mean +- s.e. [N] | difference | difference / s.e. of it |")
print("|---|---|---|---|---|")
for label, k in (("penetration: mean knife Fz", 2), ("travel: mean knife Fx (drag)", 3)):
    (a, sa, va), (l, sl, vl) = stats("abrade", k), stats("liggghts", k)
    se = (sa * sa + sl * sl) ** 0.5
    print(f"| {label} | {a:.0f} +- {sa:.0f} | {l:.0f} +- {sl:.0f} | {100 * (a / l - 1):+.1f} % | {(a - l) / se:+.2f} |")
print("\nper bed: " + "; ".join(f"{r[0]} seed {r[1]}: Fz {float(r[2]):.0f}, Fx {float(r[3]):.0f}" for r in rows))
PY
echo "command: bench/knife_bed_drag.sh --seeds \"$seeds\" --friction $mu" | tee -a "$out/results.md"
