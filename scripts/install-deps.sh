#!/usr/bin/env bash
# Installs, with apt-get, exactly the Debian bookworm packages that abrade's build, tests and
# benchmarks need. Idempotent: packages already present are not touched and apt-get is not even
# called when nothing is missing. Works as root without sudo, with sudo otherwise, and with no
# terminal (DEBIAN_FRONTEND=noninteractive).
#
#   scripts/install-deps.sh            install what is missing
#   scripts/install-deps.sh --check    list what is missing, exit 1 if anything is
set -euo pipefail

packages=(
  # build
  cmake g++ make ccache pkg-config
  # FEM: deal.II 9.4 (brings PETSc+hypre, METIS, p4est, Gmsh API, OpenCASCADE, MPI)
  libdeal.ii-dev petsc-dev libmetis-dev libgmsh-dev
  # DEM and geometry I/O
  libeigen3-dev libvtk9-dev
  # parallel
  libopenmpi-dev openmpi-bin
  # tests (chromium: the run report opened in a headless browser)
  libgtest-dev numdiff chromium strace
  # in-process fuzzing of the readers (tests/fuzz/libfuzzer): clang with libFuzzer and the sanitizers
  clang libclang-rt-14-dev
  # benchmarks: the peer codes and the plots (matplotlib-free: gnuplot draws the PNGs)
  liggghts lammps python3 gnuplot-nox
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [[ "${1:-}" == "--check" ]]; then
  ((${#missing[@]})) && { printf 'missing: %s\n' "${missing[*]}"; exit 1; }
  echo "all dependencies present"; exit 0
fi

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

SUDO=""
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: not root and no sudo; install as root: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo -n"
fi
export DEBIAN_FRONTEND=noninteractive
echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" </dev/null
echo "install-deps: done"
