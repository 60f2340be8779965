#!/usr/bin/env bash
# Configures and builds Sinew. Usage: scripts/build.sh [release|asan] (default release).
# Builds into build/<kind>. Warnings are errors in both kinds.
set -euo pipefail
kind=${1:-release}
root=$(cd "$(dirname "$0")/.." && pwd)
case "$kind" in
  release) flags=(-DCMAKE_BUILD_TYPE=Release) ;;
  asan) flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DSINEW_SANITIZE=ON -DSINEW_BUILD_BENCHMARKS=OFF) ;;
  *) echo "usage: $0 [release|asan]" >&2; exit 1 ;;
esac
cmake -S "$root" -B "$root/build/$kind" -G Ninja -DSINEW_WERROR=ON "${flags[@]}" >/dev/null
cmake --build "$root/build/$kind" -j "$(nproc)"
