#!/usr/bin/env python3
"""How much of each panel of a report picture the part covers.

  panel_fill.py PICTURE.png ROWS [--min FRACTION]

Decodes the PNG (8-bit RGB or RGBA, non-interlaced: what gnuplot's pngcairo writes) without
numpy, cuts it into ROWS panels one above the other, and counts in each the coloured pixels (the
part's: a colour map's hue, max - min of r, g, b above 40; not the white ground, the grey or black
text and lines) over the panel's area. Prints each panel's fraction; with --min, exits 1 when one
falls below it."""
import struct, sys, zlib

def decode(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, (depth, colour, interlace)
            bpp = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, bpp, rows

def main():
    path, panels = sys.argv[1], int(sys.argv[2])
    least = float(sys.argv[sys.argv.index("--min") + 1]) if "--min" in sys.argv else None
    width, height, bpp, rows = decode(path)
    h = height // panels
    fractions = []
    for k in range(panels):
        coloured = 0
        for line in rows[k * h:(k + 1) * h]:
            for x in range(0, width * bpp, bpp):
                r, g, b = line[x], line[x + 1], line[x + 2]
                coloured += max(r, g, b) - min(r, g, b) > 40
        fractions.append(coloured / (h * width))
    print("panel fill: " + ", ".join("%.2f" % f for f in fractions))
    if least is not None and min(fractions) < least:
        print("a panel is filled less than %.2f" % least)
        sys.exit(1)

main()
