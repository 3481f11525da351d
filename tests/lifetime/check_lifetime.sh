#!/usr/bin/env bash
# The lifetime job end to end on the small case: the trajectory grows (cycles, tonnes, depth,
# worn volume), the swept volume matches the Archard volume once the volume correction has
# settled (0.8 ... 1.25), the knife is written per update, and summary.json predicts a life.
#   check_lifetime.sh ABRADE PRM OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
rm -rf "$out"
"$abrade" run "$prm" --output "$out" --quiet --set "Lifetime/Maximum updates=3" > /dev/null
python3 - "$out" <<'PY'
import csv, json, sys, os
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "trajectory.csv"))))
assert len(rows) == 3, f"{len(rows)} updates"
for key in ("cycles", "tonnes", "max_depth", "worn_volume"):
    vals = [float(r[key]) for r in rows]
    assert all(b > a for a, b in zip(vals, vals[1:])), f"{key} does not grow: {vals}"
ratios = [float(r["swept_over_archard"]) for r in rows[1:]]
assert all(0.8 <= x <= 1.25 for x in ratios), f"swept / Archard volume {ratios}"
assert all(float(r["min_scaled_jacobian"]) > 0 for r in rows)
s = json.load(open(os.path.join(out, "summary.json")))
life = s["results"]["lifetime"]
assert s["status"] == "completed" and life["predicted_tonnes_to_end_of_life"] > life["tonnes"] > 0, life
for f in ("part/part.pvd", "part/part_00003.vtu", "part/part_00003.stl"):
    assert os.path.getsize(os.path.join(out, f)) > 0, f
print(f"ok: 3 updates, {life['tonnes']:.4g} t, max depth {life['max_depth']:.3g} m, swept/Archard {ratios}, "
      f"predicted life {life['predicted_tonnes_to_end_of_life']:.4g} t")
PY
