#!/usr/bin/env bash
# abrade concepts on the four knife concepts of cases/grab/concepts (two beds each): the table
# has every concept with positive knife wear in closing and in total and a positive payload, the
# baseline's change is zero, the others' changes carry an uncertainty, no particle was lost in
# any run, and the wear chart is drawn.
#   check_concepts.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out"
c="$src/cases/grab/concepts"
"$abrade" concepts "$c/baseline.prm" "$c/flow_redirect.prm" "$c/ridge.prm" "$c/blunt_edge.prm" \
  --seeds 1,2 --jobs 2 --quiet --output "$out"
! grep -l "left the domain" "$out"/runs/*.log
python3 - "$out" <<'PY'
import csv, sys, os
out = sys.argv[1]
rows = {r["concept"]: r for r in csv.DictReader(open(os.path.join(out, "concepts.csv")))}
assert list(rows) == ["baseline", "flow_redirect", "ridge", "blunt_edge"], list(rows)
for name, r in rows.items():
    assert float(r["wear_closing"]) > 0 and float(r["wear_total"]) > 0, (name, r)
    assert float(r["payload"]) > 0, (name, r)
    assert float(r["wear_per_tonne"]) > 0, (name, r)
assert float(rows["baseline"]["change_wear_total_percent"]) == 0
assert all(float(rows[n]["change_wear_total_uncertainty"]) > 0 for n in ("flow_redirect", "ridge", "blunt_edge"))
assert os.path.getsize(os.path.join(out, "wear.png")) > 0
print("ok:", "; ".join(f"{n}: wear {float(r['change_wear_total_percent']):+.0f} +- {float(r['change_wear_total_uncertainty']):.0f} %, "
                       f"payload {float(r['change_payload_percent']):+.0f} +- {float(r['change_payload_uncertainty']):.0f} %"
                       for n, r in rows.items() if n != "baseline"))
PY
