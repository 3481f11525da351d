#!/usr/bin/env bash
# A lifetime run does not hide what its DEM cycles flag (they were all dropped before):
#  1. a time step above a tenth of the Hertz contact time: the warning is in log.txt (also with
#     --quiet), counted in summary.json (dem_warnings) and per update in trajectory.csv;
#  2. a knife driven down at 1000 m/s: overlaps of half a radius, particles leave the domain;
#     with Simulation/On error = stop the run fails (exit 3, summary.json status "failed: ..."),
#     with continue it goes on and the faults are logged and counted;
#  3. an analytic rate of 0 (no wear): no life is predicted, exit 3 (it was "0 t", exit 0);
#     a rate that stops after 1000 t: no life either (it was extrapolated from the wear before);
#     a negative rate is an input error naming the point (exit 2).
#   check_dem_faults.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$(realpath "$1") src=$2 out=$3
rm -rf "$out" && mkdir -p "$out" && cd "$out"
expect="bash $src/tests/expect_error.sh"
small=("$abrade" run "$src/cases/lifetime/small.prm" --quiet --set "Lifetime/Maximum updates=1")
count() { # summary.json's dem_warnings, and trajectory.csv's last dem_warnings
  python3 - "$1" <<'PY'
import csv, json, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))["results"]["lifetime"]["dem_warnings"]
t = list(csv.DictReader(open(d + "/trajectory.csv")))[-1]["dem_warnings"]
print(s, int(float(t)))
PY
}
"${small[@]}" --output step --set "Simulation/Time step=3e-4" > /dev/null
grep -q "warning: update 1, DEM: seed 1: time step 0.0003 s exceeds a tenth of the Hertz contact time" step/log.txt
read -r total per_update < <(count step)
(( total >= 1 && per_update == total )) || { echo "time step warnings counted $total / $per_update"; exit 1; }

fast=(--set "Wall knife/Motion/Velocities=penetration: 0, 0, -1000")
$expect 3 "run failed: (overlap of|particle left the domain)" -- "${small[@]}" --output stop "${fast[@]}" --set "Simulation/On error=stop"
python3 -c "import json; s = json.load(open('stop/summary.json'))['status']; assert s.startswith('failed: overlap') or s.startswith('failed: particle left'), s"
"${small[@]}" --output continue "${fast[@]}" --set "Simulation/On error=continue" > /dev/null
grep -Eq "DEM: seed 1: (overlap of|particle left the domain)" continue/log.txt
read -r total per_update < <(count continue)
(( total >= 2 )) || { echo "lost particles counted $total"; exit 1; }

analytic=("$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --quiet --set "Lifetime/Maximum updates=2")
$expect 3 "run failed: no life predicted: no wear on the part" -- "${analytic[@]}" --output no_wear \
  --set "Lifetime/Analytic/Wear rate=0"
$expect 2 "Lifetime/Analytic/Wear rate: the rate is -1e-06 at \(" -- "${analytic[@]}" --output negative \
  --set "Lifetime/Analytic/Wear rate=-1e-6"
$expect 3 "run failed: no life predicted: the part stopped wearing after 1500 t" -- "${analytic[@]}" --output stops \
  --set "Lifetime/Analytic/Wear rate=1e-6*(t<1000)" --set "Lifetime/Maximum updates=5"
echo "DEM faults and wear-free runs: reported"
