#!/usr/bin/env python3
"""Multi-level beds against uniform beds, run by run (bench/multi_level.sh --uniform).

    multi_level_beds.py UNIFORM_SWEEP_DIR[,DIR...] NAME=MULTI_LEVEL_SWEEP_DIR[,DIR...] ...

Reads every run of each sweep (DIR/runs/*-seedN: summary.json's knife wear per phase, the
knife's forces), takes each bed's mean over its runs (runs of one bed differ by a perturbation
of the Verlet skin, --runs-per-bed: the penetration is not yet chaotic and repeats itself, the
travel is, so each run gives another sample of it), and prints a markdown table: each quantity's
mean and standard deviation over the beds, and for each multi-level sweep its ratio to the
uniform one with the 95 % interval of the difference of the means in per cent of the uniform
mean (Welch's t-interval; the bed is the unit: beds are independent, a bed's runs are not).
Several sweep directories joined by commas are one group (seeds added by later sweeps). Where
every run's walls/knife_wear_profile.csv has the phases' columns, the travel's wear is also split
at EDGE_HEIGHT (0.05 m) above the knife's edge: where along the knife a difference sits."""
import csv
import json
import math
import os
import re
import statistics
import sys

from multi_level_analysis import t_quantile_975

QUANTITIES = [
    ("total", "wear, total"),
    ("penetration", "wear, penetration"),
    ("travel", "wear, travel"),
    ("force_penetration", "mean force, penetration [N]"),
    ("force_travel_first", "mean force, travel's first half [N]"),
    ("force_travel", "steady force, travel [N]"),
    ("edge_share", "share of the wear within 0.04 m of the edge"),
    ("peak_fixed", "peak depth, filter 27.5 mm [volume / m^2]"),
    ("travel_edge", "wear, travel, within 0.05 m of the edge"),
    ("travel_above", "wear, travel, above 0.05 m"),
]
EDGE_HEIGHT = 0.05


def run_metrics(run):
    """Knife wear per phase and force (mean over penetration; over travel's second half, as the
    sweep's steady_force_travel) of one run directory."""
    wear = json.load(open(os.path.join(run, "summary.json")))["results"]["wear"]["knife"]
    rows = list(csv.DictReader(open(os.path.join(run, "walls", "knife_forces.csv"))))
    mag = lambda r: math.sqrt(sum(float(r[k]) ** 2 for k in ("fx", "fy", "fz")))
    travel = [r for r in rows if r["phase"] == "travel"]
    half = 0.5 * (float(travel[0]["time"]) + float(travel[-1]["time"]))
    steady = [mag(r) for r in travel if float(r["time"]) >= half]
    first = [mag(r) for r in travel if float(r["time"]) < half]
    pen = [mag(r) for r in rows if r["phase"] == "penetration"]
    m = {"total": wear["total"]["archard_volume"], "penetration": wear["penetration"]["archard_volume"],
         "travel": wear["travel"]["archard_volume"], "force_penetration": sum(pen) / len(pen),
         "force_travel": sum(steady) / len(steady), "force_travel_first": sum(first) / len(first)}
    profile = list(csv.DictReader(open(os.path.join(run, "walls", "knife_wear_profile.csv"))))
    bands = [r for r in profile if r["kind"] == "height"]
    below = lambda r, h: min(max((h - float(r["lower"])) / (float(r["upper"]) - float(r["lower"])), 0.0), 1.0)
    # as the sweep's edge_share (--edge-height 0.04) and peak_depth_filter_fixed
    m["edge_share"] = sum(float(r["archard_volume"]) * below(r, 0.04) for r in bands) / m["total"]
    m["peak_fixed"] = next(float(r["archard_volume"]) for r in profile if r["kind"] == "filtered_peak" and r["label"] == "fixed")
    if bands and "archard_volume_travel" in bands[0]:
        m["travel_edge"] = sum(float(r["archard_volume_travel"]) * below(r, EDGE_HEIGHT) for r in bands)
        m["travel_above"] = sum(float(r["archard_volume_travel"]) * (1 - below(r, EDGE_HEIGHT)) for r in bands)
    return m


def bed_means(sweeps):
    """{seed: {quantity: mean over the bed's runs}, ...} of the sweeps (comma-separated
    directories) and the runs per bed; a quantity some run lacks is left out."""
    runs = {}
    for sweep in sweeps.split(","):
        root = os.path.join(sweep, "runs")
        for name in sorted(os.listdir(root)):
            m = re.search(r"-seed(\d+)$", name)
            if m and os.path.exists(os.path.join(root, name, "summary.json")):
                runs.setdefault(int(m.group(1)), []).append(run_metrics(os.path.join(root, name)))
    means = {s: {q: statistics.mean(r[q] for r in rs) for q, _ in QUANTITIES if all(q in r for r in rs)}
             for s, rs in runs.items()}
    return means, max(len(rs) for rs in runs.values())


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    uniform, per_bed = bed_means(sys.argv[1])
    others = [(a.split("=", 1)[0], bed_means(a.split("=", 1)[1])[0]) for a in sys.argv[2:]]
    header = "| quantity | uniform |" + "".join(f" {n} | ratio, 95 % interval |" for n, _ in others)
    print(f"{len(uniform)} uniform beds, {per_bed} runs per bed; mean ± standard deviation over the beds\n")
    print(header)
    print("|---|---|" + "---|---|" * len(others))
    for q, name in QUANTITIES:
        if not all(q in b for _, beds in [("", uniform)] + others for b in beds.values()):
            continue # (runs without the profile's phase columns)
        u = [b[q] for b in uniform.values()]
        sd = lambda v: statistics.stdev(v) if len(v) > 1 else float("nan") # (one bed: no interval)
        mu, su = statistics.mean(u), sd(u)
        cells = [f"{mu:.4g} ± {su:.2g}"]
        for _, beds in others:
            v = [b[q] for b in beds.values()]
            m, s = statistics.mean(v), sd(v)
            v1, v2 = su * su / len(u), s * s / len(v)
            se = math.sqrt(v1 + v2)
            df = (v1 + v2) ** 2 / (v1 * v1 / (len(u) - 1) + v2 * v2 / (len(v) - 1)) if se > 0 else 1e9
            h = t_quantile_975(df) * se
            cells += [f"{m:.4g} ± {s:.2g}", f"{m / mu:.3f} ({100 * (m - h - mu) / mu:+.0f} % ... {100 * (m + h - mu) / mu:+.0f} %)"]
        print(f"| {name} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
