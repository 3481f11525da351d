#!/usr/bin/env bash
# Runs a grab case and checks that no particle is lost: none left the domain (the log) and every
# phase ends with the particles it began with (summary.json). The grab checks start here.
#   run_conserving_particles.sh ABRADE PRM OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
rm -rf "$out"
"$abrade" run "$prm" --output "$out" --quiet > /dev/null
# (a test, not a bare '! grep': set -e does not stop on a command negated with '!')
if grep "left the domain" "$out/log.txt"; then echo "particles left the domain"; exit 1; fi
python3 - "$out/summary.json" <<'PY'
import json, sys
phases = json.load(open(sys.argv[1]))["results"]["phases"]
counts = {p: v["particles"] for p, v in phases.items()}
assert len(set(counts.values())) == 1, f"particles lost: {counts}"
PY
