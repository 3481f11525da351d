"""Writes a block (x 0..400, y -15..15, z 0..500 mm) as an IGES 5.3 surface model in
millimetres: six bounded planes (entity 108, form 1), each bounded by a composite curve (102) of
four lines (110). Gmsh cannot write IGES; this is the test's IGES part (a surface model, as IGES
files from design tools often are, which abrade sews into a solid).
    python3 iges_block.py OUT.igs"""
import sys


def block_faces(x0, y0, z0, x1, y1, z1):
    c = lambda i, j, k: ((x0, x1)[i], (y0, y1)[j], (z0, z1)[k])
    # each face: outward normal (A, B, C), D of A x + B y + C z = D, corners counter-clockwise
    # seen from outside
    return [((-1, 0, 0), -x0, [c(0, 0, 0), c(0, 0, 1), c(0, 1, 1), c(0, 1, 0)]),
            ((1, 0, 0), x1, [c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)]),
            ((0, -1, 0), -y0, [c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)]),
            ((0, 1, 0), y1, [c(0, 1, 0), c(0, 1, 1), c(1, 1, 1), c(1, 1, 0)]),
            ((0, 0, -1), -z0, [c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)]),
            ((0, 0, 1), z1, [c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)])]


entities = []  # (type, form, parameters as text, status)


def add(etype, form, params, status="00000000"):
    entities.append((etype, form, params, status))
    return 2 * len(entities) - 1  # the sequence number of its first directory line


real = lambda v: repr(float(v))
for normal, d, corners in block_faces(0, -15, 0, 400, 15, 500):
    lines = [add(110, 0, [real(v) for v in (*corners[k], *corners[(k + 1) % 4])], "00010000") for k in range(4)]
    curve = add(102, 0, ["4"] + [str(l) for l in lines], "00010000")
    add(108, 1, [real(v) for v in (*normal, d)] + [str(curve)] + [real(0)] * 4)


def hollerith(s):
    return f"{len(s)}H{s}"


def records(text, width):
    """Splits at parameter delimiters, so that no number or string spans two records."""
    out, line = [], ""
    pieces = text.split(",")
    for piece in [p + "," for p in pieces[:-1]] + [pieces[-1]]:
        if len(line) + len(piece) > width:
            out.append(line)
            line = ""
        line += piece
    return out + [line]


start = ["abrade test part: a 400 x 30 x 500 mm block as six bounded planes"]
date = hollerith("20261129.120000")
global_section = ",".join(["1H,", "1H;", hollerith("abrade"), hollerith("block.igs"), hollerith("abrade"),
                           hollerith("1"), "32", "38", "6", "308", "15", hollerith("abrade"), "1.0",
                           "2", hollerith("MM"),  # unit flag 2: millimetres
                           "1", "1.0", date, "1.0E-6", "1000.0", hollerith("abrade"), hollerith("abrade"),
                           "11", "0", date]) + ";"
out = [f"{l:<72}S{i + 1:7d}" for i, l in enumerate(start)]
g = records(global_section, 72)
out += [f"{l:<72}G{i + 1:7d}" for i, l in enumerate(g)]
parameter_lines, where = [], []
for n, (etype, form, params, status) in enumerate(entities):
    chunk = records(",".join([str(etype)] + params) + ";", 64)
    where.append((len(parameter_lines) + 1, len(chunk)))
    parameter_lines += [f"{c:<64}{2 * n + 1:8d}" for c in chunk]
for n, (etype, form, params, status) in enumerate(entities):
    first, count = where[n]
    out.append(f"{etype:8d}{first:8d}{0:8d}{1:8d}{0:8d}{0:8d}{0:8d}{0:8d}{status:>8}D{2 * n + 1:7d}")
    out.append(f"{etype:8d}{0:8d}{0:8d}{count:8d}{form:8d}{'':8}{'':8}{'':8}{0:8d}D{2 * n + 2:7d}")
out += [f"{l}P{i + 1:7d}" for i, l in enumerate(parameter_lines)]
out.append(f"S{len(start):7d}G{len(g):7d}D{2 * len(entities):7d}P{len(parameter_lines):7d}{'':40}T{1:7d}")
open(sys.argv[1], "w").write("\n".join(out) + "\n")
