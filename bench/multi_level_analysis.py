#!/usr/bin/env python3
"""Multi-level beds against uniform beds of their fine size (bench/multi_level.sh).

    multi_level_analysis.py [--beds N] UNIFORM_STUDY_CSV FACTOR=MULTI_LEVEL_STUDY_CSV ...

For each fine coarse-graining ratio, a markdown table: each quantity's mean and standard
deviation over the beds, uniform and multi-level, their ratio, and the 95 % interval of the
difference of the means in per cent of the uniform mean (Welch's t-interval: the beds of the two
are independent; N beds each, 3 unless --beds says)."""
import csv
import math
import sys

QUANTITIES = [
    ("wear_total", "wear, total"),
    ("edge_share", "share on the edge"),
    ("share_face_+x", "share on the leading end"),
    ("peak_depth_filter_fixed", "peak depth, filter 27.5 mm"),
    ("peak_depth_filter_radius", "peak depth, filter = fine radius"),
    ("mean_force_penetration", "mean force, penetration [N]"),
    ("steady_force_travel", "steady force, travel [N]"),
    ("contacts_travel", "contacts, travel"),
]
FACTOR = "Particles/Coarse graining/Factor"
FRICTION = "Wall knife/Interaction/Friction"


def t_quantile_975(df):
    """Student's t 97.5 % quantile (Hill's expansion: against the exact quantile -2.5 % at df 1.5,
    -0.75 % at 2, -0.12 % at 3, within 0.03 % from 4 on; an interval with Welch's df near 2 is
    that much narrow)."""
    z = 1.959964
    g1 = (z ** 3 + z) / 4
    g2 = (5 * z ** 5 + 16 * z ** 3 + 3 * z) / 96
    g3 = (3 * z ** 7 + 19 * z ** 5 + 17 * z ** 3 - 15 * z) / 384
    g4 = (79 * z ** 9 + 776 * z ** 7 + 1482 * z ** 5 - 1920 * z ** 3 - 945 * z) / 92160
    return z + g1 / df + g2 / df ** 2 + g3 / df ** 3 + g4 / df ** 4


def welch(m1, s1, n1, m2, s2, n2):
    """95 % interval of m2 - m1."""
    v1, v2 = s1 * s1 / n1, s2 * s2 / n2
    se = math.sqrt(v1 + v2)
    if se == 0:
        return m2 - m1, m2 - m1
    df = (v1 + v2) ** 2 / (v1 * v1 / (n1 - 1) + v2 * v2 / (n2 - 1))
    h = t_quantile_975(df) * se
    return m2 - m1 - h, m2 - m1 + h


def main():
    args = sys.argv[1:]
    n = 3
    if args[:1] == ["--beds"]:
        n, args = int(args[1]), args[2:]
    if len(args) < 2:
        sys.exit(__doc__)
    uniform = list(csv.DictReader(open(args[0])))
    for arg in args[1:]:
        factor, path = arg.split("=", 1)
        ml = [r for r in csv.DictReader(open(path)) if abs(float(r.get(FRICTION, 0.4)) - 0.4) < 1e-9][0]
        same = [r for r in uniform if abs(float(r[FACTOR]) - float(factor)) < 1e-3 and abs(float(r[FRICTION]) - 0.4) < 1e-9]
        if not same:  # (the real size: no uniform bed to compare with)
            print(f"### Fine ratio {factor} (knife friction 0.4; {n} beds; no uniform bed of that size)\n")
            print("| quantity | multi-level |")
            print("|---|---|")
            for key, name in QUANTITIES:
                if key + "_mean" in ml:
                    print(f"| {name} | {float(ml[key + '_mean']):.4g} ± {float(ml[key + '_std']):.2g} |")
            print()
            continue
        u = same[0]
        print(f"### Fine ratio {factor} (knife friction 0.4; {n} beds each)\n")
        print("| quantity | uniform | multi-level | ratio | difference, 95 % interval |")
        print("|---|---|---|---|---|")
        for key, name in QUANTITIES:
            if key + "_mean" not in ml or key + "_mean" not in u:
                continue
            m1, s1 = float(u[key + "_mean"]), float(u[key + "_std"])
            m2, s2 = float(ml[key + "_mean"]), float(ml[key + "_std"])
            lo, hi = welch(m1, s1, n, m2, s2, n)
            print(f"| {name} | {m1:.4g} ± {s1:.2g} | {m2:.4g} ± {s2:.2g} | {m2 / m1:.3f} | "
                  f"{100 * lo / m1:+.0f} % ... {100 * hi / m1:+.0f} % |")
        print()


if __name__ == "__main__":
    main()
