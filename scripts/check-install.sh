#!/usr/bin/env bash
# Installs a built Sinew into a scratch prefix and builds and runs a project outside the tree
# that finds it with find_package(sinew). Usage: scripts/check-install.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:?usage: $0 BUILD_DIR}
prefix="$build/install-check/prefix"
rm -rf "$build/install-check"
cmake --install "$build" --prefix "$prefix" >/dev/null
cmake -S "$root/examples/find_package_consumer" -B "$build/install-check/consumer" -G Ninja \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build/install-check/consumer" >/dev/null
"$build/install-check/consumer/consumer" \
  "$root/tests/data/osim/projectchrono/chrono/data/opensim/double_pendulum.osim" >/dev/null
echo "install check: find_package(sinew) consumer built and ran"
