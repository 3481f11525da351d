#!/usr/bin/env bash
# The progress line under mpirun: a rank's stderr is a pipe to mpirun, which copies it to its own
# stderr as it comes ('\r' included). When mpirun's stderr is a terminal, rank 0 draws the line
# (it drew nothing before: every rank's stderr is a pipe); when it is not (a log file, ctest),
# nothing is drawn, as without mpirun. A terminal is made with script(1) (util-linux).
#   check_progress_under_mpirun.sh ABRADE CASE.prm OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
rm -rf "$out" && mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
drawn() { grep -c $'\r''\(settling\|dem\) ' "$1" || true; }

# on a terminal: one process, then two ranks, each draws the line
script -q -e -c "'$abrade' run '$prm' --output '$out/alone'" "$out/alone.typescript" > /dev/null
script -q -e -c "mpirun -np 2 --oversubscribe '$abrade' run '$prm' --output '$out/np2'" "$out/np2.typescript" > /dev/null
[ "$(drawn "$out/alone.typescript")" -gt 0 ] || fail "no progress line on a terminal without mpirun"
[ "$(drawn "$out/np2.typescript")" -gt 0 ] || fail "no progress line on a terminal under mpirun"
# ... and --quiet draws none
script -q -e -c "mpirun -np 2 --oversubscribe '$abrade' run '$prm' --quiet --output '$out/quiet'" "$out/quiet.typescript" > /dev/null
[ "$(drawn "$out/quiet.typescript")" -eq 0 ] || fail "a progress line under --quiet"
# not a terminal: nothing drawn, as without mpirun
mpirun -np 2 --oversubscribe "$abrade" run "$prm" --output "$out/piped" > "$out/piped.log" 2>&1
[ "$(drawn "$out/piped.log")" -eq 0 ] || fail "a progress line written into a file under mpirun"
if grep -q $'\r' "$out/piped.log"; then fail "a carriage return in the piped output"; fi
echo "progress under mpirun: drawn on a terminal ($(drawn "$out/np2.typescript") redraws), not into a file"
