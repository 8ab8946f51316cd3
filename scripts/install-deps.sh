#!/usr/bin/env bash
# Installs geomcheck's Debian build and test dependencies. Idempotent: packages
# already present are skipped, and apt-get runs only when something is missing.
set -euo pipefail
PKGS=(
  build-essential cmake ninja-build ccache pkg-config
  clang libclang-rt-14-dev
  libgtest-dev libgmock-dev librapidcheck-dev libbenchmark-dev
  libcgal-dev libfcl-dev libeigen3-dev libboost-dev libgmp-dev libmpfr-dev
  libcli11-dev nlohmann-json3-dev
  libode-dev libbullet-dev libmujoco-dev
  python3 python3-jsonschema
  chromium
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
