#!/usr/bin/env bash
# The coarse grab closed by its rope mechanism (cases/grab/grab_coarse_rope.prm) end to end: no
# particle is lost; lowered on its holding ropes the grab hangs
# open; released, it sinks into the pile; the closing winch closes the shells and the closing
# rope carries less than the grab's weight on average (the rest of the weight stands on the
# material); hoisted (not flung: it never rises at twice the winch's speed), it holds a plausible
# payload (20 ... 110 % of the closed shells' 0.151 m^3 x ~2200 kg/m^3); with the holding ropes
# taut, paying out the closing rope opens it; the mechanism's time series is written. The
# measured values are in docs/grab.md.
#   check_rope_grab.sh ABRADE PRM OUTDIR
set -euo pipefail
bash "$(dirname "$0")/run_conserving_particles.sh" "$@" # (ABRADE PRM OUTDIR)
python3 - "$3" "$(dirname "$0")" <<'PY'
import csv, sys, os
sys.path.insert(0, sys.argv[2])
from rope_grab_run import WEIGHT as weight, CAPACITY as capacity, phases_of
out = sys.argv[1]
phases, g = phases_of(out)
assert g["descent"]["shell_angle_end"] < 0.5, f"the grab closed while lowered open: {g['descent']}"
assert g["descent"]["hinge_height_end"] < 1.0, "not lowered"
assert g["sinking"]["hinge_height_end"] < g["sinking"]["hinge_height_start"] - 0.05, "did not sink into the pile"
assert g["closing"]["shell_angle_end"] > 40, f"did not close: {g['closing']}"
assert g["closing"]["closing_rope_tension_mean"] < weight, "the closing rope lifted the grab off the material"
payload = phases["hoisting"]["mass_above_payload_height"]
assert 0.2 * capacity < payload < 1.1 * capacity, f"payload {payload} kg against a capacity of {capacity:.0f} kg"
assert g["hoisting"]["hinge_height_end"] > g["hoisting"]["hinge_height_start"] + 0.8, "not hoisted"
assert g["opening"]["shell_angle_end"] < g["opening"]["shell_angle_start"] - 15, f"did not open: {g['opening']}"
rows = list(csv.DictReader(open(os.path.join(out, "grab_mechanism.csv"))))
assert {r["phase"] for r in rows} == set(phases), "grab_mechanism.csv misses phases"
# hoisted, not flung: the grab never rises at twice the winch's 1 m/s; the holding ropes are
# taut when the opening starts (they take the grab as the closing rope pays out)
fastest = max(float(r["hinge_velocity"]) for r in rows if r["phase"] == "hoisting")
assert fastest < 2.0, f"the grab was flung up at {fastest:.2f} m/s"
first_opening = next(r for r in rows if r["phase"] == "opening")
assert float(first_opening["holding_rope_tension"]) > 0, "the holding ropes are slack when the opening starts"
print(f"ok: hinge {g['sinking']['hinge_height_start']:.3f} -> {g['sinking']['hinge_height_end']:.3f} m sinking, "
      f"-> {g['closing']['hinge_height_end']:.3f} m closing (shells {g['closing']['shell_angle_end']:.1f} deg, "
      f"closing rope {g['closing']['closing_rope_tension_mean'] / 1e3:.2f} kN mean); payload {payload:.1f} kg "
      f"({100 * payload / capacity:.0f} % of {capacity:.0f} kg); opened to {g['opening']['shell_angle_end']:.1f} deg")
PY
