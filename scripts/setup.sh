#!/usr/bin/env bash
# One-step set-up: installs missing Debian packages (scripts/install-deps.sh), configures a
# Release build in build/ and compiles it with all cores. Safe to run again: nothing is
# reinstalled, and the build is incremental (ccache speeds up rebuilds from scratch).
#   scripts/setup.sh [extra cmake arguments]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >build-configure.log 2>&1 ||
  { cat build-configure.log; echo "setup: cmake configuration failed (log above)" >&2; exit 1; }
jobs=$(nproc 2>/dev/null || echo 2)
cmake --build build -j"$jobs"
echo "setup: build ready: $root/build/abrade"
