#!/usr/bin/env bash
# Sets up, builds and runs every test: a Release build, then the same tests under ASan+UBSan.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
for kind in release asan; do
  echo "== $kind build"
  bash "$root/scripts/build.sh" "$kind"
  echo "== $kind tests"
  (cd "$root/build/$kind" && ctest --output-on-failure -j "$(nproc)")
  if [ "$kind" = release ]; then bash "$root/scripts/check-install.sh" "$root/build/release"; fi
done
# The .osim reader's fuzz target, for a bounded time (needs clang with libFuzzer).
echo "== fuzz (60 s)"
bash "$root/scripts/fuzz.sh" 60
