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
  vtk   a wall's legacy VTK polydata (ASCII)                     abrade export-walls
  msh   the knife as a Gmsh .msh volume mesh (two tetrahedra)    abrade run (Job = part)
  step  the knife as a STEP block in mm (abrade convert)         abrade run (Job = part)
  xyz   a point-cloud scan                                       abrade compare
  vtp   a surface scan (VTK XML, ASCII)                          abrade compare
  scan.stl, scan.ply, scan.obj: surface scans                    abrade compare
  wall.vtp, wall.vtu: a wall's VTK XML surface / volume          abrade export-walls
  knife.stl: the knife as a closed STL box (Gmsh meshes it)      abrade run (Job = part)
  csv   a measurement table                                      abrade calibrate
  pvd   a lifetime run's part.pvd                                abrade calibrate
  bed   a settled bed (binary, with its checksum)                abrade run (Job = dem)
The targets that need a lifetime run (xyz, vtp, csv, pvd) share one small analytic run, made
first (a few seconds).
Mutations (several per input): a flipped byte, a line deleted or repeated, a number replaced by
an extreme one (0, -1, 1e300, nan, inf, 2147483647, -99, 1e-300, a word), the file cut short,
random bytes inserted. The random seed makes a run reproducible.

    fuzz.py ABRADE OUTDIR [--mutations N] [--seed S] [--targets prm,stl,...] [--timeout SECONDS]
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

VTK_CORPUS = {
    "vtk": """# vtk DataFile Version 3.0
a wall
ASCII
DATASET POLYDATA
POINTS 4 float
0 0 0 1 0 0 0 1 0 0 0 1
POLYGONS 3 12
3 0 2 1
3 0 1 3
3 0 3 2
""",
    "vtp": """<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
  <PolyData>
    <Piece NumberOfPoints="4" NumberOfPolys="4">
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="ascii">
          0.05 0.015 0.05  0.1 0.015 0.05  0.075 0.015 0.1  0.075 0.0 0.075
        </DataArray>
      </Points>
      <Polys>
        <DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 0 3 1 1 3 2 2 3 0</DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">3 6 9 12</DataArray>
      </Polys>
    </Piece>
  </PolyData>
</VTKFile>
""",
}
CORPUS.update(VTK_CORPUS)
CORPUS["xyz"] = "x y z\n" + "".join(f"{0.05 + 0.01 * i:.3f} 0.015 {0.05 + 0.005 * i:.4f}\n" for i in range(12))
# beds of other codes (Particles/Settling/Bed file): a LIGGGHTS dump and a CSV table
CORPUS["dump"] = ("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n0\nITEM: BOX BOUNDS ff ff ff\n-1 1\n-1 1\n0 1\n"
                  "ITEM: ATOMS id type x y z vx vy vz radius\n"
                  "ITEM: TIMESTEP\n5000\nITEM: NUMBER OF ATOMS\n3\nITEM: BOX BOUNDS ff ff ff\n-1 1\n-1 1\n0 1\n"
                  "ITEM: ATOMS id type x y z vx vy vz radius\n"
                  "1 1 0 0 0.0275 0 0 0 0.0275\n2 1 0.06 0 0.0275 0 0 -0.1 0.0275\n3 1 0 0.06 0.08 0 0 0 0.0275\n")
CORPUS["bed.csv"] = "id,x,y,z,diameter,vz\n1,0,0,0.0275,0.055,0\n2,0.06,0,0.0275,0.055,-0.1\n3,0,0.06,0.08,0.055,0\n"
# walls read from VTK XML (a VTP surface, the outer surface of a VTU), the knife as a closed STL
# (meshed by Gmsh in abrade-mesher), and scans as STL, PLY and OBJ surfaces
CORPUS["wall.vtp"] = CORPUS["vtp"]
CORPUS["wall.vtu"] = """<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
  <UnstructuredGrid>
    <Piece NumberOfPoints="4" NumberOfCells="1">
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1</DataArray>
      </Points>
      <Cells>
        <DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3</DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">4</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">10</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
"""
_box = [(0, 0, 0), (0.1, 0, 0), (0.1, 0.06, 0), (0, 0.06, 0), (0, 0, 0.02), (0.1, 0, 0.02), (0.1, 0.06, 0.02), (0, 0.06, 0.02)]
_faces = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6),
          (3, 0, 4), (3, 4, 7)]
CORPUS["knife.stl"] = "solid box\n" + "".join(
    "facet normal 0 0 0\n outer loop\n" + "".join("  vertex %g %g %g\n" % _box[i] for i in f) + " endloop\nendfacet\n"
    for f in _faces) + "endsolid box\n"
_scan = [(0.05, 0.015, 0.05), (0.1, 0.015, 0.05), (0.075, 0.015, 0.1), (0.075, 0.0, 0.075)]
CORPUS["scan.stl"] = "solid scan\n" + "".join(
    "facet normal 0 0 0\n outer loop\n" + "".join("  vertex %g %g %g\n" % _scan[i] for i in f) + " endloop\nendfacet\n"
    for f in [(0, 1, 2), (0, 3, 1), (1, 3, 2), (2, 3, 0)]) + "endsolid scan\n"
CORPUS["scan.ply"] = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face 4\nproperty list uchar int vertex_indices\nend_header\n" +
                      "".join("%g %g %g\n" % p for p in _scan) + "3 0 1 2\n3 0 3 1\n3 1 3 2\n3 2 3 0\n")
CORPUS["scan.obj"] = "".join("v %g %g %g\n" % p for p in _scan) + "f 1 2 3\nf 1 4 2\nf 2 4 3\nf 3 4 1\n"
TARGETS = ("prm", "stl", "obj", "ply", "vtk", "wall.vtp", "wall.vtu", "msh", "step", "knife.stl", "xyz", "vtp",
           "scan.stl", "scan.ply", "scan.obj", "csv", "pvd", "bed", "dump", "bed.csv")
IMPORTED = ("dump", "bed.csv")
BINARY = ("bed",)
MADE = ("step", "xyz", "vtp", "scan.stl", "scan.ply", "scan.obj", "csv", "pvd", "bed")  # need the Fixtures



class Fixtures:
    """What the targets that are not plain text share: a small analytic lifetime run (its worn
    knife, its part.pvd, a measurement table from its trajectory), a STEP block, a bed."""

    def __init__(self, abrade, out, source):
        self.abrade, self.dir, self.source = abrade, os.path.join(out, "fixtures"), source
        self.made = False

    def make(self):
        if self.made:
            return
        self.made = True
        d = self.dir
        os.makedirs(d, exist_ok=True)
        run = lambda *a: subprocess.run([self.abrade, *a], check=True, capture_output=True,
                                        env=dict(os.environ, OMP_NUM_THREADS="1"))
        self.run = os.path.join(d, "run")
        run("run", os.path.join(self.source, "tests/lifetime/analytic_uniform.prm"), "--quiet", "--output", self.run,
            "--set", "Lifetime/Maximum updates=2")
        self.worn = os.path.join(self.run, "part", "part_00002.stl")
        rows = open(os.path.join(self.run, "trajectory.csv")).read().splitlines()
        header = rows[0].split(",")
        t, dep = header.index("tonnes"), header.index("point_depth")
        CORPUS["csv"] = "x,y,z,tonnes,depth\n" + "".join(
            "0.075,0.015,0.06,%s,%s\n" % (r.split(",")[t], r.split(",")[dep]) for r in rows[1:])
        self.table = os.path.join(d, "measurements.csv")
        open(self.table, "w").write(CORPUS["csv"])
        CORPUS["pvd"] = open(os.path.join(self.run, "part", "part.pvd")).read()
        geo = os.path.join(d, "block.geo")
        open(geo, "w").write('SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 100, 60, 20};\n')
        run("convert", geo, "--output", os.path.join(d, "block.step"))
        CORPUS["step"] = open(os.path.join(d, "block.step")).read()
        run("run", os.path.join(self.source, "tests/cli/small_bed.prm"), "--quiet", "--output", os.path.join(d, "bed"))
        CORPUS["bed"] = open(os.path.join(d, "bed", "bed.bed"), "rb").read()


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


def command(abrade, target, path, work, fixtures):
    if target == "prm":
        return [abrade, "export-walls", path, "--output", work]
    if target in ("stl", "obj", "ply", "vtk", "wall.vtp", "wall.vtu"):
        prm = os.path.join(work, "wall.prm")
        with open(prm, "w") as f:
            f.write(WALL_PRM.format(file=path))
        return [abrade, "export-walls", prm, "--output", work]
    if target in ("xyz", "vtp", "scan.stl", "scan.ply", "scan.obj"):
        return [abrade, "compare", "--predicted", fixtures.worn, "--scan", path, "--output", os.path.join(work, "c")]
    if target == "csv":
        return [abrade, "calibrate", "--run", fixtures.run, "--measurements", path, "--output", os.path.join(work, "c")]
    if target == "pvd":  # the run's part outputs, under a mutated part.pvd
        run = os.path.join(work, "run")
        os.makedirs(os.path.join(run, "part"))
        for name in os.listdir(os.path.join(fixtures.run, "part")):
            if name.endswith(".vtu"):
                os.symlink(os.path.join(fixtures.run, "part", name), os.path.join(run, "part", name))
        shutil.copy(os.path.join(fixtures.run, "summary.json"), run)
        shutil.copy(path, os.path.join(run, "part", "part.pvd"))
        return [abrade, "calibrate", "--run", run, "--measurements", fixtures.table, "--output", os.path.join(work, "c")]
    if target in ("bed", "dump", "bed.csv"):
        return [abrade, "run", os.path.join(fixtures.source, "tests/cli/small_bed.prm"), "--quiet", "--output",
                os.path.join(work, "o"), "--set", f"Particles/Settling/Bed file={path}"]
    clamped = "group bolted" if target == "msh" else "normal 0, 0, -1" if target == "knife.stl" else "normal 0, 0, 1"
    return [abrade, "run", "--output", work, "--quiet", "--set", "Job=part", "--set", "Part/Geometry=file",
            "--set", f"Part/File={path}", "--set", f"Part/Clamped faces={clamped}"]


def main():
    a = argparse.ArgumentParser()
    a.add_argument("abrade")
    a.add_argument("out")
    a.add_argument("--mutations", type=int, default=200)
    a.add_argument("--seed", type=int, default=1)
    a.add_argument("--targets", default=",".join(TARGETS))
    a.add_argument("--timeout", type=float, default=20)
    o = a.parse_args()
    o.out = os.path.abspath(o.out)
    shutil.rmtree(o.out, ignore_errors=True)
    os.makedirs(os.path.join(o.out, "failures"))
    fixtures = Fixtures(os.path.abspath(o.abrade), o.out, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
    rng = random.Random(o.seed)
    failures = 0
    for target in o.targets.split(","):
        if target in MADE:
            fixtures.make()
        seen = {0: 0, 2: 0}
        valid = CORPUS[target] if target in BINARY else CORPUS[target].encode()
        for n in range(o.mutations):
            data = mutate(valid, rng)
            work = os.path.join(o.out, target)
            shutil.rmtree(work, ignore_errors=True)
            os.makedirs(work)
            path = os.path.join(work, "input." + target)
            with open(path, "wb") as f:
                f.write(data)
            try:
                r = subprocess.run(command(o.abrade, target, path, work, fixtures), capture_output=True, timeout=o.timeout,
                                   env=dict(os.environ, OMP_NUM_THREADS="1"))
                code, tail = r.returncode, (r.stdout + r.stderr).decode(errors="replace").strip().splitlines()[-1:]
            except subprocess.TimeoutExpired:
                code, tail = "hang", ["(no answer within %g s)" % o.timeout]
            # a bed of another code may hold what only the run finds (pellets overlapping by
            # several radii, a pellet thrown out of the domain): a run failure that says so (exit 3)
            if code in (0, 2) or (code == 3 and target in IMPORTED and tail and tail[0].startswith("abrade: run failed:")):
                seen[min(code, 2)] += 1
                continue
            failures += 1
            kept = os.path.join(o.out, "failures", f"{target}-{n}.{target}")
            shutil.copy(path, kept)
            print(f"FAIL {target} #{n}: exit {code}: {tail[0] if tail else ''} (input: {kept})", flush=True)
        print(f"{target}: {o.mutations} mutations: {seen[0]} still valid, {seen[2]} clear errors"
              f"{' (or run failures)' if target in IMPORTED else ''}", flush=True)
    print(f"{failures} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
