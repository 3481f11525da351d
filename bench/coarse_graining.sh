#!/usr/bin/env bash
# The coarse-graining study (docs/coarse-graining.md) from one command, each part's runtime
# recorded in DIR/runtimes.md:
#  1. the knife-bed at pellet radii 27.5, 19.4, 13.75 and 9.17 mm (coarse-graining ratio 4,
#     2.828, 2, 1.333 of real 6.875 mm pellets) x knife friction 0 and 0.4 x three beds:
#     `abrade sweep` over both (DIR/sizes: study.csv, study.md, plots/);
#  2. the knife friction 0 ... 0.5 at 27.5 mm, three beds (DIR/friction): the calibration map,
#     which friction at 27.5 mm gives the wear of the finer sizes;
#  3. the knife-bed lifetime case for N updates at 27.5 mm and at 19.4 mm, the latter with the
#     wear filter over the particle radius (the default) and over 27.5 mm (DIR/lifetime-*).
# About an hour on two cores (the 9.17 mm beds, 283,000 pellets, take 20 minutes a run).
#
#   bench/coarse_graining.sh [--factors "4,2.828,2,1.333"] [--seeds 1,2,3] [--updates 3] [--output DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=${ABRADE:-$root/build/abrade} # (ABRADE: another build, e.g. a copy taken before rebuilding)
factors="4,2.828,2,1.333" seeds="1,2,3" updates=3 out=""
while (($#)); do
  case $1 in
    --factors) factors=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --updates) updates=$2; shift 2 ;;
    --output) out=$2; shift 2 ;;
    *) echo "usage: $0 [--factors \"4,2.828,2,1.333\"] [--seeds 1,2,3] [--updates N] [--output DIR]" >&2; exit 2 ;;
  esac
done
[[ -x $abrade ]] || { echo "build abrade first: scripts/setup.sh" >&2; exit 2; }
out=${out:-$(mktemp -d /tmp/abrade-cg.XXXXXX)}
mkdir -p "$out"
cases=$root/cases/knife_bed
echo "| part | command | runtime [s] |" > "$out/runtimes.md"
echo "|---|---|---|" >> "$out/runtimes.md"
timed() { # NAME COMMAND...
  local name=$1 start; shift
  start=$(date +%s)
  "$@"
  echo "| $name | \`${*/#$abrade/abrade}\` | $(( $(date +%s) - start )) |" >> "$out/runtimes.md"
}
timed sizes "$abrade" sweep "$cases/coarse_graining.prm" --vary "Particles/Coarse graining/Factor=$factors" \
  --vary "Wall knife/Interaction/Friction=0,0.4" --seeds "$seeds" --output "$out/sizes" --quiet
timed friction "$abrade" sweep "$cases/coarse_graining.prm" --vary "Wall knife/Interaction/Friction=0,0.1,0.2,0.3,0.4,0.5" \
  --seeds "$seeds" --output "$out/friction" --quiet
life=("$cases/lifetime_coarse_graining.prm" --set "Lifetime/Maximum updates=$updates" --quiet)
timed lifetime-27.5mm "$abrade" run "${life[@]}" --output "$out/lifetime-f4"
timed lifetime-19.4mm "$abrade" run "${life[@]}" --set "Particles/Coarse graining/Factor=2.828" --output "$out/lifetime-f2.828"
timed lifetime-19.4mm-filter-27.5mm "$abrade" run "${life[@]}" --set "Particles/Coarse graining/Factor=2.828" \
  --set "Lifetime/Smoothing radius=0.0275" --output "$out/lifetime-f2.828-filter0.0275"
python3 - "$out" <<'PY' | tee "$out/lifetime.md"
import json, os, sys
out = sys.argv[1]
print("| run | predicted life [t] | 95 % interval [t] | cycles | tonnes simulated | largest depth [m] | smoothing radius [m] |")
print("|---|---|---|---|---|---|---|")
for d in sorted(os.listdir(out)):
    if d.startswith("lifetime-"):
        r = json.load(open(os.path.join(out, d, "summary.json")))["results"]["lifetime"]
        print(f"| {d} | {r.get('predicted_tonnes_to_end_of_life', float('nan')):.3g} | "
              f"{r.get('predicted_tonnes_low', float('nan')):.3g}-{r.get('predicted_tonnes_high', float('nan')):.3g} | "
              f"{r.get('cycles', '')} | {r.get('tonnes', float('nan')):.3g} | {r.get('max_depth', float('nan')):.3g} | "
              f"{r.get('smoothing_radius', float('nan')):.3g} |")
PY

python3 "$root/bench/coarse_graining_analysis.py" "$out/sizes" "$out/friction" | tee "$out/answers.md"
cat "$out/runtimes.md"
echo "results: $out/answers.md, $out/lifetime.md, $out/sizes/study.md, $out/friction/study.md, $out/sizes/plots/"
