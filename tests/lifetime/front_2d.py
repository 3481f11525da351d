#!/usr/bin/env python3
"""An independent solution of the worn knife's cross-section, to check the lifetime loop against.

Every point of the wearable surface recedes along its normal at the local rate F(y, z) per tonne
(the run's `Lifetime/Analytic/Wear rate`, a function of the current position): the worn region after t
tonnes is { T < t }, where T is the arrival time of the front, the viscosity solution of the
eikonal equation |grad T| F = 1 with T = 0 on the design's boundary. Far from the knife's ends
the section at mid-length is two-dimensional, so T is solved on a fine grid of the y-z section
(spacing 0.2 mm) by the fast marching method (Sethian 1996; first order, upwind), with no part
of abrade's geometry code: the design section is cut from the run's own part_00000.stl, the
rate parsed from its parameters.prm.

It then takes the run's worn surface after an update (part_NNNNN.stl), cuts it at mid-length and
measures every point p of that section against the front: the front lies F(p) |T(p) - t| away
along the normal (|grad T| = 1 / F); every point of the front (T = t, interpolated along the
grid lines) against the section (its distance to the nearest segment); and the edge's lowest
point against the front's (a tip too low shows in the first two only by sin(half angle) of it).
Exit 1 when any of the three exceeds the tolerance. The abrade run holds the rate of each update
at the surface it started from (forward Euler in time): its front differs from the exact one by
an error that shrinks with the update size (at the tip 0.07, 0.14, 0.23 mm after one update of
350, 500, 650 t of the edge rate), not by the geometry.

   front_2d.py RUN_DIR [--update N] [--tolerance 0.001] [--spacing 0.0002] [--top 0.12]
"""
import argparse
import csv
import heapq
import math
import os
import re
import struct
import sys


def read_stl(path):
    data = open(path, "rb").read()
    triangles = []
    if data[:5] == b"solid" and b"facet" in data[:300]:
        pts = [tuple(map(float, m)) for m in re.findall(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)]
        triangles = [pts[i:i + 3] for i in range(0, len(pts), 3)]
    else:
        n = struct.unpack("<I", data[80:84])[0]
        for k in range(n):
            v = struct.unpack("<12f", data[84 + 50 * k:84 + 50 * k + 48])
            triangles.append([v[3:6], v[6:9], v[9:12]])
    return triangles


def section(triangles, x):
    """The segments (y0, z0, y1, z1) where the plane x = const cuts the triangles."""
    segments = []
    for tri in triangles:
        cut = []
        for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            if (a[0] - x) * (b[0] - x) < 0:
                s = (x - a[0]) / (b[0] - a[0])
                cut.append((a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])))
        if len(cut) == 2:
            segments.append((cut[0][0], cut[0][1], cut[1][0], cut[1][1]))
    return segments


def inside(segments, y, z):
    """Point in polygon (the section's segments, any order): crossings of a ray towards +y."""
    crossings = 0
    for y0, z0, y1, z1 in segments:
        if (z0 > z) != (z1 > z):
            if y < y0 + (z - z0) / (z1 - z0) * (y1 - y0):
                crossings += 1
    return crossings % 2 == 1


def distance_to_segments(segments, y, z):
    best = float("inf")
    for y0, z0, y1, z1 in segments:
        dy, dz = y1 - y0, z1 - z0
        l2 = dy * dy + dz * dz
        s = 0 if l2 == 0 else max(0.0, min(1.0, ((y - y0) * dy + (z - z0) * dz) / l2))
        best = min(best, math.hypot(y - y0 - s * dy, z - z0 - s * dz))
    return best


def rate_function(expression, x):
    """The rate at (x, y, z) of the section x; a rate that changes with the tonnes (t) or follows
    the edge (zmin) is not a fixed speed field: refused."""
    if re.search(r"\b(t|zmin)\b", expression):
        sys.exit(f"front_2d.py: the rate '{expression}' depends on t or zmin: no fixed front speed to solve for")
    names = {k: getattr(math, k) for k in ("exp", "log", "sqrt", "sin", "cos", "tan", "pi")}
    code = compile(expression.replace("^", "**"), "rate", "eval")
    return lambda y, z: eval(code, {"__builtins__": {}}, dict(names, x=x, y=y, z=z))


def arrival_times(design, rate, h, top):
    """Fast marching: T on the grid nodes inside the design section below z = top."""
    y_lo = min(min(s[0], s[2]) for s in design) - h
    y_hi = max(max(s[0], s[2]) for s in design) + h
    z_lo = min(min(s[1], s[3]) for s in design) - h
    ny, nz = int((y_hi - y_lo) / h) + 2, int((top - z_lo) / h) + 1
    near = [s for s in design if min(s[1], s[3]) < top + 2 * h]
    node = lambda i, j: (y_lo + i * h, z_lo + j * h)
    inf = float("inf")
    T = [[inf] * nz for _ in range(ny)]
    inner = [[False] * nz for _ in range(ny)]
    for i in range(ny):
        for j in range(nz):
            inner[i][j] = inside(near, *node(i, j))
    accepted = [[False] * nz for _ in range(ny)]
    heap = []
    # nodes within 1.5 spacings of the boundary start at their distance over their speed
    for i in range(ny):
        for j in range(nz):
            if inner[i][j]:
                d = distance_to_segments(near, *node(i, j))
                if d < 1.5 * h:
                    T[i][j] = d / rate(*node(i, j))
                    accepted[i][j] = True
    for i in range(ny):
        for j in range(nz):
            if accepted[i][j]:
                heapq.heappush(heap, (T[i][j], i, j))
    accepted = [[False] * nz for _ in range(ny)]

    def update(i, j):
        y, z = node(i, j)
        f = rate(y, z)
        a = min(T[i - 1][j] if i > 0 and accepted[i - 1][j] else inf,
                T[i + 1][j] if i + 1 < ny and accepted[i + 1][j] else inf)
        b = min(T[i][j - 1] if j > 0 and accepted[i][j - 1] else inf,
                T[i][j + 1] if j + 1 < nz and accepted[i][j + 1] else inf)
        a, b = min(a, b), max(a, b)
        step = h / f
        if b - a >= step:
            return a + step
        return 0.5 * (a + b + math.sqrt(2 * step * step - (a - b) ** 2))

    while heap:
        t, i, j = heapq.heappop(heap)
        if accepted[i][j] or t > T[i][j]:
            continue
        accepted[i][j] = True
        for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            k, l = i + di, j + dj
            if 0 <= k < ny and 0 <= l < nz and inner[k][l] and not accepted[k][l]:
                tn = update(k, l)
                if tn < T[k][l]:
                    T[k][l] = tn
                    heapq.heappush(heap, (tn, k, l))
    return T, y_lo, z_lo, h, ny, nz


def interpolate(grid, y, z):
    T, y_lo, z_lo, h, ny, nz = grid
    u, v = (y - y_lo) / h, (z - z_lo) / h
    i, j = int(math.floor(u)), int(math.floor(v))
    if not (0 <= i < ny - 1 and 0 <= j < nz - 1):
        return None
    s, r = u - i, v - j
    corners = (T[i][j], T[i + 1][j], T[i][j + 1], T[i + 1][j + 1])
    if any(math.isinf(c) for c in corners):
        finite = [c for c in corners if not math.isinf(c)]
        return min(finite) if finite else None
    return (1 - s) * (1 - r) * corners[0] + s * (1 - r) * corners[1] + (1 - s) * r * corners[2] + s * r * corners[3]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run")
    ap.add_argument("--update", type=int, default=0, help="the update to check (0: the last)")
    ap.add_argument("--tolerance", type=float, default=0.001, help="[m] largest distance allowed")
    ap.add_argument("--spacing", type=float, default=0.0002, help="[m] the fast marching grid")
    ap.add_argument("--top", type=float, default=0.12, help="[m] the grid's top, above the edge's lowest point")
    a = ap.parse_args()
    prm = open(os.path.join(a.run, "parameters.prm")).read()
    expression = re.search(r"set\s+(?:Analytic )?[Ww]ear rate\s*=\s*(.+)", prm).group(1).strip()
    rows = list(csv.DictReader(open(os.path.join(a.run, "trajectory.csv"))))
    update = a.update or len(rows)
    tonnes = float(rows[update - 1]["tonnes"])
    design_tris = read_stl(os.path.join(a.run, "part", "part_00000.stl"))
    worn_tris = read_stl(os.path.join(a.run, "part", f"part_{update:05d}.stl"))
    xs = [p[0] for t in design_tris for p in t]
    x_mid = 0.5 * (min(xs) + max(xs)) + 1e-7  # (off the mesh's own vertices)
    design = section(design_tris, x_mid)
    rate = rate_function(expression, x_mid)
    z0 = min(min(s[1], s[3]) for s in design)
    grid = arrival_times(design, rate, a.spacing, z0 + a.top)
    worn = section(worn_tris, x_mid)
    worst, total, count, where = 0.0, 0.0, 0, None
    for y0, z0_, y1, z1 in worn:
        for k in range(5):  # points along each segment of the section
            s = (k + 0.5) / 5
            y, z = y0 + s * (y1 - y0), z0_ + s * (z1 - z0_)
            if z > z0 + a.top - 5 * a.spacing:
                continue
            T = interpolate(grid, y, z)
            if T is None:
                continue
            d = rate(y, z) * abs(T - tonnes)
            total, count = total + d, count + 1
            if d > worst:
                worst, where = d, (y, z)
    # and back: every point of the front (where T crosses t along a grid line) to the worn section
    T_grid, y_lo, z_lo, h, ny, nz = grid
    back, back_at, front_points = 0.0, (0.0, 0.0), []
    for i in range(ny - 1):
        for j in range(nz - 1):
            for k, l in ((i + 1, j), (i, j + 1)):
                t0, t1 = T_grid[i][j], T_grid[k][l]
                if math.isinf(t0) or math.isinf(t1) or (t0 - tonnes) * (t1 - tonnes) >= 0:
                    continue
                s = (tonnes - t0) / (t1 - t0)
                y, z = y_lo + (i + s * (k - i)) * h, z_lo + (j + s * (l - j)) * h
                if z < z0 + a.top - 5 * h:
                    front_points.append((y, z))
                    d = distance_to_segments(worn, y, z)
                    if d > back:
                        back, back_at = d, (y, z)
    # the edge: the lowest point of the worn section, and where the front crosses y = tip's y
    lowest = min(worn, key=lambda s: min(s[1], s[3]))
    abrade_tip = min(lowest[1], lowest[3])
    y_tip = lowest[0] if lowest[1] <= lowest[3] else lowest[2]
    i = int(round((y_tip - y_lo) / h))
    front_tip = None
    for j in range(1, nz):
        if not math.isinf(T_grid[i][j]) and T_grid[i][j] >= tonnes:
            below = T_grid[i][j - 1]
            front_tip = z_lo + j * h if math.isinf(below) else \
                z_lo + (j - 1 + (tonnes - below) / (T_grid[i][j] - below)) * h
            break
    print(f"update {update} ({tonnes:g} t), section at x = {x_mid:.4f} m: {count} points, the front "
          f"{1000 * total / max(count, 1):.3f} mm away on average, {1000 * worst:.3f} mm at most "
          f"(the section's points to the front, the largest at y = {1000 * where[0]:.2f}, z = {1000 * where[1]:.2f} mm; "
          f"the front's points to the section: {1000 * back:.3f} mm at most, at y = {1000 * back_at[0]:.2f}, "
          f"z = {1000 * back_at[1]:.2f} mm); edge's lowest point: abrade "
          f"{1000 * (abrade_tip - z0):.3f} mm above the design's, the front "
          f"{'-' if front_tip is None else f'{1000 * (front_tip - z0):.3f}'} mm")
    # the edge's lowest point against the front's (the forward distance sees a tip that is too
    # low only by sin(half angle) of it; the front's lowest point is where its tip is)
    front_lowest = min((p for p in front_points), default=None, key=lambda p: p[1])
    tip_error = abs(abrade_tip - front_lowest[1]) if front_lowest else 0.0
    print(f"  the front's lowest point {1000 * (front_lowest[1] - z0):.3f} mm above the design's edge: "
          f"the edge {1000 * (abrade_tip - front_lowest[1]):+.3f} mm off it")
    return 0 if max(worst, back, tip_error) <= a.tolerance else 1


if __name__ == "__main__":
    sys.exit(main())
