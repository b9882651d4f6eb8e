#!/usr/bin/env bash
# Installs everything framedyn needs from Debian 12's packages (and nothing
# else): the compiler and CMake, the numerical libraries, the test framework,
# and CalculiX (ccx), the peer FE code the tests compare the beam model with.
# libhdf5-dev (HDF5's C library) writes the heavy data of the XDMF ParaView output;
# paraview + python3-paraview give pvbatch, with which a test reads that output
# back with ParaView's own readers (185 packages, 198 MB, about 1.5 min);
# gnuplot (gnuplot-nox) draws the PNG figures of `framedyn sweep` and `run --figures`;
# libopenmpi-dev + openmpi-bin (Debian's Open MPI): the MPI engine of `framedyn batch` (FRAMEDYN_MPI);
# clang with its runtime (libFuzzer, sanitizers) and its OpenMP (SUNDIALS's CMake
# package asks for OpenMP) builds the fuzz harnesses of tests/fuzz.
# pybind11-dev, python3-dev and python3-numpy build the Python module (python/),
# python3-pytest runs its tests, python3-matplotlib draws the figure of
# examples/python/offset_plowing.py (Debian's /usr/bin/python3 is the interpreter).
set -euo pipefail
packages=(
  g++ make cmake pkg-config
  libeigen3-dev libspectra-dev libsuitesparse-dev libsundials-dev
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libbenchmark-dev
  calculix-ccx calculix-ccx-test
  gnuplot-nox
  libhdf5-dev
  paraview python3-paraview
  clang libclang-rt-14-dev libomp-dev
  libopenmpi-dev openmpi-bin
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
