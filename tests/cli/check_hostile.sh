#!/usr/bin/env bash
# Hostile inputs end in one clear error line and exit 2, within seconds (no crash, no hang):
# a wall OBJ whose face points past its vertices, a PLY whose header announces more vertices than
# it holds, a 5 MB parameter value, thousands of walls, .msh files of garbage, with a missing
# node or without volume elements, an STL with a NaN coordinate, a time step of 1e-9 s or a density
# of 1e-12 (runs of years: refused with the estimate), 1e9 particles (more memory than there is),
# a knife checkpoint with one byte changed, a stray checkpoint of update 999999999999
# (counting down to it took years), garbage in trajectory.csv before --resume (rebuilt from the
# checkpoint), a profile line of garbage, a loop state changed by hand, a bed file cut short, a
# knife STL with a zero-area triangle (removed, said), STEP files with a misspelt entity type or
# an entity defined twice (OpenCASCADE crashed on both).
#   check_hostile.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
expect="bash $src/tests/expect_error.sh"
rm -rf "$out" && mkdir -p "$out" && cd "$out"
wall() { printf 'set Job = dem\nset Walls = w\nsubsection Wall w\n  set Geometry = file\n  set File = %s\nend\n' "$1" > "$2"; }
wall "$src/tests/cli/bad_index.obj" obj.prm
$expect 2 "bad_index.obj:5: vertex index 2147483647 out of range \(3 vertices" -- "$abrade" run obj.prm --output o1
wall "$src/tests/cli/truncated.ply" ply.prm
$expect 2 "truncated.ply: the header announces 8 vertex elements, the file ends at vertex 4" -- "$abrade" run ply.prm --output o2
python3 -c "open('long.prm','w').write('set Job = part\nsubsection Part\n  set Length = ' + '1' * 5000000 + '\nend\n')"
$expect 2 "long.prm:3: a line of 5000015 characters, more than 20000" -- timeout 20 "$abrade" run long.prm --output o3
python3 -c "open('walls.prm','w').write('set Job = dem\nset Walls = ' + ','.join('w%d' % i for i in range(3000)) + '\n')"
$expect 2 "Walls: 3000 walls listed, more than 1000" -- timeout 20 "$abrade" run walls.prm --output o4
# runs of years, or of more memory than there is, refused before the bed is generated
kb=$src/cases/knife_bed/knife_bed.prm
$expect 2 "Simulation/Maximum particle-steps: one run needs about 1.72e\+13 particle-steps \(1.05e\+04 particles x 1.64e\+09 steps of 1e-09 s" \
  -- timeout 20 "$abrade" run "$kb" --output o_dt --set "Simulation/Time step=1e-9"
$expect 2 "Simulation/Maximum particle-steps: one run needs about 9.14e\+15 particle-steps" \
  -- timeout 20 "$abrade" run "$kb" --output o_rho --set "Particles/Material/Density=1e-12"
$expect 2 "Particles/Generation/Count: about 1e\+09 particles need about 1e\+03 GB, this machine has" \
  -- timeout 20 "$abrade" run "$kb" --output o_n --set "Particles/Generation/Count=1000000000" \
  --set "Simulation/Maximum particle-steps=0"
# a wall refined to edges of 0.1 mm: billions of triangles, refused with the count
printf 'set Job = dem\nset Walls = w\nsubsection Wall w\n  set Geometry = box\n  set Maximum edge length = 1e-4\nend\n' > refine.prm
$expect 2 "refine.prm:5: Wall w/Maximum edge length: refining the wall's 10 triangles to edges of .* makes about 2771362586 triangles" \
  -- timeout 20 "$abrade" run refine.prm --output o_refine
# solids: a .msh of garbage, one whose cell names a missing node, one with no volume elements,
# an STL with a coordinate that is not a number (Gmsh looped forever)
knife=("$abrade" run "$src/cases/knife/lip_knife.prm" --quiet --set Job=part --set Part/Geometry=file
       --set "Part/File scale=0.001")
printf 'garbage\n' > garbage.msh
$expect 2 "garbage.msh: Gmsh could not read it: .*line 1: syntax error" -- "${knife[@]}" --output o_garbage.msh --set "Part/File=$out/garbage.msh"
nodes='$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n'
printf "$nodes"'$Elements\n1\n1 4 2 1 1 1 2 3 9\n$EndElements\n' > missing_node.msh
$expect 2 "missing_node.msh: Gmsh could not read it: Wrong node index 9" -- "${knife[@]}" --output o_missing_node.msh --set "Part/File=$out/missing_node.msh"
printf "$nodes"'$Elements\n1\n1 2 2 1 1 1 2 3\n$EndElements\n' > surface_only.msh
$expect 2 "surface_only.msh: the mesh holds no volume elements" -- "${knife[@]}" --output o_surface_only.msh --set "Part/File=$out/surface_only.msh"
sed 's/vertex 0.0 -15.0 0.0/vertex nan -15.0 0.0/' "$src/tests/cli/knife_mm.stl" > nan.stl
$expect 2 "nan.stl: point [0-9]+ \(nan, -15, 0\) has a coordinate that is not a finite number" -- timeout 30 "${knife[@]}" \
  --output o_nan --set "Part/File=$out/nan.stl"
prm=$src/tests/lifetime/analytic_uniform.prm
"$abrade" run "$prm" --output life --quiet --set "Lifetime/Maximum updates=2" > /dev/null
python3 -c "
d = bytearray(open('life/checkpoint/knife-2.ckpt', 'rb').read()); d[len(d) // 2] ^= 0x55
open('life/checkpoint/knife-2.ckpt', 'wb').write(d)"
$expect 2 "knife-2.ckpt: corrupt knife checkpoint \(its checksum does not match" -- \
  "$abrade" run "$prm" --output life --quiet --set "Lifetime/Maximum updates=2" --resume
touch life/checkpoint/loop-999999999999.txt
$expect 0 "Done" -- timeout 60 "$abrade" run "$prm" --output life --set "Lifetime/Maximum updates=1"
[[ ! -e life/checkpoint/loop-999999999999.txt ]] || { echo "the stray checkpoint was not cleared"; exit 1; }
# resume after edits: trajectory.csv is rebuilt from the checkpoint (garbage there or an emptied
# file cannot leak into the result: byte-identical to the uninterrupted run); a profile line of
# garbage and a loop state changed by hand are named; a cut bed file is named
resume() { "$abrade" run "$prm" --output "$1" --quiet --set "Lifetime/Maximum updates=3" "${@:2}"; }
resume whole > /dev/null
resume edited > /dev/null
rm edited/checkpoint/*-3.*
printf 'update,garbage\n1,%%%%,x\n' > edited/trajectory.csv
echo "12 0.1" >> edited/part/profile_0.50.csv # an append cut by a crash: dropped
resume edited --resume > /dev/null
cmp whole/trajectory.csv edited/trajectory.csv
cmp whole/part/profile_0.50.csv edited/part/profile_0.50.csv
rm edited/checkpoint/*-3.*
sed -i '3s/.*/zz 1 2 3 4/' edited/part/profile_0.50.csv
$expect 2 "edited/part/profile_0.50.csv:3: not a profile line" -- "$abrade" run "$prm" --output edited --quiet --set "Lifetime/Maximum updates=3" --resume
sed -i 's/^tonnes = .*/tonnes = 2999.5/' edited/checkpoint/loop-2.txt
$expect 2 "edited/checkpoint/loop-2.txt: corrupt state file \(its checksum does not match" -- "$abrade" run "$prm" --output edited --quiet --set "Lifetime/Maximum updates=3" --resume
"$abrade" run "$src/tests/cli/small_bed.prm" --output bed --quiet > /dev/null
head -c 500 bed/bed.bed > cut.bed && mv cut.bed bed/bed.bed
$expect 2 "bed/bed.bed: corrupt bed file: it announces 20 particles, its size of 500 bytes" -- "$abrade" run "$src/tests/cli/small_bed.prm" --output bed --quiet
# a knife STL with a zero-area triangle and one of height 1e-10 (Gmsh threw inside a parallel
# region: abort): removed, said
python3 - <<'PY'
v = [(0, 0, 0), (0.1, 0, 0), (0.1, 0.06, 0), (0, 0.06, 0), (0, 0, 0.02), (0.1, 0, 0.02), (0.1, 0.06, 0.02), (0, 0.06, 0.02)]
faces = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6),
         (3, 0, 4), (3, 4, 7)]
tri = lambda *p: "facet normal 0 0 0\n outer loop\n" + "".join("  vertex %g %g %g\n" % q for q in p) + " endloop\nendfacet\n"
open("sliver.stl", "w").write("solid b\n" + "".join(tri(*(v[i] for i in f)) for f in faces) +
                              tri(v[0], v[1], (0.05, 0, 0)) + tri(v[1], v[0], (0.05, 1e-10, 0)) + "endsolid b\n")
PY
$expect 0 "sliver.stl: 2 triangle\(s\) of zero area removed" -- "${knife[@]}" --output o_sliver --set "Part/File=$out/sliver.stl" \
  --set "Part/Clamped faces=normal 0, 0, 1" --set "Part/File scale=1"
# a STEP file with an entity of a misspelt type, or an entity defined twice (OpenCASCADE crashed
# after Gmsh imported it): the entity named
printf 'SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 100, 60, 20};\n' > block.geo
"$abrade" convert block.geo --output block.step > /dev/null
# (a script runs where it is; the mesher's notes and log beside its output go when it is done)
if ls block.step.* > /dev/null 2>&1; then echo "left beside block.step: $(ls block.step.*)"; exit 1; fi
sed '0,/= DIRECTION(/s//= DIRUCTION(/' block.step > misspelt.step
$expect 2 "misspelt.step: [0-9]+ entit(y|ies) failed to read \(entity #[0-9]+" -- "${knife[@]}" --output o_misspelt \
  --set "Part/File=$out/misspelt.step" --set "Part/Clamped faces=normal 0, 0, 1"
awk '/= DIRECTION\(/ && !done { print; done = 1 } { print }' block.step > twice.step
$expect 2 "twice.step: [0-9]+ entit(y|ies) failed to read \(Ident defined SEVERAL TIMES : #[0-9]+" -- "${knife[@]}" \
  --output o_twice --set "Part/File=$out/twice.step" --set "Part/Clamped faces=normal 0, 0, 1"
# a STEP point at 1e30 (Gmsh's search tree asserted: abort; at 1e18 it looped)
sed "0,/CARTESIAN_POINT('',(\([^,]*\),/s//CARTESIAN_POINT('',(1.E30,/" block.step > far.step
$expect 2 "far.step: coordinates up to 1e\+30 mm" -- "${knife[@]}" --output o_far --set "Part/File=$out/far.step" \
  --set "Part/Clamped faces=normal 0, 0, 1"
echo "hostile inputs: all refused"
