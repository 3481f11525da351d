#!/usr/bin/env bash
# Checkpoint and resume: a lifetime run killed with SIGKILL mid-cycle and resumed with --resume
# produces the same trajectory (byte for byte) and the same prediction as an uninterrupted run.
# With ABRADE_LAUNCH="mpirun -np 2 --oversubscribe" the runs are MPI runs (every rank
# checkpoints its own copy; all are killed and resumed together).
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
state="$out/killed/checkpoint/loop.txt"
for _ in $(seq 1 600); do   # at most 60 s
  if [[ -f $state ]] && (( $(cut -d' ' -f2 "$state") >= 2 )); then break; fi
  sleep 0.1
done
kill -9 "$pid" 2>/dev/null || { echo "the run finished before it could be killed"; exit 1; }
pkill -9 -f -- "--output $out/killed" 2>/dev/null || true # the MPI ranks, if any
wait "$pid" 2>/dev/null || true
killed_at=$(cut -d' ' -f2 "$state")
run "$prm" --output "$out/killed" --quiet --resume "${sets[@]}" > /dev/null
grep -q "Resuming after update $killed_at" "$out/killed/log.txt" || { echo "did not resume"; exit 1; }
cmp "$out/whole/trajectory.csv" "$out/killed/trajectory.csv" || { diff "$out/whole/trajectory.csv" "$out/killed/trajectory.csv"; exit 1; }
cmp "$out/whole/knife/profile_0.50.csv" "$out/killed/knife/profile_0.50.csv" || { echo "profiles differ"; exit 1; }
p1=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['results']['lifetime']['predicted_tonnes_to_end_of_life'])" "$out/whole/summary.json")
p2=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['results']['lifetime']['predicted_tonnes_to_end_of_life'])" "$out/killed/summary.json")
[[ "$p1" == "$p2" ]] || { echo "predictions differ: $p1 vs $p2"; exit 1; }
echo "ok: killed after update $killed_at, resumed; trajectory, profiles and prediction ($p1 t) identical"
