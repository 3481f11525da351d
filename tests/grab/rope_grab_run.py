# What the coarse rope grab's checks (check_rope_grab.sh, check_rope_hopper.sh) read of a run:
# summary.json's phases and their `grab` records, and the grab's weight and capacity as its
# case builds it (cases/grab/grab_coarse_rope.prm).
import json, os

WEIGHT = 500 * 9.81  # [N] two shells, two heads
CAPACITY = 3.14159265 / 2 * 0.4**2 * 0.6 * 2200  # [kg] the closed shells' half cylinder x ~2200 kg/m^3


def phases_of(out):
    """The phases of summary.json in OUT, and each one's `grab` record."""
    phases = json.load(open(os.path.join(out, "summary.json")))["results"]["phases"]
    return phases, {p: v["grab"] for p, v in phases.items()}
