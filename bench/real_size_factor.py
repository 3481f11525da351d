#!/usr/bin/env python3
"""The knife-bed at the real pellet size against the coarse-grained sizes (docs/coarse-graining.md).

    real_size_factor.py [--beds N | --beds N1,N2] UNIFORM_STUDY_CSV REAL_SIZE_STUDY_CSV

UNIFORM_STUDY_CSV: the size study's sweep (docs/coarse-graining/study.csv: Factor 4, 2.828, 2,
1.333, uniform beds); REAL_SIZE_STUDY_CSV: a sweep of multi-level beds with the real pellets in
the fine region (Fine region factor 1). Knife friction 0.4 from both; N beds each (3 unless
--beds says; N1,N2: the uniform study's and the real size's, each at least 2). Prints a markdown table of the real size's means, their 95 % t-intervals and
their ratios to the 27.5 mm beds' (Factor 4) with Fieller's 95 % interval for a ratio of two
independent means (the W factor that takes a 27.5 mm run to the real size is the total wear's
ratio), and the size-convergence fit w = w0 + a R^p through the uniform sizes and the real size's
mean: the limit at zero size and the W factor against it."""
import csv
import math
import sys

from coarse_graining_analysis import fit_power
from multi_level_analysis import FACTOR, FRICTION, t_quantile_975

QUANTITIES = [
    ("wear_total", "wear, total"),
    ("wear_penetration", "wear, penetration"),
    ("wear_travel", "wear, travel"),
    ("edge_share", "share on the edge"),
    ("peak_depth_filter_fixed", "peak depth, filter 27.5 mm"),
    ("mean_force_penetration", "mean force, penetration [N]"),
    ("steady_force_travel", "steady force, travel [N]"),
]
REAL_RADIUS = 6.875  # mm: the real pellets (cases/knife_bed/real_pellets.prm); Factor f gives f times it


def fieller(m1, s1, n1, m2, s2, n2):
    """95 % interval of m2 / m1 (independent means; Welch-Satterthwaite degrees of freedom at
    the ratio's estimate); None where m1 is not significantly away from zero (unbounded)."""
    if m1 == 0:
        return None
    v1, v2 = s1 * s1 / n1, s2 * s2 / n2
    r = m2 / m1
    var = v2 + r * r * v1
    if var == 0:
        return r, r
    df = var ** 2 / (v2 * v2 / (n2 - 1) + (r * r * v1) ** 2 / (n1 - 1))
    t2 = t_quantile_975(df) ** 2
    a, b, c = m1 * m1 - t2 * v1, -2 * m1 * m2, m2 * m2 - t2 * v2
    disc = b * b - 4 * a * c
    if a <= 0 or disc < 0:
        return None
    return (-b - math.sqrt(disc)) / (2 * a), (-b + math.sqrt(disc)) / (2 * a)


def main():
    args = sys.argv[1:]
    n1 = n2 = 3
    if args[:1] == ["--beds"]:
        beds = [int(b) for b in args[1].split(",")]
        n1, n2, args = beds[0], beds[-1], args[2:]
        if min(n1, n2) < 2:
            sys.exit("real_size_factor.py: at least 2 beds each (a standard deviation)")
    if len(args) != 2:
        sys.exit(__doc__)
    at_04 = lambda rows: [r for r in rows if abs(float(r.get(FRICTION, 0.4)) - 0.4) < 1e-9]
    uniform = sorted(at_04(list(csv.DictReader(open(args[0])))), key=lambda r: -float(r[FACTOR]))
    real = at_04(list(csv.DictReader(open(args[1]))))[0]
    coarse = uniform[0]
    assert abs(float(coarse[FACTOR]) - 4) < 1e-9, "the uniform study has no 27.5 mm beds (Factor 4)"
    print(f"Real size (6.875 mm, multi-level, {n2} beds) against the 27.5 mm uniform beds ({n1}), knife friction 0.4\n")
    print("| quantity | 27.5 mm | real size | its 95 % interval | real / 27.5 mm (Fieller, 95 %) |")
    print("|---|---|---|---|---|")
    for key, name in QUANTITIES:
        m1, s1 = float(coarse[key + "_mean"]), float(coarse[key + "_std"])
        m2, s2 = float(real[key + "_mean"]), float(real[key + "_std"])
        h = t_quantile_975(n2 - 1) * s2 / math.sqrt(n2)
        ratio = fieller(m1, s1, n1, m2, s2, n2)
        span = f"{ratio[0]:.3f} ... {ratio[1]:.3f}" if ratio else "unbounded"
        print(f"| {name} | {m1:.4g} ± {s1:.2g} | {m2:.4g} ± {s2:.2g} | {m2 - h:.4g} ... {m2 + h:.4g} | "
              f"{m2 / m1:.3f} ({span}) |")
    radii = [REAL_RADIUS * float(r[FACTOR]) for r in uniform] + [REAL_RADIUS]
    wear = [float(r["wear_total_mean"]) for r in uniform] + [float(real["wear_total_mean"])]
    w0, a, p, rms = fit_power(radii, wear)
    print(f"\nSize fit of the total wear through R = {', '.join(f'{r:.4g}' for r in radii)} mm: "
          f"w = {w0:.4g} + {a:.3g} R^{p:.2f} (rms {rms:.3g}); the real size {wear[-1]:.4g} is "
          f"{wear[-1] / w0:.3f} of the limit; W factor for a 27.5 mm run: {wear[-1] / wear[0]:.3f} "
          f"(real size), {w0 / wear[0]:.3f} (the limit)")


if __name__ == "__main__":
    main()
