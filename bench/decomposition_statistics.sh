#!/usr/bin/env bash
# Decomposition independence over whole knife-bed cycles: for several beds (seeds), the case on
# 1 rank and on N ranks from the same settled bed. Over the travel phase the pellets jam under
# the knife and round-off grows to order one (as it does between 1 and 2 threads), so the two
# are compared statistically: the mean paired difference of the knife wear and of the mean knife
# force, against its standard error and against the spread between beds; and as a control the
# same for 1 rank on 2 threads (which changes only the order of the force sums, too).
#
#   bench/decomposition_statistics.sh [--seeds "1 2 3 4"] [--ranks 2] [--output DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=$root/build/abrade
seeds="1 2 3 4" ranks=2 out=""
while (($#)); do
  case $1 in
    --seeds) seeds=$2; shift 2 ;;
    --ranks) ranks=$2; shift 2 ;;
    --output) out=$2; shift 2 ;;
    *) echo "usage: $0 [--seeds \"1 2 3 4\"] [--ranks N] [--output DIR]" >&2; exit 2 ;;
  esac
done
out=${out:-$(mktemp -d /tmp/abrade-decomposition.XXXXXX)}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
case=$root/cases/knife_bed/knife_bed.prm
common=(--quiet --set "Simulation/Threads=1" --set "Output/Snapshot interval=0" --set "Output/Write particles=false")
for s in $seeds; do
  bed=(--set "Particles/Generation/Seed=$s" --set "Particles/Settling/Bed file=$out/bed-$s.bed")
  # settle the bed first, so that both runs start from the file (a bed file holds no contact
  # histories: a run that settles and goes on would start differently from one that loads it)
  "$abrade" run "$case" --output "$out/seed$s-settle" "${common[@]}" "${bed[@]}" --set Job=bed >/dev/null
  "$abrade" run "$case" --output "$out/seed$s-np1" "${common[@]}" "${bed[@]}" >/dev/null
  mpirun --oversubscribe -np "$ranks" "$abrade" run "$case" --output "$out/seed$s-np$ranks" "${common[@]}" "${bed[@]}" >/dev/null
  OMP_NUM_THREADS=2 "$abrade" run "$case" --output "$out/seed$s-t2" "${common[@]}" "${bed[@]}" --set "Simulation/Threads=2" >/dev/null
done
python3 - "$out" "$ranks" "$seeds" <<'PY' | tee "$out/results.md"
import json, math, statistics, sys
out, n, seeds = sys.argv[1], sys.argv[2], sys.argv[3].split()
def get(run):
    r = json.load(open(f"{out}/{run}/summary.json"))["results"]
    w = r["wear"]["knife"]
    return {"penetration wear": w["penetration"]["archard_volume"], "travel wear": w["travel"]["archard_volume"],
            "travel mean force x": r["phases"]["travel"]["walls"]["knife"]["mean_force"][0]}
rows = [(s, get(f"seed{s}-np1"), get(f"seed{s}-np{n}")) for s in seeds]
print(f"| seed | quantity | 1 rank | {n} ranks | difference |")
print("|---|---|---|---|---|")
for s, a, b in rows:
    for k in a:
        print(f"| {s} | {k} | {a[k]:.4g} | {b[k]:.4g} | {100 * (b[k] - a[k]) / abs(a[k]):+.1f} % |")
print()
control = {s: get(f"seed{s}-t2") for s in seeds}
def paired(k, other):
    d = [other(s)[k] - a[k] for s, a, _ in rows]
    se = statistics.stdev(d) / math.sqrt(len(d)) if len(d) > 1 else float("nan")
    return f"{statistics.mean(d):+.3g} +- {se:.2g}"
print(f"| quantity | mean over beds (1 rank) | spread between beds (std) | {n} ranks - 1 rank (mean paired difference +- standard error) | control: 2 threads - 1 thread |")
print("|---|---|---|---|---|")
by_seed = {s: b for s, _, b in rows}
for k in rows[0][1]:
    one = [a[k] for _, a, _ in rows]
    print(f"| {k} | {statistics.mean(one):.4g} | {statistics.stdev(one) if len(one) > 1 else float('nan'):.3g} | "
          f"{paired(k, lambda s: by_seed[s])} | {paired(k, lambda s: control[s])} |")
print()
print(f"command: bench/decomposition_statistics.sh --seeds \"{' '.join(seeds)}\" --ranks {n}")
PY
