#!/usr/bin/env bash
# Files that go to VTK or Gmsh, and numbers that make no sense, from the hostile-input campaign of
# issue 35: each ends in one clear error line and exit 2 within seconds, or reads right.
#  - OBJ: texture/normal index out of range (VTK crashed), NaN/inf coordinates (read as 0), a
#    vertex of two coordinates (z = 0), faces of mixed corner formats (the second kind dropped);
#  - VTP: connectivity past the points (a crash, or memory read past them), offsets broken;
#  - knife parts that are not one solid: an STL with a hole, two disjoint boxes, two boxes
#    sharing an edge, a .msh of two disjoint tetrahedra or of one tetrahedron three times, an
#    STL with inf or 1e30 in a vertex ("holds no triangles");
#  - STL with a NaN (was "zero area"), a symlink loop (an internal error), a directory, a FIFO
#    (a reader waits forever), /dev/zero (a reader reads forever), /dev/null as a mesh file;
#  - parameter files: an include bomb (time doubling per level), a byte order mark (refused
#    with an invisible character), Tonnes per cycle 1e300, a bed written outside the output
#    directory ('../x.bed'); an end-of-life limit larger than the part is warned about;
#  - compare: --tonnes nan or -1, --profile-planes nan;
#  - sweep: a misspelt --vary key, a value out of range, --seeds -1 / 1,1, --jobs -3, --wall
#    nope: refused before any run starts (no runs/ directory made).
#   check_untrusted_files.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
expect="bash $src/tests/expect_error.sh"
rm -rf "$out" && mkdir -p "$out" && cd "$out"
# a wall read from FILE, written back by export-walls
wall() { printf 'set Job = dem\nset Walls = w\nsubsection Simulation\n  set Phases = only: 0.001\nend\nsubsection Wall w\n  set Geometry = file\n  set File = %s\nend\n' "$1" > w.prm; }
tri='v 0 0 0\nv 1 0 0\nv 0 1 0\n'

printf "$tri"'f 1/9/9 2/9/9 3/9/9\n' > texture.obj && wall texture.obj
$expect 2 "texture.obj:4: texture coordinate index 9 out of range \(0 texture coordinates defined" -- timeout 30 "$abrade" export-walls w.prm --output o1
printf "$tri"'vn 0 0 1\nf 1//1 2//1 3//7\n' > normal.obj && wall normal.obj
$expect 2 "normal.obj:5: normal index 7 out of range \(1 normals" -- timeout 30 "$abrade" export-walls w.prm --output o2
printf 'v 0 0 0\nv 1 0 0\nv 0 0 nan\nf 1 2 3\n' > nan.obj && wall nan.obj
$expect 2 "nan.obj:3: vertex coordinate 'nan' is not a finite number" -- timeout 30 "$abrade" export-walls w.prm --output o3
printf 'v 0 0 0\nv 1 0 inf\nv 0 1 0\nf 1 2 3\n' > inf.obj && wall inf.obj
$expect 2 "inf.obj:2: vertex coordinate 'inf' is not a finite number" -- timeout 30 "$abrade" export-walls w.prm --output o4
printf 'v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n' > short.obj && wall short.obj
$expect 2 "short.obj:2: a vertex needs three coordinates \(x y z\), this one has 2" -- timeout 30 "$abrade" export-walls w.prm --output o5
# mixed corner formats: both faces are read (VTK dropped the second)
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 2 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\nf -3 -2/ -1\n' > mixed.obj
wall mixed.obj
$expect 0 "w.stl: 3 triangles" -- timeout 30 "$abrade" export-walls w.prm --output o6

vtp() { printf '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n<PolyData><Piece NumberOfPoints="3" NumberOfPolys="1">\n<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0</DataArray></Points>\n<Polys><DataArray type="Int64" Name="connectivity" format="ascii">%s</DataArray>\n<DataArray type="Int64" Name="offsets" format="ascii">%s</DataArray></Polys>\n</Piece></PolyData></VTKFile>\n' "$1" "$2" > "$3"; }
vtp "0 1 99999" 3 far.vtp && wall far.vtp
$expect 2 "far.vtp: point index 99999 in the polygons' connectivity \(entry 2\) is out of range \(3 points" -- timeout 30 "$abrade" export-walls w.prm --output o7
vtp "0 1 7" 3 seven.vtp && wall seven.vtp
$expect 2 "seven.vtp: point index 7 in the polygons' connectivity" -- timeout 30 "$abrade" export-walls w.prm --output o8
vtp "0 1 2" 3 good.vtp && wall good.vtp
$expect 0 "w.stl: 1 triangles" -- timeout 30 "$abrade" export-walls w.prm --output o9

sed 's/vertex 0.0 -15.0 0.0/vertex nan -15.0 0.0/' "$src/tests/cli/knife_mm.stl" > nan.stl && wall nan.stl
$expect 2 "nan.stl: point [0-9]+ \(nan, -15, 0\) has a coordinate that is not a finite number" -- timeout 30 "$abrade" export-walls w.prm --output o10
ln -s loop_b.stl loop_a.stl && ln -s loop_a.stl loop_b.stl && wall loop_a.stl
$expect 2 "loop_a.stl: is a loop of symbolic links" -- timeout 30 "$abrade" export-walls w.prm --output o11
mkdir dir.stl && wall dir.stl
$expect 2 "dir.stl: is a directory, not a file" -- timeout 30 "$abrade" export-walls w.prm --output o12
mkfifo fifo.stl && wall fifo.stl
$expect 2 "fifo.stl: is a pipe \(FIFO\), not a file" -- timeout 30 "$abrade" export-walls w.prm --output o13
wall /dev/zero
$expect 2 "/dev/zero: is a device, not a file" -- timeout 30 "$abrade" export-walls w.prm --output o14
wall /dev/null
$expect 2 "/dev/null: is a device, not a file" -- timeout 30 "$abrade" export-walls w.prm --output o15
ln -s nowhere.stl dangling.stl && wall dangling.stl
$expect 2 "dangling.stl: is a symbolic link to nothing" -- timeout 30 "$abrade" export-walls w.prm --output o16

# an include bomb: i22 includes i21 twice, ... down to i0 (2^22 inclusions)
echo "set Job = dem" > i0.prm
for k in $(seq 1 22); do printf 'include i%d.prm\ninclude i%d.prm\n' $((k - 1)) $((k - 1)) > i$k.prm; done
$expect 2 "more than 1000 files included in all" -- timeout 20 "$abrade" run i22.prm --output o_bomb
# a byte order mark (a Windows editor's) is no part of the first key
printf '\xef\xbb\xbfset Job = knife\n' > bom.prm # (knife: the part job's old name)
$expect 0 "job 'part' from bom.prm" -- timeout 60 "$abrade" run bom.prm --output o_bom

# knife parts that are not one solid: Gmsh said "No elements in volume 1", or took them
knife=(timeout 60 "$abrade" run "$src/cases/knife/lip_knife.prm" --quiet --set Job=part --set Part/Geometry=file
       --set "Part/File scale=1" --set "Part/Clamped faces=normal 0, 0, -1")
python3 - <<'PY'
def box(x0, y0, z0, x1, y1, z1):
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0), (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    f = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6),
         (3, 0, 4), (3, 4, 7)]
    return [[v[i] for i in t] for t in f]
def stl(name, triangles):
    with open(name, "w") as out:
        out.write("solid s\n")
        for t in triangles:
            out.write("facet normal 0 0 0\n outer loop\n" + "".join("  vertex %g %g %g\n" % p for p in t) +
                      " endloop\nendfacet\n")
        out.write("endsolid s\n")
stl("hole.stl", box(0, 0, 0, 0.1, 0.06, 0.02)[1:])
stl("two.stl", box(0, 0, 0, 0.1, 0.06, 0.02) + box(0.2, 0, 0, 0.3, 0.06, 0.02))
stl("edge.stl", box(0, 0, 0, 0.1, 0.06, 0.02) + box(0.1, 0.06, 0, 0.2, 0.12, 0.02))
PY
$expect 2 "hole.stl: the surface is not closed: 3 edge\(s\) belong to one triangle only" -- "${knife[@]}" --output o_hole \
  --set "Part/File=$out/hole.stl"
$expect 2 "two.stl: the surface is 2 separate closed pieces: a part is one solid" -- "${knife[@]}" --output o_two \
  --set "Part/File=$out/two.stl"
$expect 2 "edge.stl: 1 edge\(s\) are shared by more than two triangles, the first between \(0.1, 0.06, 0\) and \(0.1, 0.06, 0.02\)" \
  -- "${knife[@]}" --output o_edge --set "Part/File=$out/edge.stl"
# a knife STL with a coordinate Gmsh cannot read: it dropped the file ("holds no triangles")
sed 's/vertex 0.0 -15.0 0.0/vertex inf -15.0 0.0/' "$src/tests/cli/knife_mm.stl" > knife_inf.stl
$expect 2 "knife_inf.stl: point 0 \(inf, -15, 0\) has a coordinate that is not a finite number" -- "${knife[@]}" --output o_kinf \
  --set "Part/File=$out/knife_inf.stl" --set "Part/File scale=0.001"
sed 's/vertex 0.0 -15.0 0.0/vertex 1e30 -15.0 0.0/' "$src/tests/cli/knife_mm.stl" > knife_far.stl
$expect 2 "knife_far.stl: the part's bounding box is 1e\+27 x 0.03 x 0.5 m: a point lies far from the others" -- \
  "${knife[@]}" --output o_kfar --set "Part/File=$out/knife_far.stl" --set "Part/File scale=0.001"
nodes='$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 5 0 0\n6 6 0 0\n7 5 1 0\n8 5 0 1\n$EndNodes\n'
printf "$nodes"'$Elements\n2\n1 4 2 1 1 1 2 3 4\n2 4 2 1 1 5 6 7 8\n$EndElements\n' > disjoint.msh
$expect 2 "disjoint.msh: the mesh is in separate pieces: 1 of 2 cells share no face with cell 0" -- "${knife[@]}" \
  --output o_disjoint --set "Part/File=$out/disjoint.msh" --set "Part/Clamped faces=normal 0, 0, -1"
printf "$nodes"'$Elements\n3\n1 4 2 1 1 1 2 3 4\n2 4 2 1 1 1 2 3 4\n3 4 2 1 1 1 2 3 4\n$EndElements\n' > thrice.msh
$expect 2 "thrice.msh: cell 1 \(at \(0.25, 0.25, 0.25\)\) repeats cell 0" -- "${knife[@]}" --output o_thrice \
  --set "Part/File=$out/thrice.msh"

life=("$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --quiet)
$expect 2 "Tonnes per cycle=1e300.*Double 0...1e\+06" -- timeout 20 "${life[@]}" --output o_t --set "Lifetime/Tonnes per cycle=1e300"
# an end-of-life limit beyond the part: said, on the terminal and in the summary's warnings
$expect 0 "Lifetime/Maximum depth 1 m is more than the part's plate thickness \(0.06 m\)" -- timeout 60 "${life[@]}" \
  --output o_d --set "Lifetime/Maximum depth=1" --set "Lifetime/Maximum updates=1"
grep -q "Maximum depth 1 m is more than" o_d/summary.json || { echo "the warning is not in summary.json"; exit 1; }
$expect 0 "Lifetime/Maximum recession 5 m is more than the part's largest extent" -- timeout 60 "${life[@]}" \
  --output o_r --set "Lifetime/Maximum recession=5" --set "Lifetime/Maximum updates=1"
$expect 2 "Bed file: '../x.bed' would be written out of the output directory" -- timeout 20 "$abrade" run \
  "$src/tests/cli/small_bed.prm" --output o_bed --set "Particles/Settling/Bed file=../x.bed"
[[ ! -e x.bed ]] || { echo "a bed was written outside the output directory"; exit 1; }

cmp=("$abrade" compare --predicted "$src/tests/cli/knife_mm.stl" --scan "$src/tests/cli/knife_mm.stl" --output o_c)
$expect 2 "--tonnes: 'nan' is not a finite number" -- "${cmp[@]}" --tonnes nan
$expect 2 "--tonnes: the tonnes handled must be positive, got -1" -- "${cmp[@]}" --tonnes -1
$expect 2 "--profile-planes: 'nan' is not a finite number" -- "${cmp[@]}" --profile-planes 0.1,nan

kb=$src/cases/knife_bed/knife_bed.prm
sweep=(timeout 60 "$abrade" sweep "$kb" --output o_sweep)
$expect 2 "sweep run 1-seed1: .*Nope" -- "${sweep[@]}" --vary "Nope/Key=1,2" --seeds 1
$expect 2 "sweep run 0.5_7-seed1|sweep run 7-seed1: .*Restitution" -- "${sweep[@]}" --vary "Wall knife/Interaction/Restitution=0.5,7" --seeds 1
$expect 2 "--seeds: a seed is 0 or more, got -1" -- "${sweep[@]}" --vary "Wall knife/Interaction/Friction=0,0.1" --seeds -1
$expect 2 "--seeds: seed 1 is given twice" -- "${sweep[@]}" --vary "Wall knife/Interaction/Friction=0,0.1" --seeds 1,1
$expect 2 "--jobs must be 0 \(one per core\) or more, got -3" -- "${sweep[@]}" --vary "Wall knife/Interaction/Friction=0,0.1" --jobs -3
$expect 2 "--wall nope: no such wall in the case" -- "${sweep[@]}" --vary "Wall knife/Interaction/Friction=0,0.1" --wall nope
$expect 2 "--vary 'Part/Length' is given twice \\(as 'Knife/Length'\\)" -- "${sweep[@]}" --vary "Knife/Length=0.3,0.4" --vary "Part/Length=0.5,0.6"
$expect 2 "--vary 'Wall knife/Wear/Archard/Coefficient' is given twice" -- "${sweep[@]}" \
  --vary "Wall knife/Wear/Archard coefficient=1e-12,2e-12" --vary "Wall knife/Wear/Archard/Coefficient=3e-12"
[[ ! -e o_sweep/runs ]] || { echo "a sweep with bad input started runs"; exit 1; }
echo "untrusted files: all refused or read right"
