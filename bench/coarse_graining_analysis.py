#!/usr/bin/env python3
"""The coarse-graining study's answers (docs/coarse-graining.md) from its two sweeps:
SIZES/study.csv (coarse-graining factor x knife friction x seeds) and FRICTION/study.csv (knife
friction at the coarsest size). Prints markdown: the quantities per pellet radius and friction,
how far each size is from the finest, a power-law fit of the total wear against the radius, and
the calibration map: the knife friction at the coarsest size whose wear (total, and the share on
the edge) matches the finest size's at each friction.

    bench/coarse_graining_analysis.py SIZES_DIR FRICTION_DIR [REAL_RADIUS_MM]
"""
import csv
import math
import sys

FACTOR = "Particles/Coarse graining/Factor"
FRICTION = "Wall knife/Interaction/Friction"


def read(path):
    return list(csv.DictReader(open(path)))


def cell(r, m, digits=4):
    mean, sd = float(r[m + "_mean"]), float(r[m + "_std"])
    return f"{mean:.{digits}g} ± {sd:.2g}"


def fit_power(rs, ws):
    """w = w0 + a r^p by least squares over p (linear in w0, a for each p); returns w0, a, p, rms."""
    best = None
    for k in range(1, 401):
        p = 0.01 * k
        xs = [r ** p for r in rs]
        n, sx, sy = len(xs), sum(xs), sum(ws)
        sxx, sxy = sum(x * x for x in xs), sum(x * y for x, y in zip(xs, ws))
        det = n * sxx - sx * sx
        if abs(det) < 1e-300:
            continue
        a = (n * sxy - sx * sy) / det
        w0 = (sy - a * sx) / n
        rms = math.sqrt(sum((w0 + a * x - y) ** 2 for x, y in zip(xs, ws)) / n)
        if best is None or rms < best[3]:
            best = (w0, a, p, rms)
    return best


def crossing(xs, ys, target):
    """Where the piecewise-linear curve (xs, ys) first takes the value target (None: never)."""
    for k in range(len(xs) - 1):
        y0, y1 = ys[k], ys[k + 1]
        if (y0 - target) * (y1 - target) <= 0 and y0 != y1:
            return xs[k] + (target - y0) / (y1 - y0) * (xs[k + 1] - xs[k])
    return None


def main():
    sizes, friction = read(sys.argv[1] + "/study.csv"), read(sys.argv[2] + "/study.csv")
    real = float(sys.argv[3]) if len(sys.argv) > 3 else 6.875
    metrics = [("wear_total", "wear, total"), ("wear_per_m_penetration", "wear per m, penetration"),
               ("wear_per_m_travel", "wear per m, travel"), ("edge_share", "share on the edge"),
               ("share_face_+x", "share on the leading end (+x)"), ("share_face_+y", "share on a flank (+y)"), ("peak_depth_filter_radius", "peak depth, filter = radius"),
               ("peak_depth_filter_fixed", "peak depth, filter 27.5 mm"),
               ("mean_force_penetration", "mean force, penetration [N]"),
               ("steady_force_travel", "steady force, travel [N]"), ("layer_velocity_travel", "layer velocity [m/s]"),
               ("layer_slip_travel", "layer slip [m/s]"), ("contacts_penetration", "contacts, penetration"),
               ("contacts_travel", "contacts, travel")]
    metrics = [(m, t or m) for m, t in metrics if m + "_mean" in sizes[0]]
    mus = sorted({r[FRICTION] for r in sizes}, key=float)
    fs = sorted({r[FACTOR] for r in sizes}, key=float, reverse=True)
    at = {(r[FACTOR], r[FRICTION]): r for r in sizes}
    for mu in mus:
        print(f"\n### Knife friction {mu}\n")
        print("| quantity | " + " | ".join(f"R = {float(f) * real:.3g} mm (f = {f})" for f in fs) + " |")
        print("|---|" + "---|" * len(fs))
        for m, title in metrics:
            print(f"| {title} | " + " | ".join(cell(at[(f, mu)], m) for f in fs) + " |")
        print(f"| total wear / finest | " + " | ".join(
            f"{float(at[(f, mu)]['wear_total_mean']) / float(at[(fs[-1], mu)]['wear_total_mean']):.3f}" for f in fs) + " |")
        rs = [float(f) * real for f in fs]
        ws = [float(at[(f, mu)]["wear_total_mean"]) for f in fs]
        w0, a, p, rms = fit_power(rs, ws)
        print(f"\nFit of the total wear, w = w0 + a R^p over R = {rs[0]:.3g} ... {rs[-1]:.3g} mm: w0 = {w0:.4g} "
              f"(the limit R -> 0), p = {p:.2f}, a = {a:.3g}, rms residual {rms:.3g} "
              f"(the seeds' standard deviation at the finest size: {float(at[(fs[-1], mu)]['wear_total_std']):.3g}).")
    # the calibration map: the coarsest size's friction curve against the finest size's values
    fx = [float(r[FRICTION]) for r in friction]
    print("\n### Calibration map: the knife friction at the coarsest size that matches the finest\n")
    print("| finest size, knife friction | its wear | its edge share | friction at the coarsest giving that wear "
          "| ... giving that edge share |")
    print("|---|---|---|---|---|")
    for mu in mus:
        r = at[(fs[-1], mu)]
        out = []
        for m in ("wear_total", "edge_share"):
            ys = [float(q[m + "_mean"]) for q in friction]
            target = float(r[m + "_mean"])
            x = crossing(fx, ys, target)
            out.append(f"{x:.2f}" if x is not None else f"none in {fx[0]:g}..{fx[-1]:g} (there {min(ys):.4g}..{max(ys):.4g})")
        print(f"| {mu} | {cell(r, 'wear_total')} | {cell(r, 'edge_share', 3)} | {out[0]} | {out[1]} |")


if __name__ == "__main__":
    main()
