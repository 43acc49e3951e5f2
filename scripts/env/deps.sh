#!/usr/bin/env bash
# Installs the Debian packages the project needs (the list is in scripts/env/common.sh), only those
# missing, with apt-get (through sudo when not root). Idempotent. scripts/test.sh and .ci/run run it;
# scripts/build.sh only checks the list and names this script.
set -euo pipefail
source "$(dirname "$0")/common.sh"
mapfile -t missing < <(hbc_missing_packages)
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y "${missing[@]}"
fi
