#!/usr/bin/env bash
# A long thin part's report (issue 36): a 4 m x 0.3 m plate (tests/report/long_part.prm) drawn
# face on, each side a panel at the full width of the picture, so that the part covers at least
# half of every panel (tests/report/panel_fill.py counts the coloured pixels; drawn as the knife
# is, in two oblique views side by side, it covered a strip of them); its cross-sections
# (tests/report/check_sections.py) and the zoom on its worst region; and the page in headless
# Chromium with all these pictures.
#   check_long_part.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$abrade" run "$src/tests/report/long_part.prm" --quiet --output "$out/run" > "$out/run.log" 2>&1 || { cat "$out/run.log"; exit 1; }
# the pictures draw the part's boundary, not every face of every tetrahedron (deal.II writes
# each cell with its own vertices): the design's panel has as many triangles as the STL
# surface the run wrote beside it (every face of every tetrahedron before the report merged the vertices: 5.5 times as
# many on this mesh)
python3 - "$out/run" <<'PY'
import struct, sys
run = sys.argv[1]
with open(run + "/part/part_00000.stl", "rb") as f:
    stl = struct.unpack("<I", f.read(84)[80:84])[0]
with open(run + "/report/part_wear_0.dat") as f:
    drawn = f.read().count("\n\n\n")  # a triangle: a 2 x 2 pm3d patch and a blank line
print(f"triangles drawn {drawn}, the STL surface's {stl}")
sys.exit(0 if drawn == stl else 1)
PY
# the design and the last update, each from two sides: four panels
python3 "$src/tests/report/panel_fill.py" "$out/run/report/part_wear.png" 4 --min 0.5
# the cross-sections: closed outlines with the design's; the one through the deepest point meets
# it where the run's surface has it, zoomed (under half the plate's 0.3 m)
python3 "$src/tests/report/check_sections.py" "$out/run" --part-height 0.3
# the zoom on the worst region: the part covers a tenth of each of its two panels or more (0.16
# and 0.18 with the zoom; the whole plate drawn there covers 0.02)
python3 "$src/tests/report/panel_fill.py" "$out/run/report/worst_region.png" 2 --min 0.1
python3 "$src/tests/report/check_report.py" "$out/run" --expect-figures trajectory,part,worst,section-worst
