#!/usr/bin/env bash
# abrade concepts (and abrade sweep) on two lifetime cases (cases/lifetime/small.prm and a blunter bevel, with a
# payload height): each concept's cycle is a DEM cycle whatever the file's Job (before, the
# cycles ran lifetime jobs and the study failed on a missing walls/knife_wear.csv), and the table
# has both concepts with the knife's wear. Without a payload height the study is refused before
# any run, naming the file and the entry (exit 2, no output directory).
#   check_concepts_of_lifetime_cases.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
printf 'include %s/cases/lifetime/small.prm\n' "$src" > "$out/base.prm"
printf 'include %s/cases/lifetime/small.prm\nsubsection Part\n  set Bevel height = 0.03\nend\n' "$src" > "$out/blunt.prm"
set +e
"$abrade" concepts "$out/base.prm" "$out/blunt.prm" --knives knife --seeds 1 --quiet --output "$out/refused" 2> "$out/refused.err"
code=$?
set -e
[[ $code == 2 ]] || { echo "expected exit 2 without a payload height, got $code"; cat "$out/refused.err"; exit 1; }
grep -q "base.prm: Simulation/Payload height: concepts compares the payload" "$out/refused.err"
[[ ! -e $out/refused ]]
for f in base blunt; do printf 'subsection Simulation\n  set Payload height = 0.05\nend\n' >> "$out/$f.prm"; done
"$abrade" concepts "$out/base.prm" "$out/blunt.prm" --knives knife --seeds 1 --jobs 2 --quiet --output "$out/study"
grep -q "job 'dem'" "$out/study/runs/base-seed1/log.txt"
python3 - "$out/study/concepts.csv" <<'PY'
import csv, sys
rows = {r["concept"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert set(rows) == {"base", "blunt"}, rows.keys()
for name, r in rows.items():
    assert float(r["wear_total"]) > 0, (name, r["wear_total"])
    assert float(r["payload"]) > 0, (name, r["payload"])
PY
# abrade sweep on the same lifetime case: its runs are DEM cycles too (before, they ran lifetime
# jobs and the study failed on a missing walls/knife_wear.csv)
"$abrade" sweep "$out/base.prm" --vary "Wall knife/Interaction/Friction=0.3,0.4" --seeds 1 --jobs 2 --quiet \
  --output "$out/sweep" > /dev/null
grep -q "job 'dem'" "$out"/sweep/runs/*/log.txt
[[ $(grep -c . "$out/sweep/study.csv") -ge 3 ]] # (a header and a row per value)
echo "concepts and sweep of lifetime cases: DEM cycles, both concepts worn; no payload height refused"
