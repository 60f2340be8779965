#!/usr/bin/env bash
# Sets up, builds and runs every test: a Release build (then every benchmark once, briefly, so
# none can rot), the install check, the same tests under ASan+UBSan, and the fuzz targets.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
for kind in release asan; do
  echo "== $kind build"
  bash "$root/scripts/build.sh" "$kind"
  echo "== $kind tests"
  (cd "$root/build/$kind" && ctest --output-on-failure -j "$(nproc)")
  if [ "$kind" = release ]; then
    bash "$root/scripts/check-install.sh" "$root/build/release"
    echo "== benchmarks (each once, minimal time: they must run, the timings mean little)"
    bash "$root/scripts/run-benchmarks.sh" "$root/build/release" --quick >/dev/null
  fi
done
# The fuzz targets (readers and the build-and-simulate path), 100 s in all (needs clang with
# libFuzzer).
echo "== fuzz (100 s over all targets)"
bash "$root/scripts/fuzz.sh" 100
