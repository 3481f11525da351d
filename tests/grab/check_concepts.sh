#!/usr/bin/env bash
# abrade concepts on the four knife concepts of cases/grab/concepts (two beds each): the table
# has every concept with positive knife wear in closing and in total and a positive payload, the
# baseline's change is zero, the others' changes carry an uncertainty, no particle was lost in
# any run, and the wear chart is drawn. The changes are paired (the same beds): each concept's
# change in total wear is the geometric mean of its per-bed ratios to the baseline, with the
# 95 % t-interval of the mean log ratio (1 degree of freedom for two beds), computed here again
# from the runs' own wear tables; significant only when the interval excludes no change.
#   check_concepts.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out"
c="$src/cases/grab/concepts"
"$abrade" concepts "$c/baseline.prm" "$c/flow_redirect.prm" "$c/ridge.prm" "$c/blunt_edge.prm" \
  --seeds 1,2 --jobs 2 --quiet --output "$out"
# (a test, not a bare '! grep': set -e does not stop on a command negated with '!')
if grep -l "left the domain" "$out"/runs/*/log.txt; then echo "particles left the domain in these runs"; exit 1; fi
python3 - "$out" <<'PY'
import csv, sys, os
out = sys.argv[1]
table = list(csv.reader(open(os.path.join(out, "concepts.csv"))))
assert all(len(r) == len(table[0]) for r in table), [len(r) for r in table]  # every row has the header's cells
rows = {r["concept"]: r for r in csv.DictReader(open(os.path.join(out, "concepts.csv")))}
assert list(rows) == ["baseline", "flow_redirect", "ridge", "blunt_edge"], list(rows)
for name, r in rows.items():
    assert float(r["wear_closing"]) > 0 and float(r["wear_total"]) > 0, (name, r)
    assert float(r["payload"]) > 0, (name, r)
    assert float(r["wear_per_tonne"]) > 0, (name, r)
assert float(rows["baseline"]["change_wear_total_percent"]) == 0
assert all(float(rows[n]["change_wear_total_uncertainty"]) > 0 for n in ("flow_redirect", "ridge", "blunt_edge"))
assert os.path.getsize(os.path.join(out, "wear.png")) > 0
import math
def total(concept, seed):  # the knives' mean total wear of one run, from its wear tables
    v = []
    for knife in ("right_knife", "left_knife"):
        for r in csv.DictReader(open(os.path.join(out, "runs", f"{concept}-seed{seed}", "walls", f"{knife}_wear.csv"))):
            if r["phase"] == "total":
                v.append(float(r["archard_volume"]))
    return sum(v) / len(v)
t1 = 12.70620474  # t(0.975, 1)
assert int(rows["baseline"]["change_wear_total_significant"]) == 0
for n in ("flow_redirect", "ridge", "blunt_edge"):
    logs = [math.log(total(n, s) / total("baseline", s)) for s in (1, 2)]
    m, sd = sum(logs) / 2, abs(logs[0] - logs[1]) / math.sqrt(2)
    low, high = math.exp(m - t1 * sd / math.sqrt(2)), math.exp(m + t1 * sd / math.sqrt(2))
    r = rows[n]
    for key, want in (("change_wear_total_percent", 100 * (math.exp(m) - 1)), ("change_wear_total_low_percent", 100 * (low - 1)),
                      ("change_wear_total_high_percent", 100 * (high - 1))):
        assert abs(float(r[key]) - want) < 1e-4 * max(1, abs(want)), (n, key, r[key], want)
    assert int(r["change_wear_total_significant"]) == (low > 1 or high < 1), (n, r)
print("ok:", "; ".join(f"{n}: wear {float(r['change_wear_total_percent']):+.0f} +- {float(r['change_wear_total_uncertainty']):.0f} %, "
                       f"payload {float(r['change_payload_percent']):+.0f} +- {float(r['change_payload_uncertainty']):.0f} %"
                       for n, r in rows.items() if n != "baseline"))
PY
