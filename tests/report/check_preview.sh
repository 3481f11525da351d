#!/usr/bin/env bash
# A user's own part set up and seen (issue 36): `abrade preview` of the bolted edge (a STEP part
# with bolt holes, cases/bolted_edge) writes the part's preview page, opened in headless
# Chromium: the picture of the part as placed, coloured by role, present and not blank; the
# headline volume and the face table (id, role, area) summary.json's, face by face; and the
# knife job's faces.vtp beside it. The case is a lifetime case (its Job from
# cases/knife_bed/lifetime.prm): the preview sets its own.
#   check_preview.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$abrade" preview "$src/cases/bolted_edge/lifetime.prm" --quiet --output "$out/preview" > "$out/preview.log" 2>&1 ||
  { cat "$out/preview.log"; exit 1; }
[ -s "$out/preview/knife/faces.vtp" ] || { echo "no knife/faces.vtp"; exit 1; }
grep -q '"job": "knife"' "$out/preview/summary.json" || { echo "the preview is not the knife job"; exit 1; }
grep -q '^set Job *= *lifetime' "$src/cases/knife_bed/lifetime.prm" || { echo "the case is not a lifetime case"; exit 1; }
python3 "$src/tests/report/check_report.py" "$out/preview" --expect-figures faces --expect-face-table
