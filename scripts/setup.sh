#!/usr/bin/env bash
# Installs every dependency Sinew needs from Debian packages. Idempotent: quick when all is there.
set -euo pipefail
packages=(cmake ninja-build ccache g++ clang libclang-rt-14-dev
  libeigen3-dev libpugixml-dev libcli11-dev nlohmann-json3-dev zlib1g-dev libmuparser-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libbullet-dev libsundials-dev libsimbody-dev
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-distributed
  chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${missing[@]}"
fi

# three.js for the HTML viewer, pinned by web/package-lock.json (embedded into sinew at build).
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ ! -f "$repo_root/web/node_modules/three/package.json" ]; then
  if ! command -v npm >/dev/null; then
    sudo_cmd=""
    [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
    $sudo_cmd apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq npm
  fi
  echo "setup: installing web/ dependencies (npm ci)"
  (cd "$repo_root/web" && npm ci --no-audit --no-fund)
fi
