#!/usr/bin/env bash
# A write that fails (a full disk: the file is a link to /dev/full, whose writes fail with
# ENOSPC) ends the run with exit 3 and a message naming the file, and summary.json says
# "failed" (a CSV cut at 8 kB once left a summary saying "completed"):
#  1. trajectory.csv (a CSV written row by row);
#  2. the knife's first .vtu (a file written aside and renamed: its aside copy is the link).
#   check_failed_writes.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out" && cd "$out"
expect="bash $src/tests/expect_error.sh"
run=("$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --quiet --set "Lifetime/Maximum updates=2")
status() { python3 -c "import json, sys; s = json.load(open(sys.argv[1]))['status']; assert s.startswith('failed: cannot write'), s" "$1"; }

mkdir -p csv && ln -s /dev/full csv/trajectory.csv
$expect 3 "run failed: cannot write csv/trajectory.csv \(disk full" -- "${run[@]}" --output csv
status csv/summary.json

mkdir -p vtu/knife && ln -s /dev/full vtu/knife/knife_00000.vtu.tmp
$expect 3 "run failed: cannot write vtu/knife/knife_00000.vtu \(disk full" -- "${run[@]}" --output vtu
status vtu/summary.json
echo "failed writes: exit 3, summary failed"
