#!/usr/bin/env bash
# A shell read from a file carries a mounted knife like a parametric shell: the coarse grab's
# right shell exported to STL and read back as Geometry = file, with its lip given by
# 'Lip centre', 'Lip direction', 'Lip inward' (the parametric lip: 0.4 m radius opened 60
# degrees, hinge at 1.75 m), places the right knife where the parametric shell places it
# (to the STL files' single precision), and the cycle starts.
#   check_file_shell.sh ABRADE PRM OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$abrade" export-walls "$prm" --output "$out/parametric" > /dev/null
file_shell=(--set "Wall right/Geometry=file" --set "Wall right/File=$out/parametric/right.stl"
            --set "Wall right/Offset=0, 0, 0" --set "Wall right/Maximum edge length=0"
            --set "Wall right/Motion/Centre=0, 0, 1.75"
            --set "Wall right/Lip centre=0.346410161513775, 0, 1.55" --set "Wall right/Lip direction=0, 1, 0"
            --set "Wall right/Lip inward=0.5, 0, 0.866025403784439")
"$abrade" export-walls "$prm" --output "$out/file" "${file_shell[@]}" > /dev/null
python3 - "$out/parametric/right_knife.stl" "$out/file/right_knife.stl" <<'PY'
import struct, sys
def triangles(path):
    data = open(path, "rb").read()
    n = struct.unpack_from("<I", data, 80)[0]
    return [struct.unpack_from("<12f", data, 84 + 50 * k)[3:] for k in range(n)]
a, b = triangles(sys.argv[1]), triangles(sys.argv[2])
assert len(a) == len(b) and len(a) > 0, (len(a), len(b))
worst = max(abs(p - q) for ta, tb in zip(a, b) for p, q in zip(ta, tb))
print(f"{len(a)} knife triangles, largest vertex difference {worst:.2e} m")
sys.exit(0 if worst < 1e-6 else 1)
PY
# a lip on anything but a file is refused, as is a knife mounted on a wall without a lip
bash "$(dirname "$0")/../expect_error.sh" 2 "'Lip centre' is an entry of Geometry = file, and wall right's Geometry is clamshell shell" -- \
  "$abrade" export-walls "$prm" --output "$out/bad" --set "Wall right/Lip centre=0, 0, 0"
bash "$(dirname "$0")/../expect_error.sh" 2 "is not a wall with a lip" -- \
  "$abrade" export-walls "$prm" --output "$out/bad" --set "Wall right/Geometry=file" \
  --set "Wall right/File=$out/parametric/right.stl"
# the cycle starts with the file shell and its knife
"$abrade" run "$prm" --output "$out/run" --quiet "${file_shell[@]}" --set "Particles/Generation/Count=500" \
  --set "Simulation/Phases=descent: 0.05, sinking: 0.01, closing: 0.01, hoisting: 0.01, opening: 0.01" > /dev/null
echo "ok: the file shell carries its knife where the parametric shell does"
