#!/usr/bin/env bash
# compare warns where its numbers would be wrong without a word:
#  - a design whose triangles face inward (an export that flipped them) is turned outward, with
#    a warning, and measures as the right one does (the same measured depths);
#  - a partial scan registered without a region (--register-on) on the design, worn part
#    included, gets the warning that the wear pulls the fit; with a region on the unworn top the
#    RMS inside the region and outside it are reported apart.
#   check_scan_warnings.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$(realpath "$1") src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$abrade" run "$src/tests/lifetime/analytic_edge.prm" --quiet --output "$out/run" --set "Lifetime/Maximum updates=2" > /dev/null
python3 - "$out" <<'PY'
import struct, sys, os
out = sys.argv[1]
def read(path):
    data = open(path, "rb").read()
    n = struct.unpack("<I", data[80:84])[0]
    return [struct.unpack("<12fH", data[84 + 50 * k: 134 + 50 * k]) for k in range(n)]
def write(path, tris):
    with open(path, "wb") as f:
        f.write(b"flipped or cut by check_scan_warnings.sh".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<12fH", *t))
design = read(os.path.join(out, "run", "part", "part_00000.stl"))
# inward: the second and third corners swapped, the normal turned round
write(os.path.join(out, "design_inward.stl"),
      [(-t[0], -t[1], -t[2], *t[3:6], *t[9:12], *t[6:9], t[12]) for t in design])
# a partial scan: the worn knife's lower part (z < 0.15 m), the worn edge in it
worn = read(os.path.join(out, "run", "part", "part_00002.stl"))
write(os.path.join(out, "partial_scan.stl"), [t for t in worn if max(t[5], t[8], t[11]) < 0.15])
PY
d="$out/run/part"
"$abrade" compare --predicted "$d/part_00002.stl" --scan "$d/part_00002.stl" --reference "$d/part_00000.stl" \
  --no-registration --output "$out/right" > /dev/null 2> "$out/right.err"
"$abrade" compare --predicted "$d/part_00002.stl" --scan "$d/part_00002.stl" --reference "$out/design_inward.stl" \
  --no-registration --output "$out/inward" > /dev/null 2> "$out/inward.err"
"$abrade" compare --predicted "$d/part_00002.stl" --scan "$out/partial_scan.stl" --reference "$d/part_00000.stl" \
  --output "$out/no_region" > /dev/null 2> "$out/no_region.err"
"$abrade" compare --predicted "$d/part_00002.stl" --scan "$d/part_00002.stl" --reference "$d/part_00000.stl" \
  --register-on -1,-1,0.2,1,1,1 --output "$out/region" > /dev/null 2> "$out/region.err"
grep -q "face inward" "$out/inward.err" || { echo "no warning for the inward design"; cat "$out/inward.err"; exit 1; }
! grep -q "face inward" "$out/right.err" || { echo "a warning for the outward design"; exit 1; }
grep -q "worn part included" "$out/no_region.err" || { echo "no warning for the region-less registration"; cat "$out/no_region.err"; exit 1; }
! grep -q "worn part included" "$out/region.err" || { echo "a region-less warning with a region"; exit 1; }
python3 - "$out" <<'PY'
import csv, json, sys, os
out = sys.argv[1]
a = [float(r["depth"]) for r in csv.DictReader(open(os.path.join(out, "right", "measured_depths.csv")))]
b = [float(r["depth"]) for r in csv.DictReader(open(os.path.join(out, "inward", "measured_depths.csv")))]
assert len(a) == len(b) and max(abs(x - y) for x, y in zip(a, b)) < 1e-12, "the turned design measures differently"
assert max(a) > 1e-3, max(a)
reg = json.load(open(os.path.join(out, "region", "comparison.json")))["registration"]
assert reg["points_in_region"] > 10 and reg["points_outside_region"] > 10, reg
assert reg["rms_distance_in_region"] < 0.2 * reg["rms_distance_outside_region"], reg
print(f"ok: inward design turned (depths equal, largest {1e3 * max(a):.2f} mm); region-less warning; "
      f"RMS in the region {1e3 * reg['rms_distance_in_region']:.3f} mm, outside {1e3 * reg['rms_distance_outside_region']:.3f} mm")
PY
