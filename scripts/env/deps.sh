#!/usr/bin/env bash
# Installs the Debian packages the project needs, only those missing (idempotent).
set -euo pipefail
PKGS=(cmake g++ make pkg-config python3-dev python3-numpy python3-pytest pybind11-dev python3-pybind11
      libopenmesh-dev libeigen3-dev libboost-dev libboost-graph-dev libgtest-dev libbenchmark-dev blender
      libpugixml-dev zlib1g-dev python3-meshio libcli11-dev nlohmann-json3-dev python3-venv ccache)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y "${missing[@]}"
fi
