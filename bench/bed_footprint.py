#!/usr/bin/env python3
"""The fine column of settled knife-bed beds (docs/coarse-graining.md, "The fine column's mass per area").

    bed_footprint.py [--half-width 0.24] BED.bed ...

For each abrade bed file (a sweep's DIR/beds/*.bed): the share of the bed's mass whose centres
lie in |y| < HALF_WIDTH over that strip's share of the fill box's width (1.94 m:
cases/knife_bed/knife_bed.prm), in per cent (what the case pours over the strip: 100 %), and the
bed's top over the knife's path (the highest pellet top per 50 mm of x, |y| < 0.05 m, x from -0.7
to 0.5 m, averaged); then the means over the files."""
import array
import struct
import sys

FILL_WIDTH = 1.94


def read_bed(path):
    """x, y, z, radius, mass of an abrade bed file (format ABRBED02: generation.cc)."""
    b = open(path, "rb").read()
    if b[:8] != b"ABRBED02":
        sys.exit(f"{path}: not an abrade bed file")
    n = struct.unpack_from("<Q", b, 8)[0]
    cols = []
    for k in range(11):
        a = array.array("d")
        a.frombytes(b[24 + 8 * n * k:24 + 8 * n * (k + 1)])
        cols.append(a)
    return cols[0], cols[1], cols[2], cols[9], cols[10]


def main():
    args = sys.argv[1:]
    half = 0.24
    if args[:1] == ["--half-width"]:
        half, args = float(args[1]), args[2:]
    if not args:
        sys.exit(__doc__)
    shares, tops = [], []
    for path in args:
        x, y, z, r, m = read_bed(path)
        inside = sum(mi for yi, mi in zip(y, m) if abs(yi) < half)
        share = 100 * inside / sum(m) / (2 * half / FILL_WIDTH)
        highest = {}
        for xi, yi, zi, ri in zip(x, y, z, r):
            if abs(yi) < 0.05 and -0.7 <= xi < 0.5:
                k = int((xi + 0.7) / 0.05)
                highest[k] = max(highest.get(k, 0.0), zi + ri)
        top = sum(highest.values()) / len(highest)
        shares.append(share), tops.append(top)
        print(f"{path}: |y| < {half} m holds {share:.2f} % of its share of the mass; top over the knife's path {top:.4f} m")
    print(f"mean of {len(args)}: {sum(shares) / len(shares):.2f} %, {sum(tops) / len(tops):.4f} m")


if __name__ == "__main__":
    main()
