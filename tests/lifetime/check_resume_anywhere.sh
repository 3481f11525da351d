#!/usr/bin/env bash
# Resume is right after a kill at any moment (issue 35): a lifetime run is killed with SIGKILL
#  - as soon as its first bed file appears (before the first update: the run went on from the
#    settled state in memory, the resumed one from the file, and the life came out 1.38e7 t
#    against 4.99e6 t),
#  - while the mesher remeshes the worn knife (an abrade-mesher process of the run exists),
#  - and at nine moments spread over the run (a tenth ... nine tenths of its uninterrupted time),
# then resumed with --resume to the end: trajectory, profiles and prediction are byte-identical
# to the uninterrupted run's at every kill point.
#   check_resume_anywhere.sh ABRADE PRM OUTDIR [--set ...]...
set -euo pipefail
abrade=$1 prm=$2 out=$3
shift 3
sets=("$@")
rm -rf "$out" && mkdir -p "$out"
run() { "$abrade" run "$prm" --quiet "${sets[@]}" --output "$@"; }
prediction() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['results']['lifetime']['predicted_tonnes_to_end_of_life'])" "$1"; }
start=$(date +%s.%N)
run "$out/whole" > /dev/null
whole=$(python3 -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$start" "$(date +%s.%N)")
p_whole=$(prediction "$out/whole/summary.json")
grep -q "remeshed" "$out/whole/log.txt" || { echo "the case does not remesh: no kill during a remesh"; exit 1; }

kill_run() { # every process of the run in $1 (the run, its mesher), until none is left
  pkill -KILL -f -- "--output $1( |$)" 2>/dev/null || true
  pkill -KILL -f -- "$1/knife/work" 2>/dev/null || true
  wait "$2" 2>/dev/null || true
  for _ in $(seq 1 300); do pgrep -f -- "$1(/| |$)" > /dev/null || return 0; sleep 0.1; done
  echo "the killed run in $1 is still going after 30 s"; exit 1
}
check() { # resume $1 to the end, compare with the whole run
  local d=$1 what=$2
  run "$d" --resume > /dev/null
  cmp "$out/whole/trajectory.csv" "$d/trajectory.csv" ||
    { echo "killed $what: trajectory differs"; diff "$out/whole/trajectory.csv" "$d/trajectory.csv" | head; exit 1; }
  cmp "$out/whole/knife/profile_0.50.csv" "$d/knife/profile_0.50.csv" || { echo "killed $what: profiles differ"; exit 1; }
  [[ $(prediction "$d/summary.json") == "$p_whole" ]] ||
    { echo "killed $what: prediction $(prediction "$d/summary.json") t, uninterrupted $p_whole t"; exit 1; }
  echo "ok: killed $what, resumed: identical (prediction $p_whole t)"
}
# at an event: $1 names it, $2 a command that succeeds once it happened in directory $3
at_event() {
  local what=$1 happened=$2 d=$3
  run "$d" > /dev/null 2>&1 &
  local pid=$!
  for _ in $(seq 1 6000); do
    if $happened "$d"; then kill_run "$d" $pid; check "$d" "$what"; return; fi
    kill -0 $pid 2>/dev/null || break
    sleep 0.01
  done
  echo "the run in $d ended before $what"; exit 1
}
bed_exists() { compgen -G "$1/beds/*.bed" > /dev/null || compgen -G "$1/*.bed" > /dev/null; }
meshing() { pgrep -f -- "$1/knife/work" > /dev/null; }
if grep -q "Wear source *= *analytic" "$prm" 2>/dev/null; then :; else
  at_event "at the first bed file (before the first update)" bed_exists "$out/bed"
fi
at_event "during a remesh" meshing "$out/remesh"
killed=0
for k in 1 2 3 4 5 6 7 8 9; do
  d="$out/at_$k"
  run "$d" > /dev/null 2>&1 &
  pid=$!
  sleep "$(python3 -c "import sys; print(float(sys.argv[1]) * int(sys.argv[2]) / 10)" "$whole" $k)"
  if [[ -e $d/report.html ]] || ! kill -0 $pid 2>/dev/null; then
    echo "(the run had ended before $k tenths of the uninterrupted run's time)"; wait $pid || true
    continue
  fi
  kill_run "$d" $pid
  check "$d" "at $k/10 of its time"
  killed=$((killed + 1))
done
# a machine whose speed varies may finish a run early once; a kill point that never kills is
# no check: eight of the nine must have met a run in progress
(( killed >= 8 )) || { echo "only $killed of the nine timed kills met the run in progress"; exit 1; }
echo "resume after a kill anywhere: identical at every kill point"
