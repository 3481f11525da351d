#!/usr/bin/env bash
# The coarse rope grab's whole cycle (cases/grab/grab_coarse_rope_hopper.prm) end to end: no
# particle is lost; closing from the moment it lands, its holding ropes slack, the shells turn
# at least nine tenths of the way to their closed stop; hoisted, the grab holds a plausible
# payload (20 ... 110 % of the closed shells' 0.151 m^3 x ~2200 kg/m^3); the trolley carries it
# 1.6 m over the hopper, where it opens and the payload pours out over the knives (which wear
# while it does); at rest, the hopper carries the discharged payload's weight (its vertical wall
# force against the mass that left the grab: 3 %). The hinge's path while closing is printed
# (docs/grab.md compares it with the same grab left to sink with its closing winch idle).
#   check_rope_hopper.sh ABRADE PRM OUTDIR
set -euo pipefail
bash "$(dirname "$0")/run_conserving_particles.sh" "$@" # (ABRADE PRM OUTDIR)
python3 - "$3" "$(dirname "$0")" <<'PY'
import csv, sys, os
sys.path.insert(0, sys.argv[2])
from rope_grab_run import CAPACITY as capacity, phases_of
out = sys.argv[1]
phases, g = phases_of(out)
closing = g["closing"]
rows = list(csv.DictReader(open(os.path.join(out, "grab_mechanism.csv"))))
closed_angle = 56.4
landed = closing["hinge_height_start"]
nearly = next((r for r in rows if r["phase"] == "closing" and float(r["shell_angle"]) >= 0.9 * closed_angle), None)
assert nearly is not None, f"the shells did not close: {closing}"
closed = float(nearly["hinge_height"])
payload = phases["hoisting"]["mass_above_payload_height"]
assert 0.2 * capacity < payload < 1.1 * capacity, f"payload {payload} kg against a capacity of {capacity:.0f} kg"
carried = phases["travel"]["mass_above_payload_height"] # (a grab not quite closed spills some on the way)
assert carried > 0.9 * payload, f"{payload - carried:.1f} kg of the payload spilled while travelling"
travelled = g["opening"]["trolley_position_end"]
assert abs(travelled - 1.6) < 0.01, f"the trolley went {travelled} m, not 1.6"
assert g["opening"]["shell_angle_end"] < 5, f"did not open: {g['opening']}"
left = phases["settling"]["mass_above_payload_height"]
assert left < 0.02 * payload, f"{left} kg of the payload stayed in the grab"
rows = list(csv.DictReader(open(os.path.join(out, "walls", "hopper_forces.csv"))))
end = float(rows[-1]["time"])
last = [-float(r["fz"]) / 9.81 for r in rows if r["phase"] == "settling" and float(r["time"]) > end - 0.2]
in_hopper = sum(last) / len(last)
assert abs(in_hopper - (carried - left)) < 0.03 * carried, \
    f"the hopper carries {in_hopper:.1f} kg, the grab discharged {carried - left:.1f} kg"
share = {}
for knife in ("right_knife", "left_knife"):
    wear = {r["phase"]: float(r["archard_volume"]) for r in csv.DictReader(open(os.path.join(out, "walls", knife + "_wear.csv")))
            if r["phase"] != "total"}
    assert wear["opening"] > 0, f"no wear on {knife} while the payload poured out over it"
    share[knife] = {p: 100 * w / sum(wear.values()) for p, w in wear.items()}
print(f"ok: hinge {landed:.3f} m at landing -> {closed:.3f} m nine tenths closed (lowest {closing['hinge_height_lowest']:.3f}); "
      f"payload {payload:.1f} kg ({100 * payload / capacity:.0f} % of {capacity:.0f} kg); trolley {travelled:.3f} m; "
      f"hopper {in_hopper:.1f} kg of {carried - left:.1f} kg discharged; knife wear closing / opening: "
      + ", ".join(f"{k} {s['closing']:.1f} / {s['opening']:.1f} %" for k, s in share.items()))
PY
