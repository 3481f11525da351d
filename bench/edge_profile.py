#!/usr/bin/env python3
"""Where along its edge the knife wears: the knife-bed's Archard wear within EDGE m of the knife's
lowest point, in BINS equal lengths from the leading end (+x, the end that meets the bed first in
the travel) to the trailing end, per sweep (the mean over its runs, with the standard error), and
the second sweep's means over the first's (docs/coarse-graining.md, "Where along the edge").

    edge_profile.py [--bins 10] [--edge 0.04] SWEEP_A SWEEP_B

SWEEP_A, SWEEP_B: `abrade sweep` output directories of the knife-bed (one combination each);
each run's knife at the end of the travel (walls/knife_00002.vtp: per-triangle archard_depth
[m^3/m^2 of W = 1], the triangles' current pose)."""
import base64
import glob
import math
import os
import re
import statistics
import struct
import sys
import zlib


def _decode(text, kind):
    """A DataArray of the VTK XML writer's inline binary: a base64 header of block sizes, then
    the zlib-compressed blocks."""
    text = text.strip()
    blocks = struct.unpack("<I", base64.b64decode(text[:8])[:4])[0]
    header_bytes = (3 + blocks) * 4
    header_b64 = ((header_bytes + 2) // 3) * 4
    header = struct.unpack(f"<{3 + blocks}I", base64.b64decode(text[:header_b64])[:header_bytes])
    data, raw, at = base64.b64decode(text[header_b64:]), b"", 0
    for size in header[3:]:
        raw += zlib.decompress(data[at:at + size])
        at += size
    fmt = {"Float64": "d", "Float32": "f", "Int64": "q", "Int32": "i", "UInt8": "B"}[kind]
    return struct.unpack(f"<{len(raw) // struct.calcsize(fmt)}{fmt}", raw)


def read_vtp(path):
    """Points, triangles and cell arrays of a wall's .vtp (as abrade writes it)."""
    s = open(path).read()
    polys = (s.find("<Polys>"), s.find("</Polys>"))
    arrays = {}
    for m in re.finditer(r'<DataArray type="(\w+)" Name="(\w+)"([^>]*)>(.*?)</DataArray>', s, re.S):
        kind, name, _, body = m.groups()
        if name in ("connectivity", "offsets") and not polys[0] < m.start() < polys[1]:
            continue
        arrays[name] = _decode(body, kind)
    p = arrays["Points"]
    points = [p[i:i + 3] for i in range(0, len(p), 3)]
    conn, triangles, previous = arrays["connectivity"], [], 0
    for end in arrays["offsets"]:
        triangles.append(conn[previous:end])
        previous = end
    return points, triangles, arrays


def edge_profile(run, bins, edge):
    """The wear volume [m^3 at W = 1] of the triangles whose centroid is within @p edge of the
    knife's lowest point, in @p bins equal lengths of its x extent from the leading (+x) end."""
    points, triangles, arrays = read_vtp(os.path.join(run, "walls", "knife_00002.vtp"))
    x_max, x_min = max(p[0] for p in points), min(p[0] for p in points)
    z_min = min(p[2] for p in points)
    out = [0.0] * bins
    for i, tri in enumerate(triangles):
        a, b, c = (points[k] for k in tri)
        u, v = [b[k] - a[k] for k in range(3)], [c[k] - a[k] for k in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        area = 0.5 * math.sqrt(sum(x * x for x in n))
        centroid = [(a[k] + b[k] + c[k]) / 3 for k in range(3)]
        if centroid[2] - z_min < edge:
            k = min(bins - 1, int((x_max - centroid[0]) / ((x_max - x_min) / bins)))
            out[k] += arrays["archard_depth"][i] * area
    return out, x_max - x_min


def sweep_profiles(sweep, bins, edge):
    runs = sorted(d for d in glob.glob(os.path.join(sweep, "runs", "*-seed*")) if os.path.isdir(d))
    profiles = [edge_profile(r, bins, edge) for r in runs]
    return [p for p, _ in profiles], profiles[0][1]


def main():
    args, bins, edge = sys.argv[1:], 10, 0.04
    while args[:1] and args[0] in ("--bins", "--edge"):
        if args[0] == "--bins":
            bins = int(args[1])
        else:
            edge = float(args[1])
        args = args[2:]
    if len(args) != 2:
        sys.exit(__doc__)
    (a, length), (b, _) = (sweep_profiles(s, bins, edge) for s in args)
    se = lambda v: statistics.stdev(v) / math.sqrt(len(v)) if len(v) > 1 else float("nan")
    print(f"Wear within {edge} m of the edge, {bins} bins from the leading end; A: {args[0]} ({len(a)} runs), "
          f"B: {args[1]} ({len(b)} runs); mean ± standard error\n")
    print("| bin from the leading end [m] | A | B | B / A |")
    print("|---|---|---|---|")
    for k in range(bins):
        va, vb = [p[k] for p in a], [p[k] for p in b]
        ma, mb = statistics.mean(va), statistics.mean(vb)
        print(f"| {k * length / bins:.3f} ... {(k + 1) * length / bins:.3f} | {ma:.4g} ± {se(va):.2g} | {mb:.4g} ± {se(vb):.2g} | {mb / ma:.3f} |")
    for name, runs in (("A", a), ("B", b)):
        means = [statistics.mean(p[k] for p in runs) for k in range(bins)]
        print(f"\n{name}: largest bin / the edge's mean bin {max(means) / statistics.mean(means):.2f} "
              f"(the leading end {means[0] / statistics.mean(means):.2f}, the trailing end "
              f"{means[-1] / statistics.mean(means):.2f})", end="")
    print()


if __name__ == "__main__":
    main()
