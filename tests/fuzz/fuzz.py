#!/usr/bin/env python3
"""Mutation fuzzing of abrade's readers: every input, however broken, must end in exit 0 (it
was still valid) or exit 2 (one clear error line), within a time limit. A crash (a signal), a
hang (the time limit), an internal error (exit 1) or a run-time error (exit 3) on a mutated input
is a failure; the input is kept in OUTDIR/failures/ to become a regression test.

Each target is a small valid input and the cheapest command that reads it:
  prm   a parameter file with walls of every primitive          abrade export-walls
  stl   a wall's STL (ASCII)                                     abrade export-walls
  obj   a wall's OBJ                                             abrade export-walls
  ply   a wall's PLY (ASCII)                                     abrade export-walls
  msh   the knife as a Gmsh .msh volume mesh (two tetrahedra)    abrade run (Job = knife)
Mutations (several per input): a flipped byte, a line deleted or repeated, a number replaced by
an extreme one (0, -1, 1e300, nan, inf, 2147483647, -99, 1e-300, a word), the file cut short,
random bytes inserted. The random seed makes a run reproducible.

    fuzz.py ABRADE OUTDIR [--mutations N] [--seed S] [--targets prm,stl,...]
"""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys

WALL_PRM = """set Job   = dem
set Walls = w
subsection Simulation
  set Phases = only: 0.001
end
subsection Wall w
  set Geometry = file
  set File     = {file}
end
"""

CORPUS = {
    "prm": """set Job   = dem
set Walls = box, plate, knife
subsection Simulation
  set Phases     = fill: 0.01, travel: 0.02
  set Domain min = -1, -1, -0.5
  set Domain max = 1, 1, 1.5
end
subsection Particles
  subsection Generation
    set Radius = 0.02
    set Count  = 100
  end
end
subsection Wall box
  set Geometry = box
  set Box min  = -0.5, -0.5, 0
  set Box max  = 0.5, 0.5, 1
end
subsection Wall plate
  set Geometry     = plate
  set Plate centre = 0, 0, 0.5
  set Plate size   = 0.2, 0.3
  set Rotation axis  = 1, 1, 0
  set Rotation angle = 30
end
subsection Wall knife
  set Geometry = chisel knife
  set Offset   = 0, 0, 0.7
  subsection Motion
    set Type       = prescribed
    set Velocities = travel: 1, 0, 0
  end
end
""",
    "stl": """solid block
facet normal 0 0 -1
 outer loop
  vertex 0 0 0
  vertex 0 1 0
  vertex 1 0 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex 0 0 1
  vertex 1 0 1
  vertex 0 1 1
 endloop
endfacet
facet normal 0 -1 0
 outer loop
  vertex 0 0 0
  vertex 1 0 0
  vertex 0 0 1
 endloop
endfacet
endsolid block
""",
    "obj": """# three triangles
v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
f 1 3 2
f 1 2 4
f 1 4 3
""",
    "ply": """ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 3
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
0 0 1
3 0 2 1
3 0 1 3
3 0 3 2
""",
    "msh": """$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
1
2 7 "bolted"
$EndPhysicalNames
$Nodes
5
1 0 0 0
2 0.1 0 0
3 0 0.1 0
4 0 0 0.1
5 0.1 0.1 0.1
$EndNodes
$Elements
3
1 4 2 1 1 1 2 3 4
2 4 2 1 1 2 3 4 5
3 2 2 7 1 1 2 3
$EndElements
""",
}

EXTREMES = ["0", "-1", "1e300", "-1e300", "nan", "inf", "2147483647", "-99", "1e-300", "x", ""]
NUMBER = re.compile(rb"-?\d+(\.\d*)?([eE][-+]?\d+)?")


def mutate(data: bytes, rng: random.Random) -> bytes:
    for _ in range(rng.randint(1, 3)):
        kind = rng.randrange(6)
        lines = data.split(b"\n")
        if kind == 0 and data:  # flip a byte
            i = rng.randrange(len(data))
            data = data[:i] + bytes([data[i] ^ (1 << rng.randrange(8))]) + data[i + 1:]
        elif kind == 1 and len(lines) > 1:  # delete a line
            del lines[rng.randrange(len(lines))]
            data = b"\n".join(lines)
        elif kind == 2 and lines:  # repeat a line
            i = rng.randrange(len(lines))
            lines[i:i] = [lines[i]] * rng.randint(1, 50)
            data = b"\n".join(lines)
        elif kind == 3:  # an extreme number
            numbers = list(NUMBER.finditer(data))
            if numbers:
                m = rng.choice(numbers)
                data = data[:m.start()] + rng.choice(EXTREMES).encode() + data[m.end():]
        elif kind == 4 and data:  # cut short
            data = data[:rng.randrange(len(data))]
        else:  # random bytes
            i = rng.randrange(len(data) + 1)
            data = data[:i] + bytes(rng.randrange(256) for _ in range(rng.randint(1, 16))) + data[i:]
    return data


def command(abrade, target, path, work):
    if target == "prm":
        return [abrade, "export-walls", path, "--output", work]
    if target in ("stl", "obj", "ply"):
        prm = os.path.join(work, "wall.prm")
        with open(prm, "w") as f:
            f.write(WALL_PRM.format(file=path))
        return [abrade, "export-walls", prm, "--output", work]
    return [abrade, "run", "--output", work, "--quiet", "--set", "Job=knife", "--set", "Knife/Geometry=file",
            "--set", f"Knife/File={path}", "--set", "Knife/Clamped faces=group bolted"]


def main():
    a = argparse.ArgumentParser()
    a.add_argument("abrade")
    a.add_argument("out")
    a.add_argument("--mutations", type=int, default=200)
    a.add_argument("--seed", type=int, default=1)
    a.add_argument("--targets", default=",".join(CORPUS))
    a.add_argument("--timeout", type=float, default=20)
    o = a.parse_args()
    shutil.rmtree(o.out, ignore_errors=True)
    os.makedirs(os.path.join(o.out, "failures"))
    rng = random.Random(o.seed)
    failures = 0
    for target in o.targets.split(","):
        seen = {0: 0, 2: 0}
        for n in range(o.mutations):
            data = mutate(CORPUS[target].encode(), rng)
            work = os.path.join(o.out, target)
            shutil.rmtree(work, ignore_errors=True)
            os.makedirs(work)
            path = os.path.join(work, "input." + target)
            with open(path, "wb") as f:
                f.write(data)
            try:
                r = subprocess.run(command(o.abrade, target, path, work), capture_output=True, timeout=o.timeout,
                                   env=dict(os.environ, OMP_NUM_THREADS="1"))
                code, tail = r.returncode, (r.stdout + r.stderr).decode(errors="replace").strip().splitlines()[-1:]
            except subprocess.TimeoutExpired:
                code, tail = "hang", ["(no answer within %g s)" % o.timeout]
            if code in (0, 2):
                seen[code] += 1
                continue
            failures += 1
            kept = os.path.join(o.out, "failures", f"{target}-{n}.{target}")
            shutil.copy(path, kept)
            print(f"FAIL {target} #{n}: exit {code}: {tail[0] if tail else ''} (input: {kept})")
        print(f"{target}: {o.mutations} mutations: {seen[0]} still valid, {seen[2]} clear errors")
    print(f"{failures} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
