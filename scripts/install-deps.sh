#!/usr/bin/env bash
# Installs the Debian packages wheelwear needs, and only those that are missing: a no-op when
# everything is present. --mpi adds Open MPI, for a build with WHEELWEAR_MPI (the tests' build;
# docs/cluster.md). Usage: scripts/install-deps.sh [--mpi]
set -euo pipefail

packages=(
  cmake g++ make pkg-config clang libclang-rt-14-dev
  libeigen3-dev libcgal-dev libboost-dev libhdf5-dev hdf5-tools libssl-dev libtbb-dev
  libcli11-dev libtomlplusplus-dev libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-dev python3-numpy python3-h5py python3-matplotlib
  pybind11-dev python3-pytest python3-mypy
)
case "${1:-}" in
  --mpi) packages+=(libopenmpi-dev openmpi-bin) ;;
  "") ;;
  *)
    echo "install-deps.sh: unknown option '$1'; usage: scripts/install-deps.sh [--mpi]" >&2
    exit 2
    ;;
esac

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if ((EUID != 0)); then sudo_cmd=(sudo); fi
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
