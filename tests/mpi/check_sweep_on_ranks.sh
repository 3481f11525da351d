#!/usr/bin/env bash
# A sweep under mpirun spreads its runs over the ranks (child_runs.h, StudyRanks), each rank
# starting its share as processes outside the MPI job, and gives the study a single process
# gives:
#  - study.csv byte for byte that of the same sweep run without mpirun (--jobs 2);
#  - every run a one-rank run (summary.json mpi_ranks 1: its environment held none of the
#    launcher's variables), each rank having started one run of each batch of two;
#  - a run failing on rank 1 ends every rank with exit 3 and rank 0 naming it; a combination
#    refused before any run and a concept study's bad file end every rank with exit 2; no rank
#    is left waiting (a timeout turns a hang into a failure).
#   check_sweep_on_ranks.sh ABRADE PRM OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
expect="bash $(dirname "$0")/../expect_error.sh"
rm -rf "$out" && mkdir -p "$out"
vary=(--vary "Wall knife/Interaction/Friction=0,0.4" --seeds 1,2)
"$abrade" sweep "$prm" "${vary[@]}" --jobs 2 --output "$out/alone" --quiet
timeout 600 mpirun --quiet -np 2 --oversubscribe "$abrade" sweep "$prm" "${vary[@]}" --jobs 1 --output "$out/ranks" > "$out/ranks.out"
# two batches (the runs that settle the beds, then the rest), a run of each on each rank
[[ $(grep -c "runs started by the 2 MPI ranks: 1, 1$" "$out/ranks.out") -eq 2 ]] ||
  { echo "the runs were not spread over the ranks:"; cat "$out/ranks.out"; exit 1; }
cmp "$out/alone/study.csv" "$out/ranks/study.csv"
python3 - "$out/ranks" <<'PY'
import glob, json, os, sys
runs = [d for d in glob.glob(os.path.join(sys.argv[1], "runs", "*")) if os.path.isdir(d)]
if len(runs) != 4:
    raise SystemExit(f"{len(runs)} runs, expected 4")
for d in runs:
    s = json.load(open(os.path.join(d, "summary.json")))
    if s.get("mpi_ranks") != 1 or s.get("status") != "completed":
        raise SystemExit(f"{d}: mpi_ranks {s.get('mpi_ranks')}, status {s.get('status')}")
PY
# a run that fails on rank 1 (the batches go round the ranks: the bed's run on rank 0, the next
# on rank 1): the agreement names it on rank 0, exit 3 everywhere
rc=0
timeout 300 mpirun --quiet -np 2 --oversubscribe "$abrade" sweep "$prm" --vary "Simulation/Maximum overlap fraction=0.2,1e-9" \
  --set "Simulation/On error=stop" --seeds 1 --output "$out/failing_on_rank_1" > "$out/failing.out" 2>&1 || rc=$?
[[ $rc -eq 3 ]] && grep -q "^sweep: runs started by the 2 MPI ranks: 0, 1$" "$out/failing.out" &&
  grep -q "run failed: sweep: run .*/1e-9-seed1 failed (see" "$out/failing.out" ||
  { echo "a run failing on rank 1: exit $rc"; cat "$out/failing.out"; exit 1; }
$expect 2 "sweep run .*Restitution" -- timeout 300 mpirun --quiet -np 2 --oversubscribe "$abrade" sweep "$prm" \
  --vary "Wall knife/Interaction/Restitution=0.5,7" --seeds 1 --output "$out/failing" --quiet
# concepts: a bad file ends every rank with its message (rank 0 reads it; the others wait for runs)
$expect 2 "no_such_concept.prm" -- timeout 60 mpirun --quiet -np 2 --oversubscribe "$abrade" concepts "$prm" \
  "$out/no_such_concept.prm" --output "$out/concepts" --quiet
echo "sweep on 2 ranks: the same study.csv as alone, two runs started on each rank"
