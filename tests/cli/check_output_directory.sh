#!/usr/bin/env bash
# An output directory is the run's own (issue 35):
#  - a second run on a directory in use is refused, naming the first one's pid (two runs 3 s
#    apart once both "completed" with a torn trajectory.csv and a mixed log);
#  - a symbolic link inside it (trajectory.csv, log.txt, knife/) is refused, its target untouched;
#  - `run d/parameters.prm --output d` does not overwrite the user's edited file (and reruns
#    the run's own unedited one); export-walls does not overwrite its input mesh;
#  - a run resumes as itself when its directory is named by another spelling (absolute instead
#    of relative) or was copied elsewhere;
#  - a knife job writes nothing outside its output directory (strace: no file opened for
#    writing elsewhere; Gmsh's FLTK preferences and temporary meshes were);
#  - SIGTERM to a sweep ends its child runs too (they went on writing).
#   check_output_directory.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$1 src=$2 out=$3
expect="bash $src/tests/expect_error.sh"
rm -rf "$out" && mkdir -p "$out" && cd "$out"
life=("$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --quiet)

# the lock: a run in progress, then a second on its directory
"${life[@]}" --output busy --set "Lifetime/Maximum updates=3" > /dev/null 2>&1 &
first=$!
for _ in $(seq 1 300); do [[ -s busy/.abrade-lock ]] && break; sleep 0.05; done
$expect 2 "busy: another abrade run \(pid $first\) is writing into this output directory" -- "${life[@]}" --output busy
wait $first || { echo "the first run failed beside the refused second"; exit 1; }
# the lock goes with the process (also after SIGKILL): the directory is free again
"${life[@]}" --output busy --set "Lifetime/Maximum updates=1" > /dev/null

# links inside: refused, their targets untouched
for name in trajectory.csv log.txt parameters.prm part knife; do
  mkdir -p "links_$name" && echo keep > "target_$name"
  ln -s "$PWD/target_$name" "links_$name/$name"
  $expect 2 "links_$name/$name: a symbolic link \(to .*target_$name\) inside the output directory" -- \
    "${life[@]}" --output "links_$name" --set "Lifetime/Maximum updates=1"
  [[ $(cat "target_$name") == keep ]] || { echo "target_$name was overwritten"; exit 1; }
done

# the run's own parameters.prm as the input: rerun as it is; edited, refused and kept
"${life[@]}" --output own --set "Lifetime/Maximum updates=1" > /dev/null
"$abrade" run own/parameters.prm --output own --quiet > /dev/null
echo "# my note" >> own/parameters.prm
cp own/parameters.prm edited.prm
$expect 2 "own/parameters.prm: is the output directory's parameters.prm, which the run writes" -- \
  "$abrade" run own/parameters.prm --output own --quiet
cmp own/parameters.prm edited.prm
# export-walls whose wall file is the file it would write
mkdir -p walls && cp "$src/tests/cli/knife_mm.stl" walls/w.stl && cp walls/w.stl walls_w.stl
printf 'set Job = dem\nset Walls = w\nsubsection Simulation\n  set Phases = only: 0.001\nend\nsubsection Wall w\n  set Geometry = file\n  set File = walls/w.stl\n  set Offset = 0, 0, 1\nend\n' > w.prm
$expect 2 "walls/w.stl: is wall w's mesh and the file export-walls would write it to" -- \
  "$abrade" export-walls w.prm --output walls
cmp walls/w.stl walls_w.stl

# resume by the parameters, not the directory's spelling
three=(--set "Lifetime/Maximum updates=3")
"${life[@]}" --output spelled "${three[@]}" > /dev/null
cp spelled/trajectory.csv whole.csv && cp -r spelled copied
rm spelled/checkpoint/*-3.* copied/checkpoint/*-3.*
$expect 0 "Resuming after update 2" -- "$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --output "$PWD/spelled" \
  "${three[@]}" --resume
$expect 0 "Resuming after update 2" -- "$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --output copied \
  "${three[@]}" --resume
cmp whole.csv spelled/trajectory.csv
cmp whole.csv copied/trajectory.csv

# nothing written outside the output directory by a knife job (STEP part: Gmsh in the mesher)
if command -v strace > /dev/null; then
  printf 'SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 100, 60, 20};\n' > block.geo
  "$abrade" convert block.geo --output block.step > /dev/null
  strace -f -qq -e trace=%file -o trace.txt "$abrade" run --quiet --output knife_job \
    --set Job=part --set Part/Geometry=file --set "Part/File=$PWD/block.step" \
    --set "Part/Clamped faces=normal 0, 0, 1" > /dev/null
  # files opened for writing (O_WRONLY, O_RDWR, O_CREAT), made, moved, linked, cut or removed:
  # inside knife_job/ only (/dev/null and the terminal aside, and Open MPI's run time: its
  # session directory ompi.* in the temporary folder and its shared memory /dev/shm/open_mpi.*,
  # removed by MPI_Finalize)
  # (the mesher works in a directory of its own inside knife_job/, by relative names: its
  # process's relative paths lie there; a link's first path is what it links to, not written;
  # removing that directory goes by names relative to its opened subdirectories)
  mesher_pids=$(grep -E '^[0-9]+ +chdir\("[^"]*knife_job/' trace.txt | awk '{print $1}' | sort -u | paste -sd'|')
  outside=$(grep -E '^[0-9]+ +(open|openat|openat2)\(.*(O_WRONLY|O_RDWR|O_CREAT)|^[0-9]+ +(creat|mkdir|mkdirat|rmdir|unlink|unlinkat|rename|renameat|renameat2|link|linkat|symlink|symlinkat|truncate)\(' trace.txt |
              grep -v -- "= -1 E" | grep -vE '^[0-9]+ +unlinkat\([0-9]+, ' |
              sed -E 's/^([0-9]+ +(link|linkat|symlink|symlinkat)\()([^"]*"[^"]*")/\1/' |
              if [[ -n $mesher_pids ]]; then grep -vE "^($mesher_pids) +[a-z0-9]+\((AT_FDCWD, )?\"[^/]"; else cat; fi |
              grep -oE '"[^"]*"' | tr -d '"' |
              while read -r f; do
                case $f in
                  AT_FDCWD) ;;
                  /dev/null|/dev/tty|/dev/pts/*|/dev/shm/open_mpi.*|"${TMPDIR:-/tmp}"/ompi.*) ;;
                  knife_job|knife_job/*|"$PWD"/knife_job|"$PWD"/knife_job/*) ;;
                  *) echo "$f" ;;
                esac
              done | sort -u)
  [[ -z $outside ]] || { echo "written outside the output directory:"; echo "$outside"; exit 1; }
else
  echo "strace not installed: the write check skipped"
fi

# SIGTERM to a sweep: its child runs end with it
printf 'include %s\nset Walls = box\nsubsection Wall box\n  set Geometry = box\nend\n' "$src/tests/cli/small_bed.prm" > long.prm
"$abrade" sweep long.prm --vary "Particles/Generation/Count=20,21" --seeds 1,2 --jobs 2 \
  --wall box --output sweep --quiet --set "Simulation/Phases=long: 100" > /dev/null 2>&1 &
sweep=$!
# (signalled once a child run is in its cycle: its log exists)
for _ in $(seq 1 300); do compgen -G "sweep/runs/*/log.txt" > /dev/null && break; sleep 0.1; done
compgen -G "sweep/runs/*/log.txt" > /dev/null || { echo "no child run started"; exit 1; }
signalled=$(date +%s.%N)
kill -TERM $sweep
wait $sweep && { echo "the sweep ended 0 after SIGTERM"; exit 1; }
took=$(python3 -c "import sys, time; print(round(time.time() - float(sys.argv[1]), 1))" "$signalled")
python3 -c "import sys; sys.exit(float(sys.argv[1]) > 5)" "$took" ||
  { echo "the sweep took $took s to end after SIGTERM (its children were not told, or new ones started)"; exit 1; }
sleep 0.5
left=$(pgrep -fc -- "--output $PWD/sweep/runs" || true)
(( left == 0 )) || { echo "$left child run(s) still going after the sweep ended"; pkill -f -- "--output $PWD/sweep/runs"; exit 1; }
# no child run started after the signal: every run that started says it was interrupted
shopt -s nullglob
for s in sweep/runs/*/summary.json; do
  grep -q '"status": "interrupted' "$s" || { echo "$s: $(grep -o '"status": "[^"]*' "$s") (started after the signal?)"; exit 1; }
done
# SIGKILL to a sweep (nothing can be forwarded): its children end with it (parent-death signal)
rm -rf sweep
"$abrade" sweep long.prm --vary "Particles/Generation/Count=20,21" --seeds 1,2 --jobs 2 \
  --wall box --output sweep --quiet --set "Simulation/Phases=long: 100" > /dev/null 2>&1 &
sweep=$!
for _ in $(seq 1 300); do (( $(pgrep -fc -- "--output $PWD/sweep/runs") >= 1 )) && break; sleep 0.1; done
kill -KILL $sweep
wait $sweep 2>/dev/null || true
for _ in $(seq 1 50); do pgrep -f -- "--output $PWD/sweep/runs" > /dev/null || break; sleep 0.1; done
left=$(pgrep -fc -- "--output $PWD/sweep/runs" || true)
(( left == 0 )) || { echo "$left child run(s) still going 5 s after the sweep was killed"; pkill -f -- "--output $PWD/sweep/runs"; exit 1; }

# under MPI the ranks agree: a directory in use ends every rank (rank 1 once went on alone and
# the job hung)
if command -v mpirun > /dev/null; then
  "${life[@]}" --output mpi_busy --set "Lifetime/Maximum updates=3" > /dev/null 2>&1 &
  first=$!
  for _ in $(seq 1 300); do [[ -s mpi_busy/.abrade-lock ]] && break; sleep 0.05; done
  set +e # (mpirun adds its own lines: not expect_error.sh's single line)
  said=$(OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 timeout 60 mpirun -np 2 \
         --oversubscribe "$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --quiet --output mpi_busy 2>&1)
  rc=$?
  set -e
  [[ $rc -eq 2 ]] || { echo "mpirun on a directory in use: exit $rc (124: hung), not 2:"; echo "$said"; exit 1; }
  grep -q "mpi_busy: another abrade run (pid $first)" <<< "$said" || { echo "no refusal named:"; echo "$said"; exit 1; }
  echo "ok: under mpirun, a directory in use ends every rank (exit 2)"
  wait $first
fi
echo "output directories: the run's own"
