#!/usr/bin/env bash
# Install soma's build and run dependencies on Debian 12 (run as root; idempotent).
set -euo pipefail
packages=(
  build-essential clang-14 libclang-rt-14-dev lld cmake ninja-build ccache pkg-config git
  libeigen3-dev libmpfr-dev libgmp-dev libmpfrc++-dev
  libfmt-dev nlohmann-json3-dev libcli11-dev libpng-dev libtbb-dev
  libosmesa6-dev libfreetype-dev fonts-dejavu-core
  catch2 libbenchmark-dev liborocos-kdl-dev
  libcgal-dev libceres-dev libnlopt-cxx-dev libompl-dev libboost-filesystem-dev
  liburdfdom-dev
  phcpack
  libopenmpi-dev openmpi-bin   # soma sweep under mpirun (SOMA_MPI, found automatically; issue 26)
  python3 python3-jsonschema
  # the Python module (python/, issue 23), its tests and notebooks (tests/python/, examples/python/)
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-mpmath python3-pytest
  python3-matplotlib python3-nbclient python3-nbformat python3-ipykernel
  # the report's browser tests, search and 3-D viewer (issue 25)
  chromium libjs-lunr libjs-three
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "bootstrap: all ${#packages[@]} packages already installed"
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "bootstrap: missing packages (${missing[*]}); run this script as root" >&2
  exit 1
fi
echo "bootstrap: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
