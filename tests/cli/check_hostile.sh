#!/usr/bin/env bash
# Hostile inputs end in one clear error line and exit 2, within seconds (no crash, no hang):
# a wall OBJ whose face points past its vertices, a PLY whose header announces more vertices than
# it holds, a 5 MB parameter value, thousands of walls, a knife checkpoint with one byte changed,
# and a stray checkpoint of update 999999999999 (counting down to it took years).
#   check_hostile.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
expect="bash $src/tests/expect_error.sh"
rm -rf "$out" && mkdir -p "$out" && cd "$out"
wall() { printf 'set Job = dem\nset Walls = w\nsubsection Wall w\n  set Geometry = file\n  set File = %s\nend\n' "$1" > "$2"; }
wall "$src/tests/cli/bad_index.obj" obj.prm
$expect 2 "bad_index.obj:5: vertex index 2147483647 out of range \(3 vertices" -- "$abrade" run obj.prm --output o1
wall "$src/tests/cli/truncated.ply" ply.prm
$expect 2 "truncated.ply: the header announces 9 vertices and faces, the file holds 4" -- "$abrade" run ply.prm --output o2
python3 -c "open('long.prm','w').write('set Job = knife\nsubsection Knife\n  set Length = ' + '1' * 5000000 + '\nend\n')"
$expect 2 "long.prm:3: a line of 5000015 characters, more than 20000" -- timeout 20 "$abrade" run long.prm --output o3
python3 -c "open('walls.prm','w').write('set Job = dem\nset Walls = ' + ','.join('w%d' % i for i in range(3000)) + '\n')"
$expect 2 "Walls: 3000 walls listed, more than 1000" -- timeout 20 "$abrade" run walls.prm --output o4
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
