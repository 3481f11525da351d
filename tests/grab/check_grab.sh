#!/usr/bin/env bash
# The coarse grab cycle end to end (cases/grab/grab_coarse.prm): no particle is lost in any
# phase (mass conservation), the grab body sinks into the pile and the closing lifts or lowers
# it as the material resists (the shells move as one body), the payload after hoisting is a
# plausible fraction of the closed shells' capacity times the pile's bulk density (20 ... 110 %
# of 0.151 m^3 x ~2200 kg/m^3: a coarse sanity bound, the measured value is in docs/grab.md),
# the knives' wear is reported per phase, and the hinge torques while closing (each shell with its
# knife, about the hinge axis y) are of opposite sign and similar size (mirror-image shells).
#   check_grab.sh ABRADE PRM OUTDIR
set -euo pipefail
bash "$(dirname "$0")/run_conserving_particles.sh" "$@" # (ABRADE PRM OUTDIR)
python3 - "$3" <<'PY'
import csv, json, sys, os
out = sys.argv[1]
phases = json.load(open(os.path.join(out, "summary.json")))["results"]["phases"]
payload = phases["hoisting"]["mass_above_payload_height"]
capacity = 3.14159265 / 2 * 0.4**2 * 0.6 * 2200
assert 0.2 * capacity < payload < 1.1 * capacity, f"payload {payload} kg against a capacity of {capacity:.0f} kg"
z = {}
for row in csv.DictReader(open(os.path.join(out, "walls", "right_forces.csv"))):
    z.setdefault(row["phase"], []).append(float(row["cz"]))
left = [float(r["cz"]) for r in csv.DictReader(open(os.path.join(out, "walls", "left_forces.csv")))]
right = [float(r["cz"]) for r in csv.DictReader(open(os.path.join(out, "walls", "right_forces.csv")))]
assert max(abs(a - b) for a, b in zip(left, right)) < 1e-12, "the shells parted"
assert z["sinking"][-1] < z["sinking"][0], "the grab did not sink into the pile"
wear = {r["phase"]: float(r["archard_volume"]) for r in csv.DictReader(open(os.path.join(out, "walls", "right_knife_wear.csv")))}
assert wear["closing"] > 0 and wear["total"] > 0
share = {p: wear[p] / wear["total"] for p in ("descent", "sinking", "closing", "hoisting", "opening")}
w = phases["closing"]["walls"]
hinge = {side: w[side]["mean_torque"][1] + w[side + "_knife"]["mean_torque"][1] for side in ("right", "left")}
assert hinge["right"] * hinge["left"] < 0, f"closing hinge torques of the same sign: {hinge}"
assert min(abs(v) for v in hinge.values()) > 100, f"no closing resistance: {hinge}"
assert max(abs(v) for v in hinge.values()) < 2 * min(abs(v) for v in hinge.values()), f"asymmetric: {hinge}"
print(f"ok: payload {payload:.1f} kg ({100 * payload / capacity:.0f} % of {capacity:.0f} kg); hinge "
      f"{z['sinking'][0]:.3f} -> {z['sinking'][-1]:.3f} m sinking, -> {z['closing'][-1]:.3f} m closing; "
      f"closing hinge torque {hinge['right']:.0f} / {hinge['left']:.0f} N m; "
      "wear share " + ", ".join(f"{p} {100 * v:.1f} %" for p, v in share.items()))
PY
