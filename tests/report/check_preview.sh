#!/usr/bin/env bash
# A user's own part set up and seen (issue 36): `abrade preview` of the bolted edge (a STEP part
# with bolt holes, cases/bolted_edge) writes the part's preview page, opened in headless
# Chromium: the picture of the part as placed, coloured by role, present and not blank; the
# headline volume and the face table (id, role, area) summary.json's, face by face; and the
# knife job's faces.vtp beside it; the set-up picture (the part among the case's walls, the fill
# region, the domain and the part's path) and its numbers against the parameter files worked by
# hand. The case is a lifetime case (its Job from
# cases/knife_bed/lifetime.prm): the preview sets its own.
#   check_preview.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$abrade" preview "$src/cases/bolted_edge/lifetime.prm" --quiet --output "$out/preview" > "$out/preview.log" 2>&1 ||
  { cat "$out/preview.log"; exit 1; }
[ -s "$out/preview/part/faces.vtp" ] || { echo "no part/faces.vtp"; exit 1; }
grep -q '"job": "part"' "$out/preview/summary.json" || { echo "the preview is not the part job"; exit 1; }
grep -q '^set Job *= *lifetime' "$src/cases/knife_bed/lifetime.prm" || { echo "the case is not a lifetime case"; exit 1; }
grep -q "^Done: " "$out/preview.log" || { echo "no Done line"; cat "$out/preview.log"; exit 1; }
# a picture that cannot be drawn (a gnuplot that fails): the results kept, the page saying so
# where the picture would be, and no "Done" (issue 36: "Done" only when every output is written)
mkdir -p "$out/failing_gnuplot"
printf '#!/bin/sh\nexit 1\n' > "$out/failing_gnuplot/gnuplot" && chmod +x "$out/failing_gnuplot/gnuplot"
PATH="$out/failing_gnuplot:$PATH" "$abrade" preview "$src/cases/bolted_edge/lifetime.prm" --output "$out/no_pictures" \
  > "$out/no_pictures.log" 2>&1 || { cat "$out/no_pictures.log"; exit 1; }
if grep -q "^Done: " "$out/no_pictures.log"; then echo "Done said without the pictures"; exit 1; fi
grep -q "Finished without all its outputs (the report lacks its picture(s) faces.png, setup.png" "$out/no_pictures.log" ||
  { cat "$out/no_pictures.log"; exit 1; }
grep -q 'data-missing-figure="faces.png"' "$out/no_pictures/report.html" || { echo "the page does not say"; exit 1; }
python3 "$src/tests/report/check_report.py" "$out/preview" --expect-figures faces,setup --expect-face-table
# the case around the part (the set-up picture's numbers), against the parameter files by hand:
# cases/knife_bed/knife_bed.prm's fill region and domain; its knife goes down at 1.5 m/s for
# 0.2666667 s (penetration) and along x at 1.5 m/s for 0.8 s (travel); Wall knife/Offset
# (-0.9, 0, 0.6) moves the part's lowest point (z 0 in the part's frame) to z = 0.6
python3 - "$out/preview/summary.json" <<'PY'
import json, sys
k = json.load(open(sys.argv[1]))["results"]["part"]
c = k["case"]
near = lambda a, b, tol=1e-6: all(abs(x - y) <= tol for x, y in zip(a, b)) and len(a) == len(b)
assert near(c["fill_region"], [-0.97, -0.97, 0.03, 0.97, 0.97, 0.85]), c["fill_region"]
assert near(c["domain"], [-1.05, -1.05, -0.05, 1.05, 1.05, 1.3]), c["domain"]
assert c["particles"] == 10496 and "container" in c["walls"], c
legs = {l["phase"]: l for l in c["path"]}
assert list(legs) == ["penetration", "travel"], legs
box = k["bounding_box"]
p0 = legs["penetration"]["start"]
assert abs(p0[2] - (box[2] + 0.6)) < 1e-9 and box[0] - 0.9 - 1e-9 <= p0[0] <= box[3] - 0.9 + 1e-9, (p0, box)
assert near(legs["penetration"]["end"], [p0[0], p0[1], p0[2] - 1.5 * 0.2666667], 1e-9), legs
assert near(legs["travel"]["end"], [p0[0] + 1.5 * 0.8, p0[1], p0[2] - 1.5 * 0.2666667], 1e-9), legs
print("ok: the case around the part: fill region, domain, the path", [round(x, 4) for x in legs["travel"]["end"]])
PY
for f in scene_part.vtp scene_walls.dat scene_path.dat; do
  [ -s "$out/preview/part/$f" ] || { echo "no part/$f"; exit 1; }
done
