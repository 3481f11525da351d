#!/usr/bin/env bash
# Runs a small sweep (2 values x 2 seeds of the regression case) and checks its products:
# the study table has one row per value with finite means, the plots and surfaces exist, and
# the beds were made once per seed.
#   check_sweep.sh ABRADE PRM OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
rm -rf "$out"
"$abrade" sweep "$prm" --vary "Wall knife/Interaction/Friction=0,0.4" --seeds 1,2 --output "$out" --quiet
rows=$(tail -n +2 "$out/study.csv" | wc -l)
[[ $rows -eq 2 ]] || { echo "study.csv has $rows rows, expected 2"; exit 1; }
cut -d, -f1 "$out/study.csv" | tail -n +2 | tr '\n' ' ' | grep -q "^0 0.4 $" || { echo "unexpected values"; cat "$out/study.csv"; exit 1; }
if grep -qiE "nan|inf" "$out/study.csv"; then echo "non-finite values:"; cat "$out/study.csv"; exit 1; fi
for f in plots/wear.png plots/force.png plots/layer_velocity.png surfaces/knife_0_seed1.vtp surfaces/knife_0.4_seed2.vtp study.md; do
  [[ -s "$out/$f" ]] || { echo "missing $f"; exit 1; }
done
[[ $(ls "$out/beds" | wc -l) -eq 2 ]] || { echo "expected one bed per seed"; ls "$out/beds"; exit 1; }
echo "ok: sweep wrote study.csv (2 values), plots, surfaces and 2 beds"
