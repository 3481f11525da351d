#!/usr/bin/env bash
# Lives compared on common beds, end to end through the DEM (abrade concepts --lifetime-updates;
# coupling/include/abrade/coupling/lifetime/paired_life.h). The small lifetime case as the
# baseline, the same file again under another name, and the baseline with twice its Archard
# coefficient, three beds, two updates:
#  - every concept drew the same beds in every update (life_beds.csv: the same seeds; update
#    1's are the seeds themselves);
#  - each run's own interval, written again here from its life_beds.csv (c^2 pooled over the
#    updates' beds, phi^2 on the held elasticities' part), is its summary.json's;
#  - the baseline again: no change, no width (the same run; 1e-4 % of rounding);
#  - twice the wear: Archard wear is linear in W and the loop sizes an update by its rate, so
#    the same beds give the same depths in half the tonnes (apart from each update's whole number
#    of cycles): the life's change is -50 % within 0.5 %, its paired interval narrower than
#    +-0.5 %, where each life's own interval spans a factor of more than two (its beds scatter
#    by more than 100 % on this small case);
#  - concepts.csv's paired interval is the one written again here from the two life_beds.csv;
#  - abrade sweep over the baseline's Archard coefficient (2e-14, 4e-14: the same runs by another
#    path, --vary instead of a file) gives the same life ratio and interval in study.csv.
#   check_paired_life.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out"
c="$src/tests/lifetime/paired"
"$abrade" concepts "$c/baseline.prm" "$c/baseline_again.prm" "$c/double_wear.prm" --knives knife --seeds 1,2,3 \
  --lifetime-updates 2 --jobs 2 --quiet --output "$out"
"$abrade" sweep "$c/baseline.prm" --vary "Wall knife/Wear/Archard/Coefficient=2e-14,4e-14" --seeds 1,2,3 \
  --lifetime-updates 2 --jobs 2 --quiet --output "$out/sweep" > /dev/null
python3 - "$out" <<'PY'
import csv, json, math, os, sys
from statistics import mean
out = sys.argv[1]

def read(name):
    rows = list(csv.DictReader(open(os.path.join(out, "lifetime", name, "life_beds.csv"))))
    life, factor = float(rows[0]["life"]), float(rows[0]["place_factor"])
    updates = {}
    for r in rows:
        u = updates.setdefault(int(r["update"]), {"held": float(r["elasticity_held"]), "free": float(r["elasticity_free"]),
                                                  "seeds": [], "rates": []})
        u["seeds"].append(int(r["bed_seed"])), u["rates"].append(float(r["rate"]))
    return life, factor, [updates[k] for k in sorted(updates)]

def deviations(u):
    m = mean(u["rates"])
    return [r / m - 1 for r in u["rates"]] if len(u["rates"]) > 1 and m > 0 else []

def pooled(run):
    e = [deviations(u) for u in run]
    return sum(x * x for d in e for x in d) / sum(len(d) - 1 for d in e if d), sum(len(d) - 1 for d in e if d)

# t(0.975, dof) for the few dof used here (Boost in the code; a table here)
T = {2: 4.302652730, 4: 2.776445105, 6: 2.446911851, 8: 2.306004135}

runs = {n: read(n) for n in ("baseline", "baseline_again", "double_wear")}
for n, (life, factor, ups) in runs.items():
    assert len(ups) == 2, (n, len(ups))
    assert ups[0]["seeds"] == [1, 2, 3], (n, ups[0]["seeds"])
    assert all(u["seeds"] == b["seeds"] for u, b in zip(ups, runs["baseline"][2])), n
    # the run's own interval from its beds
    c2, dof = pooled(ups)
    held = factor * c2 * sum(u["held"] ** 2 / len(u["rates"]) for u in ups)
    free = c2 * sum((u["free"] ** 2 - u["held"] ** 2) / len(u["rates"]) for u in ups)
    s = math.sqrt(held + max(0, free))
    summ = json.load(open(os.path.join(out, "lifetime", n, "summary.json")))["results"]["lifetime"]
    assert abs(summ["predicted_tonnes_to_end_of_life"] / life - 1) < 1e-9, (n, life)
    assert abs(summ["interval"]["relative_sd"] / s - 1) < 1e-6, (n, s, summ["interval"])
    assert summ["predicted_tonnes_high"] / summ["predicted_tonnes_low"] > 2, (n, summ)

def paired(a, b):
    (la, fa, A), (lb, fb, B) = a, b
    ca2, da = pooled(A)
    cb2, db = pooled(B)
    # the beds both drew (by seed); rho from their deviations over the updates after the first
    shared, saa, sbb, sab, dc = [], 0, 0, 0, 0
    for u, (ua, ub) in enumerate(zip(A, B)):
        pairs = [(ua["rates"][i], ub["rates"][ub["seeds"].index(s)]) for i, s in enumerate(ua["seeds"]) if s in ub["seeds"]]
        ea = deviations({"rates": [p[0] for p in pairs]})
        eb = deviations({"rates": [p[1] for p in pairs]})
        shared.append(len(pairs) if ea and eb else 0)
        if ea and eb and (u > 0 or min(len(A), len(B)) == 1):
            saa += sum(x * x for x in ea); sbb += sum(x * x for x in eb); sab += sum(x * y for x, y in zip(ea, eb))
            dc += len(ea) - 1
    rho = sab / math.sqrt(saa * sbb)
    def V(key, sa, sb):
        v = sa * ca2 * sum(u[key] ** 2 / len(u["rates"]) for u in A) + sb * cb2 * sum(u[key] ** 2 / len(u["rates"]) for u in B)
        return v - 2 * math.sqrt(sa * sb) * rho * math.sqrt(ca2 * cb2) * sum(
            ua[key] * ub[key] * m / (len(ua["rates"]) * len(ub["rates"])) for ua, ub, m in zip(A, B, shared))
    var = max(0, V("held", fa, fb)) + max(0, V("free", 1, 1) - V("held", 1, 1))
    h = T[min(da, db, dc)] * math.sqrt(var)
    r = la / lb
    return r, r * math.exp(-h), r * math.exp(h)

rows = {r["concept"]: r for r in csv.DictReader(open(os.path.join(out, "concepts.csv")))}
for n in ("baseline_again", "double_wear"):
    r, low, high = paired(runs[n], runs["baseline"])
    for key, want in (("change_life_percent", 100 * (r - 1)), ("change_life_low_percent", 100 * (low - 1)),
                      ("change_life_high_percent", 100 * (high - 1))):
        assert abs(float(rows[n][key]) - want) < 1e-4 * max(1, abs(want)), (n, key, rows[n][key], want)
again, double = rows["baseline_again"], rows["double_wear"]
assert float(again["change_life_percent"]) == 0 and abs(float(again["change_life_low_percent"])) < 1e-4 \
    and abs(float(again["change_life_high_percent"])) < 1e-4, again  # (rounding: rho = 1 - 1e-16)
assert abs(float(double["change_life_percent"]) + 50) < 0.5, double
assert float(double["change_life_high_percent"]) - float(double["change_life_low_percent"]) < 1.0, double
assert int(double["change_life_significant"]) == 1, double
sweep = list(csv.DictReader(open(os.path.join(out, "sweep", "study.csv"))))
ratio = 1 + float(double["change_life_percent"]) / 100
for key, want in (("life_ratio", ratio), ("life_ratio_low", 1 + float(double["change_life_low_percent"]) / 100),
                  ("life_ratio_high", 1 + float(double["change_life_high_percent"]) / 100)):
    assert abs(float(sweep[1][key]) - want) < 1e-6, (key, sweep[1][key], want)
assert int(sweep[1]["life_ratio_significant"]) == 1 and float(sweep[0]["life_ratio"]) == 1, sweep
own = [float(rows[n]["predicted_life_high"]) / float(rows[n]["predicted_life_low"]) for n in ("baseline", "double_wear")]
print(f"ok: twice the wear: life {float(double['change_life_percent']):+.3f} % [{float(double['change_life_low_percent']):+.3f}, "
      f"{float(double['change_life_high_percent']):+.3f}] paired, where each life's own interval spans a factor "
      f"{own[0]:.3g} / {own[1]:.3g}; the baseline again: 0 % [0, 0]; the sweep's the same")
PY
