#!/usr/bin/env bash
# Resume is right after a kill at any moment (issue 35): a lifetime run is killed with SIGKILL
#  - as soon as its first bed file appears (before the first update: the run went on from the
#    settled state in memory, the resumed one from the file, and the life came out 1.38e7 t
#    against 4.99e6 t),
#  - while the mesher remeshes the worn knife (the mesher's directory of the run exists),
#  - as each update's checkpoint appears, and 0.3 s after (inside the next update's cycles),
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
run "$out/whole" > /dev/null
p_whole=$(prediction "$out/whole/summary.json")
grep -q "remeshed" "$out/whole/log.txt" || { echo "the case does not remesh: no kill during a remesh"; exit 1; }

kill_run() { # every process of the run in $1 (the run, its mesher), until none is left
  pkill -KILL -f -- "--output $1( |$)" 2>/dev/null || true
  pkill -KILL -f -- "$1/part/work" 2>/dev/null || true
  wait "$2" 2>/dev/null || true
  for _ in $(seq 1 300); do pgrep -f -- "$1(/| |$)" > /dev/null || return 0; sleep 0.1; done
  echo "the killed run in $1 is still going after 30 s"; exit 1
}
check() { # resume $1 to the end, compare with the whole run
  local d=$1 what=$2
  run "$d" --resume > /dev/null
  cmp "$out/whole/trajectory.csv" "$d/trajectory.csv" ||
    { echo "killed $what: trajectory differs"; diff "$out/whole/trajectory.csv" "$d/trajectory.csv" | head; exit 1; }
  cmp "$out/whole/part/profile_0.50.csv" "$d/part/profile_0.50.csv" || { echo "killed $what: profiles differ"; exit 1; }
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
meshing() { compgen -G "$1/part/work/abrade-mesher-*" > /dev/null; } # (the mesher's own directory)
if grep -q "Wear source *= *analytic" "$prm" 2>/dev/null; then :; else
  at_event "at the first bed file (before the first update)" bed_exists "$out/bed"
fi
at_event "during a remesh" meshing "$out/remesh"
# at each checkpoint's appearance (u = 1 ... 4: between two updates) and 0.3 s after it
# (u = 0 ... 3: inside the next update's cycles, the first of them included): points set by the
# run's own progress, not by a clock (a busy machine once let a timed point miss the run)
checkpoint() { [[ -e $1/checkpoint/loop-$u.txt || ( $u -eq 0 && -e $1/checkpoint/knife-0.ckpt ) ]]; }
for u in 1 2 3 4; do at_event "at checkpoint $u" checkpoint "$out/at_$u"; done
after_checkpoint() { checkpoint "$1" && sleep 0.3; }
for u in 0 1 2 3; do at_event "0.3 s after checkpoint $u" after_checkpoint "$out/after_$u"; done
echo "resume after a kill anywhere: identical at every kill point"
