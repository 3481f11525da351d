#!/usr/bin/env bash
# A write that fails (a full disk: /dev/full, whose writes fail with ENOSPC, bind-mounted over
# the file in a mount namespace of this test's own; a link to it would be refused, since abrade
# follows no link inside its output directory) ends the run with exit 3 and a message naming the
# file, and summary.json says "failed" (a CSV cut at 8 kB once left a summary saying "completed"):
#  1. trajectory.csv (a CSV written row by row);
#  2. the knife's first .vtu (a file written aside and renamed: its aside copy is /dev/full);
#  3. a disk that fills up during the run.
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

mkdir -p vtu/part && full vtu/part/part_00000.vtu.tmp
$expect 3 "run failed: cannot write vtu/part/part_00000.vtu \(disk full" -- "${run[@]}" --output vtu
status vtu/summary.json
# a disk that fills up at the end of the run (a file system that holds the run's data but not
# its report, sized from the same run on the real disk): the run either writes every declared
# output or ends with exit 3 naming what it could not write (a 2 MB disk once ended "completed"
# without report.html and the profile picture)
"${run[@]}" --output sized --set "Lifetime/Maximum updates=3" > /dev/null
kb=$(( $(du -sk sized | cut -f1) - $(du -sk sized/report | cut -f1) - $(du -sk sized/report.html | cut -f1) + 64 ))
mkdir -p small && mount -t tmpfs -o size=${kb}k tmpfs small
set +e
out_text=$("${run[@]}" --output small/run --set "Lifetime/Maximum updates=3" 2>&1 </dev/null)
rc=$?
set -e
if [[ $rc -eq 0 ]]; then
  missing=""
  for f in report.html trajectory.png part/profile_0.50.png summary.json; do [[ -s small/run/$f ]] || missing+=" $f"; done
  echo "the run completed on a disk too small for its report (${missing:+without$missing}):"; echo "$out_text"; exit 1
else
  [[ $rc -eq 3 ]] || { echo "a full disk ended the run with exit $rc:"; echo "$out_text"; exit 1; }
  grep -q "run failed: cannot write" <<< "$out_text" || { echo "no 'cannot write' message:"; echo "$out_text"; exit 1; }
  status small/run/summary.json
  echo "a full disk: exit 3, $(grep -o 'cannot write [^ ]*' <<< "$out_text" | head -1), summary failed"
fi
echo "failed writes: exit 3, summary failed"
