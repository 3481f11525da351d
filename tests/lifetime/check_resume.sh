#!/usr/bin/env bash
# Checkpoint and resume: a lifetime run killed with SIGKILL mid-cycle (or ABRADE_SIGNAL: TERM,
# INT), resumed with --resume and killed again inside the first resumed update, then resumed to
# the end, produces the same trajectory and profiles (byte for byte) and the same prediction as
# an uninterrupted run. (A second kill once left trajectory.csv empty and the next resume
# finished with the later rows only.)
# With ABRADE_LAUNCH="mpirun -np 2 --oversubscribe" the runs are MPI runs (every rank
# checkpoints its own copy; all are killed and resumed together). There the kill is also made to
# fall between two ranks' checkpoints of one update (rank 1's newest is removed when both have
# it): the ranks must resume together from the newest update all of them completed (they once
# resumed from different updates and hung).
#   check_resume.sh ABRADE PRM OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
read -r -a launch <<< "${ABRADE_LAUNCH:-}"
run() { "${launch[@]}" "$abrade" run "$@"; }
sets=(--set "Lifetime/Maximum updates=4" --set "Lifetime/Maximum depth=1")
rm -rf "$out" && mkdir -p "$out"
run "$prm" --output "$out/whole" --quiet "${sets[@]}" > /dev/null

run "$prm" --output "$out/killed" --quiet "${sets[@]}" > /dev/null 2>&1 &
pid=$!
newest() { # newest complete checkpoint in directory $1 (0: none)
  local u=0 f
  for f in "$1"/loop-*.txt; do [[ -f $f ]] && f=${f##*/loop-} && (( ${f%.txt} > u )) && u=${f%.txt}; done
  echo "$u"
}
for _ in $(seq 1 600); do   # at most 60 s
  (( $(newest "$out/killed/checkpoint") >= 2 )) && break
  sleep 0.1
done
signal=${ABRADE_SIGNAL:-KILL}
stop() { # the run started as $pid: signalled, with its processes (MPI ranks; the run itself where
  # the shell running the function did not exec it: a run left going finished its update beside
  # the last resume, and the profiles had that update twice), until none is left (at most 60 s)
  kill -s "$signal" "$pid" 2>/dev/null || return 1
  pkill -"$signal" -f -- "--output $out/killed" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  for _ in $(seq 1 600); do pgrep -f -- "--output $out/killed" > /dev/null || return 0; sleep 0.1; done
  echo "the killed run is still going after 60 s"; exit 1
}
stop || { echo "the run finished before it could be killed"; exit 1; }
killed_at=$(newest "$out/killed/checkpoint")
if [[ -d $out/killed/.rank-1/checkpoint ]]; then
  u1=$(newest "$out/killed/.rank-1/checkpoint")
  if (( u1 == killed_at )); then # as if killed after rank 0's checkpoint, before rank 1's
    rm "$out/killed/.rank-1/checkpoint/loop-$u1.txt"
    u1=$((u1 - 1))
  fi
  killed_at=$(( u1 < killed_at ? u1 : killed_at ))
fi
if [[ -z ${ABRADE_LAUNCH:-} ]]; then # the second kill: inside the first resumed update
  run "$prm" --output "$out/killed" --quiet --resume "${sets[@]}" > /dev/null 2>&1 &
  pid=$!
  for _ in $(seq 1 3000); do # killed as soon as it says it resumes: inside the next update's cycle
    grep -q "Resuming after update $killed_at" "$out/killed/log.txt" 2>/dev/null && break
    sleep 0.01
  done
  stop || { echo "the resumed run finished before it could be killed"; exit 1; }
  (( $(newest "$out/killed/checkpoint") == killed_at )) || { echo "the second kill came after an update"; exit 1; }
fi
run "$prm" --output "$out/killed" --quiet --resume "${sets[@]}" > /dev/null
(( $(grep -c "Resuming after update $killed_at" "$out/killed/log.txt") >= 1 )) || { echo "did not resume"; exit 1; }
cmp "$out/whole/trajectory.csv" "$out/killed/trajectory.csv" || { diff "$out/whole/trajectory.csv" "$out/killed/trajectory.csv"; exit 1; }
cmp "$out/whole/part/profile_0.50.csv" "$out/killed/part/profile_0.50.csv" || { echo "profiles differ"; exit 1; }
p1=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['results']['lifetime']['predicted_tonnes_to_end_of_life'])" "$out/whole/summary.json")
p2=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['results']['lifetime']['predicted_tonnes_to_end_of_life'])" "$out/killed/summary.json")
[[ "$p1" == "$p2" ]] || { echo "predictions differ: $p1 vs $p2"; exit 1; }
echo "ok: killed after update $killed_at, resumed (and killed again inside the next update unless under MPI);" \
     "trajectory, profiles and prediction ($p1 t) identical"
