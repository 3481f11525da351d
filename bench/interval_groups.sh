#!/usr/bin/env bash
# Does the life's stated interval mean what it says? Disjoint groups of beds run the same
# lifetime case (each group its own seeds, so its own fresh beds at every update) to a short
# criterion; their lives scatter as independent estimates do. Two statistics (issue 33):
#  - the groups' lives' standard deviation against the stated one (each group's relative_sd x
#    life, i.e. the half-width / t on the log scale): they agree within a factor 2 for honest
#    intervals (six groups know a spread to about +-50 %);
#  - over the ordered pairs of groups, how often a group's life lies inside the other's 95 %
#    interval: about 83 % for honest intervals (a difference of two estimates has sqrt(2) times
#    their spread), 100 % for intervals several times too wide.
#
#   bench/interval_groups.sh [--groups 6] [--beds 3] [--depth 0.003 | --edge 0.006] [--jobs 2] [--output DIR] [--set K=V]...
#
# Default: cases/knife_bed/lifetime.prm, six groups of three beds (seeds 1-3, 4-6, ...), to 3 mm
# of depth below the design (the other criteria off), or with --edge to that edge recession as
# the gauges read it (the reference case's own criterion); one thread per run, two runs at a time.
# Writes DIR/groups.md. Groups whose summary.json is there already are not run again.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=${ABRADE:-$root/build/abrade}
groups=6 beds=3 depth=0.003 edge=0 jobs=2 out="" sets=()
while (($#)); do
  case $1 in
    --groups) groups=$2; shift 2 ;;
    --beds) beds=$2; shift 2 ;;
    --depth) depth=$2; shift 2 ;;
    --edge) edge=$2; depth=0; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --output) out=$2; shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    *) echo "usage: $0 [--groups N] [--beds N] [--depth M | --edge M] [--jobs N] [--output DIR] [--set K=V]..." >&2; exit 2 ;;
  esac
done
out=${out:-$(mktemp -d /tmp/abrade-groups.XXXXXX)}
mkdir -p "$out"
start=$(date +%s)
for ((g = 0; g < groups; ++g)); do
  seeds=$(seq -s, $((g * beds + 1)) $((g * beds + beds)))
  [[ -f $out/group$((g + 1))/summary.json ]] && continue # done before (the same command again)
  echo "OMP_NUM_THREADS=1 \"$abrade\" run \"$root/cases/knife_bed/lifetime.prm\" --quiet --output \"$out/group$((g + 1))\" \
    --set \"Lifetime/Seeds=$seeds\" --set \"Lifetime/Maximum depth=$depth\" --set \"Lifetime/Maximum recession=0\" \
    --set \"Lifetime/Maximum edge recession=$edge\" --set \"Lifetime/Minimum plate thickness=0\" \
    --set \"Simulation/Threads=1\" ${sets[*]@Q} > \"$out/group$((g + 1)).out\" 2>&1 || echo \"group $((g + 1)) failed\""
done | xargs -d '\n' -P "$jobs" -I{} bash -c "{}"
seconds=$(( $(date +%s) - start ))
python3 - "$out" "$groups" "$beds" "$depth" "$seconds" "$edge" <<'PY'
import json, math, os, sys
out, groups, beds, depth, seconds = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
edge = float(sys.argv[6])
criterion = f"{1000 * edge:g} mm of edge recession" if edge > 0 else f"{1000 * depth:g} mm depth"
rows = []
for g in range(1, groups + 1):
    r = json.load(open(os.path.join(out, f"group{g}", "summary.json")))["results"]["lifetime"]
    rows.append((g, r["predicted_tonnes_to_end_of_life"], r["predicted_tonnes_low"], r["predicted_tonnes_high"],
                 r["interval"]["relative_sd"], r["interval"]["bed_relative_sd"], r["extrapolated"], len(r["beds_per_update"])))
lives = [x[1] for x in rows]
mean = sum(lives) / len(lives)
sd_groups = math.sqrt(sum((x - mean) ** 2 for x in lives) / (len(lives) - 1))
sd_stated = math.sqrt(sum((x[4] * x[1]) ** 2 for x in rows) / len(rows))  # rms of the stated standard deviations
inside = sum(1 for a in rows for b in rows if a is not b and a[2] <= b[1] <= a[3])
pairs = groups * (groups - 1)
md = [f"# Interval check: {groups} disjoint groups of {beds} beds, knife-bed to {criterion} ({seconds} s)", "",
      "| group | seeds | updates | life [Mt] | 95 % interval [Mt] | stated sd [%] | one bed's sd at the place [%] | extrapolated |",
      "|---|---|---|---|---|---|---|---|"]
for g, L, lo, hi, s, c, ex, u in rows:
    md.append(f"| {g} | {(g - 1) * beds + 1}-{g * beds} | {u} | {L / 1e6:.3f} | {lo / 1e6:.3f} - {hi / 1e6:.3f} | {100 * s:.1f} | {100 * c:.0f} | {ex} |")
md += ["", f"- lives: mean {mean / 1e6:.3f} Mt, standard deviation over the groups {sd_groups / 1e6:.3f} Mt "
           f"({100 * sd_groups / mean:.1f} %); stated (rms of relative_sd x life) {sd_stated / 1e6:.3f} Mt "
           f"({100 * sd_stated / mean:.1f} %): ratio groups / stated {sd_groups / sd_stated:.2f} (honest: within 0.5-2)",
       f"- a group's life inside another's 95 % interval: {inside} of {pairs} ordered pairs ({100 * inside / pairs:.0f} %; "
       "honest about 83 %, 70-95 % for six groups)"]
open(os.path.join(out, "groups.md"), "w").write("\n".join(md) + "\n")
print("\n".join(md))
PY
