#!/usr/bin/env bash
# The knife-bed described by its coarse-grained pellets (knife_bed.prm: 10,496 of 27.5 mm) and
# by the real ones coarse-grained by 4 (coarse_graining.prm: 671,744 of 6.875 mm, Factor = 4)
# is the same run: the same particles, time step and skin, so the same knife forces and wear,
# bit for bit (short phases). A rule that scales the count, a radius or the skin differently
# from the file's description changes the forces. Then the saved bed (27.5 mm) must be refused
# by a rerun at another factor.
#   check_coarse_graining_same_run.sh ABRADE CASE_DIR OUTDIR
set -euo pipefail
abrade=$1 cases=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
short=(--set "Simulation/Phases=penetration: 0.01, travel: 0.01" --set "Particles/Settling/Maximum time=0.02"
       --set "Simulation/Threads=1" --set "Output/Snapshot interval=0" --set "Output/Write particles=false" --quiet)
"$abrade" run "$cases/knife_bed.prm" --output "$out/direct" "${short[@]}"
"$abrade" run "$cases/coarse_graining.prm" --output "$out/coarse_grained" "${short[@]}"
grep -q "Coarse graining: the particles are 4 times the real ones" "$out/coarse_grained/log.txt" ||
  { echo "the coarse-grained run does not say so in its log"; exit 1; }
for f in walls/knife_forces.csv walls/knife_wear.csv walls/container_forces.csv; do
  cmp -s "$out/direct/$f" "$out/coarse_grained/$f" || { echo "$f differs:"; diff "$out/direct/$f" "$out/coarse_grained/$f" | head; exit 1; }
done
# the bed saved in the coarse-grained run's directory holds 27.5 mm pellets: a rerun there with
# another factor must not run on them
set +e
msg=$("$abrade" run "$cases/coarse_graining.prm" --output "$out/coarse_grained" "${short[@]}" \
        --set "Particles/Coarse graining/Factor=2" 2>&1)
rc=$?
set -e
[[ $rc -eq 2 ]] && grep -q "the bed's radii are 0.0275 m, the parameters give 0.01375 m" <<<"$msg" ||
  { echo "a bed of another factor was not refused (exit $rc):"; echo "$msg" | tail -3; exit 1; }
echo "ok: the coarse-grained description gives the same knife forces and wear, bit for bit; a bed of another factor is refused"
