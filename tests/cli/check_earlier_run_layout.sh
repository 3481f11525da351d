#!/usr/bin/env bash
# A run directory an abrade before the part's rename wrote (issue 37): the part's files in
# knife/ (knife/knife.pvd, knife_NNNNN.vtu and .stl), parameters.prm with `subsection Knife`
# in its sorted place, and a part job's summary.json with job "knife" and results.knife. Made
# here from runs of this abrade by renaming their files back, then:
#  - `abrade report` draws the worn part from knife/ and writes knife/open_in_paraview.py;
#  - `abrade calibrate` fits the same rate on it as on the run as written;
#  - `--resume` goes on in knife/ (knife/knife_00003.stl, no part/ folder), with the
#    trajectory of the run that was not interrupted; a fresh run there writes part/;
#  - `run DIR/parameters.prm --output DIR` with the old names reruns it (it was refused as
#    edited);
#  - the part job's directory gets its preview.
# Each fails with io::part_folder answering "part" only, or earlier_printings left out of run.
#   check_earlier_run_layout.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$(realpath "$1") src=$2 out=$3
expect="bash $src/tests/expect_error.sh"
rm -rf "$out" && mkdir -p "$out" && cd "$out"
life=("$abrade" run "$src/tests/lifetime/analytic_edge.prm" --quiet)

# the part's folder and files as an earlier abrade named them
to_knife_layout() {
  mv "$1/part" "$1/knife"
  for f in "$1"/knife/part*; do mv "$f" "$1/knife/knife${f##*/part}"; done
  sed -i 's/file="part_/file="knife_/' "$1/knife/knife.pvd"
}
# parameters.prm as the earliest abrade that still reads back printed it (written here, apart
# from abrade's own earlier_printings): subsection Knife for Part; the wear sources' entries flat
# in Lifetime (Analytic wear rate, ..., Replay run, Ranks per bed); Knife mount and Knife
# protrusion; every wall's Motion with its velocity table (a fixed wall's empty); no Fine region
# pours. deal.II's print:
# entries, then subsections, each sorted by its mangled name, the keys padded to the longest.
with_knife_subsection() {
  python3 - "$1" <<'PY'
import re, sys
def mangled(s):
    return "".join(c if c.isascii() and c.isalnum() else "_%02x" % ord(c) for c in s)
def read(lines):
    top = {"entries": {}, "subs": {}}; stack = [top]
    for l in lines:
        t = l.strip()
        if t.startswith("subsection "):
            stack.append(stack[-1]["subs"].setdefault(t[11:], {"entries": {}, "subs": {}}))
        elif t == "end":
            stack.pop()
        elif t.startswith("set "):
            key, value = l.split(" = ", 1)
            stack[-1]["entries"][key.strip()[4:].strip()] = value
    return top
def write(s, indent, out):
    width = max([len(k) for k in s["entries"]] or [0])
    for k in sorted(s["entries"], key=mangled):
        out.append(indent + "set " + k.ljust(width) + " = " + s["entries"][k])
    for name in sorted(s["subs"], key=mangled):
        out.append(indent + "subsection " + name); write(s["subs"][name], indent + "  ", out); out.append(indent + "end")
top = read(open(sys.argv[1]).read().split("\n"))
top["subs"]["Knife"] = top["subs"].pop("Part")
life = top["subs"]["Lifetime"]
for sub, key, old in [("Analytic", "Wear rate", "Analytic wear rate"), ("Analytic", "Wear is", "Analytic wear is"),
                      ("Analytic", "Seed scatter", "Analytic seed scatter"), ("Replay", "Run", "Replay run"),
                      ("DEM", "Ranks per bed", "Ranks per bed")]:
    life["entries"][old] = life["subs"][sub]["entries"].pop(key)
for sub in ("Analytic", "Replay", "DEM"):
    del life["subs"][sub]
for name, wall in top["subs"].items():
    if name.startswith("Wall "):
        for key, old in [("Mounted on", "Knife mount"), ("Protrusion", "Knife protrusion")]:
            if key in wall["entries"]:
                wall["entries"][old] = wall["entries"].pop(key)
        motion = wall["subs"]["Motion"]["entries"]
        motion.setdefault("Velocities", "penetration: 0, 0, -1.5; travel: 1.5, 0, 0" if name == "Wall knife" else "")
        motion.setdefault("Angular velocities", "")
cg = top["subs"]["Particles"]["subs"]["Coarse graining"]["entries"] # (Fine region pours came later)
if cg.get("Fine region pours") == "3":
    del cg["Fine region pours"]
out = []
write(top, "", out)
open(sys.argv[1], "w").write("\n".join(out) + "\n")
PY
}

three=(--set "Lifetime/Maximum updates=3")
"${life[@]}" --output new "${three[@]}" > /dev/null
cp new/trajectory.csv whole.csv && cp new/part/part_00003.stl whole_00003.stl
rm new/checkpoint/*-3.* # (as if killed in the last update)
cp -r new old && to_knife_layout old && with_knife_subsection old/parameters.prm
grep -q "^subsection Knife" old/parameters.prm || { echo "no subsection Knife in the made-old parameters.prm"; exit 1; }

# report
rm -rf old/report old/report.html
"$abrade" report old > /dev/null
grep -q 'data-figure="part"' old/report.html || { echo "the report of the knife/ layout draws no worn part"; exit 1; }
! grep -q 'data-missing-figure' old/report.html || { echo "the report of the knife/ layout misses a figure"; exit 1; }
[[ -s old/knife/open_in_paraview.py && ! -e old/part ]] || { echo "the ParaView script is not in knife/"; exit 1; }
grep -q "'knife.pvd'" old/knife/open_in_paraview.py || { echo "the ParaView script does not open knife.pvd"; exit 1; }

# calibrate: the same fit on both layouts
python3 - <<'PY'
import csv
rows = list(csv.DictReader(open("whole.csv")))
points = [[0.075, 0.015, 0.06], [0.075, 0.015, 0.1], [0.075, -0.015, 0.15]]
with open("measured.csv", "w") as f:
    f.write("x,y,z,tonnes,depth\n")
    for r in rows[1:3]:
        for k, p in enumerate(points):
            f.write(f"{p[0]},{p[1]},{p[2]},{r['tonnes']},{r['point_depth' if k == 0 else f'point_depth_{k + 1}']}\n")
PY
"$abrade" calibrate --run new --measurements measured.csv --output cal_new > /dev/null
"$abrade" calibrate --run old --measurements measured.csv --output cal_old > /dev/null
python3 - <<'PY'
import json
a, b = json.load(open("cal_new/calibration.json")), json.load(open("cal_old/calibration.json"))
def numbers(j, path=""):
    if isinstance(j, dict):
        return {k2: v2 for k, v in j.items() for k2, v2 in numbers(v, path + "/" + k).items()}
    if isinstance(j, list):
        return {k2: v2 for i, v in enumerate(j) for k2, v2 in numbers(v, path + f"[{i}]").items()}
    return {path: j} if isinstance(j, (int, float)) and not isinstance(j, bool) else {}
na, nb = numbers(a), numbers(b)
if not na or na != nb:
    raise SystemExit(f"calibrate on the knife/ layout differs: {sorted(set(na.items()) ^ set(nb.items()))[:6]}")
PY

# resume: on in knife/
rm old/knife/knife_00003.*
$expect 0 "Resuming after update 2" -- "${life[@]}" --output old "${three[@]}" --resume
[[ -s old/knife/knife_00003.stl && -s old/knife/knife_00003.vtu && ! -e old/part ]] ||
  { echo "the resumed run did not go on in knife/"; ls old old/knife; exit 1; }
cmp whole.csv old/trajectory.csv
cmp whole_00003.stl old/knife/knife_00003.stl

# a fresh run (no --resume) in that directory writes part/, the earlier knife/ left as it was
cp -r old fresh && rm -f fresh/report.html
"${life[@]}" --output fresh "${three[@]}" > /dev/null
[[ -s fresh/part/part_00003.stl ]] || { echo "a fresh run in an earlier abrade's directory did not write part/"; exit 1; }
cmp old/knife/knife_00003.stl fresh/knife/knife_00003.stl
grep -q 'data-figure="part"' fresh/report.html || { echo "the fresh run's report draws no worn part"; exit 1; }

# the run's own parameters.prm under the old names: rerun as it is, the file kept
"${life[@]}" --output own --set "Lifetime/Maximum updates=1" > /dev/null
with_knife_subsection own/parameters.prm && cp own/parameters.prm own_before.prm
"$abrade" run own/parameters.prm --output own --quiet > /dev/null
cmp own/parameters.prm own_before.prm

# a part job's directory as the knife job wrote it: its preview
"$abrade" run "$src/cases/knife/lip_knife.prm" --output job --quiet > /dev/null
to_knife_layout job
sed -i 's/"job": "part"/"job": "knife"/; s/"part": {/"knife": {/' job/summary.json
grep -q '"knife": {' job/summary.json || { echo "no results.knife in the made-old summary.json"; exit 1; }
rm -rf job/report job/report.html
"$abrade" report job > /dev/null
grep -q 'data-figure="faces"' job/report.html || { echo "no preview of the knife job's directory"; exit 1; }
echo "an earlier abrade's run directory: reported, calibrated, resumed and rerun in its own layout"
