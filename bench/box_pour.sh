#!/usr/bin/env bash
# Throughput of abrade against LAMMPS (the second peer; Debian `lammps`, pair granular) on a case
# both codes run: the knife-bed's 10,496 pellets poured into its container (a box of planar
# walls), 5000 steps. abrade places the pellets once (its unsettled bed); LAMMPS reads them as a
# data file and abrade loads the same bed, so both start from one state. Both run on one core
# (abrade: one rank, one thread), in turn N times (default 3); the medians of the particle-steps
# per second and their ratio are reported, with each code's pellets left at the end and the
# height of the bed's centre of mass as a check that both ran the same physics.
#
#   bench/box_pour.sh [--repeat N] [--output DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
abrade=${ABRADE:-$root/build/abrade} # (ABRADE: another build, e.g. a copy taken before rebuilding)
repeat=3 out=""
while (($#)); do
  case $1 in
    --repeat) repeat=$2; shift 2 ;;
    --output) out=$2; shift 2 ;;
    *) echo "usage: $0 [--repeat N] [--output DIR]" >&2; exit 2 ;;
  esac
done
[[ -x $abrade ]] || { echo "build abrade first: scripts/setup.sh" >&2; exit 2; }
command -v lmp >/dev/null || { echo "lammps not installed: scripts/install-deps.sh" >&2; exit 2; }
out=${out:-$(mktemp -d /tmp/abrade-pour.XXXXXX)}
mkdir -p "$out"
case=$root/bench/box_pour.prm
"$abrade" run "$case" --quiet --output "$out/place" --set Job=bed --set "Particles/Settling/Bed file=$out/initial.bed" \
  > /dev/null
python3 - "$out/initial.bed" "$out/initial.data" <<'PY'
import struct, sys
b = open(sys.argv[1], "rb").read()
n = struct.unpack_from("<Q", b, 8)[0]
x, y, z, vx, vy, vz, wx, wy, wz, r, m = (struct.unpack_from(f"<{n}d", b, 24 + 8 * n * k) for k in range(11))
with open(sys.argv[2], "w") as f:
    f.write(f"abrade's unsettled knife-bed\n\n{n} atoms\n1 atom types\n-1.05 1.05 xlo xhi\n-1.05 1.05 ylo yhi\n"
            "-0.05 1.3 zlo zhi\n\nAtoms # sphere\n\n")
    for i in range(n):  # id type diameter density x y z
        rho = m[i] / (4 / 3 * 3.141592653589793 * r[i] ** 3)
        f.write(f"{i + 1} 1 {2 * r[i]!r} {rho!r} {x[i]!r} {y[i]!r} {z[i]!r}\n")
    f.write("\nVelocities\n\n")
    for i in range(n):
        f.write(f"{i + 1} {vx[i]!r} {vy[i]!r} {vz[i]!r} 0 0 0\n")
PY
: > "$out/runs.txt" # code particles steps seconds particles_at_end zcm_at_end
for ((rep = 1; rep <= repeat; ++rep)); do
  d=$out/lammps-$rep
  mkdir -p "$d"
  ( cd "$d" && OMP_NUM_THREADS=1 lmp -in "$root/bench/lammps/box_pour.in" -var data "$out/initial.data" -log log.lammps \
      -screen none )
  awk '/^Loop time of/ { t = $4; s = $9; n = $12 } $1 ~ /^[0-9]+$/ && NF == 4 { last = $2 " " $4 }
       END { print "lammps", n, s, t, last }' "$d/log.lammps" >> "$out/runs.txt"
  OMP_NUM_THREADS=1 "$abrade" run "$case" --quiet --output "$out/abrade-$rep" --set "Simulation/Threads=1" \
    --set "Particles/Settling/Bed file=$out/initial.bed" > /dev/null
  python3 - "$out/abrade-$rep" >> "$out/runs.txt" <<'PY'
import json, sys
r = json.load(open(sys.argv[1] + "/summary.json"))["results"]
p = r["phases"]["pour"]
print("abrade", p["particles"], p["steps"], f"{p['steps'] * p['particles'] / p['particle_steps_per_second']:.4f}",
      r["particles"], p["centre_of_mass_z"])
PY
done
python3 - "$out/runs.txt" <<'PY' | tee "$out/results.md"
import statistics, sys
runs = [l.split() for l in open(sys.argv[1]) if l.strip()]
rate = lambda r: int(r[1]) * int(r[2]) / float(r[3])
med = {c: statistics.median(rate(r) for r in runs if r[0] == c) for c in ("lammps", "abrade")}
print("Box pour (the knife-bed's 10,496 pellets into its container, 5000 steps), one core each\n")
print("| code | particles | steps | median particle-steps/s | ratio abrade / LAMMPS | runs | pellets at the end | "
      "centre of mass at the end [m] |")
print("|---|---|---|---|---|---|---|---|")
for c in ("lammps", "abrade"):
    sel = [r for r in runs if r[0] == c]
    print(f"| {c} | {sel[0][1]} | {sel[0][2]} | {med[c]:.4g} | {med[c] / med['lammps']:.2f} | {len(sel)} | {sel[0][4]} | "
          f"{float(sel[0][5]):.4f} |")
PY
echo "command: bench/box_pour.sh --repeat $repeat" | tee -a "$out/results.md"
