#!/usr/bin/env bash
# Signals end a run at once, with a line saying so, summary.json status "interrupted" and exit
# 128 + the signal: SIGTERM while Gmsh meshes a part (Gmsh's own handlers ignored it before),
# SIGHUP (a closed terminal) during a lifetime run.
#   check_signals.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out" && cd "$out"
interrupted() {
  local rc=$1 want=$2 dir=$3
  [[ $rc == "$want" ]] || { echo "$dir: exit $rc, expected $want"; cat "$dir.out"; exit 1; }
  grep -q "abrade: interrupted" "$dir.out" || { echo "$dir: no message"; exit 1; }
  python3 -c "import json, sys; s = json.load(open(sys.argv[1]))['status']; assert s.startswith('interrupted'), s" \
    "$dir/summary.json"
}
# a block meshed at 2 mm (about 1e5 tetrahedra: several seconds in Gmsh)
printf 'SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 100, 60, 20};\n' > block.geo
"$abrade" convert block.geo --output block.step > /dev/null
"$abrade" run "$src/cases/knife/lip_knife.prm" --quiet --set Job=part --set Part/Geometry=file \
  --set "Part/File=$out/block.step" --set "Part/Clamped faces=normal 0, 0, 1" --set "Part/Mesh size=0.002" \
  --output mesh > mesh.out 2>&1 &
pid=$!
sleep 2
kill -TERM $pid
start=$(date +%s)
rc=0; wait $pid || rc=$?
(( $(date +%s) - start <= 3 )) || { echo "SIGTERM during meshing took $(( $(date +%s) - start )) s"; exit 1; }
interrupted $rc 143 mesh

"$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --quiet --output life --set "Lifetime/Maximum updates=50" \
  > life.out 2>&1 &
pid=$!
sleep 2
kill -HUP $pid
rc=0; wait $pid || rc=$?
interrupted $rc 129 life
echo "signals: the run ends at once, summary interrupted"
