#!/usr/bin/env bash
# A write that fails (a full disk: /dev/full, whose writes fail with ENOSPC, bind-mounted over
# the file in a mount namespace of this test's own; a link to it would be refused, since abrade
# follows no link inside its output directory) ends the run with exit 3 and a message naming the
# file, and summary.json says "failed" (a CSV cut at 8 kB once left a summary saying "completed"):
#  1. trajectory.csv (a CSV written row by row);
#  2. the knife's first .vtu (a file written aside and renamed: its aside copy is /dev/full).
#   check_failed_writes.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
if [[ -z ${ABRADE_IN_NAMESPACE:-} ]]; then
  # a private mount namespace (as root; else as root of a user namespace), skipped (77) if none
  unshare -m true 2>/dev/null && exec env ABRADE_IN_NAMESPACE=1 unshare -m bash "$0" "$@"
  unshare -rm true 2>/dev/null && exec env ABRADE_IN_NAMESPACE=1 unshare -rm bash "$0" "$@"
  echo "no mount namespace to be had here: skipped"; exit 77
fi
rm -rf "$out" && mkdir -p "$out" && cd "$out"
expect="bash $src/tests/expect_error.sh"
run=("$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --quiet --set "Lifetime/Maximum updates=2")
status() { python3 -c "import json, sys; s = json.load(open(sys.argv[1]))['status']; assert s.startswith('failed: cannot write'), s" "$1"; }
full() { touch "$1" && mount --bind /dev/full "$1"; }

mkdir -p csv && full csv/trajectory.csv
$expect 3 "run failed: cannot write csv/trajectory.csv \(disk full" -- "${run[@]}" --output csv
status csv/summary.json

mkdir -p vtu/knife && full vtu/knife/knife_00000.vtu.tmp
$expect 3 "run failed: cannot write vtu/knife/knife_00000.vtu \(disk full" -- "${run[@]}" --output vtu
status vtu/summary.json
echo "failed writes: exit 3, summary failed"
